//! Presenting in a window (render thread only): the surface, composing the tonemapped film and
//! the egui overlay into the window's frame (by the present shader, or for the CPU tracer's
//! film on the CPU: `cpu_compose`, `cpu_overlay`, shown through softbuffer: `soft`),
//! screenshots of what the window shows.

mod compose;
mod cpu_compose;
mod cpu_compose_rows;
mod cpu_overlay;
mod cpu_overlay_raster;
mod overlay;
mod presenter;
mod readback;
mod soft;
mod surface;

pub use compose::{FrameComposer, FrameTarget};
pub use cpu_compose::{HostCompose, PixelLayout, catmull_rom, compose_host_film};
pub use cpu_overlay::CpuOverlay;
pub use overlay::{OverlayPainter, TexturesToFree};
pub use presenter::{Presented, Presenter};
pub use readback::Screenshot;
pub use surface::{Acquired, PresentTarget, WindowSurface};
