//! It's About Time's event one-shots, synthesised: a torch catching fire, a wrong torch
//! snuffed, the sun altar's stone gong, the sluice gate with its rush of water, and the temple
//! waking at the end. `ruins_sound_list` lists, normalises and writes them; this file only makes
//! the raw samples (`f64`, any scale) at `SAMPLE_RATE_HZ`.
//!
//! Every one-shot starts and ends silent (`edges`) and uses fixed-seed noise, so a rerun gives
//! the same bytes. The tuned ones sit in the game's key (D: the pads, the artifact chime).
//! Must not: read files or depend on the engine.

use std::f64::consts::TAU;

use crate::ruins_sound_list::duration_of;
use crate::ruins_sounds::{LowNoise, hit};
use crate::sounds::{Noise, SAMPLE_RATE_HZ, bell, edges, frames, midi_hz, time};

/// The smoothing factor of a one-pole low-pass with cut-off `hz` at `SAMPLE_RATE_HZ`.
fn one_pole(hz: f64) -> f64 {
    1.0 - (-TAU * hz / f64::from(SAMPLE_RATE_HZ)).exp()
}

/// Fixed-seed noise band-passed between `low_hz` and `high_hz`: the difference of two one-pole
/// low-passes of the same noise.
struct Band {
    noise: Noise,
    high: (f64, f64),
    low: (f64, f64),
}

impl Band {
    fn new(seed: u64, low_hz: f64, high_hz: f64) -> Self {
        Self {
            noise: Noise(seed),
            high: (0.0, one_pole(high_hz)),
            low: (0.0, one_pole(low_hz)),
        }
    }

    fn next(&mut self) -> f64 {
        let x = self.noise.next();
        self.high.0 += self.high.1 * (x - self.high.0);
        self.low.0 += self.low.1 * (x - self.low.0);
        self.high.0 - self.low.0
    }
}

/// A torch catching, 1.2 s: a breathy whoomp (noise whose low-pass opens from 200 Hz to 3 kHz
/// in 0.15 s, with a 70 Hz thump), then a settling roar and a handful of crackling pops.
pub(crate) fn torch_ignite() -> Vec<f64> {
    let end = duration_of("torch_ignite");
    let mut breath = Noise(0x1611_0000_0000_0001);
    let mut roar = LowNoise::new(0x1611_0000_0000_0002, 350.0);
    let mut crackle = LowNoise::new(0x1611_0000_0000_0003, 4500.0);
    let mut pick = Noise(0x1611_0000_0000_0004);
    let pops: Vec<(f64, f64)> = (0..9)
        .map(|_| {
            let at = 0.2 + 0.45 * (1.0 + pick.next());
            (at, 0.004 + 0.003 * (1.0 + pick.next()))
        })
        .collect();
    let mut open = 0.0;
    (0..frames(end))
        .map(|i| {
            let t = time(i);
            // The whoomp's filter opens as the flame catches: a one-pole low-pass whose
            // cut-off sweeps up, then the burst fades.
            let cutoff = 200.0 + 2800.0 * (t / 0.15).min(1.0);
            open += one_pole(cutoff) * (breath.next() - open);
            let whoomp = 2.5 * open * hit(t, 0.0, 0.18);
            let thump = hit(t, 0.01, 0.06) * (TAU * 70.0 * t).sin();
            let settle = 1.5 * roar.next() * (t / 0.1).min(1.0) * (-(t / 0.8)).exp();
            let pop: f64 = pops.iter().map(|&(at, tau)| hit(t, at, tau)).sum();
            (whoomp + 0.7 * thump + settle + 1.2 * crackle.next() * pop) * edges(t, end, 0.005)
        })
        .collect()
}

/// A wrong torch, 1.0 s: the flames snuffed with a hiss (noise between 1.5 and 9 kHz,
/// decaying over 0.4 s) over two low falling tones a semitone apart
/// (A2 sliding down to G♯2, and D3), a dull "no" that the shrine's lit torches go out to.
pub(crate) fn torch_douse() -> Vec<f64> {
    let end = duration_of("torch_douse");
    let mut hiss = Band::new(0xD005_0000_0000_0001, 1500.0, 9000.0);
    let (a, d) = (midi_hz(45), midi_hz(50));
    let mut phase = 0.0;
    (0..frames(end))
        .map(|i| {
            let t = time(i);
            let high = hiss.next();
            // The A slides down a semitone over the sound (integrated frequency: no clicks).
            let hz = a * 2f64.powf(-(t / end) / 12.0);
            phase += TAU * hz / f64::from(SAMPLE_RATE_HZ);
            let tones = phase.sin() + 0.6 * (TAU * d * t).sin();
            let level = (t / 0.02).min(1.0) * (-(t / 0.35)).exp();
            (1.2 * high * hit(t, 0.0, 0.4) + 0.5 * tones * level) * edges(t, end, 0.01)
        })
        .collect()
}

/// The sun altar struck, 2.5 s: a stone-and-bronze gong on D3 with inharmonic partials
/// (1, 1.52, 2.0, 2.74, 3.41 × the root, each decaying faster than the one below), slightly
/// detuned pairs that beat, and a soft knock at the strike.
pub(crate) fn altar_gong() -> Vec<f64> {
    const PARTIALS: [(f64, f64, f64); 5] = [
        (1.0, 1.0, 1.2),
        (1.52, 0.6, 0.8),
        (2.0, 0.45, 0.6),
        (2.74, 0.3, 0.4),
        (3.41, 0.2, 0.25),
    ];
    let end = duration_of("altar_gong");
    let root = midi_hz(50);
    let mut knock = LowNoise::new(0xA17A_0000_0000_0001, 900.0);
    (0..frames(end))
        .map(|i| {
            let t = time(i);
            let tone: f64 = PARTIALS
                .iter()
                .map(|&(ratio, amp, tau)| {
                    let hz = root * ratio;
                    amp * hit(t, 0.0, tau)
                        * ((TAU * hz * t).sin() + 0.7 * (TAU * (hz + 1.3) * t).sin())
                })
                .sum();
            (tone + 2.0 * knock.next() * hit(t, 0.0, 0.015)) * edges(t, end, 0.02)
        })
        .collect()
}

/// The sluice gate, 2.0 s: a wooden thunk as the gate moves (two damped tones, 95 and 210 Hz),
/// then a rush of water (a 150 Hz – 2.5 kHz band of noise) that swells in 0.4 s and ebbs away.
pub(crate) fn sluice() -> Vec<f64> {
    let end = duration_of("sluice");
    let mut water = Band::new(0x5101_0000_0000_0001, 150.0, 2500.0);
    (0..frames(end))
        .map(|i| {
            let t = time(i);
            let thunk =
                hit(t, 0.0, 0.05) * ((TAU * 95.0 * t).sin() + 0.5 * (TAU * 210.0 * t).sin());
            let band = water.next();
            let swell = (t / 0.4).min(1.0).powi(2) * (-((t - 0.4).max(0.0) / 0.7)).exp();
            let gurgle = 1.0 + 0.3 * (TAU * 7.0 * t).sin() * (TAU * 3.0 * t + 0.4).sin();
            (0.9 * thunk + 2.0 * band * swell * gurgle) * edges(t, end, 0.01)
        })
        .collect()
}

/// The temple wakes (the ending), 3.0 s: the altar's gong under a rising D major arpeggio of
/// bells (D4 F♯4 A4 D5 F♯5 A5, 0.12 s apart) that rings out on a held D5–A5–D6 chord.
pub(crate) fn temple_awake() -> Vec<f64> {
    let end = duration_of("temple_awake");
    let gong = altar_gong();
    let run = [62, 66, 69, 74, 78, 81];
    (0..frames(end))
        .map(|i| {
            let t = time(i);
            let arpeggio: f64 = run
                .iter()
                .enumerate()
                .map(|(k, &note)| bell(t, 0.12 * k as f64, midi_hz(note)))
                .sum();
            let chord = [74, 81, 86]
                .iter()
                .map(|&note| 0.8 * bell(t, 0.85, midi_hz(note)))
                .sum::<f64>();
            let low = gong.get(i).copied().unwrap_or(0.0);
            // Struck at once, rung out over the last 0.4 s.
            let fade = (t / 0.003).min((end - t) / 0.4).clamp(0.0, 1.0);
            (0.5 * low + arpeggio + chord) * fade
        })
        .collect()
}
