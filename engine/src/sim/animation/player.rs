//! The animation player: a playhead per clip that advances with game time — play, pause,
//! once / loop / ping-pong, reverse, speed, events fired as the playhead passes them — and
//! crossfades from one clip to the next, producing a [`Pose`] of local transforms per target.
//!
//! Owns: [`AnimationPlayer`], [`Playback`], [`PlayMode`], [`FiredEvent`]. Must not: know
//! what the targets are (nodes, doors, platforms) or deform vertices (`deform` does).
//! Units: seconds (float64: a float32 clock loses sub-millisecond resolution after a few
//! hours of play and would round sample times onto STEP keys).
//!
//! Events fire when the playhead crosses or lands on their time in its direction of travel:
//! moving forward over (t0, t1], backward over [t1, t0); the first tick after `play` (and
//! each loop restart) includes its starting point. A ping-pong turn fires an event at the
//! turning point once. A tick longer than [`MAX_CYCLES_PER_TICK`] whole cycles skips the
//! extra cycles (their events are not fired).

use super::clip::{Clip, ClipEvent};
use super::pose::Pose;
use super::speed_blend::BlendPartner;
use super::upper_body::UpperLayer;
pub use crate::assets::PlayMode;

/// Cycles (loops or ping-pong legs) one tick walks through before skipping the rest.
pub const MAX_CYCLES_PER_TICK: u32 = 64;

/// One clip being played.
#[derive(Clone, Debug, PartialEq)]
pub struct Playback {
    /// Index into the clip list the player is ticked with.
    pub clip: usize,
    /// The playhead, seconds from the clip's start, in [0, duration].
    pub time_seconds: f64,
    /// Playback rate (1 = real time); negative values count as 0.
    pub speed: f64,
    /// Whether the playhead moves towards the start.
    pub reversed: bool,
    pub mode: PlayMode,
    pub paused: bool,
    /// Set when a [`PlayMode::Once`] playback reaches its end.
    pub finished: bool,
    /// A second clip mixed in at the same fraction of its duration (a walk/run blend, set
    /// each step by the state machine); its events are not fired.
    pub blend: Option<BlendPartner>,
    /// The next tick includes the starting point in its event range.
    fresh: bool,
}

impl Playback {
    /// Clip `clip` from its start, forward, at real time.
    pub fn new(clip: usize, mode: PlayMode) -> Self {
        Self {
            clip,
            time_seconds: 0.0,
            speed: 1.0,
            reversed: false,
            mode,
            paused: false,
            finished: false,
            blend: None,
            fresh: true,
        }
    }

    /// Clip `clip` from its end, backward (a door closing along its opening clip).
    pub fn reversed_from_end(clip: usize, mode: PlayMode, clips: &[Clip]) -> Self {
        let mut playback = Self::new(clip, mode);
        playback.reversed = true;
        playback.time_seconds = clips.get(clip).map_or(0.0, |c| c.duration_seconds);
        playback
    }

    /// Advances by `dt_seconds` of game time, pushing the events passed onto `fired`.
    pub(crate) fn advance(&mut self, clips: &[Clip], dt_seconds: f64, fired: &mut Vec<FiredEvent>) {
        let Some(clip) = clips.get(self.clip) else {
            return;
        };
        if self.paused || self.finished || dt_seconds.is_nan() || dt_seconds <= 0.0 {
            return;
        }
        let duration = clip.duration_seconds;
        let mut first = std::mem::take(&mut self.fresh);
        if duration.is_nan() || duration <= 0.0 {
            if first {
                fire(clip, self.clip, 0.0, 0.0, true, fired);
            }
            self.finished = self.mode == PlayMode::Once;
            return;
        }
        self.time_seconds = self.time_seconds.clamp(0.0, duration);
        let mut remaining = dt_seconds * self.speed.max(0.0);
        let cycle = match self.mode {
            PlayMode::PingPong => 2.0 * duration,
            _ => duration,
        };
        if remaining > cycle * f64::from(MAX_CYCLES_PER_TICK) {
            remaining %= cycle;
        }
        while remaining > 0.0 {
            let t = self.time_seconds;
            let room = if self.reversed { t } else { duration - t };
            let step = remaining.min(room);
            let next = if self.reversed { t - step } else { t + step };
            fire(clip, self.clip, t, next, first, fired);
            first = false;
            self.time_seconds = next;
            remaining -= step;
            if step < room {
                break;
            }
            match self.mode {
                PlayMode::Once => {
                    self.finished = true;
                    break;
                }
                PlayMode::Loop => {
                    self.time_seconds = if self.reversed { duration } else { 0.0 };
                    first = true;
                }
                PlayMode::PingPong => self.reversed = !self.reversed,
            }
        }
        if self.mode == PlayMode::Once {
            let end = if self.reversed { 0.0 } else { duration };
            self.finished |= self.time_seconds == end;
        }
    }
}

/// Pushes the events of clip `index` that a playhead moving from `from` to `to` passes: the
/// range is closed at `to`, and at `from` only when `include_start`; in the order met.
fn fire(
    clip: &Clip,
    index: usize,
    from: f64,
    to: f64,
    include_start: bool,
    fired: &mut Vec<FiredEvent>,
) {
    let (low, high) = (from.min(to), from.max(to));
    let mut passed: Vec<&ClipEvent> = clip
        .events
        .iter()
        .filter(|e| e.time_seconds >= low && e.time_seconds <= high)
        .filter(|e| include_start || e.time_seconds != from)
        .collect();
    passed.sort_by(|a, b| a.time_seconds.total_cmp(&b.time_seconds));
    if to < from {
        passed.reverse();
    }
    fired.extend(passed.into_iter().map(|event| FiredEvent {
        clip: index,
        name: event.name.clone(),
        time_seconds: event.time_seconds,
    }));
}

/// An event the playhead passed during a tick.
#[derive(Clone, Debug, PartialEq)]
pub struct FiredEvent {
    /// The clip it belongs to.
    pub clip: usize,
    pub name: String,
    /// Its time in the clip, seconds.
    pub time_seconds: f64,
}

/// Plays one clip at a time, crossfading from the previous one when asked.
#[derive(Clone, Debug, Default)]
pub struct AnimationPlayer {
    current: Option<Playback>,
    fading_out: Option<Playback>,
    fade_elapsed_seconds: f64,
    fade_seconds: f64,
    /// A clip blended over the upper body (`upper_body`).
    layer: Option<UpperLayer>,
}

impl AnimationPlayer {
    /// A player with nothing playing (its pose is the rest pose).
    pub fn new() -> Self {
        Self::default()
    }

    /// Starts `playback` at once, dropping whatever played (and any fade).
    pub fn play(&mut self, playback: Playback) {
        self.current = Some(playback);
        self.fading_out = None;
    }

    /// Starts `playback` and fades the current clip out over `fade_seconds` (linear weights;
    /// 0 or less cuts at once).
    pub fn crossfade(&mut self, playback: Playback, fade_seconds: f64) {
        if fade_seconds > 0.0 && self.current.is_some() {
            self.fading_out = self.current.take();
            self.fade_elapsed_seconds = 0.0;
            self.fade_seconds = fade_seconds;
        } else {
            self.fading_out = None;
        }
        self.current = Some(playback);
    }

    /// The clip playing (the one faded in, during a crossfade).
    pub fn current(&self) -> Option<&Playback> {
        self.current.as_ref()
    }

    /// The clip fading out during a crossfade (its weight is `1 − current_weight()`).
    pub fn fading_out(&self) -> Option<&Playback> {
        self.fading_out.as_ref()
    }

    /// The playing clip, to pause, resume, reverse, seek or change speed.
    pub fn current_mut(&mut self) -> Option<&mut Playback> {
        self.current.as_mut()
    }

    /// Pauses or resumes the playing clip (and any fade).
    pub fn set_paused(&mut self, paused: bool) {
        if let Some(playback) = &mut self.current {
            playback.paused = paused;
        }
        if let Some(playback) = &mut self.fading_out {
            playback.paused = paused;
        }
    }

    /// Turns the playing clip around (a finished `Once` clip plays back to its other end).
    pub fn reverse(&mut self) {
        if let Some(playback) = &mut self.current {
            playback.reversed = !playback.reversed;
            playback.finished = false;
        }
    }

    /// Sets or clears the upper-body layer.
    pub fn set_layer(&mut self, layer: Option<UpperLayer>) {
        self.layer = layer;
    }

    /// The upper-body layer, if any.
    pub fn layer(&self) -> Option<&UpperLayer> {
        self.layer.as_ref()
    }

    /// The upper-body layer, to fade it.
    pub fn layer_mut(&mut self) -> Option<&mut UpperLayer> {
        self.layer.as_mut()
    }

    /// The weight of the current clip: 1, or in [0, 1) while a crossfade runs.
    pub fn current_weight(&self) -> f32 {
        match &self.fading_out {
            Some(_) => (self.fade_elapsed_seconds / self.fade_seconds).clamp(0.0, 1.0) as f32,
            None => 1.0,
        }
    }

    /// Advances by `dt_seconds` of game time; returns the events passed, in order.
    pub fn tick(&mut self, clips: &[Clip], dt_seconds: f64) -> Vec<FiredEvent> {
        let mut fired = Vec::new();
        if let Some(playback) = &mut self.fading_out {
            playback.advance(clips, dt_seconds, &mut fired);
            if !playback.paused && dt_seconds > 0.0 {
                self.fade_elapsed_seconds += dt_seconds;
            }
            if self.fade_elapsed_seconds >= self.fade_seconds {
                self.fading_out = None;
            }
        }
        if let Some(playback) = &mut self.current {
            playback.advance(clips, dt_seconds, &mut fired);
        }
        if let Some(layer) = &mut self.layer {
            // The layer's events are not fired: the locomotion's are the character's.
            layer.playback.advance(clips, dt_seconds, &mut Vec::new());
        }
        fired
    }

    /// The pose now: `rest` with the current clip applied, blended with the clip fading out,
    /// then the upper-body layer blended over the nodes of its mask by its weight.
    pub fn pose(&self, clips: &[Clip], rest: &Pose) -> Pose {
        let mut pose = rest.clone();
        let apply = |pose: &mut Pose, playback: &Playback| {
            let Some(clip) = clips.get(playback.clip) else {
                return;
            };
            pose.apply_clip(clip, playback.time_seconds);
            let Some(partner) = playback.blend.filter(|b| b.weight > 0.0) else {
                return;
            };
            if let Some(other) = clips.get(partner.clip) {
                // Phase-synchronised: the same fraction of each cycle.
                let duration = clip.duration_seconds;
                let phase = if duration > 0.0 {
                    (playback.time_seconds / duration).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                let mut mixed = rest.clone();
                mixed.apply_clip(other, phase * other.duration_seconds);
                pose.blend(&mixed, partner.weight);
            }
        };
        match (&self.fading_out, &self.current) {
            (Some(out), Some(current)) => {
                apply(&mut pose, out);
                let mut incoming = rest.clone();
                apply(&mut incoming, current);
                pose.blend(&incoming, self.current_weight());
            }
            (None, Some(current)) => apply(&mut pose, current),
            (Some(out), None) => apply(&mut pose, out),
            (None, None) => {}
        }
        if let Some(layer) = self.layer.as_ref().filter(|l| l.weight > 0.0)
            && let Some(clip) = clips.get(layer.playback.clip)
        {
            let mut upper = rest.clone();
            upper.apply_clip(clip, layer.playback.time_seconds);
            pose.blend_masked(&upper, &layer.mask, layer.weight);
        }
        pose
    }
}
