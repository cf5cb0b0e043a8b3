//! The window runner's entry points: [`run_window`] drives a [`Game`] in a winit 0.30 window
//! through the same `Engine::frame` loop as headless runs, presenting every frame on the render
//! thread; [`run_game`] runs a game inside the shell (`app/shell/`). The event handling itself
//! is in `app.rs` and `events.rs` (the per-run state in `running.rs`). Main thread (or any
//! thread on X11). Must not: render or present (the render thread does), or hold game rules.

use super::app::WindowApp;
use super::config::{WindowConfig, WindowError, WindowReport, display_problem};
use crate::app::input::InputMap;
use crate::app::runner::{Environment, Game};
use crate::app::shell::ShellConfig;
use crate::render::RenderConfig;

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
