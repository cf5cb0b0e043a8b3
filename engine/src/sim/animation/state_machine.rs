//! The animation state machine of a character: named states (idle, walk, run, jump, fall, …)
//! each playing one clip, chosen every fixed step from how the character moves
//! ([`Locomotion`]: horizontal speed, vertical speed, on the ground or not), with the clip's
//! playback rate following the speed (so feet do not slide) and a crossfade
//! ([`AnimationPlayer::crossfade`]) on every change of state. A state may blend a second clip
//! in by speed (`speed_blend`: walk → run, phase-synchronised). An action (`action`) takes the
//! player over for a while and then has the machine crossfade back ([`StateMachine::resume_with_fade`]).
//!
//! Owns: [`StateMachine`], [`AnimState`], [`StateCondition`], [`Contact`], [`Locomotion`],
//! [`StateMachineError`]. Data-driven: a level lists the states (`level::character`); the
//! machine knows no state by name. Choosing: the current state stays while its condition
//! holds with its speed range widened by the hysteresis; otherwise the first state in list
//! order whose condition holds is chosen (none: the current one stays). Deterministic: the same
//! locomotion sequence gives the same states, rates and player on every run.
//! Main thread, once per fixed step after physics. Must not: read physics or the ECS (the
//! caller hands in [`Locomotion`]) or deform vertices.
//! Units: metres per second, seconds.

use super::player::{AnimationPlayer, PlayMode, Playback};
use super::speed_blend::{BlendPartner, SpeedBlend};
pub use crate::assets::Contact;

/// How a character moves this step: what states are chosen by.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Locomotion {
    /// Speed over the ground, m/s (≥ 0).
    pub horizontal_speed_mps: f32,
    /// Vertical speed, m/s, + up.
    pub vertical_speed_mps: f32,
    /// Standing on something.
    pub grounded: bool,
}

/// Whether `m` satisfies `contact`.
fn contact_holds(contact: Contact, m: &Locomotion) -> bool {
    match contact {
        Contact::Any => true,
        Contact::Grounded => m.grounded,
        Contact::Airborne => !m.grounded,
        Contact::Rising => !m.grounded && m.vertical_speed_mps > 0.0,
        Contact::Falling => !m.grounded && m.vertical_speed_mps <= 0.0,
    }
}

/// When a state may be chosen: its contact and a horizontal speed range `[min, max)` (m/s).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StateCondition {
    pub contact: Contact,
    pub min_speed_mps: f32,
    /// May be infinite.
    pub max_speed_mps: f32,
}

impl StateCondition {
    /// Whether `m` satisfies the condition with the speed range widened by `slack_mps` on
    /// both sides.
    fn holds(&self, m: &Locomotion, slack_mps: f32) -> bool {
        let speed = m.horizontal_speed_mps;
        contact_holds(self.contact, m)
            && speed >= self.min_speed_mps - slack_mps
            && speed < self.max_speed_mps + slack_mps
    }
}

/// One state: its clip and how it is played.
#[derive(Clone, Debug, PartialEq)]
pub struct AnimState {
    pub name: String,
    /// Index into the model's clips.
    pub clip: usize,
    pub mode: PlayMode,
    pub when: StateCondition,
    /// The ground speed (m/s) at which the clip plays at rate 1; the rate is
    /// `speed / reference`, within `[min_rate, max_rate]`. `None`: always rate 1.
    pub reference_speed_mps: Option<f32>,
    pub min_rate: f32,
    pub max_rate: f32,
    /// Crossfade from the previous state into this one, seconds (0: cut).
    pub fade_in_seconds: f64,
    /// A second clip blended in by speed (walk → run), phase-synchronised; the rate then
    /// follows the blended stride ([`SpeedBlend::rate`]; needs `reference_speed_mps`).
    pub blend: Option<SpeedBlend>,
}

/// A state machine description that cannot run.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum StateMachineError {
    #[error("a character needs at least one animation state")]
    NoStates,
    #[error("state {state:?}: {message}")]
    BadState { state: String, message: String },
    #[error("hysteresis_mps must be finite and at least 0, not {0}")]
    BadHysteresis(f32),
}

/// A change of state made by [`StateMachine::update`].
#[derive(Clone, Debug, PartialEq)]
pub struct StateChange {
    /// The state left (`None` on the first update).
    pub from: Option<usize>,
    pub to: usize,
}

/// Chooses a character's state each step and plays its clip on an [`AnimationPlayer`].
#[derive(Clone, Debug, PartialEq)]
pub struct StateMachine {
    states: Vec<AnimState>,
    hysteresis_mps: f32,
    current: Option<usize>,
    seconds_in_state: f64,
    /// The next update crossfades into its state over this many seconds, even if it is the
    /// current one (after an action took the player over).
    resume: Option<f64>,
}

impl StateMachine {
    /// A machine over `states` (chosen in list order) that keeps its current state while the
    /// speed stays within `hysteresis_mps` of its range. Checks every number.
    pub fn new(states: Vec<AnimState>, hysteresis_mps: f32) -> Result<Self, StateMachineError> {
        if states.is_empty() {
            return Err(StateMachineError::NoStates);
        }
        if !(hysteresis_mps.is_finite() && hysteresis_mps >= 0.0) {
            return Err(StateMachineError::BadHysteresis(hysteresis_mps));
        }
        for state in &states {
            check_state(state).map_err(|message| StateMachineError::BadState {
                state: state.name.clone(),
                message,
            })?;
        }
        Ok(Self {
            states,
            hysteresis_mps,
            current: None,
            seconds_in_state: 0.0,
            resume: None,
        })
    }

    /// The states, in choosing order.
    pub fn states(&self) -> &[AnimState] {
        &self.states
    }

    /// The state now (`None` before the first update).
    pub fn current(&self) -> Option<&AnimState> {
        self.states.get(self.current?)
    }

    /// The index of the state now.
    pub fn current_index(&self) -> Option<usize> {
        self.current
    }

    /// Seconds since the last change of state.
    pub fn seconds_in_state(&self) -> f64 {
        self.seconds_in_state
    }

    /// The state `m` calls for: the current one while it holds (with hysteresis), else the
    /// first that holds, else the current one (or the first state before any update).
    pub fn choose(&self, m: &Locomotion) -> usize {
        if let Some(current) = self.current
            && self.states[current].when.holds(m, self.hysteresis_mps)
        {
            return current;
        }
        self.states
            .iter()
            .position(|s| s.when.holds(m, 0.0))
            .or(self.current)
            .unwrap_or(0)
    }

    /// After something else played on the player (an action): the next
    /// [`StateMachine::update`] crossfades into its state again over `fade_seconds`, even
    /// into the current one.
    pub fn resume_with_fade(&mut self, fade_seconds: f64) {
        self.resume = Some(fade_seconds);
    }

    /// One step of `dt_seconds`: chooses the state for `m`, crossfades `player` into its clip
    /// when the state changes, and sets the clip's rate from the speed. Call before the
    /// player is ticked. Returns the change, if any.
    pub fn update(
        &mut self,
        player: &mut AnimationPlayer,
        m: &Locomotion,
        dt_seconds: f64,
    ) -> Option<StateChange> {
        let next = self.choose(m);
        let resume = self.resume.take();
        let change = (resume.is_some() || self.current != Some(next)).then_some(StateChange {
            from: self.current,
            to: next,
        });
        let state = &self.states[next];
        if change.is_some() {
            let playback = Playback::new(state.clip, state.mode);
            match self.current {
                None => player.play(playback),
                Some(_) => player.crossfade(playback, resume.unwrap_or(state.fade_in_seconds)),
            }
            self.current = Some(next);
            self.seconds_in_state = 0.0;
        } else if dt_seconds.is_finite() && dt_seconds > 0.0 {
            self.seconds_in_state += dt_seconds;
        }
        if let Some(playback) = player.current_mut() {
            playback.speed = f64::from(rate(state, m.horizontal_speed_mps));
            playback.blend = state.blend.map(|b| BlendPartner {
                clip: b.clip,
                weight: b.weight(m.horizontal_speed_mps),
            });
        }
        change
    }
}

/// The playback rate of `state` at `speed_mps` over the ground (with a blend, of the
/// blended stride: [`SpeedBlend::rate`]).
pub fn rate(state: &AnimState, speed_mps: f32) -> f32 {
    match (state.reference_speed_mps, &state.blend) {
        (Some(reference), Some(blend)) if speed_mps.is_finite() => blend
            .rate(reference, speed_mps)
            .clamp(state.min_rate, state.max_rate),
        (Some(reference), None) if speed_mps.is_finite() => {
            (speed_mps.max(0.0) / reference).clamp(state.min_rate, state.max_rate)
        }
        _ => 1.0,
    }
}

fn check_state(s: &AnimState) -> Result<(), String> {
    let w = &s.when;
    if !(w.min_speed_mps.is_finite() && w.min_speed_mps >= 0.0) {
        return Err(format!(
            "min_speed_mps must be finite and at least 0, not {}",
            w.min_speed_mps
        ));
    }
    if w.max_speed_mps.is_nan() || w.max_speed_mps <= w.min_speed_mps {
        return Err(format!(
            "max_speed_mps ({}) must be above min_speed_mps ({})",
            w.max_speed_mps, w.min_speed_mps
        ));
    }
    if let Some(r) = s.reference_speed_mps
        && !(r.is_finite() && r > 0.0)
    {
        return Err(format!(
            "reference_speed_mps must be finite and above 0, not {r}"
        ));
    }
    let rates_ok = s.min_rate.is_finite() && s.max_rate.is_finite() && s.min_rate > 0.0;
    if !rates_ok || s.max_rate < s.min_rate {
        return Err(format!(
            "rates must be finite with 0 < min_rate ({}) ≤ max_rate ({})",
            s.min_rate, s.max_rate
        ));
    }
    if let Some(blend) = &s.blend {
        blend.check()?;
        if s.reference_speed_mps.is_none() {
            return Err("a blend needs the state's reference_speed_mps".into());
        }
    }
    if !(s.fade_in_seconds.is_finite() && s.fade_in_seconds >= 0.0) {
        return Err(format!(
            "fade_in_seconds must be finite and at least 0, not {}",
            s.fade_in_seconds
        ));
    }
    Ok(())
}
