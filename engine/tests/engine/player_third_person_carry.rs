//! The third-person player's hands (`player::Hands` in `app::ThirdPersonGame`), headless on the
//! CPU tracer, in the courtyard (`assets/test_scenes/platform/third_person.ron`) with a 5 kg
//! crate or a 60 kg block 1.1 m in front of the hero (spawned at z = 6, facing −Z):
//! - E lifts the crate to the chest; it goes where the hero walks; E puts it down in front of
//!   the feet; the prompt says what E does at each stage; the hero plays its `pick_up` clip
//!   (on its upper body only once it walks: its legs walk), and while it carries, the push
//!   clip's upper body over its walk;
//! - the left mouse button throws it ahead;
//! - the block is too heavy to lift: E does nothing, and walking into it pushes it, with the
//!   `push` clip playing while the hero leans into it;
//! - a lever in front wins over the crate: E pulls the lever and lifts nothing;
//! - E with nothing in front spawns no hands entity (the world, and so every replay's state
//!   hash, stays as it was).

use std::path::{Path, PathBuf};

use candela::app::{Engine, Game, Happened, KeyCode, MouseButton, ThirdPersonGame};
use candela::assets::AssetRoot;
use candela::level::load_level;
use candela::render::RenderConfig;
use candela::sim::animation::{CharacterAnimation, load_animation_file};
use glam::Vec3;

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

const COURTYARD: &str = "assets/test_scenes/platform/third_person.ron";

/// The courtyard with `boxes` (extra `boxes:` entries), `instances` (extra instances) and
/// `gameplay` (a `gameplay:` field, or nothing), written to `dir/name.ron`.
fn level(
    dir: &Path,
    name: &str,
    boxes: &str,
    instances: &str,
    gameplay: &str,
) -> anyhow::Result<PathBuf> {
    let source = std::fs::read_to_string(repo().join(COURTYARD))?;
    let lintel = "(name: \"lintel\", size: (1.6, 1.8, 0.4), material: \"wall\"),";
    let last = "            body: Static(shape: Box)),\n    ],";
    anyhow::ensure!(
        source.contains(lintel) && source.contains(last),
        "the courtyard changed"
    );
    let source = source
        .replace(lintel, &format!("{lintel}\n        {boxes}"))
        .replace(
            last,
            &format!("            body: Static(shape: Box)),\n        {instances}\n    ],"),
        )
        .replace("    camera:", &format!("    {gameplay}\n    camera:"));
    let path = dir.join(format!("{name}.ron"));
    std::fs::write(&path, source)?;
    Ok(path)
}

const CRATE_BOX: &str = "(name: \"crate\", size: (0.4, 0.4, 0.4), material: \"wall\"),";
const CRATE: &str = "(model: \"crate\", name: \"crate\", transform: (translation: (0, 0.2, 4.9)), \
                     dynamic: true, body: Dynamic(shape: Box, mass: 5)),";
const BLOCK_BOX: &str = "(name: \"block\", size: (1, 1, 1), material: \"wall\"),";
const BLOCK: &str = "(model: \"block\", name: \"block\", transform: (translation: (0, 0.5, 4.4)), \
                     dynamic: true, body: Dynamic(shape: Box, mass: 60)),";

/// One step's input.
#[derive(Clone, Copy, Default)]
struct Keys {
    e: bool,
    w: bool,
    click: bool,
}

/// What a run saw at each step: the prompt before the step, the named body's position after
/// it, the hero's centre, whether it carried, pushed, and which action clip played.
struct Seen {
    prompt: Option<String>,
    body: Vec3,
    hero: Vec3,
    carrying: bool,
    pushing: bool,
    action: Option<usize>,
    /// The clip on the upper body, and the locomotion state.
    upper: Option<usize>,
    state: Option<String>,
}

/// Plays `level` for `steps` fixed steps with `keys(step)`; `body` names the instance whose
/// position is recorded. Returns what each step saw, the game's log and whether the hands
/// entity exists at the end.
fn play(
    level: &Path,
    body: &str,
    steps: u64,
    keys: impl Fn(u64) -> Keys,
) -> anyhow::Result<(Vec<Seen>, Vec<(u64, Happened)>, bool)> {
    let root = AssetRoot::new(repo().join("assets"))?;
    let mut game = ThirdPersonGame::of_level(level, load_level(level, &root)?);
    let mut engine = Engine::new(RenderConfig::cpu(8, 8), game.environment())?;
    game.setup(&mut engine)
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    let entity = *game
        .spawned()
        .by_name
        .get(body)
        .ok_or_else(|| anyhow::anyhow!("no instance {body:?}"))?;
    let mut seen = Vec::new();
    for step in 0..steps {
        let k = keys(step);
        engine.input_mut().key(KeyCode::KeyE, k.e);
        engine.input_mut().key(KeyCode::KeyW, k.w);
        engine.input_mut().mouse_button(MouseButton::Left, k.click);
        let prompt = game.prompt();
        engine.frame(1.0 / 60.0, &mut game)?;
        let _ = engine.rendered();
        let player = game.player().ok_or_else(|| anyhow::anyhow!("no player"))?;
        let world = engine.world();
        let body = engine
            .physics()
            .pose(entity)
            .map(|(p, _)| p)
            .ok_or_else(|| anyhow::anyhow!("{body:?} has no body"))?;
        let anim = world.get::<&CharacterAnimation>(player.body).ok();
        let action = anim
            .as_ref()
            .and_then(|a| a.action.playing().map(|r| r.clip));
        let upper = anim.as_ref().and_then(|a| a.upper.playing());
        let state = anim.as_ref().and_then(|a| a.state_name().map(String::from));
        drop(anim);
        seen.push(Seen {
            prompt,
            body,
            hero: player.centre(world, Some(engine.physics())),
            carrying: player.held(world) == Some(entity),
            pushing: player.pushing(),
            action,
            upper,
            state,
        });
    }
    let hands = game
        .player()
        .and_then(|p| p.hands.entity())
        .is_some_and(|e| engine.world().contains(e));
    let log = game.log().to_vec();
    let _ = engine.shutdown();
    Ok((seen, log, hands))
}

fn clip(name: &str) -> anyhow::Result<usize> {
    let hero = load_animation_file(&repo().join("assets/common/hero/hero.glb"))?;
    Ok(hero.find_clip(name)?)
}

fn temp_dir(name: &str) -> anyhow::Result<PathBuf> {
    let dir = std::env::temp_dir().join(format!("candela_tp_{name}_{}", std::process::id()));
    std::fs::create_dir_all(&dir)?;
    Ok(dir)
}

#[test]
fn e_lifts_the_crate_carries_it_and_puts_it_down() -> anyhow::Result<()> {
    let dir = temp_dir("carry")?;
    let path = level(&dir, "crate", CRATE_BOX, CRATE, "")?;
    // E at step 30; walk ahead over steps 60–119; E again at step 150; watch until 240.
    let (seen, _, hands) = play(&path, "crate", 240, |s| Keys {
        e: s == 30 || s == 150,
        w: (60..120).contains(&s),
        click: false,
    })?;
    let start = &seen[29];
    assert_eq!(
        start.prompt.as_deref(),
        Some("E  pick up"),
        "facing the crate"
    );
    assert!(
        !start.carrying && (start.body.y - 0.2).abs() < 0.02,
        "{}",
        start.body
    );
    // Lifted to the chest, in front of the hero.
    let held = &seen[58];
    assert!(held.carrying, "E lifted the crate");
    assert_eq!(
        held.prompt.as_deref(),
        Some("E  put down · left mouse  throw")
    );
    let ahead = held.hero - held.body;
    assert!(
        held.body.y > held.hero.y && (ahead.z - 0.8).abs() < 0.15 && ahead.x.abs() < 0.1,
        "held at {} with the hero at {}",
        held.body,
        held.hero
    );
    assert_eq!(seen[31].action, Some(clip("pick_up")?), "it reached for it");
    // Carried along: the hero walked about 2 m along −Z and the crate stayed in its hands.
    let walked = &seen[125];
    assert!(walked.carrying, "still carried after the walk");
    // The one-shot pick_up (1.4 s from step 31) holds the whole body while the hero stands;
    // once it walks (step 60), its legs walk and its arms finish the lift,
    let pick_up = clip("pick_up")?;
    assert!(
        seen[75..110]
            .iter()
            .all(|s| s.state.as_deref() == Some("walk") && s.action.is_none()),
        "the legs walk: {:?} {:?}",
        seen[75].state,
        seen[75].action
    );
    assert!(
        seen[75..110].iter().all(|s| s.upper == Some(pick_up)),
        "the arms finish the lift while the legs walk"
    );
    // then the arms hold the push clip's upper body while it carries.
    let push = clip("push")?;
    assert!(
        seen[135..150].iter().all(|s| s.upper == Some(push)),
        "the upper body carries after the lift"
    );
    assert!(
        held.hero.z - walked.hero.z > 1.5,
        "{} → {}",
        held.hero,
        walked.hero
    );
    assert!(
        (walked.hero.z - walked.body.z - 0.8).abs() < 0.2,
        "carried at {} with the hero at {}",
        walked.body,
        walked.hero
    );
    // Put down: on the ground in front of the feet, no longer carried.
    let end = seen.last().ok_or_else(|| anyhow::anyhow!("no steps"))?;
    assert!(!end.carrying, "E put it down");
    assert!((end.body.y - 0.2).abs() < 0.03, "resting at {}", end.body);
    let front = end.hero.z - end.body.z;
    assert!(
        (0.4..1.3).contains(&front) && end.body.x.abs() < 0.3,
        "put down at {} with the hero at {}",
        end.body,
        end.hero
    );
    assert_eq!(
        end.prompt.as_deref(),
        Some("E  pick up"),
        "and can take it again"
    );
    assert!(hands);
    let _ = std::fs::remove_dir_all(&dir);
    Ok(())
}

#[test]
fn the_left_button_throws_the_carried_crate_ahead() -> anyhow::Result<()> {
    let dir = temp_dir("throw")?;
    let path = level(&dir, "crate", CRATE_BOX, CRATE, "")?;
    let (seen, _, _) = play(&path, "crate", 150, |s| Keys {
        e: s == 30,
        click: s == 70,
        ..Keys::default()
    })?;
    assert!(seen[65].carrying, "lifted first");
    let end = seen.last().ok_or_else(|| anyhow::anyhow!("no steps"))?;
    assert!(!end.carrying, "thrown");
    // Held 0.8 m ahead, thrown at 4 m/s from 1.2 m up: it lands about 2.5 m ahead.
    let flew = end.hero.z - end.body.z;
    assert!(flew > 1.8, "landed {flew} m ahead, at {}", end.body);
    let _ = std::fs::remove_dir_all(&dir);
    Ok(())
}

#[test]
fn a_heavy_block_is_pushed_with_the_push_clip_not_lifted() -> anyhow::Result<()> {
    let dir = temp_dir("push")?;
    let path = level(&dir, "block", BLOCK_BOX, BLOCK, "")?;
    let push = clip("push")?;
    // E at step 30 (too heavy: nothing), then walk into it over steps 60–179.
    let (seen, _, hands) = play(&path, "block", 200, |s| Keys {
        e: s == 30,
        w: (60..180).contains(&s),
        click: false,
    })?;
    assert_eq!(
        seen[30].prompt, None,
        "no prompt for a block too heavy to lift"
    );
    assert!(!seen[59].carrying && !hands, "the block was not lifted");
    let pushing: Vec<&Seen> = seen[60..180].iter().filter(|s| s.pushing).collect();
    assert!(
        pushing.len() > 40,
        "leaned into it for {} steps",
        pushing.len()
    );
    assert!(
        pushing.iter().all(|s| s.action == Some(push)),
        "the push clip plays while it pushes"
    );
    let (before, after) = (seen[59].body, seen[185].body);
    assert!(
        before.z - after.z > 0.5,
        "the block moved from {before} to {after}"
    );
    assert!(!seen[199].pushing && seen[199].action.is_none());
    let _ = std::fs::remove_dir_all(&dir);
    Ok(())
}

#[test]
fn a_usable_wins_over_a_body_and_nothing_in_front_spawns_no_hands() -> anyhow::Result<()> {
    let dir = temp_dir("lever")?;
    let lever = "(model: \"lever\", name: \"lever\", transform: (translation: (0.5, 0.5, 4.8)), \
                 body: Static(shape: Box)),";
    let gameplay = "gameplay: (events: [\"lever\"], usables: [(instance: \"lever\", prompt: \
                    \"E  pull the lever\", event: \"lever\")], rules: [(name: \"pulled\", \
                    when: Event(\"lever\"), then: [Win], once: true)]),";
    let path = level(
        &dir,
        "lever",
        &format!(
            "{CRATE_BOX}\n        (name: \"lever\", size: (0.2, 1.0, 0.2), material: \"wall\"),"
        ),
        &format!("{CRATE}\n        {lever}"),
        gameplay,
    )?;
    let (seen, log, hands) = play(&path, "crate", 60, |s| Keys {
        e: s == 30,
        ..Keys::default()
    })?;
    assert_eq!(seen[30].prompt.as_deref(), Some("E  pull the lever"));
    assert!(
        log.iter()
            .any(|(_, h)| *h == Happened::Used("lever".into()))
    );
    assert!(
        !seen[59].carrying && !hands,
        "the crate stayed where it was"
    );
    // The bare courtyard: E with nothing in front.
    let bare = level(&dir, "bare", "", "", "")?;
    let root = AssetRoot::new(repo().join("assets"))?;
    let mut game = ThirdPersonGame::of_level(&bare, load_level(&bare, &root)?);
    let mut engine = Engine::new(RenderConfig::cpu(8, 8), game.environment())?;
    game.setup(&mut engine)
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    let entities = engine.world().len();
    for step in 0..40 {
        engine.input_mut().key(KeyCode::KeyE, step == 20);
        engine.frame(1.0 / 60.0, &mut game)?;
        let _ = engine.rendered();
    }
    assert_eq!(
        engine.world().len(),
        entities,
        "E at nothing spawned nothing"
    );
    let _ = engine.shutdown();
    let _ = std::fs::remove_dir_all(&dir);
    Ok(())
}
