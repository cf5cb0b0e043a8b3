//! `playground LEVEL --soak FRAMES [--seed N]`: the soak. The level runs headless in first
//! person on the CPU tracer (32×18), one fixed step a frame, with the seeded monkey
//! (`candela::app::Monkey`) at the controls: walking, looking, jumping, using, picking up and
//! throwing at random. Every frame it checks that no entity's transform holds NaN or infinity
//! and that nothing fell through the world (below `KILL_Y`); every `FILM_EVERY` frames it reads
//! the film back and checks every pixel is finite; it measures resident memory after the
//! warm-up (a tenth of the run) and at the end. Any failure ends the soak with an error
//! naming the frame and what broke.
//!
//! Main thread. Must not: change the level or the game (it only drives and watches).

use anyhow::bail;
use candela::app::{Engine, FirstPersonGame, Game, Monkey, StepInput};
use candela::ecs::Transform;
use candela::render::RenderConfig;

/// Nothing in a test level lies this far below the origin (metres).
const KILL_Y: f32 = -100.0;
/// Frames between film checks.
const FILM_EVERY: u64 = 500;

/// What a soak saw.
#[derive(Clone, Debug)]
pub struct SoakReport {
    pub frames: u64,
    pub film_checks: u64,
    /// Resident memory after the warm-up and at the end, bytes (0 where `/proc` is missing).
    pub rss_warm: u64,
    pub rss_end: u64,
}

/// Resident set size of this process, bytes (Linux `/proc/self/statm`; 0 elsewhere).
fn rss_bytes() -> u64 {
    std::fs::read_to_string("/proc/self/statm")
        .ok()
        .and_then(|s| s.split_whitespace().nth(1)?.parse::<u64>().ok())
        .map_or(0, |pages| pages * 4096)
}

/// Soaks `game` for `frames` frames with the monkey seeded by `seed`.
pub fn soak(mut game: FirstPersonGame, frames: u64, seed: u64) -> anyhow::Result<SoakReport> {
    let mut engine = Engine::new(RenderConfig::cpu(32, 18), game.environment())?;
    game.setup(&mut engine)
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    engine.set_step_input(StepInput::Monkey(Monkey::new(seed)));
    let warm_up = frames / 10;
    let mut report = SoakReport {
        frames: 0,
        film_checks: 0,
        rss_warm: 0,
        rss_end: 0,
    };
    for frame in 0..frames {
        let check_film = frame % FILM_EVERY == FILM_EVERY - 1;
        if check_film {
            engine.capture_next();
        }
        engine.frame(1.0 / 60.0, &mut game)?;
        check_world(&engine, frame)?;
        if check_film {
            // The captured frame is rendered after this one's hand-off: wait for it.
            loop {
                let Some(result) = engine.wait_rendered() else {
                    bail!("frame {frame}: the render thread stopped");
                };
                let rendered = result?;
                if let Some(film) = rendered.film {
                    if let Some(i) = film.mean.iter().position(|p| !p.is_finite()) {
                        bail!("frame {frame}: film pixel {i} is {}", film.mean[i]);
                    }
                    report.film_checks += 1;
                    break;
                }
            }
        } else {
            for result in engine.rendered() {
                result?;
            }
        }
        if frame == warm_up {
            report.rss_warm = rss_bytes();
        }
        report.frames = frame + 1;
    }
    report.rss_end = rss_bytes();
    let _ = engine.shutdown();
    Ok(report)
}

fn check_world(engine: &Engine, frame: u64) -> anyhow::Result<()> {
    let world = engine.world();
    let mut query = world.query::<(hecs::Entity, &Transform)>();
    for (entity, t) in query.iter() {
        let finite = t.translation.is_finite() && t.rotation.is_finite() && t.scale.is_finite();
        if !finite {
            bail!("frame {frame}: entity {entity:?} has a non-finite transform {t:?}");
        }
        if t.translation.y < KILL_Y {
            bail!(
                "frame {frame}: entity {entity:?} fell through the world (y = {} m)",
                t.translation.y
            );
        }
    }
    Ok(())
}
