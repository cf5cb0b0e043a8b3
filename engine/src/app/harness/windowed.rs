//! Playing a game in a window inside the engine's shell, as every game binary does by default:
//! [`play_windowed`] opens the window (`window::run_game`: title menu, HUD, pause, settings,
//! the player's folders) with the render configuration game binaries share — the tracer
//! `auto` picks (the CPU one on machines without a GPU) at 640×360 and 1 spp, workload
//! scaling holding the frame rate and resolution floor the level declares (`render:
//! (target_fps, min_scale)`, default 30 fps and ¼; the player's own target frame rate from the
//! settings screen wins), denoised unless asked not to — and the game's [`WindowedPlay`]
//! (its window title, its folder name, the shell's cues, the stats overlay).
//!
//! Main thread (the window's event loop; the render thread renders). Must not: set the game's
//! input up (a replay or a recording is started on the game before) or read what it did.

use super::config::{HarnessError, HarnessGame};
use crate::app::persist::UserDirs;
use crate::app::runner::Environment;
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
    let render = windowed_render(&environment, play.denoise);
    Ok(run_game(window, shell, render, environment, game)?)
}

/// The render configuration of windowed play in a level of `environment`: the tracer `auto`
/// picks at 640×360, 1 spp, workload scaling holding what the level declares; the denoiser's
/// guides from the CPU tracer's first hits (no guide pass).
pub fn windowed_render(environment: &Environment, denoise: bool) -> RenderConfig {
    RenderConfig {
        tracer: TracerChoice::Auto,
        denoise,
        scaling: Some(ScalingTarget::of_level(&environment.render)),
        // A sun turned fast (an altar) must not stall the frames: the sky's table follows on a
        // worker thread.
        sky_rebuild: crate::scene::SkyRebuild::Background,
        first_hit_guides: true,
        ..RenderConfig::cpu(640, 360)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assets::{Level, SkyDesc};
    use std::path::Path;

    /// The environment of a level whose `render` field is `render`.
    fn environment(render: &str) -> Result<Environment, crate::assets::AssetError> {
        let text = format!(
            "Level(camera: (position: (0, 1, 3), look_at: (0, 1, 0), vertical_fov_deg: 40), \
             render: {render})"
        );
        let level = Level::parse(Path::new("level.ron"), &text)?;
        Ok(Environment {
            sun: None,
            sky: SkyDesc::default(),
            render: level.render,
            default_camera: level.camera,
        })
    }

    #[test]
    fn a_level_at_20_fps_is_held_at_20() -> Result<(), Box<dyn std::error::Error>> {
        let level = environment("(max_bounces: 2, target_fps: 20, min_scale: 0.5)")?;
        let target = windowed_render(&level, true)
            .scaling
            .ok_or("windowed play without workload scaling")?;
        assert_eq!(target.frame_seconds, 1.0 / 20.0);
        assert_eq!(target.min_resolution, 0.5);
        Ok(())
    }

    #[test]
    fn a_level_declaring_nothing_is_held_at_30() -> Result<(), Box<dyn std::error::Error>> {
        let target = windowed_render(&environment("(max_bounces: 3)")?, true)
            .scaling
            .ok_or("windowed play without workload scaling")?;
        assert_eq!(target, ScalingTarget::new(1.0 / 30.0));
        Ok(())
    }

    /// Play takes the denoiser's guides from the CPU tracer's first hits (no guide pass;
    /// `docs/PERFORMANCE.md`), and denoises unless told not to.
    #[test]
    fn play_denoises_with_the_first_hits_guides() -> Result<(), Box<dyn std::error::Error>> {
        let level = environment("(max_bounces: 3)")?;
        let on = windowed_render(&level, true);
        assert!(on.denoise && on.first_hit_guides);
        assert!(!windowed_render(&level, false).denoise);
        Ok(())
    }
}
