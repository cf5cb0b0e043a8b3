//! `Audio::new` never fails: with a sound card it opens it; without one (CI) it falls back to
//! the silent recorder, which then behaves like `Audio::silent`. And `Audio` can move to
//! another thread with the engine that owns it.

use candela::audio::{Audio, PlayOptions, Sound};

#[test]
fn new_opens_the_device_or_falls_back_to_silence() -> anyhow::Result<()> {
    let mut audio = Audio::new();
    let blip = Sound::from_mono_samples("blip", 44_100, &[0.1; 441])?;
    audio.play(&blip, PlayOptions::default())?;
    audio.tick(1.0 / 60.0);
    assert_eq!(audio.played().len(), 1);
    if audio.is_silent() {
        assert_eq!(audio.recorded_samples().map(<[_]>::len), Some(735));
    } else {
        assert!(audio.recorded_samples().is_none());
    }
    Ok(())
}

#[test]
fn audio_and_sounds_are_send() {
    fn send<T: Send>() {}
    fn sync<T: Sync>() {}
    send::<Audio>();
    send::<Sound>();
    sync::<Sound>();
}
