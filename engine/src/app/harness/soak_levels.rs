//! The soak over a game's levels: [`soak_levels`] soaks each chosen level in turn from its own
//! start (`soak::soak`: the seeded monkey at the controls, every frame checked) and keeps, per
//! level, the soak's report and what the game wants noted of its game afterwards (mirrors
//! made, events). The table is the game's.
//!
//! Main thread (the render thread renders as in play). Must not: change the game.

use super::config::{HarnessError, HarnessGame};
use super::soak::{SoakReport, soak};

/// What one level's soak saw: its id, the engine's checks, the game's own notes.
#[derive(Clone, Debug)]
pub struct LevelSoak<N> {
    /// The level's id.
    pub id: String,
    /// The engine's checks and memory.
    pub report: SoakReport,
    /// What `note` read from the game after the soak.
    pub note: N,
}

/// Soaks levels `levels` (indices into `config.level_ids()`) for `frames` frames each with
/// the monkey seeded `seed`; the first failure names the level and the seed.
pub fn soak_levels<C: HarnessGame, N>(
    config: &C,
    levels: &[usize],
    frames: u64,
    seed: u64,
    mut note: impl FnMut(&C::Game) -> N,
) -> Result<Vec<LevelSoak<N>>, HarnessError> {
    let ids = config.level_ids();
    let mut out = Vec::new();
    for &index in levels {
        let id = ids.get(index).cloned().unwrap_or_else(|| index.to_string());
        let mut game = config.new_game(index);
        let environment = config.environment(&game);
        let report =
            soak(&mut game, environment, frames, seed).map_err(|source| HarnessError::Soak {
                level: id.clone(),
                seed,
                source,
            })?;
        out.push(LevelSoak {
            id,
            report,
            note: note(&game),
        });
    }
    Ok(out)
}
