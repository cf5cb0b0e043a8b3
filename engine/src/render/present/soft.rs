//! The CPU film's present without wgpu (render thread): a `softbuffer` surface on the window,
//! whose buffer (on X11 with MIT-SHM a shared-memory segment the X server reads) the CPU
//! compose and overlay write directly as `0RGB` words, then one X11 put of the frame. Which
//! path a host film takes is [`HostPresent`] (`CANDELA_PRESENT`).
//!
//! Why: on the wgpu path a host film's bytes are copied by `queue.write_texture`, then by
//! lavapipe into the swapchain image, then put to the X server by lavapipe's `queue.present`
//! (3–5 ms of the present under Xvfb, docs/PERFORMANCE.md); here only the put remains.
//!
//! Owns: [`SoftSurface`] and [`HostPresent`]. Must not: touch the wgpu device, or panic when
//! softbuffer cannot start or fails (the presenter then falls back to the wgpu path).

use std::num::NonZeroU32;
use std::sync::{Arc, OnceLock};
use std::time::Instant;

use softbuffer::SoftBufferError;
use winit::event_loop::OwnedDisplayHandle;
use winit::window::Window;

use super::readback::Screenshot;
use super::surface::PresentTarget;

/// How the presenter shows a host film (the CPU tracer's). A device film (the GPU tracer's)
/// always takes the present shader.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum HostPresent {
    /// Composed on the CPU into softbuffer's buffer and put to the window (the default,
    /// `CANDELA_PRESENT=softbuffer`); the wgpu path when softbuffer cannot start.
    Softbuffer,
    /// Composed on the CPU and copied into the wgpu surface texture (`CANDELA_PRESENT=wgpu`).
    Wgpu,
    /// Through the present shader (`CANDELA_PRESENT=shader`, or `CANDELA_PRESENT_SHADER=1`).
    Shader,
}

impl HostPresent {
    /// The choice `CANDELA_PRESENT` (and the older `CANDELA_PRESENT_SHADER`) ask for, read once.
    pub(super) fn from_env() -> Self {
        static CHOICE: OnceLock<HostPresent> = OnceLock::new();
        *CHOICE.get_or_init(|| {
            let shader = std::env::var_os("CANDELA_PRESENT_SHADER").is_some_and(|v| v == "1");
            Self::parse(std::env::var("CANDELA_PRESENT").ok().as_deref(), shader)
        })
    }

    /// `present` as `CANDELA_PRESENT` gives it (unset, empty or `auto`: softbuffer); `shader`
    /// when `CANDELA_PRESENT_SHADER=1`. softbuffer's words are native-endian `0RGB`, which
    /// the compose writes as bytes only for a little-endian machine: elsewhere, wgpu.
    pub(super) fn parse(present: Option<&str>, shader: bool) -> Self {
        let chosen = match present.map(str::trim) {
            Some("wgpu") => HostPresent::Wgpu,
            Some("shader") => HostPresent::Shader,
            _ if shader => HostPresent::Shader,
            None | Some("" | "auto" | "softbuffer") => HostPresent::Softbuffer,
            Some(other) => {
                log::warn!(
                    "CANDELA_PRESENT={other:?} is none of softbuffer, wgpu, shader: using softbuffer"
                );
                HostPresent::Softbuffer
            }
        };
        if chosen == HostPresent::Softbuffer && cfg!(target_endian = "big") {
            return HostPresent::Wgpu;
        }
        chosen
    }
}

/// A softbuffer surface on the window.
pub(super) struct SoftSurface {
    _context: softbuffer::Context<OwnedDisplayHandle>,
    surface: softbuffer::Surface<OwnedDisplayHandle, Arc<Window>>,
    /// The buffer's size in physical pixels ((0, 0) before the first frame).
    size: (u32, u32),
}

impl SoftSurface {
    /// Connects to the window's display and makes a surface on `target`'s window.
    pub(super) fn open(target: &PresentTarget) -> Result<Self, SoftBufferError> {
        let context = softbuffer::Context::new(target.display.clone())?;
        let surface = softbuffer::Surface::new(&context, Arc::clone(&target.window))?;
        Ok(Self {
            _context: context,
            surface,
            size: (0, 0),
        })
    }

    /// Shows one frame of `size` (physical pixels; nothing for a zero side): `draw` writes all
    /// of it into the buffer, 4 bytes a pixel (B, G, R, 0 on a little-endian machine), rows
    /// top to bottom; then it is put to the window. With `screenshot`, also returns the frame
    /// as RGBA. Logs (debug) the milliseconds since `started` as the presenter's other paths do.
    pub(super) fn frame(
        &mut self,
        size: (u32, u32),
        screenshot: bool,
        started: Instant,
        draw: impl FnOnce(&mut [u8]),
    ) -> Result<Option<Screenshot>, SoftBufferError> {
        let (Some(width), Some(height)) = (NonZeroU32::new(size.0), NonZeroU32::new(size.1)) else {
            return Ok(None);
        };
        if self.size != size {
            self.surface.resize(width, height)?;
            self.size = size;
        }
        // Waits for the X server to finish reading the previous frame's shared memory.
        let mut buffer = self.surface.buffer_mut()?;
        log::debug!(
            "present ms: acquire {:.2}",
            started.elapsed().as_secs_f64() * 1e3
        );
        let bytes: &mut [u8] = bytemuck::cast_slice_mut(&mut buffer[..]);
        draw(bytes);
        let shot = screenshot.then(|| xrgb_screenshot(bytes, size));
        let drawn = started.elapsed().as_secs_f64();
        buffer.present()?;
        log::debug!(
            "present ms: softbuffer: acquire+compose+overlay {:.2} present {:.2}",
            drawn * 1e3,
            (started.elapsed().as_secs_f64() - drawn) * 1e3
        );
        Ok(shot)
    }
}

/// `bytes` (B, G, R, x pixels of `size`, rows top to bottom) as a screenshot (R, G, B, 255).
fn xrgb_screenshot(bytes: &[u8], size: (u32, u32)) -> Screenshot {
    Screenshot {
        width: size.0,
        height: size.1,
        rgba: bytes
            .chunks_exact(4)
            .flat_map(|p| [p[2], p[1], p[0], 255])
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_setting_picks_the_path_and_softbuffer_is_the_default() {
        let soft = if cfg!(target_endian = "little") {
            HostPresent::Softbuffer
        } else {
            HostPresent::Wgpu
        };
        assert_eq!(HostPresent::parse(None, false), soft);
        assert_eq!(HostPresent::parse(Some(""), false), soft);
        assert_eq!(HostPresent::parse(Some("softbuffer"), false), soft);
        assert_eq!(HostPresent::parse(Some("nonsense"), false), soft);
        assert_eq!(HostPresent::parse(Some("wgpu"), false), HostPresent::Wgpu);
        assert_eq!(HostPresent::parse(Some("wgpu"), true), HostPresent::Wgpu);
        assert_eq!(
            HostPresent::parse(Some("shader"), false),
            HostPresent::Shader
        );
        assert_eq!(HostPresent::parse(None, true), HostPresent::Shader);
    }

    #[test]
    fn a_screenshot_of_the_softbuffer_bytes_is_rgba() {
        let shot = xrgb_screenshot(&[10, 20, 30, 0, 1, 2, 3, 0], (2, 1));
        assert_eq!(shot.rgba, [30, 20, 10, 255, 3, 2, 1, 255]);
        assert_eq!(shot.rgb(1, 0), Some([3, 2, 1]));
    }
}
