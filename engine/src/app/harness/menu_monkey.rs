//! The shell soak's second monkey (`soak_shell.rs`): besides the game's own input (the
//! [`crate::app::Monkey`] at the controls), now and then, while playing, it starts one
//! *episode* of what a player does around the game — pause and resume, open the settings and
//! change one, open the editor (F1) to select, drag and undo, quit to the title (which saves
//! the progress) and continue from the save read back, or quit to the title and start another
//! level. Each episode is a short script of [`MenuStep`]s a random number of frames apart;
//! the same seed gives the same episodes at the same frames.
//!
//! Owns: [`MenuMonkey`], [`Episode`], [`MenuStep`]. Main thread, once per frame of the soak.
//! Must not: reach the engine, the shell or the editor (the soak carries the steps out).

use std::collections::VecDeque;

use crate::app::shell::{Screen, ShellInput};

/// What a player does around the game, one kind per episode.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Episode {
    /// Pause (Escape), wait, resume.
    Pause,
    /// Pause, open the settings screen, change a setting, close it, resume.
    Settings,
    /// F1: select an instance, drag it by the gizmo, undo, F1 again (play from here).
    Editor,
    /// Pause, quit to the title (the progress is saved), read the save back and continue it.
    SaveLoad,
    /// Pause, quit to the title, start another level.
    ChangeLevel,
}

impl Episode {
    pub const ALL: [Episode; 5] = [
        Episode::Pause,
        Episode::Settings,
        Episode::Editor,
        Episode::SaveLoad,
        Episode::ChangeLevel,
    ];
}

/// One step of an episode, carried out by the soak.
#[derive(Clone, Debug, PartialEq)]
pub enum MenuStep {
    /// As if the player chose this in a menu or pressed the action.
    Shell(ShellInput),
    /// Change one setting on the settings screen (which of them and how: from `pick`).
    ChangeSetting { pick: u32 },
    /// In the editor: click on the instance `pick` (modulo the level's count) where it shows.
    EditorSelect { pick: u32 },
    /// In the editor: drag the selection by its gizmo handle `axis` (0..3) by `points`.
    EditorDrag { axis: usize, points: [f32; 2] },
    /// In the editor: Ctrl+Z.
    EditorUndo,
    /// At the title: read the progress save back from its file and continue from it.
    LoadSave,
    /// At the title: start level `pick` (modulo the game's count), another than the current.
    StartLevel { pick: u32 },
}

/// The seeded episode planner.
#[derive(Clone, Debug)]
pub struct MenuMonkey {
    state: u64,
    /// Steps still to come, each with the frames to wait before it.
    queue: VecDeque<(u32, MenuStep)>,
    /// The kind of the episode under way.
    current: Episode,
    /// Mean frames of play between episodes.
    pub every: u32,
    /// Episodes never started (a test shows that the soak's counts then catch it).
    pub disabled: Vec<Episode>,
}

impl MenuMonkey {
    /// A planner whose episodes follow from `seed`, one every `every` frames of play on average.
    pub fn new(seed: u64, every: u32) -> Self {
        Self {
            state: seed ^ 0xbb67_ae85_84ca_a73b,
            queue: VecDeque::new(),
            current: Episode::Pause,
            every: every.max(1),
            disabled: Vec::new(),
        }
    }

    fn next(&mut self) -> u64 {
        // SplitMix64, as the game monkey.
        self.state = self.state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    fn below(&mut self, n: u32) -> u32 {
        (self.next() % u64::from(n.max(1))) as u32
    }

    /// Frames between two steps of an episode: a quarter of a second to a second and a half.
    fn pause(&mut self) -> u32 {
        15 + self.below(75)
    }

    /// Whether an episode is under way (its steps not all taken).
    pub fn busy(&self) -> bool {
        !self.queue.is_empty()
    }

    /// The step for this frame, if any, given the screen the shell shows. An episode starts
    /// only while playing; the kind is drawn among those not disabled.
    pub fn frame(&mut self, screen: Screen) -> Option<(Episode, MenuStep)> {
        if let Some((wait, _)) = self.queue.front_mut() {
            if *wait > 0 {
                *wait -= 1;
                return None;
            }
            return self.queue.pop_front().map(|(_, s)| (self.current, s));
        }
        if screen != Screen::Playing || self.below(self.every) != 0 {
            return None;
        }
        let enabled: Vec<Episode> = Episode::ALL
            .into_iter()
            .filter(|e| !self.disabled.contains(e))
            .collect();
        if enabled.is_empty() {
            return None;
        }
        let episode = enabled[self.below(enabled.len() as u32) as usize];
        self.start(episode);
        self.frame(screen)
    }

    fn start(&mut self, episode: Episode) {
        use ShellInput as I;
        self.current = episode;
        let steps: Vec<MenuStep> = match episode {
            Episode::Pause => vec![MenuStep::Shell(I::Pause), MenuStep::Shell(I::Resume)],
            Episode::Settings => vec![
                MenuStep::Shell(I::Pause),
                MenuStep::Shell(I::OpenSettings),
                MenuStep::ChangeSetting {
                    pick: self.below(1 << 16),
                },
                MenuStep::Shell(I::CloseSettings),
                MenuStep::Shell(I::Resume),
            ],
            Episode::Editor => {
                let angle = self.below(360) as f32 * std::f32::consts::PI / 180.0;
                let length = 40.0 + self.below(200) as f32;
                vec![
                    MenuStep::Shell(I::EditorToggle),
                    MenuStep::EditorSelect {
                        pick: self.below(1 << 16),
                    },
                    MenuStep::EditorDrag {
                        axis: self.below(3) as usize,
                        points: [length * angle.cos(), length * angle.sin()],
                    },
                    MenuStep::EditorUndo,
                    MenuStep::Shell(I::EditorToggle),
                ]
            }
            Episode::SaveLoad => vec![
                MenuStep::Shell(I::Pause),
                MenuStep::Shell(I::QuitToTitle),
                MenuStep::LoadSave,
            ],
            Episode::ChangeLevel => vec![
                MenuStep::Shell(I::Pause),
                MenuStep::Shell(I::QuitToTitle),
                MenuStep::StartLevel {
                    pick: self.below(1 << 16),
                },
            ],
        };
        for (k, step) in steps.into_iter().enumerate() {
            // The first step at once; the editor's first after it opens gets time to lay out.
            let wait = if k == 0 { 0 } else { self.pause() };
            self.queue.push_back((wait, step));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Over a long stretch of play every kind of episode starts, the same seed gives the same
    /// steps, and a disabled kind never starts.
    #[test]
    fn every_episode_starts_and_a_disabled_one_never_does() {
        let run = |disabled: Vec<Episode>| {
            let mut m = MenuMonkey::new(7, 100);
            m.disabled = disabled;
            (0..100_000)
                .filter_map(|_| m.frame(Screen::Playing))
                .collect::<Vec<_>>()
        };
        let all = run(Vec::new());
        for e in Episode::ALL {
            assert!(all.iter().any(|(k, _)| *k == e), "{e:?} never started");
        }
        assert_eq!(all, run(Vec::new()), "seeded");
        let without = run(vec![Episode::Editor]);
        assert!(without.iter().all(|(k, _)| *k != Episode::Editor));
        assert!(!without.is_empty());
    }
}
