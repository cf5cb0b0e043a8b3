//! # Audio
//!
//! Sound for the games, on kira: one-shot and looping sounds, spatial sounds on entities with the
//! listener at the camera, music with crossfades, and three volume buses (`Master`, `Effects`,
//! `Music`). Without an output device (CI, headless capture) a silent recorder takes the
//! device's place: the same kira mixer runs on [`Audio::tick`] and its output is kept, so tests
//! can check what would have been heard, sample by sample. A device that is missing at start
//! or lost mid-run (unplugged) is one message ([`Audio::device_messages`]) and the silent
//! recorder from then on; [`TestDevice`] stands in for a sound card in those tests.
//!
//! Flow: `sounds` decodes files into [`Sound`]s (at load time) → the game calls [`Audio::play`]
//! / [`Audio::play_music`] / [`Audio::set_loop_volume`] (named loops, `loops.rs`) and
//! [`sync_emitters`] each step → [`Audio::tick`] advances audio time (silent: mixes into the
//! record). Units: seconds, metres, linear amplitude factors (`1.0` = as
//! authored) unless a name says decibels. Sounds are made by `tools/assetgen` (`assetgen
//! sounds`), never downloaded.
//!
//! Must not: read level files or know about triggers; they call this API.

mod backend;
mod device_loss;
mod emitters;
mod error;
mod history;
mod limits;
mod loops;
mod options;
mod pause;
mod playback;
mod riff;
mod sounds;
mod test_device;

pub use backend::SilentSettings;
pub use emitters::{EMITTER_GONE_FADE_SECONDS, SoundEmitter, sync_emitters};
pub use error::{AudioError, DecodeProblem};
pub use limits::{
    EFFECT_SOUND_CAPACITY, MAX_PLAYED_RECORDS, MAX_TICK_SECONDS, MUSIC_CROSSFADE_SECONDS,
    MUSIC_SOUND_CAPACITY, SPATIAL_MAX_DISTANCE_METERS, SPATIAL_MIN_DISTANCE_METERS,
    SPATIAL_SOUND_CAPACITY, VOLUME_RAMP_SECONDS,
};
pub use options::{Bus, PlayOptions, PlayedSound, PlayingId, decibels_of};
pub use pause::PAUSE_FADE_SECONDS;
pub use playback::Audio;
pub use sounds::{Sound, decode_sound, decode_sound_bytes};
pub use test_device::TestDevice;
