//! CPU single-ray queries for game code (Brigade §4.6): lasers, picking, line of sight, ground
//! probes, against the full-detail scene (animated objects included) as of the last sealed
//! commit, settled again before each fixed step of a frame that runs several
//! (`app/runner/step_scene.rs`).

mod queries;

pub use crate::scene::Optics;
pub use queries::{MAX_PASSED, Queries, QueryHit};
