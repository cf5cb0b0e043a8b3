//! Named loops: looping sounds, not placed, whose volume a game sets every step (wind, a music
//! pad that crossfades with another, a sound held while a button is). One loop per sound name.
//!
//! Owns: [`Audio::set_loop_volume`] and [`Audio::loop_volume`] over `Audio::loops`. The first
//! call for a sound starts it looping on the `Effects` bus; later calls ramp its volume over
//! [`VOLUME_RAMP_SECONDS`] (so a per-step change does not click); a loop at volume 0 keeps
//! running silently, so it comes back in phase. Main thread. Must not: place sounds (that is
//! `emitters.rs`) or touch the music bus.

use super::limits::VOLUME_RAMP_SECONDS;
use super::options::{clamp_volume, decibels_of};
use super::playback::tween_seconds;
use super::{Audio, AudioError, PlayOptions, Sound};

impl Audio {
    /// Sets the loop of `sound` (by `Sound::name`) to linear volume `volume` (`0.0..=1.0`,
    /// clamped), starting it looped, not placed, the first time (or after it was stopped).
    /// Errors as [`Audio::play`] when it cannot start.
    pub fn set_loop_volume(&mut self, sound: &Sound, volume: f32) -> Result<(), AudioError> {
        let volume = clamp_volume(volume);
        let name = sound.name();
        if let Some((id, level)) = self.loops.get_mut(name)
            && let Some(voice) = self.voices.get_mut(id)
        {
            if *level != volume {
                *level = volume;
                let tween = tween_seconds(VOLUME_RAMP_SECONDS);
                voice.sound.set_volume(decibels_of(volume), tween);
            }
            return Ok(());
        }
        let options = PlayOptions {
            volume,
            looped: true,
            at: None,
        };
        let id = self.play(sound, options)?;
        self.loops.insert(name.into(), (id, volume));
        Ok(())
    }

    /// The volume last set for the loop of the sound named `name`; `None` before its first
    /// [`Audio::set_loop_volume`].
    pub fn loop_volume(&self, name: &str) -> Option<f32> {
        self.loops.get(name).map(|(_, v)| *v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tone(name: &str) -> Sound {
        let samples: Vec<f32> = (0..4410).map(|i| (i as f32 * 0.0628).sin() * 0.5).collect();
        Sound::from_mono_samples(name, 44_100, &samples).expect("a valid tone")
    }

    /// A loop starts once, however many steps set it; its volume follows the last call, and
    /// it is heard in proportion (the silent recorder's peak halves with the volume).
    #[test]
    fn a_loop_starts_once_and_follows_its_volume() {
        let mut audio = Audio::silent();
        let (wind, pad) = (tone("wind"), tone("pad"));
        for _ in 0..5 {
            audio.set_loop_volume(&wind, 0.8).expect("starts");
            audio.set_loop_volume(&pad, 0.0).expect("starts");
            audio.tick(1.0 / 60.0);
        }
        let started = |name: &str| audio.played().iter().filter(|p| &*p.name == name).count();
        assert_eq!(started("wind"), 1, "the wind loop started more than once");
        assert_eq!(started("pad"), 1);
        assert_eq!(audio.loop_volume("wind"), Some(0.8));
        assert_eq!(audio.loop_volume("pad"), Some(0.0));
        assert_eq!(audio.loop_volume("water"), None);
        assert!(audio.played().iter().all(|p| p.looped));

        let peak = |audio: &mut Audio| {
            let from = audio.recorded_samples().map_or(0, <[_]>::len);
            for _ in 0..6 {
                audio.tick(1.0 / 60.0);
            }
            audio.recorded_samples().unwrap_or(&[])[from..]
                .iter()
                .fold(0.0f32, |m, [l, r]| m.max(l.abs()).max(r.abs()))
        };
        let loud = peak(&mut audio);
        audio.set_loop_volume(&wind, 0.4).expect("set");
        audio.tick(1.0 / 60.0);
        let soft = peak(&mut audio);
        assert!(loud > 0.0, "nothing heard");
        assert!(
            (soft / loud - 0.5).abs() < 0.05,
            "half the volume gave {soft} against {loud}"
        );
    }
}
