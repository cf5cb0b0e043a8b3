//! The phases of one frame on the main thread, in the order [`super::Engine::frame`] runs them
//! (Brigade §4.2, Figure 7), and their timers.
//!
//! ```text
//! main thread   Input → Steps (per fixed 60 Hz step: game rules → physics → animation tick
//!               → level logic → its effects → audio) → Pose (interpolation, deformers, waves,
//!               skinned meshes, transforms) → Upkeep (extract, BVH refit/rebuild, TLAS,
//!               lights, camera-relative origin) → Seal (the commit) → HandOff
//! render thread … render N−1 │ apply commit N │ render N │ …
//! ```
//! The hand-off is the only synchronisation point; the game rules of frame N+1 run while frame
//! N renders. Ray queries read the scene as of the last sealed commit; in a frame of several
//! fixed steps the scene is settled again (posed, applied, TLAS) before each step but the
//! first (`app/step_scene.rs`), so every step's queries see the previous step's world.
//!
//! Owns: [`Phase`] (the one list: its order is the frame's order, its names label the timers in
//! reports, the stats overlay and `docs/PERFORMANCE.md`), [`PhaseTimes`] and [`FrameReport`].
//! Main thread. Must not: run anything.

use super::work::FrameWork;
use crate::accel::UpkeepStats;

/// One phase of [`super::Engine::frame`], in frame order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Phase {
    /// The game's per-frame hook (`Game::frame`): input, cameras that follow frames.
    Input,
    /// The fixed steps: per step, the game's rules (with ray queries on the last commit), a
    /// physics step, skinned animation players, the level's logic (clips, lasers, volumes,
    /// rules) and its effects, level events to the game, audio.
    Steps,
    /// Posing the world for the render time between the last two steps: physics
    /// interpolation, level waves, skinned deformation, transform propagation.
    Pose,
    /// Extracting typed scene changes and keeping the flattened scene up to date: instance
    /// rows, BLAS refits and rebuilds, the TLAS, the light table, the render-space origin;
    /// listener and emitters follow.
    Upkeep,
    /// Sealing the commit (writes, header, view, motion, present request).
    Seal,
    /// Handing the commit to the render thread (waits only while it still holds the last).
    HandOff,
}

impl Phase {
    /// Every phase, in frame order.
    pub const ALL: [Phase; 6] = [
        Phase::Input,
        Phase::Steps,
        Phase::Pose,
        Phase::Upkeep,
        Phase::Seal,
        Phase::HandOff,
    ];

    /// The label of the phase's timer.
    pub fn name(self) -> &'static str {
        match self {
            Phase::Input => "input",
            Phase::Steps => "fixed steps",
            Phase::Pose => "pose",
            Phase::Upkeep => "scene upkeep",
            Phase::Seal => "seal commit",
            Phase::HandOff => "hand-off",
        }
    }

    fn index(self) -> usize {
        self as usize
    }
}

/// Seconds spent in each [`Phase`] of one frame.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PhaseTimes([f64; Phase::ALL.len()]);

impl PhaseTimes {
    /// Seconds of `phase`.
    pub fn get(&self, phase: Phase) -> f64 {
        self.0[phase.index()]
    }

    /// Adds `seconds` to `phase`.
    pub fn add(&mut self, phase: Phase, seconds: f64) {
        self.0[phase.index()] += seconds;
    }

    /// `(phase, seconds)` in frame order.
    pub fn iter(&self) -> impl Iterator<Item = (Phase, f64)> + '_ {
        Phase::ALL.into_iter().map(|p| (p, self.get(p)))
    }

    /// Seconds of all phases together.
    pub fn total(&self) -> f64 {
        self.0.iter().sum()
    }
}

/// What one call of [`super::Engine::frame`] did on the main thread.
#[derive(Clone, Copy, Debug, Default)]
pub struct FrameReport {
    pub frame: u64,
    /// Fixed steps taken.
    pub steps: u32,
    /// Seconds per phase.
    pub phases: PhaseTimes,
    pub commit_bytes: usize,
    /// Bytes of overlay (egui vertices, indices, texture updates) the commit carried.
    pub overlay_bytes: usize,
    /// What the upkeep did to produce the commit's writes.
    pub upkeep: UpkeepStats,
    /// What was computed: instances, BVH refits/rebuilds, TLAS builds, lights, bounces.
    pub work: FrameWork,
}

impl FrameReport {
    /// Seconds of game update: the input hook, fixed steps and posing.
    pub fn update_seconds(&self) -> f64 {
        self.phases.get(Phase::Input) + self.phases.get(Phase::Steps) + self.phases.get(Phase::Pose)
    }

    /// Seconds of scene upkeep and sealing (extraction, BVH work, TLAS, lights, the commit).
    pub fn upkeep_seconds(&self) -> f64 {
        self.phases.get(Phase::Upkeep) + self.phases.get(Phase::Seal)
    }

    /// Seconds waiting for the render thread to take the commit.
    pub fn handoff_seconds(&self) -> f64 {
        self.phases.get(Phase::HandOff)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn phases_are_listed_once_in_frame_order_with_distinct_names() {
        for (i, p) in Phase::ALL.iter().enumerate() {
            assert_eq!(p.index(), i, "{p:?} is out of order");
        }
        let mut names: Vec<_> = Phase::ALL.iter().map(|p| p.name()).collect();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), Phase::ALL.len());
    }

    #[test]
    fn report_sums_follow_the_phases() {
        let mut r = FrameReport::default();
        for (i, p) in Phase::ALL.into_iter().enumerate() {
            r.phases.add(p, (1 << i) as f64);
        }
        assert_eq!(r.update_seconds(), 1.0 + 2.0 + 4.0);
        assert_eq!(r.upkeep_seconds(), 8.0 + 16.0);
        assert_eq!(r.handoff_seconds(), 32.0);
        assert_eq!(r.phases.total(), 63.0);
    }
}
