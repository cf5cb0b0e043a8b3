//! What the render thread does when the GPU goes away mid-run (a driver reset, a GPU unplugged
//! or hung: wgpu's device-lost): the frame in hand is rendered again on the CPU tracer, which
//! renders every frame after it, and one message says so. A window's presenter, whose device
//! is the same one, is reopened on whatever device the window can get. A scene the GPU tracer
//! cannot render ([`RenderError::Unsupported`]) falls back the same way.
//!
//! Owns: [`fall_back`] (is this error a lost device? then swap in the CPU tracer) and the
//! message. Render thread only. Must not: retry the lost device (a lost wgpu device never
//! comes back) or hide any other error.

use super::cpu::CpuTracer;
use super::tracer::{RenderError, Tracer};

/// If `error` comes from a lost device (it is [`RenderError::DeviceLost`], or `tracer` says
/// its device is lost), replaces `tracer` with a [`CpuTracer`] and returns the one message
/// (also logged at warn level); so does [`RenderError::Unsupported`] (the GPU tracer has no
/// twin for what the scene asks); any other error comes back as it was.
pub(super) fn fall_back(
    tracer: &mut Box<dyn Tracer>,
    error: RenderError,
) -> Result<String, RenderError> {
    if let RenderError::Unsupported(reason) = &error {
        let message = format!(
            "the {} tracer cannot render this scene ({reason}); the CPU tracer takes over for \
             the rest of the run",
            tracer.name()
        );
        log::warn!("{message}");
        *tracer = Box::new(CpuTracer::new());
        return Ok(message);
    }
    let reason = match (&error, tracer.device_lost()) {
        (RenderError::DeviceLost(reason), _) => reason.clone(),
        (_, Some(reason)) => reason,
        _ => return Err(error),
    };
    let message = format!(
        "the GPU device was lost ({reason}); the {} tracer is replaced by the CPU tracer \
         for the rest of the run",
        tracer.name()
    );
    log::warn!("{message}");
    *tracer = Box::new(CpuTracer::new());
    Ok(message)
}
