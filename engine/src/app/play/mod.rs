//! What consumes actions, next to `crate::player`: actions and settings turned into the
//! player's per-step [`crate::player::PlayerInput`] ([`player_input`]), the first-person game
//! ([`FirstPersonGame`]: a level, the player, carrying, usables, recording and replay), the
//! third-person game ([`ThirdPersonGame`]: a level's character, its follow camera, usables), the
//! fly camera ([`FlyCamera`], [`fly_camera_system`]) and the bots' steering (`steer`).
//!
//! One file per job: `player_input`, `steer`, `fly_camera`, `first_person_game`,
//! `third_person_game`, `play_from` (the player put where the editor's camera was). Main thread
//! (the fly camera per frame, the rest inside fixed steps). Must not: read devices (they read
//! action frames and the input state), or know the shell's screens, the editor or the window.

mod first_person_game;
mod fly_camera;
mod play_from;
mod player_input;
pub mod steer;
mod third_person_game;

pub use first_person_game::{
    CARRY_PROMPT, FIRST_PERSON_GAME, FirstPersonGame, Happened, MESSAGE_STEPS, TOO_FAR,
};
pub use fly_camera::{FlyCamera, fly_camera_system};
pub use player_input::{MOUSE_RADIANS_PER_COUNT, PAD_RADIANS_PER_SECOND, player_input};
pub use third_person_game::{THIRD_PERSON_GAME, ThirdPersonGame};
