//! The engine's third-person game (`app::ThirdPersonGame`), headless on the CPU tracer:
//! - the courtyard's committed replay (`assets/test_scenes/platform/third_person.replay`)
//!   walks the level's character through the doorway with the camera behind it;
//! - a lever the character walks up to is used with E: its event reaches the level's rules
//!   (the level wins), and the same lever out of reach or behind the character is not used.

use std::path::{Path, PathBuf};

use candela::app::{Engine, Game, Happened, KeyCode, Replay, StepInput, ThirdPersonGame};
use candela::assets::AssetRoot;
use candela::ecs::Transform;
use candela::level::load_level;
use candela::render::RenderConfig;

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn game_of(level: &Path) -> anyhow::Result<ThirdPersonGame> {
    let root = AssetRoot::new(repo().join("assets"))?;
    Ok(ThirdPersonGame::of_level(level, load_level(level, &root)?))
}

#[test]
fn the_courtyard_replay_walks_the_character_through_the_doorway() -> anyhow::Result<()> {
    let folder = repo().join("assets/test_scenes/platform");
    let mut game = game_of(&folder.join("third_person.ron"))?;
    game.set_replay_names("candela-third-person", "platform/third_person");
    let replay: Replay = game.open_replay(&folder.join("third_person.replay"))?;
    let steps = replay.steps();
    game.start_with(StepInput::Replay(replay));
    let mut engine = Engine::new(RenderConfig::cpu(8, 8), game.environment())?;
    game.setup(&mut engine)
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    let player = game
        .player()
        .cloned()
        .ok_or_else(|| anyhow::anyhow!("no player"))?;
    let start = player.centre(engine.world(), None);
    let mut frames = 0;
    while !engine.replay_finished() {
        engine.frame(1.0 / 60.0, &mut game)?;
        let _ = engine.rendered();
        frames += 1;
        anyhow::ensure!(frames <= steps + 2, "the replay ends");
    }
    let end = player.centre(engine.world(), None);
    let camera = engine
        .world()
        .get::<&Transform>(player.camera)
        .map(|t| t.translation)?;
    let _ = engine.shutdown();
    // From z = 6 through the doorway in the wall at z = 0, as the test of the parts does
    // (`player_third_person.rs`), kept to the doorway's middle.
    assert!((start.z - 6.0).abs() < 0.1, "{start}");
    assert!(end.z < -8.0, "ended at {end}");
    assert!(end.x.abs() < 0.3, "strayed to {end}");
    // The camera is behind the character (larger z: it walked along −Z) and above it, at
    // about the follow distance.
    let behind = camera - end;
    assert!(
        behind.z > 2.0 && behind.y > 0.5,
        "camera at {camera}, hero at {end}"
    );
    assert!(behind.length() < 5.5, "camera {} m away", behind.length());
    Ok(())
}

/// The courtyard with a lever 1.2 m in front of the character's spawn (or at `lever_z`), a
/// rule that wins when it is used.
fn lever_level(dir: &Path, lever_z: f32) -> anyhow::Result<PathBuf> {
    let source =
        std::fs::read_to_string(repo().join("assets/test_scenes/platform/third_person.ron"))?;
    let source = source
        .replace(
            "(name: \"lintel\", size: (1.6, 1.8, 0.4), material: \"wall\"),",
            "(name: \"lintel\", size: (1.6, 1.8, 0.4), material: \"wall\"),\n        \
             (name: \"lever\", size: (0.2, 1.0, 0.2), material: \"wall\"),",
        )
        .replace(
            "    camera:",
            &format!(
                "    gameplay: (events: [\"lever\"], usables: [(instance: \"lever\", prompt: \
                 \"E  pull the lever\", event: \"lever\")], rules: [(name: \"pulled\", when: \
                 Event(\"lever\"), then: [Win], once: true)]),\n    camera:"
            ),
        )
        .replace(
            "            body: Static(shape: Box)),\n    ],",
            &format!(
                "            body: Static(shape: Box)),\n        (model: \"lever\", name: \"lever\", \
                 transform: (translation: (0, 0.5, {lever_z})), body: Static(shape: Box)),\n    ],"
            ),
        );
    anyhow::ensure!(
        source.contains("name: \"lever\", transform"),
        "the lever was placed"
    );
    let path = dir.join("lever.ron");
    std::fs::write(&path, source)?;
    Ok(path)
}

/// Plays `level` pressing E at step 30 (standing still, facing −Z); returns the log.
fn press_use(level: &Path) -> anyhow::Result<(Vec<(u64, Happened)>, Option<String>)> {
    let mut game = game_of(level)?;
    let mut engine = Engine::new(RenderConfig::cpu(8, 8), game.environment())?;
    game.setup(&mut engine)
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    let mut prompt = None;
    for step in 0..60 {
        // E (the standard `use`) held for one step: pressed in that step.
        engine.input_mut().key(KeyCode::KeyE, step == 30);
        if step == 30 {
            prompt = game.prompt();
        }
        engine.frame(1.0 / 60.0, &mut game)?;
        let _ = engine.rendered();
    }
    let _ = engine.shutdown();
    Ok((game.log().to_vec(), prompt))
}

#[test]
fn e_uses_the_lever_the_character_stands_at_and_nothing_out_of_reach() -> anyhow::Result<()> {
    let dir = std::env::temp_dir().join(format!("candela_tp_lever_{}", std::process::id()));
    std::fs::create_dir_all(&dir)?;
    let used = |z: f32| -> anyhow::Result<(bool, Option<String>)> {
        let (log, prompt) = press_use(&lever_level(&dir, z)?)?;
        let pulled = log
            .iter()
            .any(|(_, h)| *h == Happened::Used("lever".into()))
            && log
                .iter()
                .any(|(_, h)| matches!(h, Happened::Ended(o) if o.starts_with("Won")));
        Ok((pulled, prompt))
    };
    // The hero spawns at z = 6 facing −Z (the camera looks that way).
    let (near, prompt) = used(4.8)?;
    assert!(near, "a lever 1.2 m ahead is used");
    assert_eq!(prompt.as_deref(), Some("E  pull the lever"));
    let (far, prompt) = used(3.0)?;
    assert!(
        !far && prompt.is_none(),
        "a lever 3 m ahead is out of reach"
    );
    let (behind, _) = used(7.2)?;
    assert!(
        !behind,
        "a lever 1.2 m behind, away from the camera's view, is not used"
    );
    let _ = std::fs::remove_dir_all(&dir);
    Ok(())
}
