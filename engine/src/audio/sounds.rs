//! Decoding sound files into [`Sound`]s.
//!
//! Owns: [`Sound`] (decoded samples with a name, cheap to clone) and the decoders
//! [`decode_sound`] (a file), [`decode_sound_bytes`] (bytes already in memory) and
//! [`Sound::from_mono_samples`] (samples made in code: tests and tools). Formats: WAV with PCM
//! samples and Ogg Vorbis, mono or stereo, any sample rate (kira resamples to the output rate
//! at play time). Every failure is an [`AudioError`] naming the file and the problem; nothing
//! here panics on bad input. Runs on whichever thread loads assets. Must not: play anything or
//! touch the mixer (that is `playback.rs`), or resolve asset paths (that is `assets`).

use std::fmt;
use std::io::{Cursor, ErrorKind};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::Path;
use std::sync::Arc;

use kira::Frame;
use kira::sound::FromFileError;
use kira::sound::static_sound::StaticSoundData;

use super::riff::check_wave;
use super::{AudioError, DecodeProblem};

/// A decoded sound: stereo frames of linear amplitude in `-1..=1` at [`Self::sample_rate_hz`]
/// (mono files are decoded to two equal channels), and a name for logs and
/// [`super::PlayedSound`] records (the file stem for files). Cloning shares the samples.
#[derive(Clone)]
pub struct Sound {
    name: Arc<str>,
    data: StaticSoundData,
}

impl Sound {
    /// The name: the file stem (`"chime"` for `sounds/chime.wav`) or the name it was given.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Length in seconds at the sound's own sample rate.
    pub fn duration_seconds(&self) -> f64 {
        self.data.duration().as_secs_f64()
    }

    /// Samples per second per channel of the decoded data (the file's rate).
    pub fn sample_rate_hz(&self) -> u32 {
        self.data.sample_rate
    }

    /// Number of stereo frames.
    pub fn frame_count(&self) -> usize {
        self.data.num_frames()
    }

    /// Frame `index` as `[left, right]`, linear amplitude; `None` past the end.
    pub fn frame(&self, index: usize) -> Option<[f32; 2]> {
        self.data.frames.get(index).map(|f| [f.left, f.right])
    }

    /// A sound from mono samples made in code (a test tone, a tool's output): linear amplitude,
    /// clamped to `-1..=1`. Fails on a zero sample rate, no samples, or a non-finite sample.
    pub fn from_mono_samples(
        name: &str,
        sample_rate_hz: u32,
        samples: &[f32],
    ) -> Result<Self, AudioError> {
        let problem = if sample_rate_hz == 0 {
            Some(DecodeProblem::Malformed {
                detail: "sample rate 0 Hz".into(),
            })
        } else if samples.is_empty() {
            Some(DecodeProblem::NoSamples)
        } else {
            samples
                .iter()
                .position(|s| !s.is_finite())
                .map(|i| DecodeProblem::Malformed {
                    detail: format!("sample {i} is {}", samples[i]),
                })
        };
        if let Some(problem) = problem {
            return Err(AudioError::Decode {
                sound: name.into(),
                problem,
            });
        }
        let frames: Arc<[Frame]> = samples
            .iter()
            .map(|s| Frame::from_mono(s.clamp(-1.0, 1.0)))
            .collect();
        Ok(Self {
            name: name.into(),
            data: StaticSoundData {
                sample_rate: sample_rate_hz,
                frames,
                settings: Default::default(),
                slice: None,
            },
        })
    }

    /// The kira data, for the mixer.
    pub(crate) fn data(&self) -> &StaticSoundData {
        &self.data
    }
}

impl fmt::Debug for Sound {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Sound")
            .field("name", &self.name)
            .field("duration_seconds", &self.duration_seconds())
            .field("sample_rate_hz", &self.sample_rate_hz())
            .finish()
    }
}

/// Reads and decodes the sound file at `path`. The [`Sound`]'s name is the file stem. Errors
/// name `path`: [`AudioError::Io`] when it cannot be read, [`AudioError::Decode`] with the
/// problem when its bytes are not a playable sound.
pub fn decode_sound(path: &Path) -> Result<Sound, AudioError> {
    let bytes = std::fs::read(path).map_err(|source| AudioError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    let name = path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| path.display().to_string());
    decode(&name, &bytes).map_err(|problem| AudioError::Decode {
        sound: path.display().to_string(),
        problem,
    })
}

/// Decodes a sound file already in memory (`name` is used for the [`Sound`] and in errors).
pub fn decode_sound_bytes(name: &str, bytes: &[u8]) -> Result<Sound, AudioError> {
    decode(name, bytes).map_err(|problem| AudioError::Decode {
        sound: name.into(),
        problem,
    })
}

fn decode(name: &str, bytes: &[u8]) -> Result<Sound, DecodeProblem> {
    if bytes.is_empty() {
        return Err(DecodeProblem::Empty);
    }
    check_wave(bytes)?;
    // The decoders are third-party code fed untrusted bytes: a panic in them is reported as
    // this file's problem instead of taking the game down.
    let decoded = catch_unwind(AssertUnwindSafe(|| {
        StaticSoundData::from_cursor(Cursor::new(bytes))
    }))
    .map_err(|panic| DecodeProblem::Malformed {
        detail: format!("the decoder panicked: {}", panic_text(&*panic)),
    })?;
    let data = decoded.map_err(problem_of)?;
    if data.frames.is_empty() {
        return Err(DecodeProblem::NoSamples);
    }
    Ok(Sound {
        name: name.into(),
        data,
    })
}

fn panic_text(panic: &(dyn std::any::Any + Send)) -> String {
    panic
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| panic.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "(no message)".into())
}

fn io_problem(error: &std::io::Error) -> DecodeProblem {
    if error.kind() == ErrorKind::UnexpectedEof {
        DecodeProblem::EndedEarly
    } else {
        DecodeProblem::Malformed {
            detail: error.to_string(),
        }
    }
}

fn problem_of(error: FromFileError) -> DecodeProblem {
    use symphonia::core::errors::Error as Symphonia;
    let malformed = |detail: &str| DecodeProblem::Malformed {
        detail: detail.into(),
    };
    match error {
        FromFileError::NoDefaultTrack => malformed("no audio track"),
        FromFileError::UnknownSampleRate => malformed("no sample rate in the header"),
        FromFileError::UnknownDuration => malformed("no duration in the header"),
        FromFileError::UnsupportedChannelConfiguration => {
            malformed("only mono and stereo sounds are supported")
        }
        FromFileError::IoError(e) => io_problem(&e),
        FromFileError::SymphoniaError(Symphonia::IoError(e)) => io_problem(&e),
        FromFileError::SymphoniaError(Symphonia::Unsupported(what)) => DecodeProblem::NotAudio {
            detail: what.into(),
        },
        FromFileError::SymphoniaError(e) => malformed(&e.to_string()),
    }
}
