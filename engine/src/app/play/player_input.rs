//! From one fixed step's [`ActionFrame`] to the players' [`PlayerInput`], with the player's
//! [`Settings`] (mouse sensitivity, invert Y).
//!
//! Mapping (the standard actions, `action_set.rs`): walk = the move buttons plus the left
//! stick (`move_x` right, `move_y` forward), clamped to length 1; look = mouse counts ×
//! [`MOUSE_RADIANS_PER_COUNT`] × sensitivity, plus the right stick × [`PAD_RADIANS_PER_SECOND`]
//! × sensitivity × the step's length; mouse or stick right turns right (negative yaw), mouse
//! down (or stick down) looks down unless invert Y; `jump`, `run` held; `use`, `primary_fire`,
//! `secondary_fire` as pressed this step. The result depends only on the frame, the settings
//! and the step length, so a replay gives the same input as the recorded run did (with the
//! same settings). Main thread. Must not: read devices.

use glam::Vec2;

use crate::app::input::ActionFrame;
use crate::app::input::{ActionSet, game_actions as ga};
use crate::app::persist::Settings;
use crate::player::PlayerInput;

/// Look rate of the mouse at sensitivity 1, radians per count (0.1° per count).
pub const MOUSE_RADIANS_PER_COUNT: f32 = 0.001_745_329_3;
/// Look rate of a stick pushed fully at sensitivity 1, radians per second (180°/s).
pub const PAD_RADIANS_PER_SECOND: f32 = std::f32::consts::PI;

/// The player's input for one step of `step_seconds`.
pub fn player_input(
    frame: &ActionFrame,
    set: &ActionSet,
    settings: &Settings,
    step_seconds: f64,
) -> PlayerInput {
    let id = |name: &str| set.id(name);
    let held = |name: &str| id(name).is_some_and(|i| frame.held(i));
    let pressed = |name: &str| id(name).is_some_and(|i| frame.pressed(i));
    let axis = |name: &str| id(name).map_or(0.0, |i| frame.axis(i));
    let motion = |name: &str| id(name).map_or(0.0, |i| frame.motion(i));
    let buttons = |pos: &str, neg: &str| held(pos) as i32 as f32 - held(neg) as i32 as f32;

    let mut walk = Vec2::new(
        buttons(ga::MOVE_RIGHT, ga::MOVE_LEFT) + axis(ga::MOVE_X),
        buttons(ga::MOVE_FORWARD, ga::MOVE_BACK) + axis(ga::MOVE_Y),
    );
    if walk.length_squared() > 1.0 {
        walk = walk.normalize();
    }
    let sensitivity = settings.mouse_sensitivity;
    let y_sign = settings.look_y_sign();
    let mouse = MOUSE_RADIANS_PER_COUNT * sensitivity;
    let pad = PAD_RADIANS_PER_SECOND * sensitivity * step_seconds as f32;
    let look = Vec2::new(
        -motion(ga::LOOK_X) * mouse - axis(ga::LOOK_PAD_X) * pad,
        (-motion(ga::LOOK_Y) * mouse + axis(ga::LOOK_PAD_Y) * pad) * y_sign,
    );
    PlayerInput {
        move_axes: walk,
        look,
        jump: held(ga::JUMP),
        run: held(ga::RUN),
        use_pressed: pressed(ga::USE),
        primary_pressed: pressed(ga::PRIMARY_FIRE),
        secondary_pressed: pressed(ga::SECONDARY_FIRE),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::app::input::quantise_motion;

    #[test]
    fn mouse_right_turns_right_and_invert_y_flips_pitch() {
        let set = ActionSet::standard();
        let mut frame = ActionFrame::empty(&set);
        let id = |name| set.id(name).expect("a standard action");
        let (x, y) = (id(ga::LOOK_X), id(ga::LOOK_Y));
        frame.values[x.0 as usize] = quantise_motion(10.0);
        frame.values[y.0 as usize] = quantise_motion(5.0);
        let plain = player_input(&frame, &set, &Settings::default(), 1.0 / 60.0);
        assert!(
            plain.look.x < 0.0,
            "mouse right turns right: {:?}",
            plain.look
        );
        assert!(
            plain.look.y < 0.0,
            "mouse down looks down: {:?}",
            plain.look
        );
        assert!((plain.look.x + 10.0 * MOUSE_RADIANS_PER_COUNT).abs() < 1e-6);
        let inverted = Settings {
            invert_y: true,
            mouse_sensitivity: 2.0,
            ..Settings::default()
        };
        let inv = player_input(&frame, &set, &inverted, 1.0 / 60.0);
        assert!(
            (inv.look.y + 2.0 * plain.look.y).abs() < 1e-6,
            "{:?}",
            inv.look
        );
        assert!((inv.look.x - 2.0 * plain.look.x).abs() < 1e-6);
    }
}
