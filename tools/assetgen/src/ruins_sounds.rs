//! The sounds of It's About Time, synthesised: wind, water lapping, footsteps on sand and on
//! stone, a stone scrape, torch crackle, the time warp, the artifact chime, and the day and night
//! music pads. `ruins_sound_list` lists them (`RUINS_SOUNDS`: durations, loop flags),
//! normalises and writes them; this file only makes the raw samples (`f64`, any scale) at
//! `SAMPLE_RATE_HZ`.
//!
//! Loops are seamless by construction, as Reflect's (`reflect_sounds`): every frequency,
//! modulation and noise partial makes a whole number of cycles in the loop, and the torch's pops
//! wrap round its end. One-shots use the fixed-seed `Noise` and fade in and out. The two pads
//! share their root and fifth (D2, A2, D3, A3) and differ in the third and the colour notes
//! (day: F♯, E, B; night: F, C, G), so a crossfade between them is a change of mode, not of key.
//! Must not: read files or depend on the engine.

use std::f64::consts::TAU;

use crate::reflect_sounds::{loop_noise, sum_partials};
use crate::ruins_sound_list::duration_of;
use crate::sounds::{Noise, SAMPLE_RATE_HZ, bell, edges, frames, midi_hz, time};

/// A one-pole low-pass over `Noise`, cut-off `cutoff_hz`.
pub(crate) struct LowNoise {
    noise: Noise,
    state: f64,
    alpha: f64,
}

impl LowNoise {
    pub(crate) fn new(seed: u64, cutoff_hz: f64) -> Self {
        Self {
            noise: Noise(seed),
            state: 0.0,
            alpha: 1.0 - (-TAU * cutoff_hz / f64::from(SAMPLE_RATE_HZ)).exp(),
        }
    }

    pub(crate) fn next(&mut self) -> f64 {
        self.state += self.alpha * (self.noise.next() - self.state);
        self.state
    }
}

/// An exponentially decaying hit starting at `start` seconds with a 3 ms attack, time constant
/// `tau` seconds; zero before it starts.
pub(crate) fn hit(t: f64, start: f64, tau: f64) -> f64 {
    let local = t - start;
    if local < 0.0 {
        0.0
    } else {
        (local / 0.003).min(1.0) * (-local / tau).exp()
    }
}

/// A seamless 6 s desert wind: a 80–700 Hz band of noise partials under three slow gusts
/// (periods 6, 3 and 2 s), with a faint 900–1400 Hz whistle that rises with the gusts.
pub(crate) fn wind() -> Vec<f64> {
    let end = duration_of("wind");
    let body = loop_noise(0x0017_1D00_0000_0001, 80, 80.0, 700.0, end);
    let whistle = loop_noise(0x0017_1D00_0000_0002, 12, 900.0, 1400.0, end);
    (0..frames(end))
        .map(|i| {
            let t = time(i);
            let phase = TAU * t / end;
            let gust = 1.0 + 0.45 * phase.sin() + 0.2 * (2.0 * phase + 1.3).sin()
                - 0.15 * (3.0 * phase + 0.4).cos();
            let gust = gust.max(0.1);
            gust * sum_partials(&body, t) + 0.15 * gust * gust * sum_partials(&whistle, t)
        })
        .collect()
}

/// A seamless 4 s of water lapping at stone: a 120–500 Hz wash swelling at 1 Hz and 0.5 Hz,
/// and a 600–1800 Hz band of small splashes pulsing at 2 Hz.
pub(crate) fn water() -> Vec<f64> {
    let end = duration_of("water");
    let wash = loop_noise(0x0A7E_0000_0000_0001, 60, 120.0, 500.0, end);
    let splash = loop_noise(0x0A7E_0000_0000_0002, 40, 600.0, 1800.0, end);
    (0..frames(end))
        .map(|i| {
            let t = time(i);
            let lap = 0.6 + 0.4 * (TAU * 0.5 * t).sin() * (TAU * 1.0 * t + 0.5).sin();
            let pulse = (0.5 + 0.5 * (TAU * 2.0 * t + 2.0).sin()).powi(3);
            lap * sum_partials(&wash, t) + 0.5 * pulse * sum_partials(&splash, t)
        })
        .collect()
}

/// A step on sand, variant `variant` (0..3): a soft 1.8 kHz-low-passed crunch of noise spread
/// over 120 ms (heel, then toe) and no thump; each variant its own noise and timing.
pub(crate) fn footstep_sand(variant: u64) -> Vec<f64> {
    let end = 0.35;
    let mut grain = LowNoise::new(0x5A4D_0000_0000_0010 + variant, 1800.0);
    let mut body = LowNoise::new(0x5A4D_0000_0000_0020 + variant, 400.0);
    let toe = 0.07 + 0.015 * variant as f64;
    (0..frames(end))
        .map(|i| {
            let t = time(i);
            let envelope = hit(t, 0.0, 0.05) + 0.7 * hit(t, toe, 0.045);
            (1.5 * grain.next() + 2.0 * body.next()) * envelope * edges(t, end, 0.005)
        })
        .collect()
}

/// A step on stone, variant `variant` (0..3): a short bright click (noise low-passed at 5 kHz,
/// 8 ms) and a knock of two damped tones (about 190 and 430 Hz, 25 ms), heel then toe.
pub(crate) fn footstep_stone(variant: u64) -> Vec<f64> {
    let end = 0.25;
    let mut click = LowNoise::new(0x5703_0000_0000_0010 + variant, 5000.0);
    let knock_hz = 180.0 + 10.0 * variant as f64;
    let toe = 0.055 + 0.01 * variant as f64;
    (0..frames(end))
        .map(|i| {
            let t = time(i);
            let clicks = hit(t, 0.0, 0.008) + 0.6 * hit(t, toe, 0.006);
            let knocks = hit(t, 0.0, 0.025) + 0.5 * hit(t, toe, 0.02);
            let tone = (TAU * knock_hz * t).sin() + 0.5 * (TAU * knock_hz * 2.4 * t).sin();
            (2.0 * click.next() * clicks + 0.6 * tone * knocks) * edges(t, end, 0.005)
        })
        .collect()
}

/// A heavy stone dragged or a gate grinding, 1.6 s: noise low-passed at 500 Hz whose level
/// judders at 11 and 17 Hz, a 41 Hz rumble with its octave, and a thud when it stops (1.4 s).
pub(crate) fn stone_scrape() -> Vec<f64> {
    let end = duration_of("stone_scrape");
    let mut grind = LowNoise::new(0x5C4A_0000_0000_0001, 500.0);
    let mut grit = LowNoise::new(0x5C4A_0000_0000_0002, 3000.0);
    let stop = 1.4;
    (0..frames(end))
        .map(|i| {
            let t = time(i);
            let judder = 1.0 + 0.35 * (TAU * 11.0 * t).sin() * (TAU * 17.0 * t + 0.7).sin();
            let rumble = (TAU * 41.0 * t).sin() + 0.4 * (TAU * 82.0 * t).sin();
            let drag = (2.5 * grind.next() * judder + 0.3 * grit.next() + 0.35 * rumble)
                * edges(t, stop, 0.12);
            let thud = hit(t, stop, 0.07) * (TAU * 62.0 * (t - stop)).sin();
            (drag + 0.8 * thud) * edges(t, end, 0.01)
        })
        .collect()
}

/// A seamless 3 s torch: a soft 60–400 Hz roar swaying at 1/3 and 1 Hz, and 23 crackling pops
/// (noise bursts of 4–15 ms at fixed-seed times, each wrapping round the loop's end).
pub(crate) fn torch() -> Vec<f64> {
    let end = duration_of("torch");
    let roar = loop_noise(0x7042_0000_0000_0001, 50, 60.0, 400.0, end);
    let mut pick = Noise(0x7042_0000_0000_0002);
    let pops: Vec<(f64, f64, f64)> = (0..23)
        .map(|_| {
            let at = end * (0.5 + 0.5 * pick.next());
            let tau = 0.004 + 0.0055 * (1.0 + pick.next());
            let loudness = 0.4 + 0.3 * (1.0 + pick.next());
            (at, tau, loudness)
        })
        .collect();
    let mut crackle = LowNoise::new(0x7042_0000_0000_0003, 4000.0);
    (0..frames(end))
        .map(|i| {
            let t = time(i);
            let sway = 1.0 + 0.3 * (TAU * t / end).sin() + 0.15 * (TAU * t + 1.0).sin();
            let envelope: f64 = pops
                .iter()
                .map(|&(at, tau, loud)| {
                    // The distance after the pop, wrapped round the loop.
                    let after = (t - at).rem_euclid(end);
                    loud * hit(after, 0.0, tau) * (after < 0.2) as i32 as f64
                })
                .sum();
            sway * sum_partials(&roar, t) * 0.12 + 1.5 * crackle.next() * envelope
        })
        .collect()
}

/// A seamless 2 s time warp, looped while an altar turns time: a 220–3300 Hz band of noise
/// whose level sweeps up and down at 1 Hz (a whoosh each half second), and a D4–A4–D5 chord
/// with a 2 Hz vibrato of ±1.5 % (whole cycles in the loop: phase modulation, no drift).
pub(crate) fn time_warp() -> Vec<f64> {
    let end = duration_of("time_warp");
    let air = loop_noise(0x71E0_0000_0000_0001, 70, 220.0, 3300.0, end);
    let grid = |hz: f64| (hz * end).round() / end;
    let chord = [(62, 1.0), (69, 0.7), (74, 0.5)];
    (0..frames(end))
        .map(|i| {
            let t = time(i);
            let whoosh = (0.5 - 0.5 * (TAU * 2.0 * t).cos()).powi(2);
            let tones: f64 = chord
                .iter()
                .map(|&(note, amp)| {
                    let hz = grid(midi_hz(note));
                    // Phase deviation of a ±1.5 % vibrato at 2 Hz.
                    let wobble = 0.015 * hz / 2.0 * (TAU * 2.0 * t).sin();
                    amp * (TAU * hz * t + wobble).sin()
                })
                .sum();
            0.08 * (0.3 + whoosh) * sum_partials(&air, t) + 0.5 * (0.6 + 0.4 * whoosh) * tones
        })
        .collect()
}

/// An artifact taken, 1.6 s: a D major pentatonic bell run down and up (A5, F♯5, D5, then A5
/// and D6 together), over a low D3 hum that swells and fades (unlike Reflect's A–E chime).
pub(crate) fn artifact_chime() -> Vec<f64> {
    let end = duration_of("artifact_chime");
    (0..frames(end))
        .map(|i| {
            let t = time(i);
            let run = bell(t, 0.0, midi_hz(81))
                + bell(t, 0.09, midi_hz(78))
                + bell(t, 0.18, midi_hz(74))
                + 0.9 * (bell(t, 0.32, midi_hz(81)) + bell(t, 0.32, midi_hz(86)));
            let hum_level = (t / 0.25).min(1.0) * (-(t - 0.25).max(0.0) / 0.45).exp();
            let hum = 0.35 * hum_level * (TAU * midi_hz(50) * t).sin();
            (run + hum) * edges(t, end, 0.03)
        })
        .collect()
}

/// A seamless 8 s pad of `notes` (MIDI note, amplitude): each a pair detuned by 0.25 Hz with
/// its own slow swell and a soft octave, over faint air from seed `seed`.
fn pad(name: &str, notes: &[(i32, f64)], seed: u64) -> Vec<f64> {
    let end = duration_of(name);
    let grid = |hz: f64| (hz * end).round() / end;
    let air = loop_noise(seed, 30, 1500.0, 4000.0, end);
    (0..frames(end))
        .map(|i| {
            let t = time(i);
            let tones: f64 = notes
                .iter()
                .enumerate()
                .map(|(k, (note, amp))| {
                    let hz = grid(midi_hz(*note));
                    let swell = 1.0 + 0.3 * (TAU * t / end + k as f64 * 0.9).sin();
                    let pair = (TAU * hz * t).sin()
                        + (TAU * (hz + 0.25) * t + 0.9).sin()
                        + 0.15 * (TAU * 2.0 * hz * t).sin();
                    amp * swell * pair
                })
                .sum();
            tones + 0.012 * sum_partials(&air, t)
        })
        .collect()
}

/// The day pad: D major with an added sixth and ninth (D2 A2 D3 A3 F♯4 B4 E5), bright.
pub(crate) fn pad_day() -> Vec<f64> {
    const NOTES: [(i32, f64); 7] = [
        (38, 1.0),
        (45, 0.8),
        (50, 0.6),
        (57, 0.5),
        (66, 0.4),
        (71, 0.3),
        (76, 0.22),
    ];
    pad("pad_day", &NOTES, 0xDA70_0000_0000_0001)
}

/// The night pad: D minor with a seventh and eleventh (D2 A2 D3 A3 F4 C5 G5), darker and
/// softer at the top.
pub(crate) fn pad_night() -> Vec<f64> {
    const NOTES: [(i32, f64); 7] = [
        (38, 1.0),
        (45, 0.8),
        (50, 0.6),
        (57, 0.5),
        (65, 0.35),
        (72, 0.22),
        (79, 0.12),
    ];
    pad("pad_night", &NOTES, 0x4167_0000_0000_0001)
}
