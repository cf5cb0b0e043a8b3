//! Triggers: what makes a level react. Trigger volumes notice the player, bodies and laser
//! beams (traced by ray queries); rules combine what the volumes saw and clip events into
//! conditions, and on each change run actions: switch a light group, play or reverse a clip,
//! play a sound, set an instance's material, win or lose.
//!
//! Flow: the level file's `gameplay` section (`assets::GameplayEntry`) is checked into a
//! [`GameplayPlan`] (`plan`) at load time; at spawn time a [`LevelLogic`] (`runtime`) binds it
//! to entities and runs it every fixed step: `laser` traces beams, `beam_geometry` lays
//! their visible pieces, `volumes` tracks who is
//! inside, `logic` evaluates rules. Main thread, fixed step, after physics and animation.
//! Deterministic. Must not: talk to the render thread or the audio device (the engine
//! carries out the [`Effect`]s).

mod beam_geometry;
mod conditions;
mod laser;
mod logic;
mod plan;
mod runtime;
mod volumes;

pub use beam_geometry::{
    BeamPool, BeamSegment, MAX_BEAM_SEGMENTS, beam_model, is_beam, segment_transform,
    spawn_beam_pool, update_beams,
};
pub use laser::{LaserBeam, LaserPath, trace_laser};
pub use logic::{Facts, RuleBook, RuleFiring};
pub use plan::{
    Action, Condition, GameplayPlan, PlannedBeam, PlannedBreakable, PlannedEmitter, PlannedLaser,
    PlannedSound, PlannedUsable, PlannedVolume, Rule, Usable,
};
pub use runtime::{Effect, LevelLogic, Outcome, StepLog, set_material, world_from_model};
pub use volumes::{OccupantKind, Phase, VolumeEvent, VolumeFacts, VolumeTracker};
