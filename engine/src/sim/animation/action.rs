//! Actions: clips that game code asks a character to play over its locomotion — a one-shot
//! (`pick_up`, `celebrate`: plays once, then the character returns to the state its
//! locomotion calls for) or a held action (`push`: loops for as long as it is asked for, every
//! step, and stops the first step it is not).
//!
//! Owns: [`ActionKind`], [`ActionRequest`] and [`ActionSlot`] (on a
//! [`CharacterAnimation`](super::CharacterAnimation)). Game code asks through
//! `CharacterAnimation::request_action` or [`request_action`](super::request_action) in its
//! fixed step; `animate_characters` later in the same step calls [`ActionSlot::update`], which
//! crossfades the player into the action and, when the action ends, has the state machine
//! crossfade back ([`StateMachine::resume_with_fade`]). While an action plays the machine does not
//! choose states. A one-shot asked for with [`ActionRequest::yield_legs_when_moving`] (the
//! third-person lift) gives its legs back as soon as the character moves over the ground
//! ([`YIELD_SPEED_MPS`]): the rest of the clip plays on the upper body
//! ([`UpperBodySlot::play_once`]) while the machine crossfades the legs into the walk, so a
//! character never slides along crouched. Deterministic: only the fixed step's requests, the
//! locomotion and `dt` decide.
//! Main thread, once per fixed step. Must not: touch the ECS, physics or vertices.
//! Units: seconds.

use super::model::AnimatedModel;
use super::player::{AnimationPlayer, PlayMode, Playback};
use super::state_machine::{Locomotion, StateChange, StateMachine};
use super::upper_body::UpperBodySlot;

/// Ground speed (smoothed, m/s) above which a yielding one-shot hands its legs back to
/// locomotion: half the slowest walk, so standing still or shuffling keeps the whole clip.
pub const YIELD_SPEED_MPS: f32 = 0.5;

/// How an action plays.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ActionKind {
    /// Plays the clip once, then locomotion takes over again.
    Once,
    /// Loops the clip while requested every step; the first step without a request ends it.
    Held,
}

/// A request for a clip of the character's model.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ActionRequest {
    /// Index into the model's clips (`AnimatedModel::find_clip`).
    pub clip: usize,
    pub kind: ActionKind,
    /// Crossfade into the action, and back to locomotion when it ends, seconds.
    pub fade_seconds: f64,
    /// A one-shot that plays on the upper body only while the character moves (asked for
    /// while moving, or once it starts moving), so its legs walk.
    pub yield_legs_when_moving: bool,
}

impl ActionRequest {
    /// The crossfade in and out of an action unless a request says otherwise, seconds.
    pub const DEFAULT_FADE_SECONDS: f64 = 0.15;

    /// `clip` played as `kind` with the default fade.
    pub fn new(clip: usize, kind: ActionKind) -> Self {
        Self {
            clip,
            kind,
            fade_seconds: Self::DEFAULT_FADE_SECONDS,
            yield_legs_when_moving: false,
        }
    }

    /// The same request, its legs given back to locomotion while the character moves (a
    /// one-shot only: a held action keeps the whole body).
    pub fn yielding_legs(self) -> Self {
        Self {
            yield_legs_when_moving: self.kind == ActionKind::Once,
            ..self
        }
    }
}

/// A character's action: what game code asked for this step and what is playing.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ActionSlot {
    requested: Option<ActionRequest>,
    playing: Option<ActionRequest>,
    seconds: f64,
}

impl ActionSlot {
    /// Asks for `request` this step (a held action must be asked for every step). A request
    /// for the action already playing keeps it (a one-shot is not restarted); another clip
    /// replaces it.
    pub fn request(&mut self, request: ActionRequest) {
        self.requested = Some(request);
    }

    /// The action playing, if any.
    pub fn playing(&self) -> Option<&ActionRequest> {
        self.playing.as_ref()
    }

    /// Seconds since the action playing started.
    pub fn seconds(&self) -> f64 {
        self.seconds
    }

    /// Words for the engine's state hash: the action playing (clip, kind, or all ones for
    /// none) and its seconds.
    pub fn state_words(&self) -> [u64; 2] {
        let playing = self.playing.map_or(u64::MAX, |a| {
            (a.clip as u64) << 1 | u64::from(a.kind == ActionKind::Held)
        });
        [playing, self.seconds.to_bits()]
    }

    /// One step of `dt_seconds`: starts, keeps or ends the action, and otherwise lets
    /// `machine` choose the state for `m`. Call before the player is ticked. Returns the
    /// machine's change of state, if it made one.
    pub fn update(
        &mut self,
        machine: &mut StateMachine,
        player: &mut AnimationPlayer,
        m: &Locomotion,
        dt_seconds: f64,
    ) -> Option<StateChange> {
        self.update_layered(machine, player, m, dt_seconds, None)
    }

    /// [`ActionSlot::update`] for a character whose model `upper.0` has an upper-body slot
    /// `upper.1`: a yielding one-shot moves there while the character moves.
    pub fn update_layered(
        &mut self,
        machine: &mut StateMachine,
        player: &mut AnimationPlayer,
        m: &Locomotion,
        dt_seconds: f64,
        upper: Option<(&AnimatedModel, &mut UpperBodySlot)>,
    ) -> Option<StateChange> {
        let mut requested = self.requested.take();
        let moving = m.grounded && m.horizontal_speed_mps > YIELD_SPEED_MPS;
        if moving && let Some((model, slot)) = upper {
            // Asked for while moving: the arms only, faded in from the walk's.
            if let Some(request) = requested
                && request.yield_legs_when_moving
                && self.playing.map(|p| p.clip) != Some(request.clip)
                && slot
                    .play_once(model, player, request.clip, 0.0, true)
                    .is_ok()
            {
                requested = None;
            }
            // Playing on the whole body when the character sets off: the rest of the clip
            // goes on over the arms, at full weight (the pose does not jump), and the legs
            // crossfade into the walk.
            let handed = self
                .playing
                .filter(|p| p.yield_legs_when_moving)
                .and_then(|p| {
                    let time = player
                        .current()
                        .filter(|c| c.clip == p.clip && !c.finished)?
                        .time_seconds;
                    slot.play_once(model, player, p.clip, time, false).ok()?;
                    Some(p)
                });
            if let Some(handed) = handed {
                self.playing = None;
                self.seconds = 0.0;
                machine.resume_with_fade(handed.fade_seconds);
            }
        }
        if let Some(request) = requested
            && self.playing.map(|p| p.clip) != Some(request.clip)
        {
            let mode = match request.kind {
                ActionKind::Once => PlayMode::Once,
                ActionKind::Held => PlayMode::Loop,
            };
            player.crossfade(Playback::new(request.clip, mode), request.fade_seconds);
            self.playing = Some(request);
            self.seconds = 0.0;
            return None;
        }
        if let Some(playing) = self.playing {
            let over = match playing.kind {
                ActionKind::Held => requested.is_none(),
                ActionKind::Once => player
                    .current()
                    .is_none_or(|p| p.clip != playing.clip || p.finished),
            };
            if !over {
                if dt_seconds.is_finite() && dt_seconds > 0.0 {
                    self.seconds += dt_seconds;
                }
                return None;
            }
            self.playing = None;
            self.seconds = 0.0;
            machine.resume_with_fade(playing.fade_seconds);
        }
        machine.update(player, m, dt_seconds)
    }
}
