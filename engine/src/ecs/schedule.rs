//! The order of the engine's work in one frame (Brigade §4.2, Figure 7). Games insert their
//! systems in the `game rules` slot; everything else is the engine's.
//!
//! ```text
//! main thread   input → (game rules → physics → animation → triggers → audio) per fixed
//!               60 Hz step → physics interpolation → propagate_transforms → extract (typed scene changes)
//!               → upkeep (instances, refit/rebuild, TLAS, lights) → seal commit N → hand-off
//! render thread … render N−1 │ apply commit N │ render N │ …
//! ```
//! The hand-off is the only synchronisation point; game rules for frame N+1 run while frame N
//! renders. Ray queries read the scene as of the last sealed commit.

/// The engine's systems in the order the runner calls them each frame.
pub const SYSTEM_ORDER: &[&str] = &[
    "input",
    "game rules (fixed steps)",
    "physics (after each fixed step)",
    "animation (level clips, after physics)",
    "triggers (lasers, volumes, rules, their effects)",
    "audio (emitters follow entities, listener at the camera)",
    "physics interpolation",
    "propagate_transforms",
    "extract",
    "upkeep",
    "seal commit",
    "hand-off",
];
