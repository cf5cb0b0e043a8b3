//! A level to play: loading a level file with everything a game needs from it — the scene it
//! renders (`assets`), the physics components of its instances, its gameplay checked and
//! planned (sounds decoded, clips built, names resolved) — so that every problem is found at
//! load time and names the file and the item. One validator ([`validate_level`]) holds the
//! level's rules and returns typed problems ([`LevelProblem`]: item, field, message); the
//! loader stops at the first, the editor lists them all.
//!
//! Sits above `sim` and `audio` (it builds their types) and below `app` (which spawns a
//! [`PlayableLevel`] into the engine). Main thread or a loader thread.
//! Must not: spawn entities, run systems or touch the GPU.

mod body;
mod character;
mod compose;
mod gameplay_plan;
mod item;
mod load;
mod problem;
mod validate;
mod validate_breakables;
mod validate_gameplay;
mod validate_memory;

pub use body::{InstanceBody, resolve_body};
pub use character::{PlayableCharacter, load_characters};
pub use compose::{compose_levels, load_composed};
pub use item::ItemRef;
pub use load::{PlayableLevel, level_problems, load_level, playable_from_level};
pub use problem::LevelProblem;
pub use validate::validate_level;
