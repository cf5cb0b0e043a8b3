//! What the player did during one fixed step, as game rules read it: which buttons are held,
//! which went down this step, each stick axis and each motion (mouse look) in fixed point.
//!
//! Quantising here is what makes replays bit-exact: live play reads the same [`ActionFrame`]
//! that a recording stores, so a game that reads input only through frames computes the same
//! thing from a replay, whatever the frame rate, render speed or tracer. Fixed point: axes in
//! units of 1/[`AXIS_ONE`] (±1.0 = ±32767), motions in 1/[`MOTION_PER_COUNT`] mouse counts
//! (or wheel lines), rounded to nearest, saturating.
//!
//! Owns: the frame, its quantisation and capturing it from an [`InputState`]. Main thread.
//! Must not: read devices or clocks (the runner captures once per fixed step).

use super::action_set::{ActionId, ActionKind, ActionSet};
use super::map::InputState;

/// The fixed-point value of an axis at 1.0.
pub const AXIS_ONE: i32 = 32767;
/// Fixed-point units per mouse count (or wheel line) of motion.
pub const MOTION_PER_COUNT: i32 = 256;

/// One fixed step of input, laid out by the ids of one [`ActionSet`].
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash)]
pub struct ActionFrame {
    /// Bit `i`: the button with id `i` is held at the step.
    pub held: u64,
    /// Bit `i`: the button with id `i` went down since the previous step (it may be released
    /// again already: a tap shorter than a step is still seen).
    pub pressed: u64,
    /// Per action id: 0 for buttons, the fixed-point axis value or the step's motion.
    pub values: Vec<i32>,
}

/// `value` ([−1, 1]) in axis fixed point; NaN reads as 0.
pub fn quantise_axis(value: f32) -> i32 {
    if value.is_nan() {
        return 0;
    }
    (value.clamp(-1.0, 1.0) * AXIS_ONE as f32).round() as i32
}

/// `counts` of motion in motion fixed point (saturating; NaN reads as 0).
pub fn quantise_motion(counts: f32) -> i32 {
    // `as` saturates at the i32 range and maps NaN to 0.
    (counts * MOTION_PER_COUNT as f32).round() as i32
}

impl ActionFrame {
    /// A frame of `set` with nothing held and no motion.
    pub fn empty(set: &ActionSet) -> Self {
        Self {
            held: 0,
            pressed: 0,
            values: vec![0; set.len()],
        }
    }

    /// The step's input from `input`, laid out by `set`. Call once per fixed step, then
    /// [`InputState::end_step`].
    pub fn capture(input: &InputState, set: &ActionSet) -> Self {
        let mut frame = Self::empty(set);
        for (i, def) in set.defs().iter().enumerate() {
            match def.kind {
                ActionKind::Button => {
                    frame.held |= (input.held(&def.name) as u64) << i;
                    frame.pressed |= (input.pressed(&def.name) as u64) << i;
                }
                ActionKind::Axis => frame.values[i] = quantise_axis(input.analog(&def.name)),
                ActionKind::Motion => {
                    frame.values[i] = quantise_motion(input.motion_since_step(&def.name))
                }
            }
        }
        frame
    }

    /// Whether the button `id` is held.
    pub fn held(&self, id: ActionId) -> bool {
        id.0 < 64 && (self.held >> id.0) & 1 == 1
    }

    /// Whether the button `id` went down this step.
    pub fn pressed(&self, id: ActionId) -> bool {
        id.0 < 64 && (self.pressed >> id.0) & 1 == 1
    }

    /// The fixed-point value of `id` (0 for buttons and ids outside the frame).
    pub fn raw(&self, id: ActionId) -> i32 {
        self.values.get(id.0 as usize).copied().unwrap_or(0)
    }

    /// The axis `id` in [−1, 1].
    pub fn axis(&self, id: ActionId) -> f32 {
        self.raw(id) as f32 / AXIS_ONE as f32
    }

    /// The motion `id` during this step, in mouse counts (or wheel lines).
    pub fn motion(&self, id: ActionId) -> f32 {
        self.raw(id) as f32 / MOTION_PER_COUNT as f32
    }

    /// 1 while `positive` is held, −1 while `negative` is, 0 for both or neither.
    pub fn button_axis(&self, positive: ActionId, negative: ActionId) -> f32 {
        self.held(positive) as i32 as f32 - self.held(negative) as i32 as f32
    }
}
