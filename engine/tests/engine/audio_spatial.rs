//! Spatial sounds and emitters, heard through the silent recorder: a sound to the listener's
//! right is louder on the right, and the other way round; turning the listener swaps the sides;
//! farther is quieter by exactly what kira's spatial track model says; emitters on entities
//! follow their transforms and stop when the entity goes away.

use candela::audio::{
    Audio, PlayOptions, SPATIAL_MAX_DISTANCE_METERS, SPATIAL_MIN_DISTANCE_METERS, Sound,
    SoundEmitter, sync_emitters,
};
use candela::ecs::GlobalTransform;
use glam::{Mat4, Quat, Vec3};

const STEP_SECONDS: f64 = 1.0 / 60.0;
const RATE_HZ: u32 = 44_100;

fn run(audio: &mut Audio, seconds: f64) {
    for _ in 0..(seconds / STEP_SECONDS).round() as usize {
        audio.tick(STEP_SECONDS);
    }
}

/// A steady 441 Hz sine, 1 s (a whole number of cycles: it loops seamlessly).
fn hum() -> Sound {
    let samples: Vec<f32> = (0..RATE_HZ as usize)
        .map(|i| 0.5 * (std::f64::consts::TAU * 441.0 * i as f64 / f64::from(RATE_HZ)).sin() as f32)
        .collect();
    Sound::from_mono_samples("hum", RATE_HZ, &samples).expect("a valid tone")
}

/// RMS of the left and right channels over the last `seconds` recorded (a whole number of
/// 441 Hz cycles for multiples of 1/441 s; 0.1 s is 44.1 cycles, close enough for the ratios
/// below, which compare like with like).
fn last_rms(audio: &Audio, seconds: f64) -> (f64, f64) {
    let rec = audio.recorded_samples().expect("silent mode records");
    let n = ((seconds * f64::from(RATE_HZ)) as usize).min(rec.len());
    let tail = &rec[rec.len() - n..];
    let rms = |c: usize| {
        (tail.iter().map(|f| f64::from(f[c]).powi(2)).sum::<f64>() / n.max(1) as f64).sqrt()
    };
    (rms(0), rms(1))
}

fn looped_at(position: Vec3) -> PlayOptions {
    PlayOptions {
        volume: 1.0,
        looped: true,
        at: Some(position),
    }
}

#[test]
fn a_sound_to_the_right_is_louder_on_the_right_and_vice_versa() -> anyhow::Result<()> {
    let mut audio = Audio::silent();
    audio.set_listener(Vec3::ZERO, Quat::IDENTITY); // looks along -Z, +X on its right
    let id = audio.play(&hum(), looped_at(Vec3::new(5.0, 0.0, 0.0)))?;
    run(&mut audio, 0.3);
    let (left, right) = last_rms(&audio, 0.1);
    assert!(
        right > 2.0 * left && left > 0.0,
        "right source: L {left} R {right}"
    );

    audio.set_position(id, Vec3::new(-5.0, 0.0, 0.0));
    run(&mut audio, 0.3);
    let (left, right) = last_rms(&audio, 0.1);
    assert!(
        left > 2.0 * right && right > 0.0,
        "left source: L {left} R {right}"
    );

    // Turn the listener around (now looking along +Z): the source at -X is on its right.
    audio.set_listener(Vec3::ZERO, Quat::from_rotation_y(std::f32::consts::PI));
    run(&mut audio, 0.3);
    let (left, right) = last_rms(&audio, 0.1);
    assert!(right > 2.0 * left, "after turning: L {left} R {right}");
    Ok(())
}

/// kira's attenuation: full volume up to the minimum distance, then linear in decibels down to
/// −60 dB (silence) at the maximum distance.
fn model_amplitude(distance: f32) -> f64 {
    let (min, max) = (SPATIAL_MIN_DISTANCE_METERS, SPATIAL_MAX_DISTANCE_METERS);
    let relative = ((distance.clamp(min, max) - min) / (max - min)) as f64;
    10f64.powf(-60.0 * relative / 20.0)
}

#[test]
fn farther_is_quieter_as_the_spatial_model_says() -> anyhow::Result<()> {
    // On the +X axis the direction from both ears is the same at every distance, so panning is
    // equal and the level ratio is the attenuation ratio alone.
    let mut levels = Vec::new();
    for distance in [0.5f32, 5.0, 20.0] {
        let mut audio = Audio::silent();
        audio.play(&hum(), looped_at(Vec3::new(distance, 0.0, 0.0)))?;
        run(&mut audio, 0.3);
        levels.push((distance, last_rms(&audio, 0.1).1));
    }
    let (near_distance, near) = levels[0];
    for &(distance, level) in &levels[1..] {
        let want = model_amplitude(distance) / model_amplitude(near_distance);
        // Same samples, same gains but one: only f32 rounding differs (1e-4 relative).
        assert!(
            ((level / near) / want - 1.0).abs() < 1e-4,
            "{distance} m: ratio {} vs model {want}",
            level / near
        );
        assert!(level < near);
    }
    // Past the maximum distance: silent.
    let mut audio = Audio::silent();
    audio.play(
        &hum(),
        looped_at(Vec3::new(SPATIAL_MAX_DISTANCE_METERS + 10.0, 0.0, 0.0)),
    )?;
    run(&mut audio, 0.2);
    assert_eq!(last_rms(&audio, 0.1), (0.0, 0.0));
    Ok(())
}

fn at(x: f32) -> GlobalTransform {
    GlobalTransform(Mat4::from_translation(Vec3::new(x, 0.0, 0.0)))
}

#[test]
fn emitters_follow_their_entity_and_stop_when_it_goes() -> anyhow::Result<()> {
    let mut audio = Audio::silent();
    let mut world = hecs::World::new();
    let entity = world.spawn((at(4.0), SoundEmitter::new(hum(), 1.0, true)));
    sync_emitters(&mut audio, &mut world);
    run(&mut audio, 0.3);
    let (left, right) = last_rms(&audio, 0.1);
    assert!(right > 2.0 * left, "emitter at +X: L {left} R {right}");
    let id = world
        .get::<&SoundEmitter>(entity)?
        .playing
        .expect("sync_emitters started it");
    assert_eq!(audio.played()[0].position, Some(Vec3::new(4.0, 0.0, 0.0)));

    // Move the entity; the next sync moves the sound, and does not start another.
    *world.get::<&mut GlobalTransform>(entity)? = at(-4.0);
    sync_emitters(&mut audio, &mut world);
    run(&mut audio, 0.3);
    let (left, right) = last_rms(&audio, 0.1);
    assert!(
        left > 2.0 * right,
        "emitter moved to -X: L {left} R {right}"
    );
    assert_eq!(audio.played().len(), 1);
    assert!(audio.is_playing(id));

    world.despawn(entity)?;
    sync_emitters(&mut audio, &mut world);
    run(&mut audio, 0.4);
    assert_eq!(last_rms(&audio, 0.1), (0.0, 0.0));
    assert!(!audio.is_playing(id));
    Ok(())
}

#[test]
fn a_one_shot_emitter_plays_once_until_reset() -> anyhow::Result<()> {
    let short = Sound::from_mono_samples("blip", RATE_HZ, &[0.25; 2205])?; // 0.05 s
    let mut audio = Audio::silent();
    let mut world = hecs::World::new();
    let entity = world.spawn((at(1.0), SoundEmitter::new(short, 0.5, false)));
    for _ in 0..30 {
        sync_emitters(&mut audio, &mut world);
        audio.tick(STEP_SECONDS);
    }
    assert_eq!(audio.played().len(), 1);
    assert_eq!(audio.played()[0].volume, 0.5);
    world.get::<&mut SoundEmitter>(entity)?.playing = None;
    sync_emitters(&mut audio, &mut world);
    assert_eq!(audio.played().len(), 2);
    Ok(())
}
