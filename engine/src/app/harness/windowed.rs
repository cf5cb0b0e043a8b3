//! Playing a game in a window inside the engine's shell, as every game binary does by default:
//! [`play_windowed`] opens the window (`window::run_game`: title menu, HUD, pause, settings,
//! the player's folders) with the render configuration game binaries share — the tracer
//! `auto` picks (the CPU one on machines without a GPU) at 640×360 and 1 spp, workload
//! scaling holding 30 fps, denoised unless asked not to — and the game's [`WindowedPlay`]
//! (its window title, its folder name, the shell's cues, the stats overlay).
//!
//! Main thread (the window's event loop; the render thread renders). Must not: set the game's
//! input up (a replay or a recording is started on the game before) or read what it did.

use super::config::{HarnessError, HarnessGame};
use crate::app::persist::UserDirs;
use crate::app::shell::{Cue, ShellConfig};
use crate::app::window::{WindowConfig, WindowReport, run_game};
use crate::render::scaling::ScalingTarget;
use crate::render::{RenderConfig, TracerChoice};

/// What a game binary asks of its windowed run.
#[derive(Debug, Default)]
pub struct WindowedPlay {
    /// The window's title.
    pub title: String,
    /// The game's name for the player's config, data and save folders (`UserDirs::from_env`).
    pub app: String,
    /// The shell's cues (screenshots, a level started at once, quit); none for a player.
    pub cues: Vec<Cue>,
    /// Show the stats overlay from the start (F3 toggles it).
    pub stats: bool,
    /// Denoise each frame before it is shown.
    pub denoise: bool,
    /// Under a physical sky, the most exposure (stops) the sky's meter may set: the meter
    /// reads the sky alone, so at night it would expose for starlight and blow out a
    /// torch-lit scene (`None`: no cap).
    pub max_exposure_ev: Option<f32>,
}

/// Plays `game` (of `config`'s game) in a window until the player or a cue quits.
pub fn play_windowed<C: HarnessGame>(
    config: &C,
    game: &mut C::Game,
    play: WindowedPlay,
) -> Result<WindowReport, HarnessError> {
    let window = WindowConfig {
        title: play.title,
        show_stats: play.stats,
        // A level under a physical sky is exposed for its time of day (noon and night read).
        auto_exposure: true,
        max_exposure_ev: play.max_exposure_ev.unwrap_or(f32::INFINITY),
        ..WindowConfig::default()
    };
    let shell = ShellConfig {
        dirs: UserDirs::from_env(&play.app)?,
        cues: play.cues,
    };
    let environment = config.environment(game);
    let render = RenderConfig {
        tracer: TracerChoice::Auto,
        denoise: play.denoise,
        scaling: Some(ScalingTarget::new(1.0 / 30.0)),
        // A sun turned fast (an altar) must not stall the frames: the sky's table follows on a
        // worker thread.
        sky_rebuild: crate::scene::SkyRebuild::Background,
        ..RenderConfig::cpu(640, 360)
    };
    Ok(run_game(window, shell, render, environment, game)?)
}
