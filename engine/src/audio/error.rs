//! The audio subsystem's one error type.
//!
//! Owns: [`AudioError`] and [`DecodeProblem`]. Every variant names what it is about: the sound
//! file (or in-memory sound name) and the problem, the bus and its limit, or the device. Must
//! not: log, retry or fall back; callers decide (see `Audio::new` for the device fallback).

use std::fmt;
use std::path::PathBuf;

use super::Bus;

/// Why a sound's bytes are not a playable sound.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum DecodeProblem {
    /// Zero bytes.
    Empty,
    /// The bytes are not in a format the engine decodes (WAV with PCM samples, or Ogg Vorbis).
    NotAudio { detail: String },
    /// The file ends before what its header promised: a chunk (`"RIFF"`, `"data"`, ...) declares
    /// `declared_bytes` but only `present_bytes` follow.
    Truncated {
        chunk: String,
        declared_bytes: u64,
        present_bytes: u64,
    },
    /// The decoder reached the end of the bytes in the middle of a packet or header.
    EndedEarly,
    /// A recognised container whose content the decoder rejects (unsupported codec, more than
    /// two channels, a malformed header).
    Malformed { detail: String },
    /// Decodes, but holds no samples.
    NoSamples,
}

impl fmt::Display for DecodeProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Empty => f.write_str("the file is empty (0 bytes)"),
            Self::NotAudio { detail } => write!(
                f,
                "not a supported audio format (WAV or Ogg Vorbis expected): {detail}"
            ),
            Self::Truncated {
                chunk,
                declared_bytes,
                present_bytes,
            } => write!(
                f,
                "truncated: the {chunk:?} chunk declares {declared_bytes} bytes but only \
                 {present_bytes} are present"
            ),
            Self::EndedEarly => f.write_str("truncated: the data ends in the middle of a packet"),
            Self::Malformed { detail } => write!(f, "malformed audio: {detail}"),
            Self::NoSamples => f.write_str("decodes to zero samples"),
        }
    }
}

/// Everything that can go wrong in `candela::audio`.
#[derive(Debug, thiserror::Error)]
pub enum AudioError {
    /// A sound file could not be read from disk (missing, unreadable).
    #[error("sound file {}: cannot read it: {source}", path.display())]
    Io {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
    /// A sound's bytes could not be decoded. `sound` is the file path for files, or the name
    /// given for in-memory bytes.
    #[error("sound {sound}: {problem}")]
    Decode {
        sound: String,
        problem: DecodeProblem,
    },
    /// The output device could not be opened or started (no sound card, ALSA/cpal failure).
    #[error("audio device: {0}")]
    Device(String),
    /// More sounds are playing on `bus` at once than it has room for. Finished sounds free
    /// their slot on the next `Audio::tick`.
    #[error(
        "too many sounds playing at once on the {bus:?} bus (limit {limit}); finished sounds free \
         their slots on the next tick"
    )]
    TooManySounds { bus: Bus, limit: usize },
    /// A kira resource that is created once at start-up (listener, bus track) could not be.
    #[error("audio start-up: cannot create the {what}: {detail}")]
    Setup { what: &'static str, detail: String },
}
