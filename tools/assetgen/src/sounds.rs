//! The games' sounds, synthesised from code: `assetgen sounds` writes them to
//! `assets/common/sounds/` as mono 16-bit PCM WAV at [`SAMPLE_RATE_HZ`].
//!
//! Owns: [`SOUNDS`] (names, durations, what each is for), the synthesis of each sound, and the
//! WAV writer ([`wav_bytes`]). Deterministic: noise comes from a fixed-seed xorshift generator
//! and everything else is arithmetic on `f64` (`sin`, `exp`) rounded to 16 bits at the end, so a
//! rerun gives the same bytes (a test checks the committed files). Every sound is scaled to a
//! peak of [`PEAK_AMPLITUDE`] and starts and ends at (near) zero, so it does not click. Must not:
//! read third-party data or depend on the engine's audio code (the engine decodes what this
//! writes; that is the test of both).

use std::f64::consts::TAU;

/// Samples per second of every generated sound. 22.05 kHz keeps the files small (44 KB per
/// second) and holds everything these sounds contain (nothing above 8 kHz matters here).
pub const SAMPLE_RATE_HZ: u32 = 22_050;

/// Peak linear amplitude of every sound (−3.1 dBFS): head-room for a few sounds mixed at once.
pub const PEAK_AMPLITUDE: f64 = 0.7;

/// A generated sound: its file stem, length in seconds and use.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SoundSpec {
    pub name: &'static str,
    pub duration_seconds: f64,
    pub looped: bool,
    pub purpose: &'static str,
}

/// Every sound `assetgen sounds` writes, in file-name order. The Reflect sounds are
/// synthesised in `reflect_sounds`.
pub const SOUNDS: [SoundSpec; 11] = [
    SoundSpec {
        name: "ambient_pad",
        duration_seconds: 8.0,
        looped: true,
        purpose: "Reflect, seamless loop: a slow A-minor pad of detuned pairs with a faint air",
    },
    SoundSpec {
        name: "chime",
        duration_seconds: 0.8,
        looped: false,
        purpose: "one-shot: a pressure plate pressed, a puzzle solved (A5 then E6, bell partials)",
    },
    SoundSpec {
        name: "door_slide",
        duration_seconds: 1.2,
        looped: false,
        purpose: "one-shot: a stone door sliding (low-passed noise, a 55 Hz rumble, a thud)",
    },
    SoundSpec {
        name: "elevator_loop",
        duration_seconds: 4.0,
        looped: true,
        purpose: "Reflect, seamless loop: an elevator motor (50 Hz drive, 400 Hz whine, rumble)",
    },
    SoundSpec {
        name: "fail_buzz",
        duration_seconds: 0.5,
        looped: false,
        purpose: "one-shot: a wrong move (two falling square-wave tones)",
    },
    SoundSpec {
        name: "footstep",
        duration_seconds: 0.3,
        looped: false,
        purpose: "Reflect, one-shot: a soft step (low-passed noise, heel and toe, a low thump)",
    },
    SoundSpec {
        name: "hum_loop",
        duration_seconds: 2.0,
        looped: true,
        purpose: "seamless loop for spatial emitters: a 60 Hz machine hum with a slow swell",
    },
    SoundSpec {
        name: "laser_hum",
        duration_seconds: 2.0,
        looped: true,
        purpose: "Reflect, seamless loop for per-beam spatial emitters: a 100 Hz electric buzz",
    },
    SoundSpec {
        name: "mirror_toggle",
        duration_seconds: 0.4,
        looped: false,
        purpose: "Reflect, one-shot: a panel turns mirror or back (a bright rising shimmer)",
    },
    SoundSpec {
        name: "music_loop",
        duration_seconds: 4.0,
        looped: true,
        purpose: "seamless music loop: two bars at 120 bpm, Am-F-C-G bass and a melody",
    },
    SoundSpec {
        name: "receiver_chime",
        duration_seconds: 1.0,
        looped: false,
        purpose: "Reflect, one-shot: a receiver lit (G5-C6-E6-G6 bell arpeggio)",
    },
];

/// All sounds as `(file name, WAV bytes)`, in [`SOUNDS`] order.
pub fn sound_files() -> Vec<(String, Vec<u8>)> {
    SOUNDS
        .iter()
        .map(|spec| (format!("{}.wav", spec.name), wav_bytes(&samples(spec.name))))
        .collect()
}

/// The samples (linear amplitude, peak [`PEAK_AMPLITUDE`]) of the sound named `name`; empty for
/// an unknown name.
pub fn samples(name: &str) -> Vec<f32> {
    let raw = match name {
        "chime" => chime(),
        "door_slide" => door_slide(),
        "fail_buzz" => fail_buzz(),
        "hum_loop" => hum_loop(),
        "music_loop" => music_loop(),
        "ambient_pad" => crate::reflect_sounds::ambient_pad(),
        "elevator_loop" => crate::reflect_sounds::elevator_loop(),
        "footstep" => crate::reflect_sounds::footstep(),
        "laser_hum" => crate::reflect_sounds::laser_hum(),
        "mirror_toggle" => crate::reflect_sounds::mirror_toggle(),
        "receiver_chime" => crate::reflect_sounds::receiver_chime(),
        _ => Vec::new(),
    };
    normalized(&raw)
}

/// `samples` as a mono 16-bit PCM WAV file at [`SAMPLE_RATE_HZ`] (a 44-byte header, then
/// little-endian samples).
pub fn wav_bytes(samples: &[f32]) -> Vec<u8> {
    const CHANNELS: u16 = 1;
    const BITS: u16 = 16;
    let block_align = CHANNELS * BITS / 8;
    let data_bytes = (samples.len() * usize::from(block_align)) as u32;
    let mut out = Vec::with_capacity(44 + data_bytes as usize);
    out.extend_from_slice(b"RIFF");
    out.extend_from_slice(&(36 + data_bytes).to_le_bytes());
    out.extend_from_slice(b"WAVE");
    out.extend_from_slice(b"fmt ");
    out.extend_from_slice(&16u32.to_le_bytes());
    out.extend_from_slice(&1u16.to_le_bytes()); // PCM
    out.extend_from_slice(&CHANNELS.to_le_bytes());
    out.extend_from_slice(&SAMPLE_RATE_HZ.to_le_bytes());
    out.extend_from_slice(&(SAMPLE_RATE_HZ * u32::from(block_align)).to_le_bytes());
    out.extend_from_slice(&block_align.to_le_bytes());
    out.extend_from_slice(&BITS.to_le_bytes());
    out.extend_from_slice(b"data");
    out.extend_from_slice(&data_bytes.to_le_bytes());
    for s in samples {
        let q = (f64::from(*s) * 32767.0).round().clamp(-32768.0, 32767.0) as i16;
        out.extend_from_slice(&q.to_le_bytes());
    }
    out
}

pub(crate) fn normalized(raw: &[f64]) -> Vec<f32> {
    let peak = raw.iter().fold(0.0f64, |m, s| m.max(s.abs()));
    let gain = if peak > 0.0 {
        PEAK_AMPLITUDE / peak
    } else {
        0.0
    };
    raw.iter().map(|s| (s * gain) as f32).collect()
}

pub(crate) fn frames(duration_seconds: f64) -> usize {
    (duration_seconds * f64::from(SAMPLE_RATE_HZ)).round() as usize
}

pub(crate) fn time(i: usize) -> f64 {
    i as f64 / f64::from(SAMPLE_RATE_HZ)
}

pub(crate) fn duration_of(name: &str) -> f64 {
    SOUNDS
        .iter()
        .find(|s| s.name == name)
        .map_or(0.0, |s| s.duration_seconds)
}

/// A linear ramp from 0 to 1 over `seconds` after `t = 0`, and down to 0 over `seconds` before
/// `end`: removes clicks at the ends.
pub(crate) fn edges(t: f64, end: f64, seconds: f64) -> f64 {
    (t / seconds).min((end - t) / seconds).clamp(0.0, 1.0)
}

/// Frequency of MIDI note `note`, Hz (A4 = 69 = 440 Hz).
pub(crate) fn midi_hz(note: i32) -> f64 {
    440.0 * 2f64.powf(f64::from(note - 69) / 12.0)
}

/// xorshift64*: a tiny fixed-seed noise source, the same on every machine.
pub(crate) struct Noise(pub(crate) u64);

impl Noise {
    /// Uniform in `-1..1`.
    pub(crate) fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let bits = self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11;
        bits as f64 / (1u64 << 52) as f64 - 1.0
    }
}

/// A struck bell at `hz` starting at `start` seconds: inharmonic partials, each decaying
/// exponentially.
pub(crate) fn bell(t: f64, start: f64, hz: f64) -> f64 {
    const PARTIALS: [(f64, f64, f64); 3] =
        [(1.0, 1.0, 0.30), (2.76, 0.35, 0.12), (5.40, 0.12, 0.05)];
    let t = t - start;
    if t < 0.0 {
        return 0.0;
    }
    let attack = (t / 0.003).min(1.0);
    PARTIALS
        .iter()
        .map(|(ratio, amp, tau)| amp * (-t / tau).exp() * (TAU * hz * ratio * t).sin())
        .sum::<f64>()
        * attack
}

fn chime() -> Vec<f64> {
    let end = duration_of("chime");
    (0..frames(end))
        .map(|i| {
            let t = time(i);
            (bell(t, 0.0, midi_hz(81)) + bell(t, 0.12, midi_hz(88))) * edges(t, end, 0.02)
        })
        .collect()
}

fn door_slide() -> Vec<f64> {
    let end = duration_of("door_slide");
    let mut noise = Noise(0x5EED_D00D_0000_0001);
    let mut low_passed = 0.0;
    (0..frames(end))
        .map(|i| {
            let t = time(i);
            // A one-pole low-pass whose cut-off falls from 900 Hz to 300 Hz as the door slows.
            let cutoff_hz = 900.0 - 600.0 * (t / end);
            let alpha = 1.0 - (-TAU * cutoff_hz / f64::from(SAMPLE_RATE_HZ)).exp();
            low_passed += alpha * (noise.next() - low_passed);
            let grind = 1.0 + 0.3 * (TAU * 7.0 * t).sin();
            let rumble = 0.6 * (TAU * 55.0 * t).sin() + 0.3 * (TAU * 82.5 * t).sin();
            let slide = (1.6 * low_passed * grind + 0.5 * rumble) * edges(t, 0.95, 0.08);
            let thud_t = t - 0.95;
            let thud = if thud_t >= 0.0 {
                (-thud_t / 0.06).exp() * (TAU * 70.0 * thud_t).sin() * (thud_t / 0.002).min(1.0)
            } else {
                0.0
            };
            (slide + thud) * edges(t, end, 0.01)
        })
        .collect()
}

fn fail_buzz() -> Vec<f64> {
    let end = duration_of("fail_buzz");
    // A band-limited square wave: odd harmonics up to the 15th.
    let square = |hz: f64, t: f64| {
        (1..=15)
            .step_by(2)
            .map(|k| (TAU * hz * f64::from(k) * t).sin() / f64::from(k))
            .sum::<f64>()
    };
    (0..frames(end))
        .map(|i| {
            let t = time(i);
            let first = square(155.0, t) * edges(t, 0.22, 0.008);
            let second = square(110.0, t - 0.25) * edges(t - 0.25, 0.25, 0.008);
            first + second
        })
        .collect()
}

fn hum_loop() -> Vec<f64> {
    // Every frequency makes a whole number of cycles in the 2 s loop, so the last sample runs
    // into the first without a step.
    const PARTIALS: [(f64, f64); 5] = [
        (60.0, 1.0),
        (120.0, 0.55),
        (180.0, 0.25),
        (240.0, 0.10),
        (1000.0, 0.02),
    ];
    let end = duration_of("hum_loop");
    (0..frames(end))
        .map(|i| {
            let t = time(i);
            let swell = 1.0 + 0.15 * (TAU * (1.0 / end) * t).sin();
            PARTIALS
                .iter()
                .map(|(hz, amp)| amp * (TAU * hz * t).sin())
                .sum::<f64>()
                * swell
        })
        .collect()
}

/// A note: start and length in beats, MIDI note.
type Note = (f64, f64, i32);

fn music_loop() -> Vec<f64> {
    const BEAT_SECONDS: f64 = 0.5; // 120 bpm
    // Am - F - C - G, one chord per two beats.
    const BASS: [Note; 4] = [
        (0.0, 2.0, 45),
        (2.0, 2.0, 41),
        (4.0, 2.0, 48),
        (6.0, 2.0, 43),
    ];
    const MELODY: [Note; 10] = [
        (0.0, 1.0, 69),
        (1.0, 0.5, 72),
        (1.5, 0.5, 76),
        (2.0, 1.0, 77),
        (3.0, 1.0, 76),
        (4.0, 1.0, 72),
        (5.0, 0.5, 74),
        (5.5, 0.5, 76),
        (6.0, 1.5, 74),
        (7.5, 0.5, 71),
    ];
    // Attack, decay to the sustain level, and a release that ends inside the note, so every
    // note (the last included) is silent by its end and the loop joins without a step.
    let envelope = |t: f64, length: f64| {
        if t < 0.0 || t >= length {
            return 0.0;
        }
        let attack = (t / 0.01).min(1.0);
        let decay = 0.6 + 0.4 * (-t / 0.15).exp();
        let release = ((length - t) / 0.06).min(1.0);
        attack * decay * release
    };
    let voice = |notes: &[Note], t: f64, harmonics: &[(f64, f64)]| {
        notes
            .iter()
            .map(|&(start, beats, note)| {
                let local = t - start * BEAT_SECONDS;
                let env = envelope(local, beats * BEAT_SECONDS);
                if env == 0.0 {
                    return 0.0;
                }
                let hz = midi_hz(note);
                env * harmonics
                    .iter()
                    .map(|(k, amp)| amp * (TAU * hz * k * local).sin())
                    .sum::<f64>()
            })
            .sum::<f64>()
    };
    let end = duration_of("music_loop");
    (0..frames(end))
        .map(|i| {
            let t = time(i);
            let bass = voice(&BASS, t, &[(1.0, 1.0), (2.0, 0.3)]);
            // Odd harmonics falling as 1/k²: a soft triangle-like lead.
            let lead = voice(
                &MELODY,
                t,
                &[(1.0, 1.0), (3.0, 1.0 / 9.0), (5.0, 1.0 / 25.0)],
            );
            0.8 * bass + 0.6 * lead
        })
        .collect()
}
