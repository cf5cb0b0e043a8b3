//! It's About Time's shell hooks: the title menu's entry, the HUD (objective, the artifacts
//! counter, the time of day, the prompt, messages) and the ending's summary.
//!
//! Main thread. Must not: change the game (the hooks read it).

use candela::app::shell::{GameSummary, HudInfo, LevelEntry, ShellHooks, ShellInfo};

use super::{TimeGame, day, recent};
use crate::world::LEVEL_ID;

/// The prompt at a sun altar.
pub const ALTAR_PROMPT: &str = "Hold Q  turn time back · hold R  turn time forward";

impl TimeGame {
    /// The objective line for where the player is in the game: the sun gate first, then
    /// where the next artifact not yet taken lies.
    fn objective(&self) -> String {
        if self.ended() {
            return "The ruins are at peace".into();
        }
        let left: Vec<&String> = (self.artifacts_in_level().iter())
            .filter(|a| !self.artifacts.contains(a))
            .collect();
        match left.first() {
            None => "Bring the artifacts back to the temple altar".into(),
            Some(a) if a.as_str() == "artifact_sun" && self.gate_open => {
                "The sun gate stands open: take what lies behind it before the light moves on"
                    .into()
            }
            Some(a) if self.artifacts.is_empty() => format!(
                "Find the artifacts hidden in the ruins. First, {}",
                day::artifact_hint(a)
            ),
            Some(a) => format!("{} to find. Next, {}", left.len(), day::artifact_hint(a)),
        }
    }

    /// The counters: artifacts taken and the time of day.
    fn counters(&self) -> Vec<(String, String)> {
        let total = self.artifacts_in_level().len();
        let mut counters = vec![(
            "Artifacts".to_string(),
            format!("{} / {total}", self.artifacts.len()),
        )];
        if let Some(sky) = &self.sky
            && let Some(hours) = day::local_hours(sky)
        {
            let part = day::part_of_day(sky.sun.elevation_deg, hours < 12.0);
            counters.push((
                "Time".into(),
                format!("{} · {part}", day::clock_label(hours)),
            ));
        }
        counters
    }

    /// The prompt: the altar's (with Q / R), else the usable's the explorer faces.
    fn prompt(&self) -> Option<String> {
        if self.at_altar {
            return Some(ALTAR_PROMPT.into());
        }
        self.inner.prompt()
    }
}

impl ShellHooks for TimeGame {
    fn shell_info(&self) -> ShellInfo {
        ShellInfo {
            title: "It's About Time".into(),
            subtitle: "Turn the sun over the ruins and find what the temple lost".into(),
            levels: vec![LevelEntry {
                id: LEVEL_ID.into(),
                name: "The ruins".into(),
            }],
            finished_only: false,
        }
    }

    fn hud(&self) -> HudInfo {
        HudInfo {
            crosshair: false,
            objective: Some(self.objective()),
            prompt: self.prompt(),
            counters: self.counters(),
            messages: recent(&self.messages, self.steps),
            ..HudInfo::default()
        }
    }

    fn summary(&self) -> GameSummary {
        let seconds = self.play_seconds();
        let names: Vec<String> = self
            .artifacts
            .iter()
            .map(|a| day::artifact_name(a))
            .collect();
        GameSummary {
            headline: "The temple is whole again".into(),
            lines: vec![
                format!(
                    "Artifacts: {} / {} ({})",
                    self.artifacts.len(),
                    self.artifacts_in_level().len(),
                    names.join(", ")
                ),
                format!(
                    "Time: {}:{:02}",
                    (seconds / 60.0) as u64,
                    (seconds % 60.0) as u64
                ),
            ],
        }
    }
}
