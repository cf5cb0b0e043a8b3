//! A still view converges (issue 37): the player stands at each chamber's start, touching
//! nothing, under the game's render settings (CPU tracer, 1 spp at the start, workload scaling
//! holding 30 fps), and the converging blend of the displayed film falls below 0.05 — the
//! picture becomes the mean of twenty and more frames instead of one frame's noise — and once
//! the player has landed, the image restarts only when workload scaling lowers the resolution. Before the fix the camera's rotation measure (`2·acos(q·q)`) read a still pose as a
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

/// Frames each chamber stands still; the blend must fall below 0.05 on the way.
const FRAMES: usize = 90;
/// Frames in which the player spawns and lands (its eye moves by millimetres).
const SETTLE_FRAMES: usize = 20;

#[test]
fn a_still_view_converges_in_every_chamber_at_game_settings() -> anyhow::Result<()> {
    let (path, root) = reflect::cli::locate(None)?;
    let world = ReflectWorld::load(&path, &root)?;
    let mut failures = Vec::new();
    // The game denoises by default (`--denoise`); the raw film converges by the same policy.
    for denoise in [true, false] {
        for (index, chamber) in world.chambers.iter().enumerate() {
            let mut game = ReflectGame::new(world.clone(), index);
            let config = RenderConfig {
                tracer: TracerChoice::Cpu,
                denoise,
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
            // Restarts once the player has settled (the first frames spawn and land it): only
            // workload scaling may restart a still view, by lowering the resolution (a load spike
            // on a shared machine), never raising it, and never with the film size unchanged.
            let settled = SETTLE_FRAMES.min(blends.len());
            let stray: Vec<usize> = (settled.max(1)..blends.len())
                .filter(|&i| blends[i] >= 1.0 && films[i] == films[i - 1])
                .collect();
            let grew = (settled.max(1)..films.len())
                .any(|i| films[i].0 * films[i].1 > films[i - 1].0 * films[i - 1].1);
            let best = blends[settled..].iter().copied().fold(1.0f32, f32::min);
            if blends.len() < FRAMES / 2 || best >= 0.05 || !stray.is_empty() || grew {
                failures.push(format!(
                "{} (denoise {denoise}): {} frames rendered, lowest blend {best:.3} after the first {settled}, \
                 restarts without a resize at frames {stray:?}, film grew: {grew}; blends {:?}; \
                 film sizes {:?}",
                chamber.id,
                blends.len(),
                blends,
                films
            ));
            }
        }
    }
    assert!(
        failures.is_empty(),
        "a still view did not converge:\n{}",
        failures.join("\n")
    );
    Ok(())
}
