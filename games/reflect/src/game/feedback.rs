//! What the player is told when a puzzle event happens: the HUD's short messages ("Plate
//! pressed", "The door opens", "The laser sent you back", "Chamber 1 complete"), the flash of a
//! send-back, which chamber's exit door stands open (the HUD counts that chamber as solved),
//! and the sound each message plays.
//!
//! Owns: [`Feedback`] and the messages' texts. Which level rules open or close a door comes
//! from the level's plan (a rule that plays a clip named `door…` opens one; its `otherwise`
//! reversing it closes it; a rule that only reverses one closes the door behind the player,
//! said only when that door had opened); plates are the trigger volumes named `plate…`
//! (pressed while anything is on them).
//!
//! Main thread, Reflect's fixed step and level events (noting), the HUD (reading). Must not:
//! change the world or the level's logic (messages and sounds only: replays and the state hash
//! stay as they were).

use std::collections::{BTreeMap, BTreeSet};

use candela::app::Commands;
use candela::sim::triggers::{Action, GameplayPlan, Phase, VolumeEvent};

/// Fixed steps a message stays on the HUD (2.5 s at 60 steps per second).
pub const NOTICE_STEPS: u64 = 150;

/// Fixed steps the send-back flash takes to fade out (0.5 s).
pub const FLASH_STEPS: u64 = 30;

/// The most messages the HUD shows at once (the newest).
pub const MAX_NOTICES: usize = 3;

// The messages' texts (tests look for them).
pub const PLATE_PRESSED: &str = "Plate pressed";
pub const PLATE_RELEASED: &str = "Plate released";
pub const DOOR_OPENS: &str = "The door opens";
pub const DOOR_CLOSES: &str = "The door closes";
pub const DOOR_CLOSED_BEHIND: &str = "The door closed behind you";
pub const SENT_BACK: &str = "The laser sent you back";
pub const NO_MIRRORS_LEFT: &str = "No mirrors left in this chamber";

/// "Chamber N complete" for chamber `index` (0-based).
pub fn chamber_complete(index: usize) -> String {
    format!("Chamber {} complete", index + 1)
}

/// What a level rule does to a door (the door's clip index), for its messages.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct DoorRule {
    /// Rising opens a door.
    opens: Option<usize>,
    /// Falling closes it again.
    closes_on_fall: Option<usize>,
    /// Rising closes a door (the one behind the player).
    closes_behind: Option<usize>,
}

/// The messages and the flash, and what they follow.
#[derive(Clone, Debug, Default)]
pub struct Feedback {
    doors: BTreeMap<String, DoorRule>,
    /// Per plate volume, what is on it (entity bits).
    plates: BTreeMap<String, BTreeSet<u64>>,
    /// Messages with the step they came at, oldest first (those of the last
    /// [`NOTICE_STEPS`] only).
    notices: Vec<(u64, String)>,
    flash_at: Option<u64>,
    /// The chamber whose exit door is open.
    exit_open: Option<usize>,
    /// The door clips that played open and were not reversed since.
    open_doors: BTreeSet<usize>,
}

fn door_clip(plan: &GameplayPlan, clip: usize) -> bool {
    plan.clips
        .get(clip)
        .is_some_and(|c| c.name.starts_with("door"))
}

/// The first door clip `actions` play (`reverse` false) or reverse (true).
fn door_in(plan: &GameplayPlan, actions: &[Action], reverse: bool) -> Option<usize> {
    actions.iter().find_map(|a| match *a {
        Action::Play { clip, .. } if !reverse && door_clip(plan, clip) => Some(clip),
        Action::Reverse { clip } if reverse && door_clip(plan, clip) => Some(clip),
        _ => None,
    })
}

impl Feedback {
    /// Feedback for a level of `plan`.
    pub fn new(plan: &GameplayPlan) -> Self {
        let doors = plan
            .rules
            .iter()
            .filter_map(|rule| {
                let opens = door_in(plan, &rule.then, false);
                let door = DoorRule {
                    opens,
                    closes_on_fall: door_in(plan, &rule.otherwise, true),
                    closes_behind: door_in(plan, &rule.then, true).filter(|_| opens.is_none()),
                };
                (door != DoorRule::default()).then(|| (rule.name.clone(), door))
            })
            .collect();
        Self {
            doors,
            ..Self::default()
        }
    }

    /// Adds message `text` at step `step`, and plays `sound` (a sound of the level) with it.
    pub fn notice(
        &mut self,
        step: u64,
        text: impl Into<String>,
        sound: Option<(&str, f32)>,
        commands: &mut Commands,
    ) {
        self.push(step, text.into(), false);
        if let Some((name, volume)) = sound {
            commands.play_sound(name, volume);
        }
    }

    /// Adds message `text` at step `step`: after the others, or `first` before the others of
    /// the same step (a plate pressed before the door it opens, whose rule the level reports
    /// first).
    fn push(&mut self, step: u64, text: String, first: bool) {
        let at = if first {
            self.notices
                .iter()
                .position(|(s, _)| *s == step)
                .unwrap_or(self.notices.len())
        } else {
            self.notices.len()
        };
        self.notices.insert(at, (step, text));
    }

    /// Forgets messages older than [`NOTICE_STEPS`] at step `now` (every step: the list
    /// stays short however long the game runs).
    pub fn expire(&mut self, now: u64) {
        self.notices
            .retain(|(at, _)| now.saturating_sub(*at) < NOTICE_STEPS);
    }

    /// The laser sent the player back at step `step` (its buzz is the level's `zapped` rule).
    pub fn sent_back(&mut self, step: u64, commands: &mut Commands) {
        self.notice(step, SENT_BACK, None, commands);
        self.flash_at = Some(step);
    }

    /// Chamber `index` was finished at step `step`.
    pub fn finished(&mut self, step: u64, index: usize, commands: &mut Commands) {
        self.notice(
            step,
            chamber_complete(index),
            Some(("chime", 0.7)),
            commands,
        );
    }

    /// Level rule `name` rose or fell at step `step` while the player was in chamber `current`:
    /// a door's message, and which chamber's exit stands open (the door's own sound is the
    /// rule's).
    pub fn rule(
        &mut self,
        step: u64,
        name: &str,
        rising: bool,
        current: Option<usize>,
        commands: &mut Commands,
    ) {
        let Some(door) = self.doors.get(name).copied() else {
            return;
        };
        if rising && let Some(clip) = door.opens {
            self.open_doors.insert(clip);
            self.exit_open = current;
            self.notice(step, DOOR_OPENS, None, commands);
        } else if !rising && let Some(clip) = door.closes_on_fall {
            if self.exit_open == current {
                self.exit_open = None;
            }
            if self.open_doors.remove(&clip) {
                self.notice(step, DOOR_CLOSES, None, commands);
            }
        } else if rising
            && let Some(clip) = door.closes_behind
            && self.open_doors.remove(&clip)
        {
            self.notice(step, DOOR_CLOSED_BEHIND, None, commands);
        }
    }

    /// Something entered or left trigger volume `name` at step `step`: a plate pressed (the
    /// first thing on it) or released (the last thing off it).
    pub fn volume(&mut self, step: u64, name: &str, event: &VolumeEvent, commands: &mut Commands) {
        if !name.starts_with("plate") {
            return;
        }
        let on = self.plates.entry(name.to_string()).or_default();
        let who = event.occupant.to_bits().get();
        match event.phase {
            Phase::Enter => {
                if on.insert(who) && on.len() == 1 {
                    self.push(step, PLATE_PRESSED.into(), true);
                    commands.play_sound("chime", 0.45);
                }
            }
            Phase::Exit => {
                if on.remove(&who) && on.is_empty() {
                    self.push(step, PLATE_RELEASED.into(), true);
                    commands.play_sound("chime", 0.2);
                }
            }
            Phase::Stay => {}
        }
    }

    /// The level was spawned again (the editor): what stood on plates is not known any more.
    pub fn respawned(&mut self) {
        self.plates.clear();
        self.exit_open = None;
        self.open_doors.clear();
    }

    /// Whether chamber `index`'s exit door stands open.
    pub fn exit_open(&self, index: usize) -> bool {
        self.exit_open == Some(index)
    }

    /// The messages to show at step `now`, oldest first; `extra` (a message of the player's
    /// own, with its step) joins them in step order.
    pub fn messages(&self, now: u64, extra: Option<(u64, &str)>) -> Vec<String> {
        let mut all: Vec<(u64, &str)> = self
            .notices
            .iter()
            .map(|(at, text)| (*at, text.as_str()))
            .chain(extra)
            .filter(|(at, _)| now.saturating_sub(*at) < NOTICE_STEPS)
            .collect();
        all.sort_by_key(|(at, _)| *at);
        let skip = all.len().saturating_sub(MAX_NOTICES);
        all[skip..].iter().map(|(_, t)| t.to_string()).collect()
    }

    /// The send-back flash at step `now`: 1 at the send-back, fading to 0 over
    /// [`FLASH_STEPS`].
    pub fn flash(&self, now: u64) -> f32 {
        let Some(at) = self.flash_at else {
            return 0.0;
        };
        let age = now.saturating_sub(at);
        if age >= FLASH_STEPS {
            return 0.0;
        }
        1.0 - age as f32 / FLASH_STEPS as f32
    }
}
