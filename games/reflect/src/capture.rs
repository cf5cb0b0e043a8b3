//! `reflect --capture DIR`: a converged picture of every chamber as the player sees it, for
//! the README and `docs/`: the chamber started as from the menu, the player's eye put at the
//! chamber file's own `camera`, nothing pressed, the game paused once settled, frames rendered
//! on the CPU tracer until the still image has converged, the last one written as `DIR/<chamber>.png`.
//!
//! Owns: [`capture_chambers`]. Main thread (the render thread renders). Must not: change the
//! game.

use std::path::Path;

use candela::app::{Engine, Game};
use candela::assets::Level;
use candela::render::RenderConfig;
use candela::render::film::{TonemapSettings, write_png};

use crate::game::ReflectGame;
use crate::world::ReflectWorld;

/// Renders every chamber for `frames` frames at `width` × `height` (one sample per pixel per
/// frame, blended while nothing moves); returns the files written.
pub fn capture_chambers(
    world: &ReflectWorld,
    dir: &Path,
    width: u32,
    height: u32,
    frames: u32,
) -> anyhow::Result<Vec<String>> {
    std::fs::create_dir_all(dir)?;
    let mut written = Vec::new();
    for (i, chamber) in world.chambers.iter().enumerate() {
        let camera = Level::read(&world.files[i + 1])?.camera;
        let mut game = ReflectGame::new(world.clone(), i);
        game.start_at_view(&candela::extract::RenderCamera::from_desc(&camera));
        let mut engine = Engine::new(RenderConfig::cpu(width, height), game.inner().environment())?;
        game.setup(&mut engine)
            .map_err(|e| anyhow::anyhow!("{e}"))?;
        // Let the start settle (the player lands, the lights of the room come on).
        for _ in 0..30 {
            engine.frame(1.0 / 60.0, &mut game)?;
            let _ = engine.rendered();
        }
        // Paused, nothing steps: the still image converges (the player's capsule would
        // otherwise settle by fractions of a millimetre, enough to restart it).
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
                None => anyhow::bail!("{}: the render thread stopped", chamber.id),
            }
        }
        let _ = engine.shutdown();
        let Some(film) = last.and_then(|r| r.film) else {
            anyhow::bail!("{}: no film", chamber.id);
        };
        let path = dir.join(format!("{}.png", chamber.id));
        write_png(
            &path,
            film.width,
            film.height,
            &film.mean,
            &TonemapSettings::default(),
        )?;
        eprintln!("{}: {} samples per pixel", path.display(), film.samples);
        written.push(path.display().to_string());
    }
    Ok(written)
}
