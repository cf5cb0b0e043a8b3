//! Players: the game platform's neutral player controllers, driven by a plain per-step
//! [`PlayerInput`] (built by `app` from the step's actions and the player's settings), so that
//! they know nothing of devices, bindings or replays: the first-person player (`first_person`)
//! and what is under its crosshair (`interact`), the third-person character (`third_person`),
//! the camera that follows it (`follow_camera`) and the two played together with the usables
//! the character faces (`third_person_player`) and what it lifts and carries
//! (`third_person_hands`).
//!
//! Sits above `level` (it reads `sim::triggers::Usable` that level spawning puts on usable
//! instances) and below `app`. Main thread, fixed step, before physics. Must not: read
//! devices, clocks or the engine's runner.

mod drop_preview;
mod first_person;
mod follow_camera;
mod input;
mod interact;
mod third_person;
mod third_person_hands;
mod third_person_player;

pub use drop_preview::outline as drop_outline;
pub use first_person::{FirstPersonConfig, FirstPersonPlayer, PlayerStep, TOO_FAR_FACTOR};
pub use follow_camera::{CameraPose, FollowCamera, ease_distance};
pub use input::PlayerInput;
pub use interact::{Focus, FocusKind, focus};
pub use third_person::{ThirdPersonController, camera_relative_move, turn_towards};
pub use third_person_hands::{Hands, HandsAct, HandsConfig, nearest_takeable};
pub use third_person_player::{ThirdPersonPlayer, ThirdPersonStep, nearest_usable};
