//! Clips that move entities: the level's doors, lifts and platforms. The one place where the
//! animation library meets the ECS.
//!
//! Owns: [`EntityAnimations`]: a set of clips, the entity each clip target moves, each target's
//! rest [`Transform`] (where the level placed it), and one playhead per clip. Each fixed step
//! it advances the playheads that run and writes the `Transform`s of their targets; a clip that
//! is not running writes nothing (so a closed door costs no commit). Main thread, fixed step,
//! after physics (a kinematic body follows its `Transform` at the next step).
//! Must not: decide when clips play (rules and game code call [`EntityAnimations::play`]).
//!
//! A clip's values are relative to the rest transform: translation adds (metres, world axes
//! of the target's parent), rotation turns the target about its own origin (`q · rest`),
//! scale multiplies. Where two clips move the same target, the later clip in the list wins.

use hecs::{Entity, World};

use super::clip::Clip;
use super::player::{FiredEvent, PlayMode, Playback};
use super::pose::Pose;
use crate::ecs::Transform;

/// Clips bound to entities, with a playhead each.
#[derive(Clone, Debug, Default)]
pub struct EntityAnimations {
    clips: Vec<Clip>,
    targets: Vec<Entity>,
    rest: Vec<Transform>,
    playheads: Vec<Option<Playback>>,
}

impl EntityAnimations {
    /// Binds `clips` (channel targets index `targets`) to entities; their current
    /// `Transform`s become the rest transforms (identity for an entity without one).
    pub fn new(clips: Vec<Clip>, targets: Vec<Entity>, world: &World) -> Self {
        let rest = targets
            .iter()
            .map(|&e| {
                world
                    .get::<&Transform>(e)
                    .map_or(Transform::IDENTITY, |t| *t)
            })
            .collect();
        let playheads = vec![None; clips.len()];
        Self {
            clips,
            targets,
            rest,
            playheads,
        }
    }

    /// The clips.
    pub fn clips(&self) -> &[Clip] {
        &self.clips
    }

    /// The index of the clip named `name`.
    pub fn clip_index(&self, name: &str) -> Option<usize> {
        self.clips.iter().position(|c| c.name == name)
    }

    /// The playhead of clip `clip` (`None` before it first plays).
    pub fn playhead(&self, clip: usize) -> Option<&Playback> {
        self.playheads.get(clip)?.as_ref()
    }

    /// Plays clip `clip` forward in `mode` from where its playhead is (the start, the first
    /// time).
    pub fn play(&mut self, clip: usize, mode: PlayMode) {
        let Some(slot) = self.playheads.get_mut(clip) else {
            return;
        };
        let playback = slot.get_or_insert_with(|| Playback::new(clip, mode));
        playback.mode = mode;
        playback.reversed = false;
        playback.paused = false;
        playback.finished = false;
    }

    /// Plays clip `clip` backward from where its playhead is, once; nothing if it never
    /// played (it is at its start already).
    pub fn reverse(&mut self, clip: usize) {
        if let Some(Some(playback)) = self.playheads.get_mut(clip) {
            playback.mode = PlayMode::Once;
            playback.reversed = true;
            playback.paused = false;
            playback.finished = false;
        }
    }

    /// Stops clip `clip` where it is.
    pub fn pause(&mut self, clip: usize) {
        if let Some(Some(playback)) = self.playheads.get_mut(clip) {
            playback.paused = true;
        }
    }

    /// Advances the running clips by `dt_seconds` and writes the `Transform`s of the targets
    /// they move. Returns the clip events passed, clips in list order.
    pub fn step(&mut self, world: &mut World, dt_seconds: f64) -> Vec<FiredEvent> {
        let mut fired = Vec::new();
        let mut moving = vec![false; self.targets.len()];
        for playback in self.playheads.iter_mut().flatten() {
            if playback.paused || playback.finished {
                continue;
            }
            playback.advance(&self.clips, dt_seconds, &mut fired);
            if let Some(clip) = self.clips.get(playback.clip) {
                for channel in &clip.channels {
                    if let Some(m) = moving.get_mut(channel.target) {
                        *m = true;
                    }
                }
            }
        }
        if !moving.contains(&true) {
            return fired;
        }
        // Every clip that has played contributes, so that a finished clip's offset stays
        // while another clip moves the same target.
        let mut pose = Pose::identity(self.targets.len());
        for playback in self.playheads.iter().flatten() {
            if let Some(clip) = self.clips.get(playback.clip) {
                pose.apply_clip(clip, playback.time_seconds);
            }
        }
        for (i, &entity) in self.targets.iter().enumerate() {
            if !moving[i] || !pose.animated[i] {
                continue;
            }
            let rest = self.rest[i];
            let animated = Transform {
                translation: rest.translation + pose.translation[i],
                rotation: (pose.rotation[i] * rest.rotation).normalize(),
                scale: rest.scale * pose.scale[i],
            };
            if let Ok(mut transform) = world.get::<&mut Transform>(entity) {
                *transform = animated;
            }
        }
        fired
    }
}
