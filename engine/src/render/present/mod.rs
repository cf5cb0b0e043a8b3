//! Presenting in a window (render thread only): the surface, composing the tonemapped film and
//! the egui overlay into the window's frame, screenshots of what the window shows.

mod compose;
mod overlay;
mod presenter;
mod readback;
mod surface;

pub use compose::{FrameComposer, FrameTarget};
pub use overlay::{OverlayPainter, TexturesToFree};
pub use presenter::{Presented, Presenter};
pub use readback::Screenshot;
pub use surface::{Acquired, PresentTarget, WindowSurface};
