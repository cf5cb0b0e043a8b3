//! [`Audio`]: the game's one handle on sound.
//!
//! Owns: the kira `AudioManager` (on [`OutputBackend`]: the device or the silent recorder), the
//! listener, the `Effects` and `Music` buses (sub-tracks of kira's main track, which is
//! `Master`), the handles of sounds still playing, the `played` log and, silent, the capped
//! record of the mixed output. Runs on the main (game) thread; with a device, kira mixes on its
//! own audio thread and this side only sends commands. Spatial sounds each get a kira spatial
//! sub-track of `Effects` linked to the one listener. Conventions: right-handed, +Y up, metres;
//! the listener looks along its local −Z with +X to its right (the camera's convention).
//! Must not: touch the ECS (that is `emitters.rs`), decode files (`sounds.rs`), or block.

use std::collections::{HashMap, HashSet};
use std::time::Duration;

use glam::{Quat, Vec3};
use kira::listener::ListenerHandle;
use kira::sound::PlaybackState;
use kira::sound::static_sound::StaticSoundHandle;
use kira::track::{SpatialTrackBuilder, SpatialTrackHandle, TrackBuilder, TrackHandle};
use kira::{AudioManager, AudioManagerSettings, PlaySoundError, Tween};

use super::backend::{OutputBackend, OutputSettings, SilentSettings};
use super::history::Capped;
use super::limits::{
    EFFECT_SOUND_CAPACITY, MAX_PLAYED_RECORDS, MAX_TICK_SECONDS, MUSIC_CROSSFADE_SECONDS,
    MUSIC_SOUND_CAPACITY, SPATIAL_MAX_DISTANCE_METERS, SPATIAL_MIN_DISTANCE_METERS,
    SPATIAL_SOUND_CAPACITY, VOLUME_RAMP_SECONDS,
};
use super::options::{clamp_volume, decibels_of};
use super::{AudioError, Bus, PlayOptions, PlayedSound, PlayingId, Sound};

/// kira's mixing block, frames: the silent recorder calls `on_start_processing` once per block
/// (kira's default; 2.9 ms at 44.1 kHz), so a new sound starts within one block.
const INTERNAL_BUFFER_FRAMES: usize = 128;

pub(super) fn tween_seconds(seconds: f64) -> Tween {
    let seconds = if seconds.is_finite() {
        seconds.max(0.0)
    } else {
        0.0
    };
    Tween {
        duration: Duration::from_secs_f64(seconds),
        ..Default::default()
    }
}

/// A playing sound's kira handles. Dropping the spatial track handle lets kira remove the track
/// once its sound has finished.
pub(super) struct Voice {
    pub(super) sound: StaticSoundHandle,
    track: Option<SpatialTrackHandle>,
}

/// Sound output: one-shot and looping sounds, spatial sounds, music, bus volumes.
pub struct Audio {
    pub(super) manager: AudioManager<OutputBackend>,
    pub(super) listener: ListenerHandle,
    pub(super) effects: TrackHandle,
    pub(super) music: TrackHandle,
    pub(super) voices: HashMap<PlayingId, Voice>,
    /// Named loops a game keeps at a volume it sets each step (see `loops.rs`): sound name →
    /// the loop playing and its volume.
    pub(super) loops: HashMap<std::sync::Arc<str>, (PlayingId, f32)>,
    pub(super) music_voice: Option<StaticSoundHandle>,
    pub(super) next_id: u64,
    /// Game seconds: the sum of all (clamped) `tick` steps.
    pub(super) time_seconds: f64,
    /// Silent: frames mixed so far.
    pub(super) frames_mixed: u64,
    pub(super) played: Capped<PlayedSound>,
    pub(super) recorded: Capped<[f32; 2]>,
    pub(super) volumes: HashMap<Bus, f32>,
    /// The recorder's sample rate; `None` with a device.
    pub(super) silent_rate_hz: Option<u32>,
    /// Sounds owned by `SoundEmitter`s (see `emitters.rs`).
    pub(super) emitter_sounds: HashSet<PlayingId>,
    /// What was opened (reopened once when a device is lost).
    pub(super) output: OutputSettings,
    /// A device (real or test) mixes at this rate; `None` for the silent recorder and for the
    /// real device (its own thread pulls).
    pub(super) test_rate_hz: Option<u32>,
    /// What went wrong with the sound device, one message per failure (also logged).
    pub(super) device_messages: Vec<String>,
    /// Effect sounds are held (the game is paused; see `pause.rs`).
    pub(super) effects_paused: bool,
}

impl Audio {
    /// The default output device, or the error that kept it from opening.
    pub fn with_device() -> Result<Self, AudioError> {
        Self::build(OutputSettings::Device)
    }

    /// Always the silent recorder at [`SilentSettings::default`] (44.1 kHz, 30 s kept): tests,
    /// CI, headless capture.
    pub fn silent() -> Self {
        Self::silent_with(SilentSettings::default())
    }

    /// The silent recorder with its sample rate and record length chosen. A zero sample rate is
    /// replaced by the default one.
    pub fn silent_with(mut settings: SilentSettings) -> Self {
        if settings.sample_rate_hz == 0 {
            settings.sample_rate_hz = SilentSettings::default().sample_rate_hz;
        }
        Self::build(OutputSettings::Silent(settings)).unwrap_or_else(|e| {
            // Only kira's fixed start-up allocations can fail here, well inside its limits.
            panic!("the silent audio recorder cannot fail to start, but did: {e}")
        })
    }

    pub(super) fn build(settings: OutputSettings) -> Result<Self, AudioError> {
        let keep_frames = match &settings {
            OutputSettings::Silent(s) => {
                let frames = s.max_recorded_seconds.max(0.0) * f64::from(s.sample_rate_hz);
                if frames.is_finite() {
                    frames as usize
                } else {
                    0
                }
            }
            OutputSettings::Device | OutputSettings::Test(_) => 0,
        };
        let output = settings.clone();
        let mut manager = AudioManager::<OutputBackend>::new(AudioManagerSettings {
            capacities: Default::default(),
            main_track_builder: Default::default(),
            internal_buffer_size: INTERNAL_BUFFER_FRAMES,
            backend_settings: settings,
        })?;
        let setup = |what: &'static str| {
            move |e: kira::ResourceLimitReached| AudioError::Setup {
                what,
                detail: e.to_string(),
            }
        };
        let listener = manager
            .add_listener(Vec3::ZERO, Quat::IDENTITY)
            .map_err(setup("listener"))?;
        let effects = manager
            .add_sub_track(
                TrackBuilder::new()
                    .sound_capacity(EFFECT_SOUND_CAPACITY)
                    .sub_track_capacity(SPATIAL_SOUND_CAPACITY),
            )
            .map_err(setup("effects bus"))?;
        let music = manager
            .add_sub_track(TrackBuilder::new().sound_capacity(MUSIC_SOUND_CAPACITY))
            .map_err(setup("music bus"))?;
        let silent_rate_hz = manager.backend_mut().silent_sample_rate_hz();
        let test_rate_hz = manager.backend_mut().test_sample_rate_hz();
        Ok(Self {
            output,
            test_rate_hz,
            device_messages: Vec::new(),
            effects_paused: false,
            silent_rate_hz,
            manager,
            listener,
            effects,
            music,
            voices: HashMap::new(),
            loops: HashMap::new(),
            music_voice: None,
            next_id: 0,
            time_seconds: 0.0,
            frames_mixed: 0,
            played: Capped::new(MAX_PLAYED_RECORDS),
            recorded: Capped::new(keep_frames),
            volumes: HashMap::new(),
            emitter_sounds: HashSet::new(),
        })
    }

    /// `true` when no device is open and the silent recorder mixes on `tick`.
    pub fn is_silent(&self) -> bool {
        self.silent_rate_hz.is_some()
    }

    /// Game seconds so far: the sum of the (clamped) steps passed to [`Self::tick`].
    pub fn time_seconds(&self) -> f64 {
        self.time_seconds
    }

    /// Advances audio time by `dt_seconds` of game time (at most [`MAX_TICK_SECONDS`]; zero,
    /// negative or non-finite steps are ignored). Silent: mixes exactly the frames that game time
    /// now covers and appends them to the record. With a device: logs stream errors kira
    /// reported. Both: forgets sounds that have finished. Called once per fixed step.
    pub fn tick(&mut self, dt_seconds: f64) {
        if !dt_seconds.is_finite() || dt_seconds <= 0.0 {
            return;
        }
        self.time_seconds += dt_seconds.min(MAX_TICK_SECONDS);
        if let Some(rate) = self.silent_rate_hz {
            // Frames due are counted from the total time, so rounding never drifts.
            let target = (self.time_seconds * f64::from(rate)).round() as u64;
            let frames = target.saturating_sub(self.frames_mixed) as usize;
            self.frames_mixed = target.max(self.frames_mixed);
            let mixed = self.manager.backend_mut().render(frames);
            self.recorded
                .extend_from_slice(bytemuck::cast_slice::<f32, [f32; 2]>(mixed));
        } else {
            if let Some(rate) = self.test_rate_hz {
                let target = (self.time_seconds * f64::from(rate)).round() as u64;
                let frames = target.saturating_sub(self.frames_mixed) as usize;
                self.frames_mixed = target.max(self.frames_mixed);
                self.manager.backend_mut().pump(frames);
            }
            let mut lost = None;
            while let Some(problem) = self.manager.backend_mut().pop_device_error() {
                if problem.lost {
                    lost.get_or_insert(problem.message);
                } else {
                    log::warn!("audio device: {}", problem.message);
                }
            }
            if let Some(problem) = lost {
                self.lose_device(&problem);
            }
        }
        self.voices
            .retain(|_, v| v.sound.state() != PlaybackState::Stopped);
        let voices = &self.voices;
        self.emitter_sounds.retain(|id| voices.contains_key(id));
        if self
            .music_voice
            .as_ref()
            .is_some_and(|m| m.state() == PlaybackState::Stopped)
        {
            self.music_voice = None;
        }
    }

    /// Starts a one-shot or looping sound on the `Effects` bus. `options.at: Some(position)`
    /// makes it spatial (panned and attenuated relative to the listener: full volume within
    /// [`SPATIAL_MIN_DISTANCE_METERS`], falling linearly in decibels to silence at
    /// [`SPATIAL_MAX_DISTANCE_METERS`]); `None` plays it as authored. The sound starts at the
    /// next mixed block (within 128 frames, 2.9 ms at 44.1 kHz).
    pub fn play(&mut self, sound: &Sound, options: PlayOptions) -> Result<PlayingId, AudioError> {
        let volume = clamp_volume(options.volume);
        let mut data = sound.data().volume(decibels_of(volume));
        if options.looped {
            data = data.loop_region(..);
        }
        let full = |limit| {
            move |e: PlaySoundError<()>| match e {
                PlaySoundError::SoundLimitReached => AudioError::TooManySounds {
                    bus: Bus::Effects,
                    limit,
                },
                PlaySoundError::IntoSoundError(()) => AudioError::Setup {
                    what: "sound",
                    detail: "kira rejected the sound data".into(),
                },
            }
        };
        let voice = match options.at {
            None => Voice {
                sound: self
                    .effects
                    .play(data)
                    .map_err(full(EFFECT_SOUND_CAPACITY))?,
                track: None,
            },
            Some(position) => {
                let builder = SpatialTrackBuilder::new()
                    .distances((SPATIAL_MIN_DISTANCE_METERS, SPATIAL_MAX_DISTANCE_METERS))
                    .persist_until_sounds_finish(true)
                    .sound_capacity(1)
                    .sub_track_capacity(1);
                let mut track = self
                    .effects
                    .add_spatial_sub_track(self.listener.id(), position, builder)
                    .map_err(|_| AudioError::TooManySounds {
                        bus: Bus::Effects,
                        limit: SPATIAL_SOUND_CAPACITY,
                    })?;
                let sound = track.play(data).map_err(full(1))?;
                Voice {
                    sound,
                    track: Some(track),
                }
            }
        };
        let id = PlayingId(self.next_id);
        self.next_id += 1;
        self.voices.insert(id, voice);
        self.played.push(PlayedSound {
            name: sound.name().into(),
            time_seconds: self.time_seconds,
            position: options.at,
            volume,
            looped: options.looped,
            bus: Bus::Effects,
            id: Some(id),
        });
        Ok(id)
    }

    /// Stops sound `id`, fading out over `fade_seconds` (0 for at once). Finished or unknown ids
    /// are ignored.
    pub fn stop(&mut self, id: PlayingId, fade_seconds: f64) {
        if let Some(voice) = self.voices.get_mut(&id) {
            voice.sound.stop(tween_seconds(fade_seconds));
        }
    }

    /// `true` while sound `id` has not finished (as of the last `tick`).
    pub fn is_playing(&self, id: PlayingId) -> bool {
        self.voices
            .get(&id)
            .is_some_and(|v| v.sound.state() != PlaybackState::Stopped)
    }

    /// Sounds started by `play` that have not finished (as of the last `tick`).
    pub fn playing_count(&self) -> usize {
        self.voices.len()
    }

    /// Moves spatial sound `id` to `position` (world, metres). Ignored for non-spatial, finished
    /// or unknown ids.
    pub fn set_position(&mut self, id: PlayingId, position: Vec3) {
        if let Some(track) = self.voices.get_mut(&id).and_then(|v| v.track.as_mut()) {
            track.set_position(position, tween_seconds(0.0));
        }
    }

    /// Places the listener: the camera pose, `position` in metres, `orientation` rotating the
    /// listener's frame (looks along −Z, +X to its right, +Y up) into the world.
    pub fn set_listener(&mut self, position: Vec3, orientation: Quat) {
        self.listener.set_position(position, tween_seconds(0.0));
        self.listener
            .set_orientation(orientation, tween_seconds(0.0));
    }

    /// Plays `sound` as the music (on the `Music` bus), looping if `looped`. One track at a
    /// time: music already playing fades out while the new one fades in over
    /// [`MUSIC_CROSSFADE_SECONDS`].
    pub fn play_music(&mut self, sound: &Sound, looped: bool) -> Result<(), AudioError> {
        let mut data = sound.data().clone();
        if looped {
            data = data.loop_region(..);
        }
        let crossfade = self.music_voice.is_some();
        if crossfade {
            data = data.fade_in_tween(tween_seconds(MUSIC_CROSSFADE_SECONDS));
        }
        let handle = self
            .music
            .play(data)
            .map_err(|_| AudioError::TooManySounds {
                bus: Bus::Music,
                limit: MUSIC_SOUND_CAPACITY,
            })?;
        if let Some(mut old) = self.music_voice.replace(handle) {
            old.stop(tween_seconds(MUSIC_CROSSFADE_SECONDS));
        }
        self.played.push(PlayedSound {
            name: sound.name().into(),
            time_seconds: self.time_seconds,
            position: None,
            volume: 1.0,
            looped,
            bus: Bus::Music,
            id: None,
        });
        Ok(())
    }

    /// Fades the music out over `fade_seconds`.
    pub fn stop_music(&mut self, fade_seconds: f64) {
        if let Some(mut music) = self.music_voice.take() {
            music.stop(tween_seconds(fade_seconds));
        }
    }

    /// Sets a bus's volume: a linear amplitude factor in `0.0..=1.0` (clamped; NaN counts as 0),
    /// reached over [`VOLUME_RAMP_SECONDS`]. Buses multiply: an effect sound is scaled by its
    /// own volume, `Effects` and `Master`.
    pub fn set_volume(&mut self, bus: Bus, linear: f32) {
        self.set_volume_over(bus, linear, VOLUME_RAMP_SECONDS);
    }

    /// [`Self::set_volume`] reached over `seconds` (0: from the next mixed block on).
    pub(super) fn set_volume_over(&mut self, bus: Bus, linear: f32, seconds: f64) {
        let linear = clamp_volume(linear);
        self.volumes.insert(bus, linear);
        let db = decibels_of(linear);
        let ramp = tween_seconds(seconds);
        match bus {
            Bus::Master => self.manager.main_track().set_volume(db, ramp),
            Bus::Effects => self.effects.set_volume(db, ramp),
            Bus::Music => self.music.set_volume(db, ramp),
        }
    }

    /// A bus's volume as last set (linear amplitude factor; `1.0` until set).
    pub fn volume(&self, bus: Bus) -> f32 {
        self.volumes.get(&bus).copied().unwrap_or(1.0)
    }

    /// What was started so far, oldest first: at least the latest [`MAX_PLAYED_RECORDS`]. Kept
    /// in both modes.
    pub fn played(&self) -> &[PlayedSound] {
        self.played.as_slice()
    }

    /// Silent mode only: the mixed stereo output, frames of `[left, right]` linear amplitude at
    /// [`Self::recorded_sample_rate_hz`], oldest first; at least the latest
    /// `SilentSettings::max_recorded_seconds`. Frame `i` of the slice is frame
    /// `recorded_start_frame() + i` of the whole output, which starts at game time 0. `None`
    /// with a device.
    pub fn recorded_samples(&self) -> Option<&[[f32; 2]]> {
        self.silent_rate_hz.map(|_| self.recorded.as_slice())
    }

    /// Silent mode: how many frames were dropped from the front of the record so far.
    pub fn recorded_start_frame(&self) -> u64 {
        self.recorded.dropped()
    }

    /// Silent mode: the recorder's sample rate, frames per second; `None` with a device.
    pub fn recorded_sample_rate_hz(&self) -> Option<u32> {
        self.silent_rate_hz
    }
}

impl Default for Audio {
    /// [`Audio::new`]: the device if there is one, else the silent recorder.
    fn default() -> Self {
        Self::new()
    }
}
