//! It's About Time's sounds as files: `assetgen ruins-sounds` writes [`RUINS_SOUNDS`] to
//! `assets/its_about_time/sounds/` as mono 16-bit PCM WAV, through the same normalising and
//! writer as the common sounds (`sounds::wav_bytes`), so a rerun gives the same bytes (the cross
//! test `sounds` checks the committed files).
//!
//! Owns: the list (names, durations, loop flags, use) and the name → samples table. The
//! synthesis is `ruins_sounds`. Must not: read files or depend on the engine.

use crate::ruins_sound_events as events;
use crate::ruins_sounds as synth;
use crate::sounds::{SoundSpec, normalized, wav_bytes};

/// Every sound `assetgen ruins-sounds` writes, in file-name order. Footsteps come in three
/// variants each (`_1` … `_3`), which the game cycles through.
pub const RUINS_SOUNDS: [SoundSpec; 19] = [
    spec(
        "altar_gong",
        2.5,
        false,
        "the sun altar struck (a stone-and-bronze gong on D3)",
    ),
    spec(
        "artifact_chime",
        1.6,
        false,
        "an artifact taken (D pentatonic bells)",
    ),
    spec("footstep_sand_1", 0.35, false, "a step on sand"),
    spec("footstep_sand_2", 0.35, false, "a step on sand"),
    spec("footstep_sand_3", 0.35, false, "a step on sand"),
    spec("footstep_stone_1", 0.25, false, "a step on stone"),
    spec("footstep_stone_2", 0.25, false, "a step on stone"),
    spec("footstep_stone_3", 0.25, false, "a step on stone"),
    spec(
        "pad_day",
        8.0,
        true,
        "music loop for the day (D major, crossfades with pad_night)",
    ),
    spec(
        "pad_night",
        8.0,
        true,
        "music loop for the night (D minor, same root and fifth as pad_day)",
    ),
    spec(
        "sluice",
        2.0,
        false,
        "the sluice gate moved: a wooden thunk and a rush of water",
    ),
    spec(
        "stone_scrape",
        1.6,
        false,
        "a gate grinding open or shut, a block dragged, a thud",
    ),
    spec(
        "temple_awake",
        3.0,
        false,
        "the ending: the gong under a rising D major arpeggio of bells",
    ),
    spec(
        "time_warp",
        2.0,
        true,
        "loop while an altar turns time (whooshes, a wavering chord)",
    ),
    spec("torch", 3.0, true, "loop at a lit torch (roar and crackle)"),
    spec(
        "torch_douse",
        1.0,
        false,
        "a wrong torch: the lit flames snuffed with a hiss and a falling tone",
    ),
    spec(
        "torch_ignite",
        1.2,
        false,
        "a torch catching fire: a whoomp and crackles",
    ),
    spec("water", 4.0, true, "loop at water (lapping)"),
    spec("wind", 6.0, true, "loop everywhere (desert wind in gusts)"),
];

const fn spec(name: &'static str, seconds: f64, looped: bool, purpose: &'static str) -> SoundSpec {
    SoundSpec {
        name,
        duration_seconds: seconds,
        looped,
        purpose,
    }
}

/// Seconds of the ruins sound `name` (0 for an unknown name).
pub(crate) fn duration_of(name: &str) -> f64 {
    RUINS_SOUNDS
        .iter()
        .find(|s| s.name == name)
        .map_or(0.0, |s| s.duration_seconds)
}

/// All ruins sounds as `(file name, WAV bytes)`, in [`RUINS_SOUNDS`] order.
pub fn ruins_sound_files() -> Vec<(String, Vec<u8>)> {
    RUINS_SOUNDS
        .iter()
        .map(|spec| (format!("{}.wav", spec.name), wav_bytes(&samples(spec.name))))
        .collect()
}

/// The samples (linear amplitude, peak `sounds::PEAK_AMPLITUDE`) of the ruins sound `name`;
/// empty for an unknown name.
pub fn samples(name: &str) -> Vec<f32> {
    let raw = match name {
        "altar_gong" => events::altar_gong(),
        "artifact_chime" => synth::artifact_chime(),
        "footstep_sand_1" => synth::footstep_sand(0),
        "footstep_sand_2" => synth::footstep_sand(1),
        "footstep_sand_3" => synth::footstep_sand(2),
        "footstep_stone_1" => synth::footstep_stone(0),
        "footstep_stone_2" => synth::footstep_stone(1),
        "footstep_stone_3" => synth::footstep_stone(2),
        "pad_day" => synth::pad_day(),
        "pad_night" => synth::pad_night(),
        "sluice" => events::sluice(),
        "stone_scrape" => synth::stone_scrape(),
        "temple_awake" => events::temple_awake(),
        "time_warp" => synth::time_warp(),
        "torch" => synth::torch(),
        "torch_douse" => events::torch_douse(),
        "torch_ignite" => events::torch_ignite(),
        "water" => synth::water(),
        "wind" => synth::wind(),
        _ => Vec::new(),
    };
    normalized(&raw)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sounds::{PEAK_AMPLITUDE, frames};

    /// Every sound has its listed length, is finite, peaks at `PEAK_AMPLITUDE` and has no DC
    /// offset (mean under 1 % of the peak).
    #[test]
    fn every_sound_is_clean() {
        for spec in RUINS_SOUNDS {
            let s = samples(spec.name);
            assert_eq!(s.len(), frames(spec.duration_seconds), "{}", spec.name);
            assert!(s.iter().all(|v| v.is_finite()), "{}: NaN or ∞", spec.name);
            let peak = s.iter().fold(0.0f32, |m, v| m.max(v.abs()));
            assert!(
                (f64::from(peak) - PEAK_AMPLITUDE).abs() < 1e-6,
                "{}: peak {peak}",
                spec.name
            );
            let mean = s.iter().map(|v| f64::from(*v)).sum::<f64>() / s.len() as f64;
            assert!(
                mean.abs() < 0.01 * PEAK_AMPLITUDE,
                "{}: DC {mean}",
                spec.name
            );
        }
    }

    /// A loop's last samples run into its first as its own samples run on: the seam's second
    /// difference (`s[0] - 2 s[n-1] + s[n-2]`, the step in slope) is no larger than the largest
    /// inside the loop. One-shots start and end silent.
    #[test]
    fn loops_are_seamless_and_one_shots_do_not_click() {
        for spec in RUINS_SOUNDS {
            let s = samples(spec.name);
            let n = s.len();
            if spec.looped {
                let curve = |a: f32, b: f32, c: f32| (a - 2.0 * b + c).abs();
                let inside = s
                    .windows(3)
                    .map(|w| curve(w[0], w[1], w[2]))
                    .fold(0.0f32, f32::max);
                let seam = curve(s[n - 2], s[n - 1], s[0]).max(curve(s[n - 1], s[0], s[1]));
                assert!(seam <= inside, "{}: seam {seam} > {inside}", spec.name);
            } else {
                assert!(s[0].abs() < 1e-3 && s[n - 1].abs() < 1e-3, "{}", spec.name);
            }
        }
    }

    /// The pads differ (a crossfade changes something) but share their lowest notes: their
    /// correlation is well above that of unrelated sounds and below 1.
    #[test]
    fn pads_are_related_but_distinct() {
        let (day, night) = (samples("pad_day"), samples("pad_night"));
        let dot = |a: &[f32], b: &[f32]| {
            a.iter()
                .zip(b)
                .map(|(x, y)| f64::from(*x) * f64::from(*y))
                .sum::<f64>()
        };
        let r = dot(&day, &night) / (dot(&day, &day) * dot(&night, &night)).sqrt();
        assert!(r > 0.3 && r < 0.99, "pad correlation {r}");
    }
}
