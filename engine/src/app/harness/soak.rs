//! The soak: any [`Game`] played headless for many frames with the seeded [`Monkey`] at the
//! controls, one fixed step a frame on the CPU tracer at 32×18, watched for what must never
//! happen. Every frame: no entity's transform holds NaN or infinity and nothing lies below
//! [`KILL_Y`]; every [`FILM_EVERY`] frames: the film is read back and every pixel is finite;
//! resident memory is read after the warm-up (a tenth of the run) and at the end. The first
//! failure ends the soak with a [`SoakError`] naming the frame and what broke.
//!
//! Owns: [`soak`], [`SoakReport`], [`SoakError`]. Main thread (the render thread renders as in
//! play). Must not: change the game or its level (it only drives and watches).

use crate::ecs::Transform;
use crate::render::{RenderConfig, RenderError};

use crate::app::replay::{Monkey, StepInput};
use crate::app::runner::{Engine, EngineError, Environment, Game};

/// Nothing in a level lies this far below the origin (metres).
pub const KILL_Y: f32 = -100.0;
/// Frames between film checks.
pub const FILM_EVERY: u64 = 500;
/// Film size of the soak (pixels): small, since the soak is about the game, not the picture.
pub(super) const FILM: (u32, u32) = (32, 18);

/// What a soak saw.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SoakReport {
    /// Frames played (one fixed step each).
    pub frames: u64,
    /// Films read back and found finite.
    pub film_checks: u64,
    /// Resident memory after the warm-up and at the end, bytes (0 where `/proc` is missing).
    pub rss_warm: u64,
    pub rss_end: u64,
}

impl SoakReport {
    /// Growth of resident memory from the warm-up to the end, bytes (negative: it shrank).
    pub fn growth(&self) -> i64 {
        self.rss_end as i64 - self.rss_warm as i64
    }
}

/// Why a soak stopped early.
#[derive(Debug, thiserror::Error)]
pub enum SoakError {
    #[error("the engine: {0}")]
    Engine(#[from] EngineError),
    #[error("frame {frame}: rendering failed: {source}")]
    Render { frame: u64, source: RenderError },
    #[error("the game's setup failed: {0}")]
    Setup(String),
    #[error("frame {frame}: the render thread stopped")]
    RenderStopped { frame: u64 },
    #[error("frame {frame}: film pixel {pixel} is {value}")]
    FilmNotFinite {
        frame: u64,
        pixel: usize,
        value: glam::Vec3,
    },
    #[error("frame {frame}: entity {entity} has a non-finite transform {transform}")]
    NotFinite {
        frame: u64,
        entity: String,
        transform: String,
    },
    #[error("frame {frame}: entity {entity} fell through the world (y = {y} m)")]
    FellOut { frame: u64, entity: String, y: f32 },
}

/// Resident set size of this process, bytes (Linux `/proc/self/statm`; 0 elsewhere).
pub fn rss_bytes() -> u64 {
    std::fs::read_to_string("/proc/self/statm")
        .ok()
        .and_then(|s| s.split_whitespace().nth(1)?.parse::<u64>().ok())
        .map_or(0, |pages| pages * 4096)
}

/// Soaks `game` (not yet set up) in `environment` for `frames` frames with the monkey seeded
/// by `seed`.
pub fn soak<G: Game>(
    game: &mut G,
    environment: Environment,
    frames: u64,
    seed: u64,
) -> Result<SoakReport, SoakError> {
    let mut engine = Engine::new(RenderConfig::cpu(FILM.0, FILM.1), environment)?;
    game.setup(&mut engine)
        .map_err(|e| SoakError::Setup(e.to_string()))?;
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
        engine.frame(1.0 / 60.0, game)?;
        check_world(&engine, frame)?;
        if check_film {
            check_film_of(&engine, frame)?;
            report.film_checks += 1;
        } else {
            for result in engine.rendered() {
                result.map_err(|source| SoakError::Render { frame, source })?;
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

/// Waits for the captured frame (rendered after this frame's hand-off) and checks its film.
pub(super) fn check_film_of(engine: &Engine, frame: u64) -> Result<(), SoakError> {
    loop {
        let Some(result) = engine.wait_rendered() else {
            return Err(SoakError::RenderStopped { frame });
        };
        let rendered = result.map_err(|source| SoakError::Render { frame, source })?;
        if let Some(film) = rendered.film {
            if let Some(pixel) = film.mean.iter().position(|p| !p.is_finite()) {
                return Err(SoakError::FilmNotFinite {
                    frame,
                    pixel,
                    value: film.mean[pixel],
                });
            }
            return Ok(());
        }
    }
}

pub(super) fn check_world(engine: &Engine, frame: u64) -> Result<(), SoakError> {
    let world = engine.world();
    let mut query = world.query::<(hecs::Entity, &Transform)>();
    for (entity, t) in query.iter() {
        let finite = t.translation.is_finite() && t.rotation.is_finite() && t.scale.is_finite();
        if !finite {
            return Err(SoakError::NotFinite {
                frame,
                entity: format!("{entity:?}"),
                transform: format!("{t:?}"),
            });
        }
        if t.translation.y < KILL_Y {
            return Err(SoakError::FellOut {
                frame,
                entity: format!("{entity:?}"),
                y: t.translation.y,
            });
        }
    }
    Ok(())
}
