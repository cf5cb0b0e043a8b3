//! The committed sounds (`assets/common/sounds/`, `assets/its_about_time/sounds/`) are exactly
//! what `tools/assetgen` makes, and the engine decodes each one to what the generator meant: the
//! same rate, length and samples.

use candela::audio::decode_sound;

fn sounds_dir() -> std::path::PathBuf {
    candela_tests::repo().join("assets/common/sounds")
}

#[test]
fn committed_sounds_are_what_assetgen_makes() -> anyhow::Result<()> {
    let files = assetgen::sounds::sound_files();
    assert_eq!(files.len(), assetgen::sounds::SOUNDS.len());
    for (file, bytes) in files {
        let path = sounds_dir().join(&file);
        let committed = std::fs::read(&path)?;
        assert!(
            committed == bytes,
            "{} is stale: run `cargo run --release -p assetgen -- sounds`",
            path.display()
        );
    }
    Ok(())
}

#[test]
fn engine_decodes_generated_sounds_sample_for_sample() -> anyhow::Result<()> {
    for spec in assetgen::sounds::SOUNDS {
        let sound = decode_sound(&sounds_dir().join(format!("{}.wav", spec.name)))?;
        let made = assetgen::sounds::samples(spec.name);
        assert_eq!(sound.sample_rate_hz(), assetgen::sounds::SAMPLE_RATE_HZ);
        assert_eq!(sound.frame_count(), made.len(), "{}", spec.name);
        assert!((sound.duration_seconds() - spec.duration_seconds).abs() < 1e-9);
        // 16-bit quantisation: rounding to the nearest of 32767 steps per unit is off by at most
        // half a step (1.5e-5); the decoder's own i16 -> f32 scale (1/32768 vs 1/32767) adds at
        // most 3.1e-5 at full scale. 5e-5 covers both.
        for (i, want) in made.iter().enumerate() {
            let [left, right] = sound.frame(i).unwrap_or([f32::NAN; 2]);
            assert!(
                (left - want).abs() < 5e-5 && left == right,
                "{} frame {i}: decoded {left}/{right}, generated {want}",
                spec.name
            );
        }
    }
    Ok(())
}

#[test]
fn committed_ruins_sounds_are_what_assetgen_makes() -> anyhow::Result<()> {
    use assetgen::ruins_sound_list::{RUINS_SOUNDS, ruins_sound_files, samples};
    let dir = candela_tests::repo().join("assets/its_about_time/sounds");
    let files = ruins_sound_files();
    assert_eq!(files.len(), RUINS_SOUNDS.len());
    for (file, bytes) in files {
        let path = dir.join(&file);
        let committed = std::fs::read(&path)?;
        assert!(
            committed == bytes,
            "{} is stale: run `cargo run --release -p assetgen -- ruins-sounds`",
            path.display()
        );
    }
    // The engine reads each back at the generator's rate and length.
    for spec in RUINS_SOUNDS {
        let sound = decode_sound(&dir.join(format!("{}.wav", spec.name)))?;
        assert_eq!(sound.sample_rate_hz(), assetgen::sounds::SAMPLE_RATE_HZ);
        assert_eq!(
            sound.frame_count(),
            samples(spec.name).len(),
            "{}",
            spec.name
        );
    }
    Ok(())
}
