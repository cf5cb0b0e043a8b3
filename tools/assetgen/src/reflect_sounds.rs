//! The sounds of the game Reflect, synthesised: mirror toggle, laser hum, receiver chime,
//! elevator motor, footstep and ambient pad. `sounds` lists them in `SOUNDS` (durations, loop
//! flags), normalises and writes them; this file only makes the raw samples (`f64`, any scale)
//! at `SAMPLE_RATE_HZ`.
//!
//! Loops are seamless by construction: every component is periodic in the loop's length (each
//! frequency, modulation and "noise" partial makes a whole number of cycles in it), so the
//! sample after the last equals the first. Noise for loops is a sum of fixed-seed random-phase
//! partials on that frequency grid; one-shots use the xorshift `Noise` and fade in and out.
//! Must not: read files or depend on the engine.

use std::f64::consts::TAU;

use crate::sounds::{Noise, SAMPLE_RATE_HZ, bell, duration_of, edges, frames, midi_hz, time};

/// `count` partials `(hz, amplitude, phase)` between `low_hz` and `high_hz` on a grid of
/// `1 / loop_seconds`, with random phases and amplitudes: band noise that loops seamlessly.
pub(crate) fn loop_noise(
    seed: u64,
    count: usize,
    low_hz: f64,
    high_hz: f64,
    loop_seconds: f64,
) -> Vec<(f64, f64, f64)> {
    let mut noise = Noise(seed);
    (0..count)
        .map(|_| {
            let hz = low_hz + (high_hz - low_hz) * (0.5 + 0.5 * noise.next());
            let hz = (hz * loop_seconds).round() / loop_seconds;
            let amp = 0.5 + 0.5 * (0.5 + 0.5 * noise.next());
            let phase = TAU * (0.5 + 0.5 * noise.next());
            (hz, amp, phase)
        })
        .collect()
}

pub(crate) fn sum_partials(partials: &[(f64, f64, f64)], t: f64) -> f64 {
    partials
        .iter()
        .map(|(hz, amp, phase)| amp * (TAU * hz * t + phase).sin())
        .sum()
}

/// A bright rising shimmer: four inharmonic partials gliding up an octave (900 → 1800 Hz, the
/// top partial to 5.5 kHz) with a 32 Hz tremolo, over a soft E6 bell (partials to 7.1 kHz).
pub(crate) fn mirror_toggle() -> Vec<f64> {
    const RATIOS: [(f64, f64); 4] = [(1.0, 1.0), (1.5, 0.6), (2.01, 0.45), (3.03, 0.25)];
    let end = duration_of("mirror_toggle");
    let dt = 1.0 / f64::from(SAMPLE_RATE_HZ);
    let mut phase = 0.0;
    (0..frames(end))
        .map(|i| {
            let t = time(i);
            let glide = 900.0 * 2f64.powf((t / 0.12).min(1.0));
            phase += TAU * glide * dt;
            let body: f64 = RATIOS.iter().map(|(r, a)| a * (phase * r).sin()).sum();
            let envelope = (t / 0.004).min(1.0) * (-t / 0.11).exp();
            let tremolo = 0.75 + 0.25 * (TAU * 32.0 * t).sin();
            (body * envelope * tremolo + 0.5 * bell(t, 0.03, midi_hz(88))) * edges(t, end, 0.01)
        })
        .collect()
}

/// A seamless 2 s electric hum: a 100 Hz buzz (odd and even harmonics falling as 1/k), a
/// 2–3.5 kHz crackle band pulsing at 25 Hz, and a slow swell.
pub(crate) fn laser_hum() -> Vec<f64> {
    let end = duration_of("laser_hum");
    let crackle = loop_noise(0x1A5E_0000_0000_0007, 24, 2000.0, 3500.0, end);
    (0..frames(end))
        .map(|i| {
            let t = time(i);
            let buzz: f64 = (1..=12)
                .map(|k| (TAU * 100.0 * f64::from(k) * t).sin() / f64::from(k))
                .sum();
            let pulse = 0.5 + 0.5 * (TAU * 25.0 * t).sin();
            let swell = 1.0 + 0.12 * (TAU * t / end).sin();
            (buzz + 0.08 * pulse * pulse * sum_partials(&crackle, t)) * swell
        })
        .collect()
}

/// A receiver lit: a rising G5–C6–E6–G6 bell arpeggio (the bell's top partial, 5.4 × G6 =
/// 8.5 kHz, stays under the 11 kHz Nyquist limit).
pub(crate) fn receiver_chime() -> Vec<f64> {
    let end = duration_of("receiver_chime");
    (0..frames(end))
        .map(|i| {
            let t = time(i);
            let notes = 0.8 * bell(t, 0.0, midi_hz(79))
                + bell(t, 0.07, midi_hz(84))
                + bell(t, 0.14, midi_hz(88))
                + bell(t, 0.21, midi_hz(91));
            notes * edges(t, end, 0.02)
        })
        .collect()
}

/// A seamless 4 s elevator motor: a 50 Hz drive with harmonics, a 400 Hz whine with a slow
/// 0.5 Hz vibrato, a low rumble band and a soft 2 Hz mechanical pulse.
pub(crate) fn elevator_loop() -> Vec<f64> {
    let end = duration_of("elevator_loop");
    let rumble = loop_noise(0xE1E7_0000_0000_0003, 40, 30.0, 220.0, end);
    (0..frames(end))
        .map(|i| {
            let t = time(i);
            let drive: f64 = [(1.0, 1.0), (2.0, 0.5), (3.0, 0.3), (4.0, 0.15)]
                .iter()
                .map(|(k, a)| a * (TAU * 50.0 * k * t).sin())
                .sum();
            let whine = (TAU * 400.0 * t + 3.0 * (TAU * 0.5 * t).sin()).sin();
            let pulse = 0.8 + 0.2 * (TAU * 2.0 * t).sin();
            (0.6 * drive + 0.18 * whine + 0.05 * sum_partials(&rumble, t)) * pulse
        })
        .collect()
}

/// A soft step: low-passed noise for the heel and, 60 ms later, the toe, over an 80 Hz thump.
pub(crate) fn footstep() -> Vec<f64> {
    let end = duration_of("footstep");
    let mut noise = Noise(0xF007_0000_0000_0005);
    let mut low_passed = 0.0;
    let alpha = 1.0 - (-TAU * 700.0 / f64::from(SAMPLE_RATE_HZ)).exp();
    (0..frames(end))
        .map(|i| {
            let t = time(i);
            low_passed += alpha * (noise.next() - low_passed);
            let hit = |start: f64, tau: f64| {
                let local = t - start;
                if local < 0.0 {
                    0.0
                } else {
                    (local / 0.003).min(1.0) * (-local / tau).exp()
                }
            };
            let scuff = low_passed * (hit(0.0, 0.035) + 0.6 * hit(0.06, 0.03));
            let thump = 0.5 * hit(0.0, 0.04) * (TAU * 80.0 * t).sin();
            (3.0 * scuff + thump) * edges(t, end, 0.005)
        })
        .collect()
}

/// A seamless 8 s pad: A2, E3, A3, C4, E4 and B4, each a pair detuned by 0.25 Hz (one beat
/// every 4 s) with its own slow swell, over faint high air.
pub(crate) fn ambient_pad() -> Vec<f64> {
    const NOTES: [(i32, f64); 6] = [
        (45, 1.0),
        (52, 0.8),
        (57, 0.6),
        (60, 0.5),
        (64, 0.4),
        (71, 0.25),
    ];
    let end = duration_of("ambient_pad");
    let grid = |hz: f64| (hz * end).round() / end;
    let air = loop_noise(0xA1B1_0000_0000_0009, 30, 2500.0, 5000.0, end);
    (0..frames(end))
        .map(|i| {
            let t = time(i);
            let pad: f64 = NOTES
                .iter()
                .enumerate()
                .map(|(k, (note, amp))| {
                    let hz = grid(midi_hz(*note));
                    let swell = 1.0 + 0.35 * (TAU * t / end + k as f64 * 1.1).sin();
                    let pair = (TAU * hz * t).sin()
                        + (TAU * (hz + 0.25) * t + 0.7).sin()
                        + 0.2 * (TAU * 2.0 * hz * t).sin();
                    amp * swell * pair
                })
                .sum();
            pad + 0.01 * sum_partials(&air, t)
        })
        .collect()
}
