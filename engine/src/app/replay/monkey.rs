//! The soak test's monkey: random but plausible input for any [`ActionSet`], one
//! [`ActionFrame`] per fixed step, the same sequence for the same seed. Buttons are held for
//! random spans (walking for seconds, tapping jump or use), axes drift and snap back, mouse
//! motion is a random walk with bursts; the runner's own buttons (pause, the editor) are
//! pressed only when asked, since a pause with nobody to resume it would end the soak.
//!
//! Owns: [`Monkey`]. Main thread, once per fixed step (through [`super::StepInput::Monkey`]).
//! Must not: read devices or clocks.

use crate::app::input::{AXIS_ONE, ActionFrame, MOTION_PER_COUNT};
use crate::app::input::{ActionKind, ActionSet, game_actions};

/// A seeded random input source.
#[derive(Clone, Debug)]
pub struct Monkey {
    state: u64,
    /// Per action id: steps left in the current hold (buttons) or the current target (axes).
    hold: Vec<u32>,
    axis_target: Vec<i32>,
    /// Press the runner's buttons (pause, editor toggle) too.
    pub runner_buttons: bool,
}

impl Monkey {
    /// A monkey whose whole sequence follows from `seed`.
    pub fn new(seed: u64) -> Self {
        Self {
            state: seed ^ 0x6a09_e667_f3bc_c908,
            hold: Vec::new(),
            axis_target: Vec::new(),
            runner_buttons: false,
        }
    }

    fn next(&mut self) -> u64 {
        // SplitMix64.
        self.state = self.state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// A number in `0..n` (`n` > 0).
    fn below(&mut self, n: u32) -> u32 {
        (self.next() % u64::from(n)) as u32
    }

    /// The next step's input, laid out by `set`.
    pub fn frame(&mut self, set: &ActionSet) -> ActionFrame {
        let n = set.len();
        self.hold.resize(n, 0);
        self.axis_target.resize(n, 0);
        let mut frame = ActionFrame::empty(set);
        for (i, def) in set.defs().iter().enumerate() {
            let runner = def.name == game_actions::PAUSE || def.name == game_actions::EDITOR_TOGGLE;
            match def.kind {
                ActionKind::Button => {
                    if runner && !self.runner_buttons {
                        continue;
                    }
                    if self.hold[i] > 0 {
                        self.hold[i] -= 1;
                        frame.held |= 1 << i;
                    } else {
                        // Start a hold now and then: rarely for runner buttons, a tap (1–3
                        // steps) or a long hold (up to 4 s at 60 Hz) for the rest.
                        let chance = if runner { 5000 } else { 240 };
                        if self.below(chance) == 0 {
                            self.hold[i] = if self.below(3) == 0 {
                                1 + self.below(3)
                            } else {
                                10 + self.below(230)
                            };
                            frame.held |= 1 << i;
                            frame.pressed |= 1 << i;
                        }
                    }
                }
                ActionKind::Axis => {
                    if self.below(120) == 0 {
                        self.axis_target[i] = if self.below(3) == 0 {
                            0
                        } else {
                            self.below(2 * AXIS_ONE as u32 + 1) as i32 - AXIS_ONE
                        };
                    }
                    frame.values[i] = self.axis_target[i];
                }
                ActionKind::Motion => {
                    // Mostly small motion, sometimes a flick of up to ±200 counts.
                    let counts = if self.below(40) == 0 {
                        self.below(401) as i32 - 200
                    } else {
                        self.below(11) as i32 - 5
                    };
                    frame.values[i] = counts * MOTION_PER_COUNT;
                }
            }
        }
        frame
    }
}
