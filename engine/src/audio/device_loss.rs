//! What [`Audio`] does without a sound device: none at start (one message, the silent
//! recorder), or one lost mid-run (unplugged, disconnected: opened once more, else the silent
//! recorder, one message; game time, the `played` log, volumes and ids carry over).
//!
//! Owns: opening with that fallback, the device messages, and the switch on a loss. Main
//! (game) thread. Must not: retry a lost device more than once per loss.

use super::backend::{OutputSettings, SilentSettings};
use super::history::Capped;
use super::playback::Audio;
use super::test_device::TestDevice;

impl Audio {
    /// Tries the default output device; on failure logs one line (kept in
    /// [`Self::device_messages`]) and falls back to the silent recorder. Never fails. A device
    /// lost later (unplugged) is handled on [`Self::tick`] the same way.
    pub fn new() -> Self {
        Self::open_or_silent(OutputSettings::Device)
    }

    /// [`Self::new`] on a test's stand-in device (absent, present, unplugged later).
    pub fn with_test_device(device: TestDevice) -> Self {
        Self::open_or_silent(OutputSettings::Test(device))
    }

    fn open_or_silent(output: OutputSettings) -> Self {
        match Self::build(output) {
            Ok(audio) => audio,
            Err(e) => {
                let message = format!("{e}; sound is off (the silent recorder takes its place)");
                log::warn!("{message}");
                let mut audio = Self::silent();
                audio.device_messages.push(message);
                audio
            }
        }
    }

    /// What went wrong with the sound device so far: one message for a device missing at start,
    /// one for each loss mid-run. Empty while all is well or when silent was asked for.
    pub fn device_messages(&self) -> &[String] {
        &self.device_messages
    }

    /// The device is gone: open it once more (a new default device may have taken its place),
    /// else go on with the silent recorder. Game time, the `played` log, bus volumes and ids
    /// carry over; the sounds that were playing are lost with the device. One message.
    pub(super) fn lose_device(&mut self, problem: &str) {
        let (mut next, outcome) = match Self::build(self.output.clone()) {
            Ok(reopened) => (
                reopened,
                "sound goes on on the default device, opened again",
            ),
            Err(_) => (
                Self::silent(),
                "sound is off (the silent recorder takes its place)",
            ),
        };
        let message = format!("audio device lost ({problem}); {outcome}");
        log::warn!("{message}");
        next.time_seconds = self.time_seconds;
        next.next_id = self.next_id;
        next.played = std::mem::replace(&mut self.played, Capped::new(0));
        next.device_messages = std::mem::take(&mut self.device_messages);
        next.device_messages.push(message);
        if let Some(rate) = next.silent_rate_hz.or(next.test_rate_hz) {
            // The new output starts now: its record starts at this point of the whole output.
            next.frames_mixed = (next.time_seconds * f64::from(rate)).round() as u64;
            let keep = match &next.output {
                OutputSettings::Silent(_) => {
                    let s = SilentSettings::default();
                    (s.max_recorded_seconds * f64::from(s.sample_rate_hz)) as usize
                }
                _ => 0,
            };
            next.recorded = Capped::starting_at(keep, next.frames_mixed);
        }
        for (bus, volume) in self.volumes.clone() {
            next.set_volume_over(bus, volume, 0.0);
        }
        *self = next;
    }
}
