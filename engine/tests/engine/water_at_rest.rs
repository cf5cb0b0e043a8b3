//! A simulated water that starts at rest (`waves.simulate.start_at_rest`, issue 36): a pool
//! with no swell and a kinematic float standing in it, as It's About Time's pool and reed
//! float. At rest from the start, the pool's mesh is written once and then never changes: no
//! refit, no geometry in any later commit, every height exactly 0. Without `start_at_rest` the
//! same float's push rings the pool for seconds (refitted and committed every frame), the
//! ripples this setting settles at load.

use std::path::PathBuf;

use candela::app::{Engine, Environment, Step};
use candela::assets::AssetRoot;
use candela::level::load_level;
use candela::render::RenderConfig;
use candela::sim::water::WaterSim;

struct Dir(PathBuf);

impl Dir {
    fn new(name: &str) -> Self {
        let path = std::env::temp_dir().join(format!("candela_rest_{name}_{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&path);
        std::fs::create_dir_all(&path).expect("temp dir");
        Dir(path)
    }
}

impl Drop for Dir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// A 12 m pool (64 × 64 quads, no swell), a floor 0.6 m under it and a 2.2 m float whose
/// bottom is 0.1 m under the surface.
fn level(start_at_rest: bool) -> String {
    format!(
        r#"Level(
    materials: [(name: "water", kind: Dielectric), (name: "reed", kind: Diffuse)],
    grids: [(name: "pool", size: (12, 12), divisions: (64, 64), material: "water"),
            (name: "floor", size: (12, 12), divisions: (1, 1), material: "reed")],
    boxes: [(name: "float", size: (2.2, 0.28, 2.2), material: "reed")],
    instances: [
        (model: "pool", name: "pool", dynamic: true, waves: Some((amplitude: 0, wavelength: 2.5,
         speed: 0.4, simulate: Some((wave_speed: 1.2, damping: 0.5, push: 0.12,
         start_at_rest: {start_at_rest}))))),
        (model: "floor", transform: (translation: (0, -0.6, 0)), body: Static(shape: Trimesh)),
        (model: "float", name: "float", transform: (translation: (1, 0.04, -0.5)),
         dynamic: true, body: Kinematic(shape: Box)),
    ],
    camera: (position: (0, 6, 9), look_at: (0, 0, 0), vertical_fov_deg: 45),
)"#
    )
}

/// Per frame from the second on: the upkeep's BLAS refits and the commit's geometry bytes;
/// and the largest height of the water at the end, metres.
struct Run {
    refits: Vec<u32>,
    geometry_bytes: Vec<usize>,
    pool_vertices_changed: usize,
    worst_height: f32,
}

fn run(start_at_rest: bool, frames: usize) -> anyhow::Result<Run> {
    let dir = Dir::new(if start_at_rest { "rest" } else { "drop" });
    let path = dir.0.join("pool.ron");
    std::fs::write(&path, level(start_at_rest))?;
    let level = load_level(&path, &AssetRoot::new(&dir.0)?)?;
    let mut engine = Engine::new(RenderConfig::cpu(16, 9), Environment::of(&level.scene))?;
    engine.settle_every_step(true);
    let spawned = engine.spawn_level(&level);
    let pool = spawned.by_name["pool"];
    let mut out = Run {
        refits: Vec::new(),
        geometry_bytes: Vec::new(),
        pool_vertices_changed: 0,
        worst_height: 0.0,
    };
    let mut after_first = Vec::new();
    for frame in 0..frames {
        let report = engine.frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})?;
        let _ = engine.rendered();
        let vertices: Vec<[u32; 3]> = (engine.scene().vertices.iter())
            .map(|v| v.position.map(f32::to_bits))
            .collect();
        if frame == 0 {
            after_first = vertices;
        } else {
            out.refits
                .push(report.upkeep.blas_refits + report.upkeep.blas_rebuilds);
            out.geometry_bytes.push(report.upkeep.geometry_bytes);
            out.pool_vertices_changed += (vertices.iter().zip(&after_first))
                .filter(|(a, b)| a != b)
                .count();
        }
    }
    let sim = engine.world().get::<&WaterSim>(pool)?;
    out.worst_height = (sim.field.heights().iter()).fold(0.0f32, |m, h| m.max(h.abs()));
    drop(sim);
    drop(engine.shutdown());
    Ok(out)
}

#[test]
fn a_pool_at_rest_from_the_start_is_written_once_and_never_refitted() -> anyhow::Result<()> {
    // Two seconds: the float's entry ring would still be refitted every frame.
    let rest = run(true, 120)?;
    assert!(
        rest.refits.iter().all(|&r| r == 0),
        "refits after the first frame: {:?}",
        rest.refits
    );
    assert!(
        rest.geometry_bytes.iter().all(|&b| b == 0),
        "geometry committed after the first frame: {:?}",
        rest.geometry_bytes
    );
    assert_eq!(rest.pool_vertices_changed, 0, "the scene's vertices moved");
    assert_eq!(rest.worst_height, 0.0, "the water moved");

    // The same float dropped into a pool that starts flat: the ripples this setting removes.
    let dropped = run(false, 120)?;
    let refitted = dropped.refits.iter().filter(|&&r| r > 0).count();
    println!(
        "without start_at_rest: {refitted} of {} frames refitted, {} m ripples after 2 s",
        dropped.refits.len(),
        dropped.worst_height
    );
    assert!(refitted > 100, "only {refitted} frames refitted");
    assert!(dropped.worst_height > 1e-4, "{} m", dropped.worst_height);
    Ok(())
}
