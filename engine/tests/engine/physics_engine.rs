//! Physics inside the engine's frame loop (headless, CPU tracer at 32×16): a level's crate
//! falls onto its floor through `Engine::frame`'s fixed steps, and once it sleeps the frames
//! carry no instance changes (sleeping bodies produce no commits).

use candela::app::{Engine, Environment, Step};
use candela::assets::AssetRoot;
use candela::ecs::Transform;
use candela::level::load_level;
use candela::render::RenderConfig;

const LEVEL: &str = r#"Level(
    materials: [(name: "grey", kind: Diffuse)],
    grids: [(name: "floor", size: (10, 10), divisions: (1, 1), material: "grey")],
    boxes: [(name: "crate", size: (0.6, 0.6, 0.6), material: "grey")],
    instances: [
        (model: "floor", body: Static(shape: Trimesh)),
        (model: "crate", name: "crate", transform: (translation: (0, 3, 0), rotation_deg: (20, 30, 10)), body: Dynamic(shape: Box, mass: 20)),
    ],
    camera: (position: (0, 2, 6), look_at: (0, 0, 0), vertical_fov_deg: 45),
)"#;

#[test]
fn crate_falls_in_the_frame_loop_and_sleeping_costs_no_commits() -> anyhow::Result<()> {
    let dir = std::env::temp_dir().join(format!("candela_phys_engine_{}", std::process::id()));
    std::fs::create_dir_all(&dir)?;
    let path = dir.join("drop.ron");
    std::fs::write(&path, LEVEL)?;
    let scene = load_level(&path, &AssetRoot::new(&dir)?)?;
    let config = RenderConfig {
        seed: 3,
        ..RenderConfig::cpu(32, 16)
    };
    let mut engine = Engine::new(config, Environment::of(&scene.scene))?;
    let spawned = engine.spawn_level(&scene);
    let crate_entity = spawned.by_name["crate"];

    let mut moving_bytes = Vec::new();
    let mut frames = 0;
    // Frames of 1/60 s: one fixed step each. At most 10 s for the crate to land and sleep.
    while frames < 600 {
        let report = engine.frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})?;
        frames += 1;
        moving_bytes.push(report.commit_bytes);
        if frames > 5 && engine.physics().awake_bodies() == 0 {
            break;
        }
    }
    assert_eq!(
        engine.physics().awake_bodies(),
        0,
        "the crate never fell asleep"
    );
    let y = engine
        .world()
        .get::<&Transform>(crate_entity)?
        .translation
        .y;
    // A 0.6 m crate resting on a face: centre 0.3 m up (1 cm for contact softness).
    assert!((y - 0.3).abs() < 0.01, "crate rests at y = {y}");

    // The frame that saw the last move may still carry it; after that, nothing.
    engine.frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})?;
    let mut idle_bytes = Vec::new();
    for _ in 0..10 {
        let report = engine.frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})?;
        assert_eq!(engine.physics().last_step().transform_writes, 0);
        idle_bytes.push(report.commit_bytes);
    }
    let falling = moving_bytes[10];
    println!("commit bytes: falling {falling}, asleep {idle_bytes:?}, {frames} frames to sleep");
    // A static scene's commit carries no buffer writes at all.
    assert!(falling > 0, "a falling crate should cost commit bytes");
    assert!(
        idle_bytes.iter().all(|&b| b == 0),
        "a sleeping crate still costs commit bytes: {idle_bytes:?}"
    );
    drop(engine.shutdown());
    let _ = std::fs::remove_dir_all(&dir);
    Ok(())
}
