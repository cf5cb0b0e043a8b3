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
//! choose states. Deterministic: only the fixed step's requests and `dt` decide.
//! Main thread, once per fixed step. Must not: touch the ECS, physics or vertices.
//! Units: seconds.

use super::player::{AnimationPlayer, PlayMode, Playback};
use super::state_machine::{Locomotion, StateChange, StateMachine};

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
        let requested = self.requested.take();
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
