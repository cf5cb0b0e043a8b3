//! Recording and replaying in the engine's own frame loop, headless on the CPU tracer: a run
//! whose input comes from the devices (keys and mouse motion fed between frames of uneven
//! length) is recorded per fixed step; replaying the recording in a fresh engine at another
//! frame rate, with the devices sending other input, gives the same state at every step, and
//! the engine says when the replay has ended. The look settings the run was recorded with
//! (here mouse sensitivity 2) travel in the recording: a player whose settings differ
//! (sensitivity 0.5) replays it turning exactly as recorded.

use std::path::PathBuf;

use candela::app::{
    ActionSet, Engine, Environment, Game, KeyCode, Recorder, Replay, ReplayTarget, Settings, Step,
    StepInput, game_actions,
};
use candela::assets::{CameraDesc, SkyDesc};
use candela::ecs::Transform;
use candela::render::RenderConfig;
use glam::{Quat, Vec3};

/// Moves one entity by the step's actions and keeps a hash of its transform after each step.
struct Walker {
    body: Option<hecs::Entity>,
    hashes: Vec<u64>,
}

impl Game for Walker {
    fn fixed_step(&mut self, step: &mut Step<'_>) {
        let set = step.action_set;
        let id = |name| set.id(name).expect("standard action");
        let Some(body) = self.body else { return };
        let Ok(mut t) = step.world.get::<&mut Transform>(body) else {
            return;
        };
        let forward = step
            .actions
            .button_axis(id(game_actions::MOVE_FORWARD), id(game_actions::MOVE_BACK));
        let yaw = -step.actions.motion(id(game_actions::LOOK_X))
            * 0.003
            * step.settings.mouse_sensitivity;
        t.rotation = (Quat::from_rotation_y(yaw) * t.rotation).normalize();
        let ahead = t.rotation * Vec3::NEG_Z;
        t.translation += ahead * forward * 4.0 * step.step_seconds as f32;
        if step.actions.pressed(id(game_actions::JUMP)) {
            t.translation.y += 1.0;
        }
        let mut h = 0xcbf2_9ce4_8422_2325_u64;
        for v in t
            .translation
            .to_array()
            .into_iter()
            .chain(t.rotation.to_array())
        {
            h = (h ^ u64::from(v.to_bits())).wrapping_mul(0x0100_0000_01b3);
        }
        self.hashes.push(h);
    }
}

fn engine() -> (Engine, Walker) {
    let camera = CameraDesc {
        position: [0.0, 2.0, 4.0],
        look_at: [0.0, 0.0, 0.0],
        up: [0.0, 1.0, 0.0],
        vertical_fov_deg: 50.0,
        aperture_radius: 0.0,
        focus_distance: None,
    };
    let environment = Environment {
        sun: None,
        sky: SkyDesc::Constant([0.1, 0.1, 0.1]),
        render: Default::default(),
        default_camera: camera,
    };
    let mut engine = Engine::new(RenderConfig::cpu(8, 8), environment).expect("engine");
    engine.set_actions(ActionSet::standard());
    let body = engine.world_mut().spawn((Transform::IDENTITY,));
    (
        engine,
        Walker {
            body: Some(body),
            hashes: Vec::new(),
        },
    )
}

fn target(set: &ActionSet) -> ReplayTarget<'_> {
    ReplayTarget {
        game: "test",
        level_id: "empty",
        level_hash: 7,
        step_hz: 60.0,
        actions: set,
    }
}

fn temp(name: &str) -> PathBuf {
    std::env::temp_dir().join(format!("candela_{name}_{}.replay", std::process::id()))
}

#[test]
fn a_replay_repeats_every_step_at_another_frame_rate() {
    let path = temp("engine_replay");
    // Record: 90 frames of uneven length, keys and mouse motion between frames.
    let (mut live, mut walker) = engine();
    let set = ActionSet::standard();
    live.set_settings(Settings {
        mouse_sensitivity: 2.0,
        ..Settings::default()
    });
    live.set_step_input(StepInput::record(
        Recorder::new("test", "empty", 7, 60.0, &set),
        &path,
    ));
    for frame in 0..90u32 {
        let input = live.input_mut();
        input.key(KeyCode::KeyW, (10..60).contains(&frame));
        input.key(KeyCode::Space, frame % 25 == 3);
        input.mouse_motion(((frame * 37) % 11) as f32 - 5.0, 0.0);
        let seconds = [1.0 / 30.0, 1.0 / 90.0, 1.0 / 60.0, 1.0 / 45.0][frame as usize % 4];
        live.frame(seconds, &mut walker).expect("frame");
        let _ = live.rendered();
    }
    live.finish_recording().expect("recording written");
    let recorded = walker.hashes.clone();
    let _ = live.shutdown();
    assert!(recorded.len() > 60, "{} steps recorded", recorded.len());
    assert!(
        recorded.windows(2).filter(|w| w[0] != w[1]).count() > 30,
        "the input moved the body"
    );

    // Replay at 20 fps (3 steps a frame), the devices holding S the whole time.
    let (mut replayed, mut walker) = engine();
    replayed.set_settings(Settings {
        mouse_sensitivity: 0.5,
        ..Settings::default()
    });
    let replay = Replay::open(&path, &target(&set)).expect("the recording opens");
    replayed.set_step_input(StepInput::Replay(replay));
    while !replayed.replay_finished() {
        replayed.input_mut().key(KeyCode::KeyS, true);
        replayed.frame(1.0 / 20.0, &mut walker).expect("frame");
        let _ = replayed.rendered();
        assert!(walker.hashes.len() <= recorded.len() + 3, "the replay ends");
    }
    let _ = replayed.shutdown();
    let _ = std::fs::remove_file(&path);
    let played = &walker.hashes[..recorded.len()];
    for (step, (a, b)) in recorded.iter().zip(played).enumerate() {
        assert_eq!(a, b, "state differs at step {step}");
    }
    // After the last recorded step the game gets no input: the body stands still.
    let after = &walker.hashes[recorded.len()..];
    assert!(
        after.iter().all(|h| Some(h) == recorded.last()),
        "{after:?}"
    );
}

#[test]
fn a_replay_of_another_level_is_refused_naming_the_file() {
    let path = temp("engine_replay_other");
    let set = ActionSet::standard();
    let mut recorder = Recorder::new("test", "empty", 7, 60.0, &set);
    for _ in 0..3 {
        recorder
            .push(candela::app::ActionFrame::empty(&set))
            .expect("push");
    }
    recorder.write(&path).expect("write");
    let other = ReplayTarget {
        level_hash: 8,
        ..target(&set)
    };
    let error = Replay::open(&path, &other).expect_err("another level");
    let _ = std::fs::remove_file(&path);
    let message = error.to_string();
    assert!(
        message.contains(&path.display().to_string()),
        "the error names the file: {message}"
    );
}
