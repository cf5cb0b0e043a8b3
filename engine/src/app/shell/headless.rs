//! [`run_headless`]: the shell's loop without a window — the same per-frame calls as the
//! window runner (`before_frame`, egui on a screen of a given size, `after_ui`,
//! `Engine::frame`, `after_frame`), with the overlay built but not shown. Tests use it to play
//! the menus, change settings and restart; tools to run a game's menus on a machine without
//! a display.
//!
//! Main thread. Must not: open a window (there is none).

use super::run::ShellRun;
use crate::app::runner::Game;
use crate::app::runner::{Engine, EngineError};
use crate::commit::PresentRequest;
use crate::render::film::TonemapSettings;

/// Runs up to `frames` frames of `frame_seconds` each on a `size` (pixels) screen, stopping
/// early when the player quits; returns the frames run. The game must be set up already
/// (`Game::setup`) and `shell` made for this engine.
pub fn run_headless(
    engine: &mut Engine,
    game: &mut dyn Game,
    shell: &mut ShellRun,
    frames: u32,
    frame_seconds: f64,
    size: (u32, u32),
) -> Result<u32, EngineError> {
    let ctx = egui::Context::default();
    for n in 0..frames {
        shell.before_frame(engine, game);
        if shell.wants().exit {
            shell.finish();
            return Ok(n);
        }
        let input = egui::RawInput {
            screen_rect: Some(egui::Rect::from_min_size(
                egui::Pos2::ZERO,
                egui::vec2(size.0 as f32, size.1 as f32),
            )),
            ..Default::default()
        };
        let _ = ctx.run_pass(input, |ctx| shell.ui(ctx));
        shell.after_ui(engine, game);
        engine.present_next(PresentRequest {
            surface_size: size,
            tonemap: TonemapSettings::default(),
            vsync: shell.wants().vsync,
            overlay: None,
            screenshot: false,
            scaling: Some(shell.scaling_goal()),
        });
        let report = engine.frame(frame_seconds, game)?;
        shell.after_frame(engine, &report);
    }
    shell.finish();
    Ok(frames)
}
