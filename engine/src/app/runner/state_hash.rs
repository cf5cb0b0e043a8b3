//! [`Engine::state_hash`]: one 64-bit fingerprint of the simulation, to check that two runs
//! (a recording and its replay, two replays) went through the very same states. Compare hashes
//! of runs with the same steps per frame: `Transform`s are hashed as the frame posed them
//! (physics interpolation), the bodies' simulated states as of the last step.
//!
//! Covers, in this order (FNV-1a over 64-bit words): the fixed steps run; every entity's
//! `Transform` (translation, rotation, scale as f32 bits) in entity order; every character's
//! state (vertical speed, grounded, sliding) and every carrier's held body; every physics
//! body's pose, linear and angular velocity and sleep state in entity order
//! (`PhysicsWorld::state_words`); the level logic's state (`LevelLogic::state_words`: steps,
//! outcome, rule states, volume occupants, clip playheads, pending events); the light groups
//! switched off; a physical sky's time of day (date, UTC hours, day rate) or sun angles; every
//! simulated water's heights, speeds and waders' push (`HeightField::state_words`) in entity
//! order; every character's animation (state, action, playheads:
//! `CharacterAnimation::state_words`) in body order. Not covered: rendering (images, converging), audio output, wall-clock time,
//! and the game's own fields outside the world (a game hashes those itself).
//!
//! Main thread, between frames. Must not: change anything.

use super::engine::Engine;
use crate::ecs::Transform;
use crate::sim::animation::{CharacterAnimation, SkinnedAnimator};
use crate::sim::physics::{Carrier, CharacterState};
use crate::sim::water::WaterSim;

/// FNV-1a over 64-bit words.
struct Fnv(u64);

impl Fnv {
    fn word(&mut self, w: u64) {
        for b in w.to_le_bytes() {
            self.0 = (self.0 ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3);
        }
    }

    fn floats(&mut self, values: impl IntoIterator<Item = f32>) {
        for v in values {
            self.word(u64::from(v.to_bits()));
        }
    }
}

impl Engine {
    /// The fingerprint of the simulation's state now (see the module doc for what it covers).
    /// Equal hashes at every step of two runs mean the runs did the same thing.
    pub fn state_hash(&self) -> u64 {
        let mut h = Fnv(0xcbf2_9ce4_8422_2325);
        h.word(self.clock.steps);
        let mut transforms: Vec<(u64, Transform)> = self
            .world
            .query::<(hecs::Entity, &Transform)>()
            .iter()
            .map(|(e, t)| (e.to_bits().get(), *t))
            .collect();
        transforms.sort_by_key(|(e, _)| *e);
        for (e, t) in transforms {
            h.word(e);
            h.floats(t.translation.to_array());
            h.floats(t.rotation.to_array());
            h.floats(t.scale.to_array());
        }
        let mut characters: Vec<(u64, CharacterState)> = self
            .world
            .query::<(hecs::Entity, &CharacterState)>()
            .iter()
            .map(|(e, s)| (e.to_bits().get(), *s))
            .collect();
        characters.sort_by_key(|(e, _)| *e);
        for (e, s) in characters {
            h.word(e);
            h.floats([s.vertical_speed]);
            h.word(u64::from(s.grounded) | u64::from(s.sliding) << 1);
        }
        let mut carriers: Vec<(u64, u64)> = self
            .world
            .query::<(hecs::Entity, &Carrier)>()
            .iter()
            .map(|(e, c)| (e.to_bits().get(), c.held.map_or(0, |b| b.to_bits().get())))
            .collect();
        carriers.sort_unstable();
        for (e, held) in carriers {
            h.word(e);
            h.word(held);
        }
        for w in self.physics.state_words() {
            h.word(w);
        }
        for w in self.logic.state_words() {
            h.word(w);
        }
        let mut waters: Vec<(u64, &WaterSim)> = Vec::new();
        let mut query = self.world.query::<(hecs::Entity, &WaterSim)>();
        waters.extend(query.iter().map(|(e, w)| (e.to_bits().get(), w)));
        waters.sort_by_key(|(e, _)| *e);
        for (e, water) in waters {
            h.word(e);
            for w in water.field.state_words() {
                h.word(w);
            }
        }
        drop(query);
        let mut animated: Vec<(u64, Vec<u64>)> = Vec::new();
        for (e, anim) in self
            .world
            .query::<(hecs::Entity, &CharacterAnimation)>()
            .iter()
        {
            let animator = self.world.get::<&SkinnedAnimator>(anim.visual).ok();
            let words = anim.state_words(animator.as_ref().map(|a| &a.player));
            animated.push((e.to_bits().get(), words));
        }
        animated.sort_by_key(|(e, _)| *e);
        for (e, words) in animated {
            h.word(e);
            words.into_iter().for_each(|w| h.word(w));
        }
        for group in 0..64 {
            h.word(u64::from(self.upkeep.light_group_on(group)));
        }
        for w in self.sky_state_words() {
            h.word(w);
        }
        h.0
    }
}
