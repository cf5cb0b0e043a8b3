//! Players: the game platform's neutral player controllers, driven by a plain per-step
//! [`PlayerInput`] (built by `app` from the step's actions and the player's settings), so that
//! they know nothing of devices, bindings or replays.
//!
//! Sits above `level` (it reads `sim::triggers::Usable` that level spawning puts on usable
//! instances) and below `app`. Main thread, fixed step, before physics. Must not: read
//! devices, clocks or the engine's runner.

mod first_person;
mod input;
mod interact;

pub use first_person::{FirstPersonConfig, FirstPersonPlayer, PlayerStep};
pub use input::PlayerInput;
pub use interact::{Focus, FocusKind, focus};
