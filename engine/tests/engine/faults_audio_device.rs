//! Fault: no sound device, or one that disappears mid-run. The game must go on silent — every
//! call still works, game time runs on, what was started is still in the `played` log, bus
//! volumes hold — with exactly one message per failure (`Audio::device_messages`). The device
//! is a [`TestDevice`] (a stand-in sound card the test can make absent or unplug), because the
//! machines the tests run on have no sound card to pull out.

use candela::app::{Engine, Step};
use candela::audio::{Audio, Bus, PlayOptions, Sound, TestDevice};

use crate::pipeline_common::{config, environment};

const STEP_SECONDS: f64 = 1.0 / 60.0;

/// A 441 Hz sine, 1 s at 44.1 kHz, amplitude 0.5 (a whole number of cycles: it loops).
fn tone() -> Sound {
    let samples: Vec<f32> = (0..44_100)
        .map(|i| 0.5 * (std::f32::consts::TAU * 441.0 * i as f32 / 44_100.0).sin())
        .collect();
    Sound::from_mono_samples("tone", 44_100, &samples).expect("a valid tone")
}

fn run(audio: &mut Audio, steps: usize) {
    for _ in 0..steps {
        audio.tick(STEP_SECONDS);
    }
}

/// The loudest recorded sample (silent mode), skipping the record's first `skip` frames.
fn peak_after(audio: &Audio, skip: usize) -> f32 {
    audio
        .recorded_samples()
        .expect("the silent recorder records")
        .iter()
        .skip(skip)
        .flat_map(|f| f.iter())
        .fold(0.0f32, |m, s| {
            if s.abs() > m || s.is_nan() {
                s.abs()
            } else {
                m
            }
        })
}

#[test]
fn no_sound_device_at_start_is_one_message_and_silence() -> anyhow::Result<()> {
    let mut audio = Audio::with_test_device(TestDevice::absent());
    assert!(
        audio.is_silent(),
        "without a device the silent recorder takes over"
    );
    let messages = audio.device_messages().to_vec();
    assert_eq!(messages.len(), 1, "{messages:?}");
    assert!(
        messages[0].contains("no sound device") && messages[0].contains("sound is off"),
        "{}",
        messages[0]
    );
    audio.play(&tone(), PlayOptions::default())?;
    run(&mut audio, 30);
    assert_eq!(audio.device_messages().len(), 1, "no further messages");
    assert!(
        peak_after(&audio, 0) > 0.4,
        "the recorder mixes what was played"
    );

    // The control: a device that is there opens, and says nothing.
    let audio = Audio::with_test_device(TestDevice::new());
    assert!(!audio.is_silent());
    assert!(audio.device_messages().is_empty());
    Ok(())
}

#[test]
fn a_sound_device_unplugged_mid_run_leaves_the_game_silent_with_one_message() -> anyhow::Result<()>
{
    let device = TestDevice::new();
    let mut audio = Audio::with_test_device(device.clone());
    assert!(!audio.is_silent());
    audio.set_volume(Bus::Effects, 0.5);
    let looping = PlayOptions {
        looped: true,
        ..PlayOptions::default()
    };
    let first = audio.play(&tone(), looping)?;
    run(&mut audio, 60);
    assert!(audio.is_playing(first));
    assert!(audio.device_messages().is_empty());

    device.unplug();
    run(&mut audio, 1);
    assert!(
        audio.is_silent(),
        "the lost device is replaced by the silent recorder"
    );
    let messages = audio.device_messages().to_vec();
    assert_eq!(messages.len(), 1, "{messages:?}");
    assert!(
        messages[0].contains("audio device lost") && messages[0].contains("sound is off"),
        "{}",
        messages[0]
    );
    // Nothing the game had is lost but the sound itself.
    assert!((audio.time_seconds() - 61.0 * STEP_SECONDS).abs() < 1e-9);
    assert_eq!(audio.played().len(), 1);
    assert_eq!(audio.volume(Bus::Effects), 0.5);
    assert!(!audio.is_playing(first), "the device's sounds went with it");

    // The game goes on calling: plays work, ids stay unique, no further messages.
    let second = audio.play(&tone(), PlayOptions::default())?;
    assert_ne!(second, first);
    run(&mut audio, 120);
    assert_eq!(audio.device_messages().len(), 1);
    assert_eq!(audio.played().len(), 2);
    let start = audio.recorded_start_frame();
    assert_eq!(start, (61.0 * STEP_SECONDS * 44_100.0_f64).round() as u64);
    // The second tone at 0.5 through Effects at 0.5: peak about 0.25 (after its first 0.1 s).
    let p = peak_after(&audio, 4410);
    assert!((0.2..0.3).contains(&p), "peak {p}");
    Ok(())
}

#[test]
fn an_engine_whose_sound_device_goes_away_keeps_running() -> anyhow::Result<()> {
    let device = TestDevice::new();
    let mut engine = Engine::new(config(1, 8), environment())?;
    engine.set_audio(Audio::with_test_device(device.clone()));
    let tone = tone();
    for frame in 0..40 {
        if frame == 20 {
            device.unplug();
        }
        if frame % 10 == 0 {
            // A game that plays a sound now and then, and ignores what comes back.
            let _ = engine.audio_mut().play(&tone, PlayOptions::default());
        }
        engine.frame(STEP_SECONDS, &mut |_: &mut Step<'_>| {})?;
    }
    assert!(engine.audio().is_silent());
    assert_eq!(engine.audio().device_messages().len(), 1);
    assert!(engine.audio().played().len() >= 3);
    let results = engine.shutdown();
    assert_eq!(results.len(), 40, "every frame rendered");
    assert!(results.iter().all(|r| r.is_ok()));
    Ok(())
}
