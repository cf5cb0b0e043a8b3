//! Breakable walls and pillars in a level file's `gameplay` section.
//!
//! Owns: the serde type [`BreakableEntry`]. Checking it is `level/validate_breakables.rs`;
//! running it is `sim::physics` (`breaking.rs`). Must not: load files or spawn anything.
//!
//! ```ron
//! gameplay: (
//!     breakables: [(name: "old_wall", pieces: ["wall_a", "wall_b", "wall_c"],
//!                   impact_speed: Some(6.0), piece_mass: 40.0)],
//!     rules: [(name: "quake", when: Event("lever"), then: [Break("old_wall")])],
//! )
//! ```

use serde::{Deserialize, Serialize};

/// A wall or a pillar of pre-fractured pieces that break together. Each piece is a named
/// instance with a `Static` or `Kinematic` body: it stands until the breakable breaks, then
/// falls as a dynamic body of `piece_mass` kilograms.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BreakableEntry {
    /// What `Break(name)` actions call it.
    pub name: String,
    /// The pieces' instance names.
    pub pieces: Vec<String>,
    /// Metres per second: a dynamic body at least this fast about to hit a piece breaks it
    /// (`None`: only a `Break` action does).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub impact_speed: Option<f32>,
    /// Kilograms of each piece once free.
    #[serde(default = "default_piece_mass")]
    pub piece_mass: f32,
    /// Metres per second each piece is sent away from the pieces' centre as it breaks (0: the
    /// pieces only fall, and a stacked wall may stay standing).
    #[serde(default = "default_scatter_speed")]
    pub scatter_speed: f32,
}

fn default_scatter_speed() -> f32 {
    1.5
}

fn default_piece_mass() -> f32 {
    20.0
}
