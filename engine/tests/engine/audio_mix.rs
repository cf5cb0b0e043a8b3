//! The silent recorder mixes what a sound card would have played: a sound at volume 1 comes out
//! sample for sample, volume 0.5 halves it, loops keep going, `stop` fades out, bus volumes scale
//! the music, `played()` records what started, and a long run of plays neither fails nor grows
//! memory without bound.
//!
//! Why exact comparisons hold: at the recorder's own sample rate kira's player advances one
//! source frame per output frame, so its cubic interpolation is evaluated at fraction 0 and
//! returns the source sample itself; volume 1 is 0 dB, which kira multiplies as exactly 1.0; a
//! mono sound is centred (no panning) and the buses are at 0 dB. The only error left is `f32`
//! rounding, so "the same" is checked to 1e-6 (16 ulp near full scale).

use candela::audio::{
    Audio, AudioError, Bus, EFFECT_SOUND_CAPACITY, MAX_PLAYED_RECORDS, PlayOptions, SilentSettings,
    Sound, decode_sound,
};
use glam::Vec3;

const STEP_SECONDS: f64 = 1.0 / 60.0;

fn sounds_dir() -> std::path::PathBuf {
    std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../assets/common/sounds")
}

fn silent(rate_hz: u32) -> Audio {
    Audio::silent_with(SilentSettings {
        sample_rate_hz: rate_hz,
        max_recorded_seconds: 20.0,
    })
}

/// Ticks like the engine: fixed 60 Hz steps.
fn run(audio: &mut Audio, seconds: f64) {
    for _ in 0..(seconds / STEP_SECONDS).round() as usize {
        audio.tick(STEP_SECONDS);
    }
}

/// A sine at `hz` (a whole number of cycles in `seconds`, so it loops seamlessly).
fn tone(rate_hz: u32, hz: f64, seconds: f64, amplitude: f32) -> Sound {
    let n = (seconds * f64::from(rate_hz)).round() as usize;
    let samples: Vec<f32> = (0..n)
        .map(|i| {
            let t = i as f64 / f64::from(rate_hz);
            amplitude * (std::f64::consts::TAU * hz * t).sin() as f32
        })
        .collect();
    Sound::from_mono_samples("tone", rate_hz, &samples).expect("a valid tone")
}

fn recorded(audio: &Audio) -> &[[f32; 2]] {
    audio.recorded_samples().expect("silent mode records")
}

fn rms(frames: &[[f32; 2]], channel: usize) -> f64 {
    let sum: f64 = frames.iter().map(|f| f64::from(f[channel]).powi(2)).sum();
    (sum / frames.len().max(1) as f64).sqrt()
}

/// Frames `[from, to)` seconds of the record.
fn window(audio: &Audio, from: f64, to: f64) -> &[[f32; 2]] {
    let rate = f64::from(audio.recorded_sample_rate_hz().expect("silent"));
    let start = audio.recorded_start_frame() as f64;
    let rec = recorded(audio);
    let a = ((from * rate - start).max(0.0) as usize).min(rec.len());
    let b = ((to * rate - start).max(0.0) as usize).min(rec.len());
    &rec[a..b]
}

/// The lag (frames, `0..=max_lag`) at which `source` scaled by `gain` best matches the record,
/// and the largest difference there over the source's length.
fn best_match(rec: &[[f32; 2]], source: &Sound, gain: f32, max_lag: usize) -> (usize, f32) {
    let n = source.frame_count();
    assert!(
        n > 0,
        "the source sound has no frames: nothing would be compared"
    );
    let diff_at = |lag: usize| -> f32 {
        // A record too short to hold the whole sound at this lag does not match (an empty
        // record must not give a difference of 0).
        if rec.len() < lag + n {
            return f32::INFINITY;
        }
        (0..n)
            .map(|i| {
                let [sl, sr] = source.frame(i).unwrap_or([f32::NAN; 2]);
                let [rl, rr] = rec[i + lag];
                [(rl - gain * sl).abs(), (rr - gain * sr).abs()]
            })
            // NaN propagates (`f32::max` would drop it): a NaN sample never matches.
            .fold(0.0f32, |m, [l, r]| {
                if m.is_nan() || l.is_nan() || r.is_nan() {
                    f32::NAN
                } else {
                    m.max(l).max(r)
                }
            })
    };
    (0..=max_lag)
        .map(|lag| (lag, diff_at(lag)))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .unwrap_or((0, f32::INFINITY))
}

/// kira's mixing block: a sound starts at the next block, so within this many frames.
const BLOCK_FRAMES: usize = 128;
/// `f32` rounding only (see the module doc).
const SAME: f32 = 1e-6;

#[test]
fn a_sound_at_volume_1_comes_out_sample_for_sample() -> anyhow::Result<()> {
    let chime = decode_sound(&sounds_dir().join("chime.wav"))?;
    let mut audio = silent(chime.sample_rate_hz());
    assert!(audio.is_silent());
    audio.play(&chime, PlayOptions::default())?;
    run(&mut audio, chime.duration_seconds() + 0.2);
    let rec = recorded(&audio);
    let (lag, diff) = best_match(rec, &chime, 1.0, BLOCK_FRAMES);
    assert!(diff <= SAME, "largest difference {diff} at lag {lag}");
    // Nothing after it ends.
    let tail = &rec[lag + chime.frame_count()..];
    assert!(!tail.is_empty() && tail.iter().all(|f| f == &[0.0, 0.0]));
    Ok(())
}

#[test]
fn volume_half_halves_the_amplitude() -> anyhow::Result<()> {
    let chime = decode_sound(&sounds_dir().join("chime.wav"))?;
    let mut audio = silent(chime.sample_rate_hz());
    let options = PlayOptions {
        volume: 0.5,
        ..Default::default()
    };
    audio.play(&chime, options)?;
    run(&mut audio, chime.duration_seconds() + 0.1);
    // 0.5 goes to kira as 20 log10(0.5) dB and back with powf: a few f32 ulp of 0.5.
    let (lag, diff) = best_match(recorded(&audio), &chime, 0.5, BLOCK_FRAMES);
    assert!(diff <= SAME, "largest difference {diff} at lag {lag}");
    Ok(())
}

#[test]
fn a_generated_tone_at_44_1_khz_comes_out_unchanged() -> anyhow::Result<()> {
    let source = tone(44_100, 441.0, 0.5, 0.8);
    let mut audio = Audio::silent();
    assert_eq!(audio.recorded_sample_rate_hz(), Some(44_100));
    audio.play(&source, PlayOptions::default())?;
    run(&mut audio, 0.6);
    let (lag, diff) = best_match(recorded(&audio), &source, 1.0, BLOCK_FRAMES);
    assert!(diff <= SAME, "largest difference {diff} at lag {lag}");
    Ok(())
}

#[test]
fn a_looping_sound_plays_past_its_length_and_stop_fades_it_out() -> anyhow::Result<()> {
    let hum = decode_sound(&sounds_dir().join("hum_loop.wav"))?;
    let rate = hum.sample_rate_hz();
    let mut audio = silent(rate);
    let options = PlayOptions {
        looped: true,
        ..Default::default()
    };
    let id = audio.play(&hum, options)?;
    run(&mut audio, 2.5 * hum.duration_seconds());
    assert!(audio.is_playing(id));
    // Still the source, wrapped around: frame i of the record is source frame (i - lag) mod n.
    let rec = recorded(&audio);
    let (lag, diff) = best_match(rec, &hum, 1.0, BLOCK_FRAMES);
    assert!(diff <= SAME, "first pass: {diff}");
    let n = hum.frame_count();
    let second_pass = lag + n..lag + 2 * n + n / 4;
    for i in second_pass {
        let want = hum.frame((i - lag) % n).unwrap_or([f32::NAN; 2]);
        assert!(
            (rec[i][0] - want[0]).abs() <= SAME,
            "frame {i} after looping"
        );
    }

    let stopped_at = audio.time_seconds();
    audio.stop(id, 0.25);
    run(&mut audio, 0.5);
    let before = rms(window(&audio, stopped_at - 0.25, stopped_at), 0);
    let early_fade = rms(window(&audio, stopped_at, stopped_at + 0.1), 0);
    let late_fade = rms(window(&audio, stopped_at + 0.15, stopped_at + 0.25), 0);
    assert!(before > 0.1 && early_fade < before && late_fade < early_fade);
    let after = window(&audio, stopped_at + 0.3, stopped_at + 0.5);
    assert!(!after.is_empty() && after.iter().all(|f| f == &[0.0, 0.0]));
    assert!(!audio.is_playing(id));
    assert_eq!(audio.playing_count(), 0);
    Ok(())
}

#[test]
fn bus_volumes_scale_the_music() -> anyhow::Result<()> {
    let music = tone(44_100, 440.0, 1.0, 0.5);
    let mut audio = Audio::silent();
    audio.play_music(&music, true)?;
    run(&mut audio, 0.5);
    // Windows of 0.25 s hold 110 whole cycles of 440 Hz, so each RMS is the amplitude / √2
    // exactly up to f32 rounding; ratios are checked to 1e-4.
    let full = rms(window(&audio, 0.25, 0.5), 0);
    assert!((full - 0.5 / 2f64.sqrt()).abs() < 1e-4, "{full}");

    audio.set_volume(Bus::Music, 0.25);
    run(&mut audio, 0.5);
    let quarter = rms(window(&audio, 0.75, 1.0), 0);
    assert!((quarter / full - 0.25).abs() < 1e-4, "{}", quarter / full);

    audio.set_volume(Bus::Effects, 0.0); // not the music's bus
    audio.set_volume(Bus::Master, 0.5);
    run(&mut audio, 0.5);
    let eighth = rms(window(&audio, 1.25, 1.5), 0);
    assert!((eighth / full - 0.125).abs() < 1e-4, "{}", eighth / full);
    assert_eq!(audio.volume(Bus::Music), 0.25);

    audio.set_volume(Bus::Music, 0.0);
    run(&mut audio, 0.25);
    let muted = window(&audio, 1.6, 1.75);
    assert!(muted.iter().all(|f| f == &[0.0, 0.0]));
    Ok(())
}

#[test]
fn new_music_crossfades_from_the_old() -> anyhow::Result<()> {
    let first = tone(44_100, 440.0, 1.0, 0.5);
    let second = tone(44_100, 660.0, 1.0, 0.2);
    let mut audio = Audio::silent();
    audio.play_music(&first, true)?;
    run(&mut audio, 0.5);
    audio.play_music(&second, true)?;
    run(&mut audio, 2.0);
    // After the 1 s crossfade only the second track is left: RMS = 0.2 / √2.
    let after = rms(window(&audio, 2.0, 2.5), 0);
    assert!((after - 0.2 / 2f64.sqrt()).abs() < 1e-4, "{after}");
    let music: Vec<&str> = audio
        .played()
        .iter()
        .filter(|p| p.bus == Bus::Music)
        .map(|p| &*p.name)
        .collect();
    assert_eq!(music, ["tone", "tone"]);
    Ok(())
}

#[test]
fn played_records_name_time_and_position() -> anyhow::Result<()> {
    let chime = decode_sound(&sounds_dir().join("chime.wav"))?;
    let mut audio = Audio::silent();
    run(&mut audio, 0.5);
    let at = Vec3::new(1.0, 2.0, -3.0);
    let id = audio.play(
        &chime,
        PlayOptions {
            volume: 0.8,
            looped: false,
            at: Some(at),
        },
    )?;
    run(&mut audio, 0.25);
    audio.play(&chime, PlayOptions::default())?;
    let played = audio.played();
    assert_eq!(played.len(), 2);
    let first = &played[0];
    assert_eq!(&*first.name, "chime");
    assert!(
        (first.time_seconds - 0.5).abs() < 1e-9,
        "{}",
        first.time_seconds
    );
    assert_eq!(first.position, Some(at));
    assert_eq!(
        (first.volume, first.looped, first.bus, first.id),
        (0.8, false, Bus::Effects, Some(id))
    );
    assert!((played[1].time_seconds - 0.75).abs() < 1e-9);
    assert_eq!(played[1].position, None);
    Ok(())
}

#[test]
fn a_thousand_plays_in_a_row_do_not_fail() -> anyhow::Result<()> {
    // kira frees a finished sound's slot only when its mixer runs; the recorder runs it on every
    // tick, so a game that plays a sound every step never runs out (kira's own mock backend,
    // never run, fails after 128).
    let click = tone(44_100, 1000.0, 0.05, 0.3);
    let mut audio = Audio::silent();
    for i in 0..1000 {
        let at = (i % 2 == 1).then_some(Vec3::new(2.0, 0.0, 0.0));
        audio.play(
            &click,
            PlayOptions {
                at,
                ..Default::default()
            },
        )?;
        audio.tick(STEP_SECONDS);
        assert!(audio.playing_count() <= 8, "{}", audio.playing_count());
    }
    assert_eq!(audio.played().len(), 1000);
    Ok(())
}

#[test]
fn too_many_sounds_in_one_step_is_a_typed_error_then_recovers() -> anyhow::Result<()> {
    let click = tone(44_100, 1000.0, 0.05, 0.01);
    let mut audio = Audio::silent();
    for _ in 0..EFFECT_SOUND_CAPACITY {
        audio.play(&click, PlayOptions::default())?;
    }
    match audio.play(&click, PlayOptions::default()) {
        Err(AudioError::TooManySounds {
            bus: Bus::Effects,
            limit,
        }) => {
            assert_eq!(limit, EFFECT_SOUND_CAPACITY)
        }
        other => panic!("expected TooManySounds, got {other:?}"),
    }
    run(&mut audio, 0.2);
    assert_eq!(audio.playing_count(), 0);
    audio.play(&click, PlayOptions::default())?;
    Ok(())
}

#[test]
fn memory_stays_bounded_over_a_long_run() -> anyhow::Result<()> {
    let click = tone(44_100, 1000.0, 0.05, 0.01);
    let mut audio = Audio::silent_with(SilentSettings {
        sample_rate_hz: 44_100,
        max_recorded_seconds: 1.0,
    });
    let plays = 3 * MAX_PLAYED_RECORDS;
    for i in 0..plays {
        audio.play(&click, PlayOptions::default())?;
        if i % 100 == 99 {
            audio.tick(STEP_SECONDS);
        }
    }
    run(&mut audio, 5.0);
    let played = audio.played();
    assert!((MAX_PLAYED_RECORDS..2 * MAX_PLAYED_RECORDS).contains(&played.len()));
    let last_id = played.last().and_then(|p| p.id).map(|id| id.0);
    assert_eq!(last_id, Some(plays as u64 - 1));
    let rec = recorded(&audio);
    assert!((44_100..2 * 44_100).contains(&rec.len()), "{}", rec.len());
    let total = audio.recorded_start_frame() + rec.len() as u64;
    assert_eq!(total, (audio.time_seconds() * 44_100.0).round() as u64);
    Ok(())
}

#[test]
fn odd_ticks_are_harmless() {
    let mut audio = Audio::silent();
    for dt in [f64::NAN, -1.0, 0.0, f64::INFINITY] {
        audio.tick(dt);
    }
    assert_eq!(audio.time_seconds(), 0.0);
    audio.tick(1e9);
    assert_eq!(audio.time_seconds(), candela::audio::MAX_TICK_SECONDS);
    assert_eq!(recorded(&audio).len(), 44_100);
}
