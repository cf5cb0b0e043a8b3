//! Gamepads through gilrs: [`Gamepads::poll`] drains gilrs's events into the [`InputState`]
//! as [`PadButton`] presses and [`PadAxis`] values, sticks with a radial dead zone.
//!
//! Absent gamepad support (no udev, a container, an unsupported platform) is not an error:
//! [`Gamepads::new`] logs it once and [`Gamepads::poll`] then does nothing. Every connected pad
//! drives the same bindings (the last event wins for an axis); a pad that disconnects lets go
//! of its buttons and centres its sticks. gilrs's own filters stay on (its small per-axis
//! dead zone, the d-pad axes turned into buttons); the radial dead zone here comes on top.
//!
//! Main thread (gilrs reads devices when polled). Must not: map pads to actions (the input map
//! does) or apply look sensitivity (the player controller does, from the settings).

use std::collections::HashMap;

use glam::Vec2;

use super::map::InputState;
use super::pad::{PadAxis, PadButton};

/// Default radial dead zone of the sticks, as a fraction of full deflection (worn sticks
/// rest at up to about 0.1–0.15 off centre).
pub const DEFAULT_DEAD_ZONE: f32 = 0.15;

/// A stick position after a radial dead zone: inside `dead_zone` of centre → zero; beyond it
/// the remaining travel is rescaled to [0, 1], keeping the direction (so small deflections
/// are usable and the full range is reachable). Not finite → zero.
pub fn apply_dead_zone(stick: Vec2, dead_zone: f32) -> Vec2 {
    if !stick.is_finite() {
        return Vec2::ZERO;
    }
    let dz = dead_zone.clamp(0.0, 0.99);
    let length = stick.length();
    if length <= dz {
        return Vec2::ZERO;
    }
    let scaled = ((length - dz) / (1.0 - dz)).min(1.0);
    stick * (scaled / length)
}

/// The engine's name of a gilrs button (`None` for buttons bindings cannot name).
pub fn pad_button(button: gilrs::Button) -> Option<PadButton> {
    use gilrs::Button as G;
    Some(match button {
        G::South => PadButton::South,
        G::East => PadButton::East,
        G::North => PadButton::North,
        G::West => PadButton::West,
        G::LeftTrigger => PadButton::LeftTrigger,
        G::RightTrigger => PadButton::RightTrigger,
        G::LeftTrigger2 => PadButton::LeftTrigger2,
        G::RightTrigger2 => PadButton::RightTrigger2,
        G::Select => PadButton::Select,
        G::Start => PadButton::Start,
        G::Mode => PadButton::Mode,
        G::LeftThumb => PadButton::LeftThumb,
        G::RightThumb => PadButton::RightThumb,
        G::DPadUp => PadButton::DPadUp,
        G::DPadDown => PadButton::DPadDown,
        G::DPadLeft => PadButton::DPadLeft,
        G::DPadRight => PadButton::DPadRight,
        _ => return None,
    })
}

/// Which stick a gilrs axis belongs to (0 left, 1 right) and whether it is its Y.
fn stick_of(axis: gilrs::Axis) -> Option<(usize, bool)> {
    use gilrs::Axis as G;
    match axis {
        G::LeftStickX => Some((0, false)),
        G::LeftStickY => Some((0, true)),
        G::RightStickX => Some((1, false)),
        G::RightStickY => Some((1, true)),
        _ => None,
    }
}

const STICK_AXES: [(PadAxis, PadAxis); 2] = [
    (PadAxis::LeftStickX, PadAxis::LeftStickY),
    (PadAxis::RightStickX, PadAxis::RightStickY),
];

/// What one pad is doing (to let go of it when it disconnects).
#[derive(Clone, Debug, Default)]
struct PadState {
    sticks: [Vec2; 2],
    held: Vec<PadButton>,
}

/// The gamepad reader.
pub struct Gamepads {
    gilrs: Option<gilrs::Gilrs>,
    /// Radial dead zone of both sticks (fraction of full deflection).
    pub dead_zone: f32,
    pads: HashMap<gilrs::GamepadId, PadState>,
}

impl std::fmt::Debug for Gamepads {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Gamepads")
            .field("available", &self.available())
            .field("dead_zone", &self.dead_zone)
            .field("pads", &self.pads.len())
            .finish()
    }
}

impl Gamepads {
    /// Opens gilrs; without gamepad support, logs why once and reads nothing.
    pub fn new() -> Self {
        let gilrs = match gilrs::Gilrs::new() {
            Ok(g) => Some(g),
            Err(e) => {
                log::info!("gamepads: not available ({e}); keyboard and mouse only");
                None
            }
        };
        Self {
            gilrs,
            dead_zone: DEFAULT_DEAD_ZONE,
            pads: HashMap::new(),
        }
    }

    /// A reader that never reads a device (headless runs, replays, tests).
    pub fn disabled() -> Self {
        Self {
            gilrs: None,
            dead_zone: DEFAULT_DEAD_ZONE,
            pads: HashMap::new(),
        }
    }

    /// Whether gamepads can be read here.
    pub fn available(&self) -> bool {
        self.gilrs.is_some()
    }

    /// Pads connected now.
    pub fn connected(&self) -> usize {
        self.gilrs.as_ref().map_or(0, |g| {
            g.gamepads().filter(|(_, p)| p.is_connected()).count()
        })
    }

    /// Feeds every event since the last poll into `input` and returns the buttons pressed
    /// since then, in order (the window forwards them to the shell, for rebinding). Call once
    /// per frame, before the frame's fixed steps.
    pub fn poll(&mut self, input: &mut InputState) -> Vec<PadButton> {
        let mut presses = Vec::new();
        let Some(gilrs) = self.gilrs.as_mut() else {
            return presses;
        };
        while let Some(gilrs::Event { id, event, .. }) = gilrs.next_event() {
            let pad = self.pads.entry(id).or_default();
            match event {
                gilrs::EventType::ButtonPressed(b, _) => {
                    if let Some(b) = pad_button(b) {
                        if !pad.held.contains(&b) {
                            pad.held.push(b);
                            presses.push(b);
                        }
                        input.pad_button(b, true);
                    }
                }
                gilrs::EventType::ButtonReleased(b, _) => {
                    if let Some(b) = pad_button(b) {
                        pad.held.retain(|h| *h != b);
                        input.pad_button(b, false);
                    }
                }
                gilrs::EventType::AxisChanged(axis, value, _) => {
                    if let Some((stick, is_y)) = stick_of(axis) {
                        let s = &mut pad.sticks[stick];
                        if is_y {
                            s.y = value;
                        } else {
                            s.x = value;
                        }
                        let v = apply_dead_zone(*s, self.dead_zone);
                        input.pad_axis(STICK_AXES[stick].0, v.x);
                        input.pad_axis(STICK_AXES[stick].1, v.y);
                    }
                }
                gilrs::EventType::Disconnected => {
                    for b in pad.held.drain(..) {
                        input.pad_button(b, false);
                    }
                    pad.sticks = [Vec2::ZERO; 2];
                    for (x, y) in STICK_AXES {
                        input.pad_axis(x, 0.0);
                        input.pad_axis(y, 0.0);
                    }
                }
                _ => {}
            }
        }
        presses
    }
}

impl Default for Gamepads {
    fn default() -> Self {
        Self::new()
    }
}
