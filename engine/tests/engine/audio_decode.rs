//! Decoding sounds: every committed sound decodes at its rate and length; files that are not
//! audio, cut short, empty or missing each give a typed `AudioError` whose message names the file
//! and the problem; damaged headers never panic.

use std::path::{Path, PathBuf};

use candela::audio::{AudioError, DecodeProblem, Sound, decode_sound, decode_sound_bytes};

/// Every sound in `assets/common/sounds/` with its length in seconds (all mono 22.05 kHz, made
/// by `cargo run --release -p assetgen -- sounds`).
const COMMITTED: [(&str, f64); 11] = [
    ("ambient_pad", 8.0),
    ("chime", 0.8),
    ("door_slide", 1.2),
    ("elevator_loop", 4.0),
    ("fail_buzz", 0.5),
    ("footstep", 0.3),
    ("hum_loop", 2.0),
    ("laser_hum", 2.0),
    ("mirror_toggle", 0.4),
    ("music_loop", 4.0),
    ("receiver_chime", 1.0),
];
const COMMITTED_RATE_HZ: u32 = 22_050;

fn sounds_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../assets/common/sounds")
}

/// A scratch folder for this test process.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("candela-audio-decode-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir is writable");
    dir.join(name)
}

fn decode_error(path: &Path) -> AudioError {
    match decode_sound(path) {
        Ok(sound) => panic!("{} decoded ({sound:?}) but should not", path.display()),
        Err(e) => e,
    }
}

#[test]
fn every_committed_sound_decodes_at_its_rate_and_length() -> anyhow::Result<()> {
    let mut on_disk: Vec<String> = std::fs::read_dir(sounds_dir())?
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".wav"))
        .collect();
    on_disk.sort();
    let listed: Vec<String> = COMMITTED.iter().map(|(n, _)| format!("{n}.wav")).collect();
    assert_eq!(
        on_disk, listed,
        "a sound was added or removed: update COMMITTED"
    );
    for (name, seconds) in COMMITTED {
        let sound = decode_sound(&sounds_dir().join(format!("{name}.wav")))?;
        assert_eq!(sound.name(), name);
        assert_eq!(sound.sample_rate_hz(), COMMITTED_RATE_HZ, "{name}");
        // Lengths are whole frames: exact to one frame (45 µs).
        assert!(
            (sound.duration_seconds() - seconds).abs() <= 1.0 / f64::from(COMMITTED_RATE_HZ),
            "{name}: {} s, expected {seconds} s",
            sound.duration_seconds()
        );
        let peak = (0..sound.frame_count())
            .filter_map(|i| sound.frame(i))
            .fold(0.0f32, |m, [l, r]| m.max(l.abs()).max(r.abs()));
        assert!(peak > 0.5 && peak <= 1.0, "{name}: peak {peak}");
    }
    Ok(())
}

#[test]
fn a_file_that_is_not_audio_names_the_file_and_the_problem() -> anyhow::Result<()> {
    let path = scratch("level_notes.wav");
    std::fs::write(
        &path,
        b"This is a text file that someone named .wav by mistake.\n",
    )?;
    let error = decode_error(&path);
    let message = error.to_string();
    assert!(
        matches!(
            &error,
            AudioError::Decode {
                problem: DecodeProblem::NotAudio { .. },
                ..
            }
        ),
        "{error:?}"
    );
    assert!(message.contains(&path.display().to_string()), "{message}");
    assert!(
        message.contains("not a supported audio format"),
        "{message}"
    );
    Ok(())
}

#[test]
fn a_truncated_wav_names_the_file_and_the_short_chunk() -> anyhow::Result<()> {
    let whole = std::fs::read(sounds_dir().join("chime.wav"))?;
    let path = scratch("chime_cut.wav");
    let cut = whole.len() / 2;
    std::fs::write(&path, &whole[..cut])?;
    let error = decode_error(&path);
    let message = error.to_string();
    // The generator writes a 44-byte header: the data chunk's body starts at byte 44.
    let declared = (whole.len() - 44) as u64;
    let present = (cut - 44) as u64;
    match &error {
        AudioError::Decode {
            sound,
            problem:
                DecodeProblem::Truncated {
                    chunk,
                    declared_bytes,
                    present_bytes,
                },
        } => {
            assert_eq!(sound, &path.display().to_string());
            assert_eq!(chunk, "data");
            assert_eq!((*declared_bytes, *present_bytes), (declared, present));
        }
        other => panic!("expected a truncated-data error, got {other:?}"),
    }
    assert!(message.contains(&path.display().to_string()), "{message}");
    assert!(message.contains("truncated"), "{message}");
    assert!(message.contains(&declared.to_string()), "{message}");

    // Cut inside the header: still a clear error naming the file, never a panic.
    let path = scratch("chime_header_only.wav");
    std::fs::write(&path, &whole[..30])?;
    let message = decode_error(&path).to_string();
    assert!(message.contains(&path.display().to_string()), "{message}");
    assert!(message.contains("truncated"), "{message}");
    Ok(())
}

#[test]
fn a_missing_file_is_an_io_error_naming_it() {
    let path = sounds_dir().join("no_such_sound.wav");
    let error = decode_error(&path);
    match &error {
        AudioError::Io { path: p, source } => {
            assert_eq!(p, &path);
            assert_eq!(source.kind(), std::io::ErrorKind::NotFound);
        }
        other => panic!("expected an io error, got {other:?}"),
    }
    let message = error.to_string();
    assert!(message.contains("no_such_sound.wav"), "{message}");
    assert!(message.contains("cannot read"), "{message}");
}

#[test]
fn an_empty_file_and_empty_bytes_say_so() -> anyhow::Result<()> {
    let path = scratch("empty.wav");
    std::fs::write(&path, b"")?;
    let error = decode_error(&path);
    assert!(
        matches!(
            &error,
            AudioError::Decode {
                problem: DecodeProblem::Empty,
                ..
            }
        ),
        "{error:?}"
    );
    assert!(error.to_string().contains("empty"));
    let error = decode_sound_bytes("door.wav in memory", &[]).err();
    assert!(
        error
            .as_ref()
            .is_some_and(|e| e.to_string().contains("door.wav in memory")),
        "{error:?}"
    );
    Ok(())
}

#[test]
fn damaged_headers_give_results_not_panics() -> anyhow::Result<()> {
    let whole = std::fs::read(sounds_dir().join("fail_buzz.wav"))?;
    let mut errors = 0;
    // Every header byte set to 0x00 and to 0xFF, and every 7th header byte incremented.
    for at in 0..44 {
        for change in [0u8, 0xFF, whole[at].wrapping_add(1)] {
            let mut bytes = whole.clone();
            bytes[at] = change;
            match decode_sound_bytes("damaged", &bytes) {
                Ok(sound) => assert!(sound.frame_count() > 0),
                Err(e) => {
                    assert!(e.to_string().starts_with("sound damaged: "), "{e}");
                    errors += 1;
                }
            }
        }
    }
    assert!(errors > 0, "no damaged header was rejected");
    Ok(())
}

#[test]
fn sounds_made_in_code_are_checked_too() {
    assert!(Sound::from_mono_samples("tone", 0, &[0.0]).is_err());
    assert!(Sound::from_mono_samples("tone", 48_000, &[]).is_err());
    let error = Sound::from_mono_samples("tone", 48_000, &[0.0, f32::NAN]).err();
    assert!(
        error
            .as_ref()
            .is_some_and(|e| e.to_string().contains("sample 1")),
        "{error:?}"
    );
    let sound = Sound::from_mono_samples("tone", 48_000, &[0.25, 2.0]);
    assert!(sound.is_ok_and(|s| s.frame(1) == Some([1.0, 1.0]) && s.frame(2).is_none()));
}
