//! The upper-body layer: a clip game code asks a character to play on its upper body — the
//! joint [`UPPER_BODY_JOINT`] and every node below it — while its locomotion goes on below, so
//! a character carries a crate with its arms while its legs walk or run.
//!
//! Owns: [`UpperBodySlot`] (on a [`CharacterAnimation`](super::CharacterAnimation)) and
//! [`UpperLayer`] (what the [`AnimationPlayer`] blends over its pose). The layer is held: game
//! code asks for it every step it should go on ([`request_upper_body`](super::request_upper_body));
//! it fades in over [`UPPER_FADE_SECONDS`] while asked for and out as long once it is not.
//! A one-shot can play there too ([`UpperBodySlot::play_once`]: the rest of a lift handed over
//! by the action slot when the character sets off): it plays to its end whatever is asked for,
//! then fades out, and only then does a held clip fade in.
//! Deterministic: only the fixed step's requests and `dt` decide.
//! Main thread, once per fixed step. Must not: touch the ECS, physics or vertices.
//! Units: seconds.

use std::sync::Arc;

use super::error::AnimResult;
use super::model::AnimatedModel;
use super::player::{AnimationPlayer, PlayMode, Playback};

/// The joint whose subtree is the upper body (the hero's `spine`: chest, neck, head, arms).
pub const UPPER_BODY_JOINT: &str = "spine";

/// Fade of the layer in and out, seconds.
pub const UPPER_FADE_SECONDS: f64 = 0.2;

/// A clip blended over a player's pose on the nodes its mask weighs.
#[derive(Clone, Debug, PartialEq)]
pub struct UpperLayer {
    pub playback: Playback,
    /// Per node (the model's node order): 1 on the upper body, 0 elsewhere.
    pub mask: Arc<[f32]>,
    /// How much of the layer shows, in [0, 1] (fades).
    pub weight: f32,
}

/// 1 for `root` and every node below it, 0 for the others (`model`'s node order).
pub fn subtree_mask(model: &AnimatedModel, root: usize) -> Arc<[f32]> {
    let nodes = &model.nodes.nodes;
    let mut mask = vec![0.0_f32; nodes.len()];
    let mut stack = vec![root];
    while let Some(node) = stack.pop() {
        if let (Some(m), Some(n)) = (mask.get_mut(node), nodes.get(node))
            && *m == 0.0
        {
            *m = 1.0;
            stack.extend(n.children.iter().copied());
        }
    }
    mask.into()
}

/// A character's upper-body layer: the clip asked for this step and the one playing.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct UpperBodySlot {
    requested: Option<usize>,
    playing: Option<usize>,
    mask: Option<Arc<[f32]>>,
    /// The clip playing is a one-shot (`play_once`).
    once: bool,
}

impl UpperBodySlot {
    /// Asks for clip `clip` on the upper body this step of the model `model` (whose
    /// [`UPPER_BODY_JOINT`] must exist: else [`AnimError::NoSuchJoint`](super::AnimError)).
    pub fn request(&mut self, model: &AnimatedModel, clip: usize) -> AnimResult<()> {
        if self.mask.is_none() {
            let root = model.find_joint(UPPER_BODY_JOINT)?;
            self.mask = Some(subtree_mask(model, root));
        }
        self.requested = Some(clip);
        Ok(())
    }

    /// Plays clip `clip` of `model` once on the upper body of `player`, from `time_seconds`,
    /// fading in from nothing when `fade_in`, else at full weight at once (the whole body
    /// showed that clip until now). It replaces whatever the layer played. A model without
    /// [`UPPER_BODY_JOINT`] is [`AnimError::NoSuchJoint`](super::AnimError).
    pub fn play_once(
        &mut self,
        model: &AnimatedModel,
        player: &mut AnimationPlayer,
        clip: usize,
        time_seconds: f64,
        fade_in: bool,
    ) -> AnimResult<()> {
        let mask = match self.mask.clone() {
            Some(mask) => mask,
            None => {
                let mask = subtree_mask(model, model.find_joint(UPPER_BODY_JOINT)?);
                self.mask = Some(mask.clone());
                mask
            }
        };
        let mut playback = Playback::new(clip, PlayMode::Once);
        playback.time_seconds = time_seconds;
        player.set_layer(Some(UpperLayer {
            playback,
            mask,
            weight: if fade_in { 0.0 } else { 1.0 },
        }));
        self.playing = Some(clip);
        self.once = true;
        Ok(())
    }

    /// Whether the clip on the upper body is a one-shot ([`UpperBodySlot::play_once`]).
    pub fn playing_once(&self) -> bool {
        self.once && self.playing.is_some()
    }

    /// The clip on the upper body, if any (fading in, held or fading out).
    pub fn playing(&self) -> Option<usize> {
        self.playing
    }

    /// Words for the engine's state hash: none while nothing ever played (so characters
    /// that never use the layer hash as before), else the clip and the layer's playhead and
    /// weight.
    pub fn state_words(&self, player: &AnimationPlayer) -> Vec<u64> {
        match (self.playing, player.layer()) {
            (Some(clip), Some(layer)) => vec![
                clip as u64,
                layer.playback.time_seconds.to_bits(),
                u64::from(layer.weight.to_bits()),
            ],
            _ => Vec::new(),
        }
    }

    /// One step of `dt_seconds`: starts or keeps the layer asked for (fading in), or fades
    /// out and drops the one no longer asked for.
    pub fn update(&mut self, player: &mut AnimationPlayer, dt_seconds: f64) {
        let requested = self.requested.take();
        let step = if dt_seconds.is_finite() && dt_seconds > 0.0 {
            (dt_seconds / UPPER_FADE_SECONDS) as f32
        } else {
            0.0
        };
        if self.once {
            match player.layer_mut() {
                // A one-shot plays to its end whatever is asked for,
                Some(layer) if !layer.playback.finished => {
                    layer.weight = (layer.weight + step).min(1.0);
                    return;
                }
                // then fades out (held at its last key) before anything else plays.
                Some(layer) => {
                    layer.weight = (layer.weight - step).max(0.0);
                    if layer.weight > 0.0 {
                        return;
                    }
                    player.set_layer(None);
                }
                None => {}
            }
            self.once = false;
            self.playing = None;
            if requested.is_none() {
                return;
            }
        }
        match (requested, self.mask.clone()) {
            (Some(clip), Some(mask)) => {
                if self.playing != Some(clip) || player.layer().is_none() {
                    player.set_layer(Some(UpperLayer {
                        playback: Playback::new(clip, PlayMode::Loop),
                        mask,
                        weight: 0.0,
                    }));
                    self.playing = Some(clip);
                }
                if let Some(layer) = player.layer_mut() {
                    layer.weight = (layer.weight + step).min(1.0);
                }
            }
            _ => {
                if self.playing.is_none() {
                    return;
                }
                let done = player.layer_mut().is_none_or(|layer| {
                    layer.weight = (layer.weight - step).max(0.0);
                    layer.weight <= 0.0
                });
                if done {
                    player.set_layer(None);
                    self.playing = None;
                }
            }
        }
    }
}
