//! Where the mixed sound goes: the sound card (kira's cpal backend), the silent recorder, or a
//! [`TestDevice`] standing in for a sound card in fault tests.
//!
//! Owns: [`OutputBackend`], the one kira `Backend` the engine builds its `AudioManager` on, so
//! that `playback.rs` has a single code path for both; and [`SilentSettings`]. With a device, kira's
//! audio thread pulls samples on its own. Silent, nothing pulls: the recorder keeps kira's
//! `Renderer` and mixes exactly as many frames as the game asked for in [`OutputBackend::render`]
//! (called from `Audio::tick` on the game thread), in blocks of at most one kira internal buffer,
//! each preceded by `on_start_processing` just as a device callback does. That is what lets kira
//! pick up new sounds and free finished ones (without it every `play` would fail once 128 sounds
//! had been queued) and what makes the mixed samples available to tests. Must not: know about
//! sounds, buses or the ECS; keep more than one tick's samples (the capped record lives in
//! `playback.rs`).

use kira::backend::cpal::{CpalBackend, CpalBackendSettings};
use kira::backend::{Backend, Renderer};

use super::AudioError;
use super::test_device::TestDevice;

/// Settings of the silent recorder.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SilentSettings {
    /// Frames per second the recorder mixes at. Sounds at another rate are resampled by kira
    /// (cubic interpolation); at the same rate they are reproduced sample for sample.
    pub sample_rate_hz: u32,
    /// How much of the mixed output `Audio::recorded_samples` keeps, in seconds: the most recent
    /// `max_recorded_seconds` are always there, and at most twice that is held (older frames are
    /// dropped in one block). `0.0` records nothing. Memory: 8 bytes per frame, so the default
    /// 30 s at 44.1 kHz holds 10.6 MB to 21.2 MB.
    pub max_recorded_seconds: f64,
}

impl Default for SilentSettings {
    fn default() -> Self {
        Self {
            sample_rate_hz: 44_100,
            max_recorded_seconds: 30.0,
        }
    }
}

/// Which output to open.
#[derive(Clone, Debug)]
pub enum OutputSettings {
    /// The default output device of the default host (ALSA on Linux).
    Device,
    /// No device: mix on `Audio::tick` into memory.
    Silent(SilentSettings),
    /// A stand-in device a test can make absent or unplug (mixes at 44.1 kHz).
    Test(TestDevice),
}

/// Something the device reported.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DeviceProblem {
    pub message: String,
    /// The device is gone (unplugged, disconnected, its stream invalidated): nothing more will
    /// be heard from it.
    pub lost: bool,
}

/// The silent recorder: kira's renderer and a scratch buffer of interleaved stereo samples.
pub struct Recorder {
    sample_rate_hz: u32,
    /// kira's internal buffer size, frames: the largest block mixed between two
    /// `on_start_processing` calls.
    block_frames: usize,
    renderer: Option<Renderer>,
    scratch: Vec<f32>,
}

/// The backend the engine's `AudioManager` runs on.
pub enum OutputBackend {
    Device(CpalBackend),
    /// Boxed: the renderer is large (1.8 KB) next to the cpal handle.
    Silent(Box<Recorder>),
    /// A test's stand-in device: a recorder whose output is thrown away, and its switch.
    Test(Box<Recorder>, TestDevice, bool),
}

impl OutputBackend {
    /// The recorder's sample rate; `None` with a device.
    pub fn silent_sample_rate_hz(&self) -> Option<u32> {
        match self {
            Self::Silent(r) => Some(r.sample_rate_hz),
            Self::Device(_) | Self::Test(..) => None,
        }
    }

    /// A test device: mixes (and drops) `frames` frames, as a device's own thread would play
    /// them. Does nothing for the others.
    pub fn pump(&mut self, frames: usize) {
        if let Self::Test(recorder, _, _) = self {
            recorder.mix(frames);
        }
    }

    /// A test device's sample rate.
    pub fn test_sample_rate_hz(&self) -> Option<u32> {
        match self {
            Self::Test(r, _, _) => Some(r.sample_rate_hz),
            _ => None,
        }
    }

    /// Silent mode: mixes the next `frames` frames and returns them as interleaved stereo
    /// (`[l0, r0, l1, r1, ...]`, linear amplitude clamped to `-1..=1` by kira). Returns an
    /// empty slice with a device (its own thread mixes) or before kira has started.
    pub fn render(&mut self, frames: usize) -> &[f32] {
        let Self::Silent(recorder) = self else {
            return &[];
        };
        recorder.mix(frames)
    }

    /// Device mode: the next problem the device reported (kira's cpal backend: a stream error;
    /// a test device: its unplugging, once).
    pub fn pop_device_error(&mut self) -> Option<DeviceProblem> {
        match self {
            Self::Device(cpal) => cpal.pop_error().map(|e| {
                use kira::backend::cpal::cpal::ErrorKind;
                DeviceProblem {
                    message: e.to_string(),
                    lost: matches!(
                        e.kind(),
                        ErrorKind::DeviceNotAvailable | ErrorKind::StreamInvalidated
                    ),
                }
            }),
            Self::Test(_, device, reported) if device.is_unplugged() && !*reported => {
                *reported = true;
                Some(DeviceProblem {
                    message: "the device was unplugged (test device)".into(),
                    lost: true,
                })
            }
            Self::Silent(_) | Self::Test(..) => None,
        }
    }
}

impl Recorder {
    fn new(sample_rate_hz: u32, internal_buffer_size: usize) -> Self {
        Self {
            sample_rate_hz,
            block_frames: internal_buffer_size.max(1),
            renderer: None,
            scratch: Vec::new(),
        }
    }

    /// Mixes the next `frames` frames (interleaved stereo; empty before kira has started).
    fn mix(&mut self, frames: usize) -> &[f32] {
        let Some(renderer) = self.renderer.as_mut() else {
            return &[];
        };
        self.scratch.clear();
        self.scratch.resize(frames * 2, 0.0);
        for block in self.scratch.chunks_mut(self.block_frames * 2) {
            renderer.on_start_processing();
            renderer.process(block, 2);
        }
        &self.scratch
    }
}

impl Backend for OutputBackend {
    type Settings = OutputSettings;
    type Error = AudioError;

    fn setup(
        settings: Self::Settings,
        internal_buffer_size: usize,
    ) -> Result<(Self, u32), Self::Error> {
        match settings {
            OutputSettings::Device => {
                CpalBackend::setup(CpalBackendSettings::default(), internal_buffer_size)
                    .map(|(backend, rate)| (Self::Device(backend), rate))
                    .map_err(|e| AudioError::Device(e.to_string()))
            }
            OutputSettings::Silent(s) => {
                if s.sample_rate_hz == 0 {
                    return Err(AudioError::Device(
                        "the silent recorder needs a sample rate above 0 Hz".into(),
                    ));
                }
                let recorder = Recorder::new(s.sample_rate_hz, internal_buffer_size);
                Ok((Self::Silent(Box::new(recorder)), s.sample_rate_hz))
            }
            OutputSettings::Test(device) => {
                if let Some(refusal) = device.refusal() {
                    return Err(AudioError::Device(refusal.into()));
                }
                let rate = SilentSettings::default().sample_rate_hz;
                let recorder = Recorder::new(rate, internal_buffer_size);
                Ok((Self::Test(Box::new(recorder), device, false), rate))
            }
        }
    }

    fn start(&mut self, renderer: Renderer) -> Result<(), Self::Error> {
        match self {
            Self::Device(cpal) => cpal
                .start(renderer)
                .map_err(|e| AudioError::Device(e.to_string())),
            Self::Silent(recorder) | Self::Test(recorder, _, _) => {
                recorder.renderer = Some(renderer);
                Ok(())
            }
        }
    }
}
