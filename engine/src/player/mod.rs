//! Players: what one player does in a fixed step ([`PlayerInput`], `input`) and the
//! controllers that turn it into motion — the third-person character (`third_person`) and the
//! camera that follows it (`follow_camera`).
//!
//! Sits above `level` and below `app` (it must not use `app`: game code turns an
//! `app::ActionFrame` into a [`PlayerInput`]). Main thread, in the game's fixed step.
//! Must not: read devices or clocks (input arrives per step), or render.

mod follow_camera;
mod input;
mod third_person;

pub use follow_camera::{CameraPose, FollowCamera, ease_distance};
pub use input::PlayerInput;
pub use third_person::{ThirdPersonController, camera_relative_move, turn_towards};
