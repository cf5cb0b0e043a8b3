//! Pausing the game holds its effect sounds (issue 10: audio kept playing while paused): a
//! looping hum on the effects bus falls silent within the pause fade and comes back where it
//! was on resume, while the music plays on under the pause; `Engine::set_paused` does it.

use candela::app::{Engine, Environment};
use candela::assets::{AssetRoot, load_scene};
use candela::audio::{Audio, PAUSE_FADE_SECONDS, PlayOptions, SilentSettings, Sound, decode_sound};
use candela::render::RenderConfig;

const STEP_SECONDS: f64 = 1.0 / 60.0;

fn run(audio: &mut Audio, seconds: f64) {
    for _ in 0..(seconds / STEP_SECONDS).round() as usize {
        audio.tick(STEP_SECONDS);
    }
}

/// RMS of the left channel over `[from, to)` seconds of the record.
fn rms(audio: &Audio, from: f64, to: f64) -> f64 {
    let rate = f64::from(audio.recorded_sample_rate_hz().expect("silent"));
    let start = audio.recorded_start_frame() as f64;
    let rec = audio.recorded_samples().expect("silent mode records");
    let a = ((from * rate - start).max(0.0) as usize).min(rec.len());
    let b = ((to * rate - start).max(0.0) as usize).min(rec.len());
    let frames = &rec[a..b];
    assert!(!frames.is_empty(), "nothing recorded in [{from}, {to})");
    let sum: f64 = frames.iter().map(|f| f64::from(f[0]).powi(2)).sum();
    (sum / frames.len() as f64).sqrt()
}

fn tone(rate_hz: u32, hz: f64, seconds: f64) -> Sound {
    let n = (seconds * f64::from(rate_hz)).round() as usize;
    let samples: Vec<f32> = (0..n)
        .map(|i| 0.5 * (std::f64::consts::TAU * hz * i as f64 / f64::from(rate_hz)).sin() as f32)
        .collect();
    Sound::from_mono_samples("music", rate_hz, &samples).expect("a valid tone")
}

#[test]
fn a_pause_holds_the_effects_and_the_music_plays_on() -> anyhow::Result<()> {
    let sounds =
        std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../assets/common/sounds");
    let hum = decode_sound(&sounds.join("hum_loop.wav"))?;
    let rate = hum.sample_rate_hz();
    let mut audio = Audio::silent_with(SilentSettings {
        sample_rate_hz: rate,
        max_recorded_seconds: 20.0,
    });
    let looped = PlayOptions {
        looped: true,
        ..Default::default()
    };
    audio.play(&hum, looped)?;
    run(&mut audio, 1.0);
    let playing = rms(&audio, 0.5, 1.0);
    assert!(playing > 0.05, "the hum plays: {playing}");
    audio.set_effects_paused(true);
    assert!(audio.effects_paused());
    run(&mut audio, 1.0);
    let held = rms(&audio, 1.0 + 2.0 * PAUSE_FADE_SECONDS, 2.0);
    assert!(held < 1e-4, "held while paused: {held} (playing {playing})");
    audio.set_effects_paused(false);
    run(&mut audio, 1.0);
    let back = rms(&audio, 2.0 + 2.0 * PAUSE_FADE_SECONDS, 3.0);
    assert!(
        back > 0.5 * playing,
        "back after the pause: {back} (playing {playing})"
    );

    // Music is not an effect: it plays on while the effects are held.
    audio.play_music(&tone(rate, 220.0, 1.0), true)?;
    audio.set_effects_paused(true);
    run(&mut audio, 1.0);
    let music = rms(&audio, 3.0 + 2.0 * PAUSE_FADE_SECONDS, 4.0);
    assert!(music > 0.1, "the music plays on under the pause: {music}");
    Ok(())
}

#[test]
fn holding_the_game_holds_its_effects() -> anyhow::Result<()> {
    let assets = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../assets/test_scenes");
    let scene = load_scene(&assets.join("cornell_box.ron"), &AssetRoot::new(&assets)?)?;
    let mut engine = Engine::new(RenderConfig::cpu(8, 8), Environment::of(&scene))?;
    assert!(!engine.audio().effects_paused());
    engine.set_paused(true);
    assert!(engine.audio().effects_paused(), "paused: effects held");
    engine.set_paused(false);
    assert!(!engine.audio().effects_paused(), "resumed: effects play");
    Ok(())
}
