//! Holding the effect sounds while the game is paused: every sound on the effects bus (one-shots,
//! loops, the spatial sub-tracks of laser hums and footsteps) fades out over
//! [`PAUSE_FADE_SECONDS`] and stops advancing; resuming fades them back in where they were.
//! Music plays on under the pause menu.
//!
//! Main thread (kira's audio thread carries the fade). Must not: change the bus volumes the
//! settings set (`Audio::volume` keeps reporting them).

use super::playback::{Audio, tween_seconds};

/// Seconds of the fade when effects are held or released.
pub const PAUSE_FADE_SECONDS: f64 = 0.1;

impl Audio {
    /// Holds (`true`) or releases (`false`) every effect sound; music is not affected.
    pub fn set_effects_paused(&mut self, paused: bool) {
        if paused == self.effects_paused {
            return;
        }
        self.effects_paused = paused;
        let tween = tween_seconds(PAUSE_FADE_SECONDS);
        if paused {
            self.effects.pause(tween);
        } else {
            self.effects.resume(tween);
        }
    }

    /// Whether effect sounds are held ([`Audio::set_effects_paused`]).
    pub fn effects_paused(&self) -> bool {
        self.effects_paused
    }
}
