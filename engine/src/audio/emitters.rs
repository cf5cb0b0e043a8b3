//! Sound emitters on entities: the ECS side of spatial audio.
//!
//! Owns: [`SoundEmitter`] and [`sync_emitters`], which each step starts the sounds of emitters
//! that have none, moves every playing emitter's spatial sound to its entity's
//! [`GlobalTransform`] translation, and stops (with a short fade) the sounds of emitters that
//! were despawned or lost their component. Runs on the main thread after transforms are
//! propagated. Must not: write transforms or any other component but `SoundEmitter::playing`;
//! place the listener (the camera owner calls `Audio::set_listener`).

use std::collections::HashSet;

use crate::ecs::GlobalTransform;

use super::{Audio, PlayOptions, PlayingId, Sound};

/// When an emitter's entity goes away, its sound fades out over this long, seconds.
pub const EMITTER_GONE_FADE_SECONDS: f64 = 0.1;

/// A sound that comes from an entity (a humming machine, a door): spatial, at the entity's
/// [`GlobalTransform`] translation. Needs a `GlobalTransform` on the same entity.
#[derive(Clone, Debug)]
pub struct SoundEmitter {
    pub sound: Sound,
    /// Linear amplitude factor, `0.0..=1.0`, applied when the sound starts.
    pub volume: f32,
    /// Loops until the emitter goes away; otherwise plays once.
    pub looped: bool,
    /// The sound started for this emitter, written by [`sync_emitters`]. A one-shot emitter
    /// keeps its (finished) id and does not replay: set this to `None` to play it again.
    pub playing: Option<PlayingId>,
}

impl SoundEmitter {
    /// An emitter that has not started yet.
    pub fn new(sound: Sound, volume: f32, looped: bool) -> Self {
        Self {
            sound,
            volume,
            looped,
            playing: None,
        }
    }
}

/// Starts emitters that have no sound yet, moves playing ones to their entity's position, and
/// stops sounds whose emitter is gone. A sound that cannot start (too many at once) is logged
/// and retried on the next call. Cost: one query over emitters, O(emitters).
pub fn sync_emitters(audio: &mut Audio, world: &mut hecs::World) {
    let mut seen: HashSet<PlayingId> = HashSet::new();
    let query = world.query_mut::<(hecs::Entity, &mut SoundEmitter, &GlobalTransform)>();
    for (entity, emitter, transform) in query {
        let position = transform.0.w_axis.truncate();
        match emitter.playing {
            Some(id) => {
                audio.set_position(id, position);
                seen.insert(id);
            }
            None => {
                let options = PlayOptions {
                    volume: emitter.volume,
                    looped: emitter.looped,
                    at: Some(position),
                };
                match audio.play(&emitter.sound, options) {
                    Ok(id) => {
                        emitter.playing = Some(id);
                        audio.emitter_sounds.insert(id);
                        seen.insert(id);
                    }
                    Err(e) => {
                        log::warn!("sound emitter {entity:?} ({}): {e}", emitter.sound.name())
                    }
                }
            }
        }
    }
    let gone: Vec<PlayingId> = audio
        .emitter_sounds
        .iter()
        .filter(|id| !seen.contains(id))
        .copied()
        .collect();
    for id in gone {
        audio.stop(id, EMITTER_GONE_FADE_SECONDS);
        audio.emitter_sounds.remove(&id);
    }
}
