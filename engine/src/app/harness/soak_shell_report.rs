//! What the shell soak (`soak_shell.rs`) reports: the actions that took effect
//! ([`ActionCounts`], with the names of those that never did), the frames checked per screen
//! and each frame's wall time ([`ShellSoakReport`], with the distribution).
//!
//! Owns: [`ActionCounts`], [`ShellSoakReport`]. Data; main thread. Must not: run anything.

use std::collections::BTreeMap;

use super::soak::SoakReport;

/// What the menu monkey did that took effect (each counted once it is seen done).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ActionCounts {
    /// Playing → Paused, and back.
    pub paused: u64,
    pub resumed: u64,
    /// The settings screen shown, a setting changed and saved to the settings file, left.
    pub settings_opened: u64,
    pub settings_changed: u64,
    pub settings_closed: u64,
    /// The editor drawn over the level (F1), and left for play.
    pub editor_opened: u64,
    pub editor_closed: u64,
    /// A click in the editor's view selected an instance.
    pub selected: u64,
    /// A drag on the gizmo made one edit.
    pub dragged: u64,
    /// Ctrl+Z put the dragged instance back.
    pub undone: u64,
    /// Quitting to the title wrote the progress save (read back equal).
    pub saved: u64,
    /// The save read back from its file and continued from: playing its level.
    pub loaded: u64,
    /// Another level started from the title: playing it.
    pub levels_changed: u64,
}

impl ActionCounts {
    /// The actions that never took effect, by name (empty: every one did).
    pub fn missing(&self) -> Vec<&'static str> {
        let all = [
            ("pause", self.paused),
            ("resume", self.resumed),
            ("settings opened", self.settings_opened),
            ("setting changed", self.settings_changed),
            ("settings closed", self.settings_closed),
            ("editor opened", self.editor_opened),
            ("editor closed", self.editor_closed),
            ("editor select", self.selected),
            ("editor drag", self.dragged),
            ("editor undo", self.undone),
            ("save", self.saved),
            ("load", self.loaded),
            ("level changed", self.levels_changed),
        ];
        all.iter()
            .filter(|(_, n)| *n == 0)
            .map(|(s, _)| *s)
            .collect()
    }
}

/// What a shell soak saw.
#[derive(Clone, Debug)]
pub struct ShellSoakReport {
    /// The soak's checks and memory.
    pub soak: SoakReport,
    pub counts: ActionCounts,
    /// Frames the per-frame checks ran on, by the screen shown (`Playing`, `Paused`, …).
    pub checked: BTreeMap<String, u64>,
    /// Each frame's wall time, milliseconds (the whole loop: shell, editor, engine, checks).
    pub frame_ms: Vec<f32>,
}

impl ShellSoakReport {
    /// The frame-time distribution: (median, p99, max), milliseconds.
    pub fn frame_times(&self) -> (f32, f32, f32) {
        let mut v = self.frame_ms.clone();
        if v.is_empty() {
            return (0.0, 0.0, 0.0);
        }
        v.sort_by(f32::total_cmp);
        let at = |p: f64| v[((v.len() - 1) as f64 * p).round() as usize];
        (at(0.5), at(0.99), v[v.len() - 1])
    }
}
