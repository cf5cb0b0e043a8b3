//! The window runner: a winit 0.30 window driving the same [`Engine::frame`] loop as headless
//! runs, presenting every frame on the render thread.
//!
//! Owns: [`WindowConfig`] (size, fullscreen, vsync, frame limiter, exposure, overlay, input
//! map, a frame count with a screenshot, the stop flag Ctrl-C sets), [`run_window`] (which
//! drives a [`Game`]) and its [`WindowReport`] and typed [`WindowError`]s. The event
//! handling itself is in `window_app.rs` (the per-run state in `window_running.rs`), and
//! [`run_game`] runs a game inside the shell (`app/shell/`). Main thread (or any thread on X11).
//! Must not: render or present (the render thread does), or hold game rules.

use std::ffi::OsStr;
use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::AtomicBool;

use super::engine::{EngineError, Environment};
use super::game::Game;
use super::input::InputMap;
use super::shell::ShellConfig;
use super::stats::FrameStats;
use super::window_app::WindowApp;
use crate::render::film::{ImageIoError, TonemapSettings};
use crate::render::{RenderConfig, RenderError};

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

impl Default for WindowConfig {
    fn default() -> Self {
        Self {
            title: "Candela".into(),
            size: (1280, 720),
            fullscreen: false,
            vsync: true,
            max_fps: None,
            tonemap: TonemapSettings::default(),
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
    Game(super::game::SetupError),
    #[error("screenshot: {0}")]
    Screenshot(#[from] ImageIoError),
    #[error("input recording: {0}")]
    Recording(#[from] super::replay_error::ReplayError),
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

/// Runs `game` inside the shell (`app::shell`): title menu, HUD, pause, settings, editor hook,
/// ending; the player's settings and progress from `shell.dirs`, applied live and saved.
/// `config.input` is replaced by the runner's keys ([`InputMap::runner_keys`]) next to the
/// game's actions with the player's bindings; the settings decide vsync, fullscreen and the
/// frame limiter, and workload scaling follows the target frame rate and resolution scale.
/// Escape pauses (and frees the mouse); Resume or a click in the playing window captures it.
pub fn run_game(
    mut config: WindowConfig,
    shell: ShellConfig,
    render: RenderConfig,
    environment: Environment,
    game: &mut dyn Game,
) -> Result<WindowReport, WindowError> {
    config.input = InputMap::runner_keys();
    run_loop(config, render, environment, game, Some(shell))
}

/// Opens a window, starts the engine presenting into it (`render` gives the tracer, spp, seed,
/// converging and scaling; its size is replaced by the window's), calls `game.start`, and runs
/// frames until the window closes, the stop flag is set or `config.frames` are done. The render
/// thread is joined before this returns. Winit allows one event loop per process.
pub fn run_window(
    config: WindowConfig,
    render: RenderConfig,
    environment: Environment,
    game: &mut dyn Game,
) -> Result<WindowReport, WindowError> {
    run_loop(config, render, environment, game, None)
}

fn run_loop(
    config: WindowConfig,
    render: RenderConfig,
    environment: Environment,
    game: &mut dyn Game,
    shell: Option<ShellConfig>,
) -> Result<WindowReport, WindowError> {
    if let Some(problem) = display_problem(std::env::var_os("DISPLAY").as_deref()) {
        return Err(problem);
    }
    let mut builder = winit::event_loop::EventLoop::builder();
    #[cfg(any(
        target_os = "linux",
        target_os = "dragonfly",
        target_os = "freebsd",
        target_os = "netbsd",
        target_os = "openbsd"
    ))]
    {
        // Tests and tools may run the loop off the process's first thread; X11 allows it.
        use winit::platform::x11::EventLoopBuilderExtX11;
        builder.with_any_thread(true);
    }
    let event_loop = builder.build().map_err(|e| {
        WindowError::NoDisplay(format!(
            "cannot open the display {:?}: {e}",
            std::env::var("DISPLAY").unwrap_or_default()
        ))
    })?;
    event_loop.set_control_flow(winit::event_loop::ControlFlow::Poll);
    let mut app = WindowApp::new(config, render, environment, game, shell);
    event_loop
        .run_app(&mut app)
        .map_err(|e| WindowError::Window(e.to_string()))?;
    app.into_outcome()
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
