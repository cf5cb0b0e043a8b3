//! Reflect's HUD and ending screen: the chamber's objective (or, once its exit door stands
//! open, to go on), the chamber counter (marked solved then), the mirrors used, the prompt
//! (the player's own — pick up, drop while carrying, a usable's — or the mirror gun's for the
//! panel under the crosshair: make a mirror, or only turn it back when it is one), the
//! messages of what just happened with the send-back's flash, and the ending's summary.
//!
//! Also the rest of Reflect's shell hooks ([`ShellHooks`]): the chamber select and starting a
//! chamber (which only notes it; the next fixed step puts the player there).
//!
//! Main thread, the shell's hooks. Must not: change anything but the chamber to start.

use candela::app::shell::{GameSummary, HudInfo, LevelEntry, LevelStart, ShellHooks, ShellInfo};
use candela::app::{SetupError, TOO_FAR};

use super::ReflectGame;

/// The gun's prompt on a plain panel.
pub const MAKE_MIRROR: &str = "Left mouse  make a mirror";
/// The gun's prompt on a panel that is a mirror.
pub const TURN_BACK: &str = "Right mouse  turn it back";
/// The gun's prompt on a plain panel when its chamber has all the mirrors it allows.
pub const AT_CAP: &str = "No mirrors left · right mouse on a mirror turns it back";

impl ReflectGame {
    /// What the HUD shows now.
    pub(super) fn hud_info(&self) -> HudInfo {
        let mut hud = self.inner.hud();
        let too_far = self.inner.too_far_at().map(|at| (at, TOO_FAR));
        hud.messages = self.feedback.messages(self.now, too_far);
        hud.flash = self.feedback.flash(self.now);
        let Some(k) = self.current else {
            hud.objective = None;
            return hud;
        };
        let chamber = &self.world.chambers[k];
        let count = self.world.chambers.len();
        let solved = self.feedback.exit_open(k) && k + 1 < count;
        hud.objective = Some(if solved {
            format!("The door is open: go on to chamber {}", k + 2)
        } else {
            chamber.objective.clone()
        });
        if hud.prompt.is_none() {
            hud.prompt = self.gun_prompt().map(String::from);
        }
        let counter = if solved {
            format!("{} / {count} solved", k + 1)
        } else {
            format!("{} / {count}", k + 1)
        };
        hud.counters = vec![("Chamber".into(), counter)];
        if chamber.mirror_cap > 0 {
            hud.counters.push((
                "Mirrors".into(),
                format!("{} / {}", self.gun.active_in(k), chamber.mirror_cap),
            ));
        }
        hud
    }

    /// The mirror gun's prompt for the panel under the crosshair.
    fn gun_prompt(&self) -> Option<&'static str> {
        let panel = self.aimed?;
        if self.gun.is_mirror(panel) {
            return Some(TURN_BACK);
        }
        let Some(c) = self.gun.chamber_of(panel) else {
            return Some(MAKE_MIRROR);
        };
        let cap = self.world.chambers.get(c).map_or(0, |c| c.mirror_cap);
        if cap == 0 {
            None
        } else if self.gun.active_in(c) >= cap {
            Some(AT_CAP)
        } else {
            Some(MAKE_MIRROR)
        }
    }

    /// What the ending screen shows.
    pub(super) fn ending_summary(&self) -> GameSummary {
        let seconds = self.play_seconds();
        GameSummary {
            headline: "You reached the surface".into(),
            lines: vec![
                format!(
                    "Time  {}:{:02}",
                    (seconds / 60.0) as u64,
                    (seconds % 60.0) as u64
                ),
                format!("Mirrors made  {}", self.gun.made),
                format!("Sent back by lasers  {}", self.sent_back),
            ],
        }
    }
}

impl ShellHooks for ReflectGame {
    fn shell_info(&self) -> ShellInfo {
        ShellInfo {
            title: "Reflect".into(),
            subtitle: "Mirrors, lasers and glass in five test chambers".into(),
            levels: self
                .world
                .chambers
                .iter()
                .enumerate()
                .map(|(i, c)| LevelEntry {
                    id: c.id.clone(),
                    name: format!("{} · {}", i + 1, c.name),
                })
                .collect(),
            finished_only: true,
        }
    }

    fn hud(&self) -> HudInfo {
        self.hud_info()
    }

    fn summary(&self) -> GameSummary {
        self.ending_summary()
    }

    fn begin_level(
        &mut self,
        _engine: &mut candela::app::Engine,
        start: &LevelStart,
    ) -> Result<(), SetupError> {
        let index = self
            .world
            .chamber_index(&start.level)
            .ok_or_else(|| format!("Reflect has no chamber {:?}", start.level))?;
        self.pending_start = Some(index);
        Ok(())
    }
}
