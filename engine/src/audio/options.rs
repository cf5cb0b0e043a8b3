//! The small value types of the audio API: buses, play options, handle ids, play records, and
//! the one amplitude-to-decibel conversion.
//!
//! Owns: [`Bus`], [`PlayOptions`], [`PlayingId`], [`PlayedSound`], [`decibels_of`]. Units:
//! volumes are linear amplitude factors (`1.0` = as authored, `0.5` = half the amplitude,
//! about −6 dB); positions are world space, metres; times are game seconds. Must not: hold kira
//! handles or any state.

use std::sync::Arc;

use glam::Vec3;
use kira::Decibels;

/// A mixer bus with its own volume. Every sound goes through `Master`; sounds started with
/// `Audio::play` also through `Effects`, music through `Music`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Bus {
    Master,
    Effects,
    Music,
}

/// How `Audio::play` starts a sound.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlayOptions {
    /// Linear amplitude factor, `0.0..=1.0` (clamped; NaN counts as 0). Default `1.0`.
    pub volume: f32,
    /// Repeat the whole sound until stopped. Default `false` (one-shot).
    pub looped: bool,
    /// `Some(world position, metres)`: a spatial sound, panned and attenuated relative to the
    /// listener (see `Audio::set_listener`); `None` (default): plays as authored, centred.
    pub at: Option<Vec3>,
}

impl Default for PlayOptions {
    fn default() -> Self {
        Self {
            volume: 1.0,
            looped: false,
            at: None,
        }
    }
}

/// Names a sound started by `Audio::play`. Ids are never reused within one `Audio`; an id whose
/// sound has finished is simply ignored by `stop` and `set_position`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct PlayingId(pub u64);

/// A record of one sound started (by `play` or `play_music`), kept in both modes.
#[derive(Clone, Debug, PartialEq)]
pub struct PlayedSound {
    /// The sound's name (`Sound::name`).
    pub name: Arc<str>,
    /// Game time when it was started: the sum of `dt_seconds` passed to `Audio::tick` so far.
    pub time_seconds: f64,
    /// World position, metres, for spatial sounds; `None` otherwise.
    pub position: Option<Vec3>,
    /// Linear amplitude factor it was started with (after clamping).
    pub volume: f32,
    pub looped: bool,
    pub bus: Bus,
    /// The id `play` returned; `None` for music.
    pub id: Option<PlayingId>,
}

/// A linear amplitude factor clamped to `0.0..=1.0`; NaN gives `0.0`.
pub fn clamp_volume(linear: f32) -> f32 {
    if linear.is_nan() {
        0.0
    } else {
        linear.clamp(0.0, 1.0)
    }
}

/// Decibels of a linear amplitude factor: `20 log10(linear)`, with anything at or below kira's
/// silence floor (−60 dB, amplitude 0.001) mapped to silence.
pub fn decibels_of(linear: f32) -> Decibels {
    if linear.is_nan() || linear <= 0.0 {
        return Decibels::SILENCE;
    }
    Decibels((20.0 * linear.log10()).max(Decibels::SILENCE.0))
}
