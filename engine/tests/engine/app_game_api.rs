//! The game-facing API end to end, headless on the CPU tracer: a [`Game`]'s hooks run in
//! frame order (frame hook, then each fixed step, then that step's level events), level events
//! reach the game (rule firings, volume events, clip events, the win), the commands a hook
//! queues are carried out (light groups, events sent to the level's rules, sounds played by
//! name), and level waves move in `Engine::frame` without any call from the game.

use std::path::Path;

use candela::app::{Engine, Environment, FrameInput, Game, LevelEvent, Step};
use candela::assets::{
    AssetRoot, CameraDesc, Material, Mesh, Model, Placement, SceneDesc, SceneInstance, WaveDesc,
};
use candela::level::{PlayableLevel, load_level};
use candela::render::RenderConfig;
use candela::sim::triggers::Outcome;
use glam::{Mat4, Vec3};

/// Records what it was called with and, at step `send_at`, sends `event` to the rules.
#[derive(Default)]
struct Recorder {
    calls: Vec<String>,
    /// Per call, the event it delivered (`None` for frame and step calls).
    events_at: Vec<Option<LevelEvent>>,
    events: Vec<LevelEvent>,
    send_at: Option<(u64, &'static str)>,
    lights_off_at: Option<(u64, u32)>,
}

impl Game for Recorder {
    fn frame(&mut self, frame: &mut FrameInput<'_>) {
        assert!(frame.frame_seconds > 0.0);
        self.calls.push("frame".into());
        self.events_at.push(None);
    }

    fn fixed_step(&mut self, step: &mut Step<'_>) {
        self.calls.push(format!("step {}", step.index));
        self.events_at.push(None);
        if let Some((at, name)) = self.send_at
            && step.index == at
        {
            step.commands.send_event(name);
        }
        if let Some((at, group)) = self.lights_off_at
            && step.index == at
        {
            step.commands.set_light_group(group, false);
        }
    }

    fn level_event(&mut self, step: &mut Step<'_>, event: &LevelEvent) {
        self.calls.push(format!("event {}", step.index));
        self.events_at.push(Some(event.clone()));
        self.events.push(event.clone());
    }
}

fn repo() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
}

fn plate_door() -> PlayableLevel {
    let root = AssetRoot::new(repo().join("assets")).expect("assets folder");
    load_level(
        &repo().join("assets/test_scenes/gameplay/plate_door.ron"),
        &root,
    )
    .expect("plate_door loads")
}

#[test]
fn hooks_run_in_frame_order_and_level_events_reach_the_game() {
    let level = plate_door();
    let mut engine =
        Engine::new(RenderConfig::cpu(16, 12), Environment::of(&level.scene)).expect("engine");
    engine.spawn_level(&level);
    let mut game = Recorder::default();
    // Two steps per frame (1/30 s frames at 60 Hz).
    for _ in 0..150 {
        engine.frame(1.0 / 30.0, &mut game).expect("frame");
        let _ = engine.rendered();
        if engine.logic().outcome().is_some() {
            break;
        }
    }
    // Order: each frame hook is followed by that frame's steps; events follow their step.
    assert_eq!(game.calls[0], "frame");
    assert_eq!(game.calls[1], "step 0");
    assert_eq!(game.calls[2], "step 1");
    assert_eq!(game.calls[3], "frame");
    let mut last_step = None;
    for call in &game.calls {
        if let Some(n) = call.strip_prefix("step ") {
            let n: u64 = n.parse().expect("step index");
            assert_eq!(Some(n), last_step.map_or(Some(0), |l: u64| Some(l + 1)));
            last_step = Some(n);
        } else if let Some(n) = call.strip_prefix("event ") {
            assert_eq!(
                n.parse::<u64>().ok(),
                last_step,
                "an event after its own step"
            );
        }
    }
    // The crate lands on the plate: a volume event, the rule, the door's clip event, the win.
    let has = |f: &dyn Fn(&LevelEvent) -> bool| game.events.iter().any(f);
    assert!(has(
        &|e| matches!(e, LevelEvent::Volume { name, .. } if name == "plate")
    ));
    assert!(has(
        &|e| matches!(e, LevelEvent::Rule { name, firing } if name == "plate_pressed" && firing.rising)
    ));
    assert!(has(
        &|e| matches!(e, LevelEvent::Clip(c) if c.name == "door_opened")
    ));
    let ended: Vec<_> = game
        .events
        .iter()
        .filter(|e| matches!(e, LevelEvent::Ended(_)))
        .collect();
    assert_eq!(
        ended,
        [&LevelEvent::Ended(Outcome::Won("door_opened".into()))],
        "the win is delivered once"
    );
    let _ = engine.shutdown();
}

#[test]
fn commands_switch_lights_and_send_events_to_the_rules() {
    let level;
    // A rule on an event only the game sends (declared in `events`): it loses the level.
    let text = std::fs::read_to_string(repo().join("assets/test_scenes/gameplay/plate_door.ron"))
        .expect("level text");
    let with_rule = text
        .replace(
            "(name: \"door_opened\", when: Event(\"door_opened\"), then: [Win], once: true),",
            "(name: \"door_opened\", when: Event(\"door_opened\"), then: [Win], once: true),\n            (name: \"used\", when: Event(\"switch_used\"), then: [Lose], once: true),",
        )
        .replace("        rules: [", "        events: [\"switch_used\"],\n        rules: [");
    assert_ne!(with_rule, text, "the rule was added");
    let dir = std::env::temp_dir().join(format!("candela_game_api_{}", std::process::id()));
    std::fs::create_dir_all(dir.join("common/sounds")).expect("temp dir");
    std::fs::copy(
        repo().join("assets/common/sounds/chime.wav"),
        dir.join("common/sounds/chime.wav"),
    )
    .expect("copy the chime");
    let path = dir.join("level.ron");
    std::fs::write(&path, with_rule).expect("write level");
    let loaded = load_level(&path, &AssetRoot::new(&dir).expect("root"));
    let _ = std::fs::remove_dir_all(&dir);
    level = loaded.expect("the edited level loads");
    assert!(
        level.gameplay.rules.iter().any(|r| r.name == "used"),
        "the edited level loaded"
    );
    let mut engine =
        Engine::new(RenderConfig::cpu(16, 12), Environment::of(&level.scene)).expect("engine");
    engine.spawn_level(&level);
    assert!(engine.light_group_on(1));
    let mut game = Recorder {
        send_at: Some((3, "switch_used")),
        lights_off_at: Some((2, 1)),
        ..Default::default()
    };
    for _ in 0..6 {
        engine.frame(1.0 / 60.0, &mut game).expect("frame");
        let _ = engine.rendered();
    }
    assert!(!engine.light_group_on(1), "the game switched group 1 off");
    assert_eq!(
        engine.logic().outcome(),
        Some(&Outcome::Lost("used".into())),
        "the sent event reached the rule"
    );
    // Sent from the step hook, the event reaches the rules in the same step (the level's
    // logic runs after the game's rules), and the game hears the rule fire in that step.
    let step_of_rule: Vec<&str> = game
        .calls
        .iter()
        .zip(&game.events_at)
        .filter(|(_, e)| matches!(e, Some(LevelEvent::Rule { name, .. }) if name == "used"))
        .map(|(c, _)| c.as_str())
        .collect();
    assert_eq!(step_of_rule, ["event 3"]);
    let _ = engine.shutdown();
}

#[test]
fn a_game_plays_a_sound_of_the_level_by_name() {
    let level = plate_door();
    let mut engine =
        Engine::new(RenderConfig::cpu(16, 12), Environment::of(&level.scene)).expect("engine");
    engine.spawn_level(&level);
    let mut game = |step: &mut Step<'_>| match step.index {
        1 => step.commands.play_sound("chime", 0.5),
        // Not a sound of the level: logged and skipped.
        2 => step.commands.play_sound("no_such_sound", 1.0),
        _ => {}
    };
    let mut playing = Vec::new();
    for _ in 0..3 {
        engine.frame(1.0 / 60.0, &mut game).expect("frame");
        let _ = engine.rendered();
        playing.push(engine.audio().playing_count());
    }
    assert_eq!(playing, [0, 1, 1], "sounds playing after each step");
    let _ = engine.shutdown();
}

/// A flat grid of `n`×`n` quads, 4 m across, in the XZ plane.
fn grid(n: usize) -> Model {
    let mut positions = Vec::new();
    for z in 0..=n {
        for x in 0..=n {
            positions.push(Vec3::new(
                x as f32 * 4.0 / n as f32 - 2.0,
                0.0,
                z as f32 * 4.0 / n as f32 - 2.0,
            ));
        }
    }
    let mut triangles = Vec::new();
    let row = n as u32 + 1;
    for z in 0..n as u32 {
        for x in 0..n as u32 {
            let i = z * row + x;
            triangles.push([i, i + row, i + 1]);
            triangles.push([i + 1, i + row, i + row + 1]);
        }
    }
    let mesh = Mesh {
        triangle_materials: vec![0; triangles.len()],
        positions,
        triangles,
        ..Default::default()
    };
    Model {
        meshes: vec![mesh],
        materials: vec![Material::default()],
        placements: vec![Placement {
            mesh: 0,
            model_from_mesh: Mat4::IDENTITY,
        }],
        ..Default::default()
    }
}

#[test]
fn level_waves_move_in_the_engine_frame() {
    let camera = CameraDesc {
        position: [0.0, 3.0, 5.0],
        look_at: [0.0, 0.0, 0.0],
        up: [0.0, 1.0, 0.0],
        vertical_fov_deg: 50.0,
        aperture_radius: 0.0,
        focus_distance: None,
    };
    let mut scene = SceneDesc::single(grid(8), camera);
    scene.instances = vec![SceneInstance {
        dynamic: true,
        waves: Some(WaveDesc {
            amplitude: 0.2,
            wavelength: 2.0,
            speed: 1.0,
            simulate: None,
        }),
        ..SceneInstance::placed(0, Mat4::IDENTITY)
    }];
    let level = PlayableLevel::of_scene(scene);
    let mut engine =
        Engine::new(RenderConfig::cpu(8, 8), Environment::of(&level.scene)).expect("engine");
    engine.spawn_level(&level);
    let heights = |engine: &Engine| -> Vec<f32> {
        engine
            .scene()
            .vertices
            .iter()
            .map(|v| v.position[1])
            .collect()
    };
    let mut frames = Vec::new();
    for _ in 0..3 {
        engine
            .frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})
            .expect("frame");
        frames.push(heights(&engine));
    }
    assert!(frames.iter().flatten().all(|h| h.is_finite()));
    assert!(
        frames[0].iter().any(|h| h.abs() > 1e-3),
        "the waves raised the grid in the first frame"
    );
    assert_ne!(frames[1], frames[2], "the waves move from frame to frame");
    let _ = engine.shutdown();
}
