//! The numbers that bound and tune audio: how many sounds can play at once, fade and ramp
//! lengths, the spatial distance model, and the caps that keep a long run's memory bounded.
//!
//! Owns: constants only, each with its unit and why it is what it is. Must not: hold state or
//! logic.

/// Non-spatial effect sounds that can play at once. Finished sounds free their slot on the next
/// [`super::Audio::tick`]; past this, `play` returns [`super::AudioError::TooManySounds`].
pub const EFFECT_SOUND_CAPACITY: usize = 512;
/// Spatial sounds that can play at once (each is a kira spatial track).
pub const SPATIAL_SOUND_CAPACITY: usize = 128;
/// Music tracks that can play at once (a crossfade holds two).
pub const MUSIC_SOUND_CAPACITY: usize = 8;
/// How long `play_music` crossfades from the old track to the new one, seconds.
pub const MUSIC_CROSSFADE_SECONDS: f64 = 1.0;
/// Bus volume changes ramp over this long, seconds, so they do not click.
pub const VOLUME_RAMP_SECONDS: f64 = 0.02;
/// Spatial sounds are at full volume up to this distance from the listener, metres.
pub const SPATIAL_MIN_DISTANCE_METERS: f32 = 1.0;
/// ... and fall off linearly in decibels to silence (−60 dB) at this distance, metres.
pub const SPATIAL_MAX_DISTANCE_METERS: f32 = 50.0;
/// `played()` keeps at least this many of the latest records (at most twice as many).
pub const MAX_PLAYED_RECORDS: usize = 4096;
/// One `tick` advances audio by at most this much, seconds: a longer stall (a debugger break, a
/// level load) does not make the silent recorder mix minutes of audio in one call.
pub const MAX_TICK_SECONDS: f64 = 1.0;
