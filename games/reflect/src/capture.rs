//! `reflect --capture DIR`: a converged picture of every chamber as the player sees it, for
//! the README and `docs/`: the chamber started as from the menu, the player's eye put at the
//! chamber file's own `camera`, nothing pressed; the engine's harness
//! (`candela::app::harness::capture_converged`) lets it settle, holds the game and renders on
//! the CPU tracer until the still image has converged, the last one written as
//! `DIR/<chamber>.png`.
//!
//! Owns: [`capture_chambers`] (where each chamber's picture is taken from). Main thread (the render thread renders). Must not: change the
//! game.

use std::path::Path;

use candela::app::harness::{HarnessGame, capture_converged};
use candela::assets::Level;

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
    let mut written = Vec::new();
    for (i, chamber) in world.chambers.iter().enumerate() {
        let camera = Level::read(&world.files[i + 1])?.camera;
        let mut game = world.new_game(i);
        game.start_at_view(&candela::extract::RenderCamera::from_desc(&camera));
        let path = dir.join(format!("{}.png", chamber.id));
        let samples = capture_converged(world, game, (width, height), frames, &path, &chamber.id)?;
        eprintln!("{}: {samples} samples per pixel", path.display());
        written.push(path.display().to_string());
    }
    Ok(written)
}
