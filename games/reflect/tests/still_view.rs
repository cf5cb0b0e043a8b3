//! A still view converges (issue 37): the player stands at each chamber's start, touching
//! nothing, under the game's render settings (CPU tracer, 1 spp at the start, workload scaling
//! holding 30 fps), and the converging blend of the displayed film falls below 0.05 — the
//! picture becomes the mean of twenty and more frames instead of one frame's noise — and stays
//! there. Before the fix the camera's rotation measure (`2·acos(q·q)`) read a still pose as a
//! turn of 0.7 mrad on many headings, and the image restarted on every frame (blend 1.000).
//!
//! The player is turned to an arbitrary heading first, as one who looked around and stopped.
//!
//! Counted in frames, not seconds: the test holds on any machine speed. Workload scaling may
//! lower the resolution a few times at the start (each a restart); it never raises it while
//! the view is still, so the count of restarts is bounded.

use candela::app::{Engine, Game};
use candela::render::scaling::ScalingTarget;
use candela::render::{RenderConfig, TracerChoice};
use reflect::game::ReflectGame;
use reflect::world::ReflectWorld;

/// Frames each chamber stands still; the blend must be below 0.05 by the end.
const FRAMES: usize = 90;

#[test]
fn a_still_view_converges_in_every_chamber_at_game_settings() -> anyhow::Result<()> {
    let (path, root) = reflect::cli::locate(None)?;
    let world = ReflectWorld::load(&path, &root)?;
    let mut failures = Vec::new();
    for (index, chamber) in world.chambers.iter().enumerate() {
        let mut game = ReflectGame::new(world.clone(), index);
        let config = RenderConfig {
            tracer: TracerChoice::Cpu,
            scaling: Some(ScalingTarget::new(1.0 / 30.0)),
            ..RenderConfig::cpu(640, 360)
        };
        let mut engine = Engine::new(config, game.inner().environment())?;
        game.setup(&mut engine)
            .map_err(|e| anyhow::anyhow!("{e}"))?;
        // A player who looked around and stopped: an arbitrary heading, a little down.
        let player = game
            .inner_mut()
            .player_mut()
            .ok_or_else(|| anyhow::anyhow!("{}: no player", chamber.id))?;
        player.yaw += 0.731 + 1.37 * index as f32;
        player.pitch = -0.21;
        let mut blends = Vec::new();
        let mut films = Vec::new();
        for frame in 0..FRAMES {
            // Frame times as a window sees them: uneven, so the physics interpolation factor
            // differs every frame.
            let dt = 1.0 / 30.0 + 0.023 * ((frame as f64 * 1.618).fract() - 0.5);
            engine.frame(dt, &mut game)?;
            for rendered in engine.rendered().into_iter().flatten() {
                blends.push(rendered.blend);
                films.push(rendered.film_size);
            }
        }
        let _ = engine.shutdown();
        let last = blends.last().copied().unwrap_or(1.0);
        // The tail must be an exact running mean: each blend below the one before.
        let tail = &blends[blends.len().saturating_sub(10)..];
        let decreasing = tail.windows(2).all(|w| w[1] < w[0]);
        if blends.len() < FRAMES / 2 || last >= 0.05 || !decreasing {
            failures.push(format!(
                "{}: {} frames rendered, last blend {last:.3}; blends {:?}; film sizes {:?}",
                chamber.id,
                blends.len(),
                blends,
                films
            ));
        }
    }
    assert!(
        failures.is_empty(),
        "a still view did not converge:\n{}",
        failures.join("\n")
    );
    Ok(())
}
