//! What a window run is given and what it gives back: [`WindowConfig`] (size, fullscreen,
//! vsync, frame limiter, exposure, overlay, input map, a frame count with a screenshot, the stop
//! flag Ctrl-C sets), [`WindowReport`], how the run ended ([`WindowEnd`]) and its typed
//! [`WindowError`]s, and whether a display is there at all ([`display_problem`]).
//!
//! Kept apart from the entry points (`run.rs`) so that the per-run work (`app.rs`) names these
//! types without depending on the function that starts it. Plain data, main thread. Must not:
//! open a window.

use std::ffi::OsStr;
use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::AtomicBool;

use crate::app::input::InputMap;
use crate::app::runner::EngineError;
use crate::app::runner::FrameStats;
use crate::render::RenderError;
use crate::render::film::{ImageIoError, TonemapSettings};

/// How the window runs.
#[derive(Clone, Debug)]
pub struct WindowConfig {
    pub title: String,
    /// Inner size at start, physical pixels (the render size follows the window).
    pub size: (u32, u32),
    /// Start in borderless fullscreen (F11 toggles).
    pub fullscreen: bool,
    /// Present with FIFO (wait for vertical blank); otherwise mailbox or immediate (F4 toggles).
    pub vsync: bool,
    /// Start frames at most this often (frames per second); `None`: as fast as they come.
    /// Vsync does not pace under Xvfb, so tests and captures rely on this.
    pub max_fps: Option<f64>,
    pub tonemap: TonemapSettings,
    /// Expose each frame for the physical sky's light now (`Engine::sky_exposure_ev`, in
    /// place of `tonemap.exposure_ev`: a function of the time of day, as capture scripts'
    /// `render.auto_exposure`, so noon and night both read); with other skies, or off,
    /// `tonemap` as it is.
    pub auto_exposure: bool,
    /// With `auto_exposure`: the most exposure the sky's meter may set, stops (it reads the
    /// sky alone; a game lit by torches at night caps it).
    pub max_exposure_ev: f32,
    /// Show the stats overlay from the start (F3 toggles).
    pub show_stats: bool,
    pub input: InputMap,
    /// Leave after this many frames.
    pub frames: Option<u64>,
    /// With `frames`: write what the window showed on the last frame here (8-bit sRGB PNG).
    pub screenshot: Option<PathBuf>,
    /// With `frames`: keep the last frame on screen this long (seconds) before closing.
    pub hold_seconds: f64,
    /// Set it (from a Ctrl-C handler, another thread, a test) to leave at the next frame.
    pub stop: Arc<AtomicBool>,
}

impl WindowConfig {
    /// The tonemap for the frame `engine` is about to present (see [`Self::auto_exposure`]).
    pub fn tonemap_now(&self, engine: &mut crate::app::runner::Engine) -> TonemapSettings {
        let sky = if self.auto_exposure {
            engine.sky_exposure_ev()
        } else {
            None
        };
        TonemapSettings {
            exposure_ev: sky.map_or(self.tonemap.exposure_ev, |ev| ev.min(self.max_exposure_ev)),
            ..self.tonemap
        }
    }
}

impl Default for WindowConfig {
    fn default() -> Self {
        Self {
            title: "Candela".into(),
            size: (1280, 720),
            fullscreen: false,
            vsync: true,
            max_fps: None,
            tonemap: TonemapSettings::default(),
            auto_exposure: false,
            max_exposure_ev: f32::INFINITY,
            show_stats: true,
            input: InputMap::fly_camera_defaults(),
            frames: None,
            screenshot: None,
            hold_seconds: 0.0,
            stop: Arc::new(AtomicBool::new(false)),
        }
    }
}

/// Why the window loop ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WindowEnd {
    /// The configured frame count was reached.
    Frames,
    /// The window was closed (or Escape pressed with the mouse free).
    Closed,
    /// The stop flag was set (Ctrl-C).
    Stopped,
    /// The player chose Quit in the shell's menus.
    Quit,
}

/// What a window run did.
#[derive(Clone, Debug)]
pub struct WindowReport {
    pub frames: u64,
    pub seconds: f64,
    pub ended_by: WindowEnd,
    /// Where the screenshot was written.
    pub screenshot: Option<PathBuf>,
    /// The client area's top-left corner on the screen at the end, physical pixels.
    pub inner_position: Option<(i32, i32)>,
    /// The client area's size at the end, physical pixels.
    pub inner_size: (u32, u32),
    pub stats: FrameStats,
}

/// Errors of the window runner.
#[derive(Debug, thiserror::Error)]
pub enum WindowError {
    #[error(
        "no display: {0}. Render without a window instead: `cargo run --release -p capture -- \
         <level.ron> --out frame.png` (see README.md), or start a virtual display, e.g. \
         `Xvfb :99 -screen 0 1280x720x24 -nolisten tcp &` and run with DISPLAY=:99"
    )]
    NoDisplay(String),
    #[error("window system: {0}")]
    Window(String),
    #[error(transparent)]
    Engine(#[from] EngineError),
    #[error(transparent)]
    Render(#[from] RenderError),
    #[error("game setup: {0}")]
    Game(crate::app::runner::SetupError),
    #[error("screenshot: {0}")]
    Screenshot(#[from] ImageIoError),
    #[error("input recording: {0}")]
    Recording(#[from] crate::app::replay::ReplayError),
}

/// Why no window can open with this `DISPLAY` value, if so (this build talks X11; Wayland
/// desktops provide XWayland and set `DISPLAY`).
pub fn display_problem(display: Option<&OsStr>) -> Option<WindowError> {
    match display {
        None => Some(WindowError::NoDisplay("DISPLAY is not set".into())),
        Some(d) if d.is_empty() => Some(WindowError::NoDisplay("DISPLAY is empty".into())),
        Some(_) => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn without_a_display_it_says_so_and_points_to_headless_mode() {
        for display in [None, Some(OsStr::new(""))] {
            let message = display_problem(display).map(|e| e.to_string());
            let message = message.unwrap_or_default();
            assert!(message.starts_with("no display"), "{message}");
            assert!(
                message.contains("capture") && message.contains("Xvfb"),
                "{message}"
            );
        }
        assert!(display_problem(Some(OsStr::new(":99"))).is_none());
    }
}
