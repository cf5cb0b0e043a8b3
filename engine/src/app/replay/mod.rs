//! Per-step input recorded and replayed: the binary recording format ([`Recording`], its
//! header and runs, documented in `format.rs`), the [`Recorder`] and [`Replay`], their
//! [`ReplayError`]s, the soak's seeded [`Monkey`], and [`StepInput`], which says where each
//! fixed step's [`crate::app::input::ActionFrame`] comes from (live, recorded, replayed, the
//! monkey).
//!
//! One file per job: `error`, `format`, `record`, `monkey`, `step_input`. Main thread, once per
//! fixed step. Must not: read clocks or count frames (a replay runs step by step at any speed),
//! or know the engine or a game (the engine's fingerprint, `Engine::state_hash`, is in
//! `runner`).

mod error;
mod format;
mod monkey;
mod record;
mod step_input;

pub use error::ReplayError;
pub use format::{
    FORMAT_VERSION, OLDEST_VERSION, RecordedAction, RecordedLook, Recording, RecordingHeader, Run,
    fnv1a64, level_hash,
};
pub use monkey::Monkey;
pub use record::{Recorder, Replay, ReplayTarget};
pub use step_input::StepInput;
