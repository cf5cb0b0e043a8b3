//! Converged captures of a game as the player sees it: [`capture_converged`] sets a prepared
//! game up (the game put the player where the picture is taken), lets the start settle for
//! [`SETTLE_FRAMES`] frames, then holds the game (nothing steps: the still image converges,
//! where a standing capsule would otherwise settle by fractions of a millimetre, enough to
//! restart it) and renders frames on the CPU tracer, one sample per pixel each, blended; the
//! last film is written as a PNG.
//!
//! Main thread (the render thread renders). Must not: change the game beyond holding it.

use std::path::Path;

use super::config::{HarnessError, HarnessGame};
use crate::app::runner::{Engine, Game};
use crate::render::RenderConfig;
use crate::render::film::{TonemapSettings, write_png};

/// Frames played before the game is held (the player lands, a room's lights come on).
pub const SETTLE_FRAMES: u32 = 30;

/// Renders `game` (made by `config`, already placed) for `frames` frames at `width` ×
/// `height` once settled and writes the last film to `png`; returns the samples per pixel it
/// holds. `label` names the picture in errors.
pub fn capture_converged<C: HarnessGame>(
    config: &C,
    mut game: C::Game,
    (width, height): (u32, u32),
    frames: u32,
    png: &Path,
    label: &str,
) -> Result<u32, HarnessError> {
    let mut engine = Engine::new(RenderConfig::cpu(width, height), config.environment(&game))?;
    game.setup(&mut engine)
        .map_err(|e| HarnessError::Setup(e.to_string()))?;
    for _ in 0..SETTLE_FRAMES {
        engine.frame(1.0 / 60.0, &mut game)?;
        let _ = engine.rendered();
    }
    engine.set_paused(true);
    let mut last = None;
    for f in 0..frames {
        if f + 1 == frames {
            engine.capture_next();
        }
        engine.frame(1.0 / 60.0, &mut game)?;
        for r in engine.rendered().into_iter().flatten() {
            if r.film.is_some() {
                last = Some(r);
            }
        }
    }
    while last.is_none() {
        match engine.wait_rendered() {
            Some(Ok(r)) if r.film.is_some() => last = Some(r),
            Some(Ok(_)) => {}
            Some(Err(e)) => return Err(e.into()),
            None => break,
        }
    }
    let _ = engine.shutdown();
    let Some(film) = last.and_then(|r| r.film) else {
        return Err(HarnessError::NoFilm {
            level: label.to_string(),
        });
    };
    write_png(
        png,
        film.width,
        film.height,
        &film.mean,
        &TonemapSettings::default(),
    )?;
    Ok(film.samples)
}
