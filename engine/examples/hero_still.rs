//! Renders a still of the hero (`assets/common/hero/hero.glb`, made by `assetgen hero`) on
//! the CPU tracer to `docs/hero.png`: the hero mid-stride (clip `walk`, a quarter into its
//! cycle, skinned through the engine's animation code) on a small floor, seen from the front
//! left, sun and sky light. Shows what `docs/LEVELS.md` "The hero" describes.
//!
//! `cargo run --release -p candela --example hero_still [-- --spp N --out FILE --clip NAME --at F]`
//! (defaults: 256 samples per pixel, `docs/hero.png`, clip `walk` at 0.25 of its cycle; about
//! 15 s on two cores). The explorer's action stills (`docs/hero_push.png`, `hero_pick_up.png`,
//! `hero_celebrate.png`) are `--clip push --at 0.25`, `--clip pick_up --at 0.5` and
//! `--clip celebrate --at 0.4`, each with `--spp 128`.
//! Deterministic for a given sample count (fixed seed). Main thread only.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use anyhow::Context;
use candela::assets::{AssetRoot, load_scene};
use candela::render::cpu::CpuTracer;
use candela::render::film::{TonemapSettings, write_png};
use candela::render::{FrameSettings, Tracer, frame_uniforms};
use candela::scene::RenderScene;
use candela::sim::animation::{SkinnedAnimator, deform_mesh, load_animation};

const MODEL: &str = "common/hero/hero.glb";
const WIDTH: u32 = 360;
const HEIGHT: u32 = 420;

/// The still's level: a floor and the hero at the origin (metres; the hero faces +Z).
const LEVEL: &str = r#"Level(
    models: [(name: "hero", path: "common/hero/hero.glb")],
    materials: [(name: "floor", kind: Diffuse, base_color: (0.45, 0.45, 0.42))],
    boxes: [(name: "floor", size: (8, 0.2, 8), material: "floor")],
    instances: [
        (model: "floor", transform: (translation: (0, -0.1, 0))),
        (model: "hero", name: "hero"),
    ],
    camera: (position: (1.3, 1.35, 3.1), look_at: (0, 0.9, 0), vertical_fov_deg: 40),
    sun: (direction: (0.5, 1, 0.7), irradiance: (3, 2.9, 2.7)),
    sky: Gradient(zenith: (0.15, 0.25, 0.5), horizon: (0.6, 0.6, 0.6), ground: (0.1, 0.1, 0.1)),
    render: (max_bounces: 3, roulette_start: 2),
)"#;

fn main() -> anyhow::Result<()> {
    let repo = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut spp = 256u32;
    let mut out = repo.join("docs/hero.png");
    let mut clip = String::from("walk");
    let mut at = 0.25f64;
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        match (arg.as_str(), args.next()) {
            ("--spp", Some(n)) => spp = n.parse().context("--spp takes a number")?,
            ("--out", Some(path)) => out = PathBuf::from(path),
            ("--clip", Some(name)) => clip = name,
            ("--at", Some(f)) => at = f.parse().context("--at takes a fraction of the clip")?,
            _ => anyhow::bail!("usage: hero_still [--spp N] [--out FILE] [--clip NAME] [--at F]"),
        }
    }
    let dir = std::env::temp_dir().join(format!("candela_hero_still_{}", std::process::id()));
    std::fs::create_dir_all(&dir)?;
    let level = dir.join("hero_still.ron");
    std::fs::write(&level, LEVEL)?;
    let root = AssetRoot::new(repo.join("assets"))?;
    let loaded = load_scene(&level, &root);
    let animated = load_animation(&root, &level, MODEL);
    let _ = std::fs::remove_dir_all(&dir);
    let mut desc = loaded?;
    let animated = Arc::new(animated?);

    // Pose the hero: skin its mesh `at` into `clip` and draw that instead of the rest pose.
    let hero = desc
        .instances
        .iter()
        .find(|i| i.name.as_deref() == Some("hero"))
        .map(|i| i.model)
        .context("no hero instance")?;
    let model = &mut desc.models[hero];
    let (animator, _) =
        SkinnedAnimator::single(animated.clone(), model).context("the hero is not a character")?;
    let index = animated.find_clip(&clip)?;
    let pose = animated.pose_at(index, at * animated.clips[index].duration_seconds);
    let world = animated.world_matrices(&pose);
    let deformed = deform_mesh(
        &animated,
        &pose,
        &world,
        animator.node,
        animator.model_from_mesh,
    )
    .context("no mesh to pose")?;
    let mesh = &mut model.meshes[model.placements[0].mesh];
    anyhow::ensure!(deformed.positions.len() == mesh.positions.len());
    mesh.positions = deformed.positions;
    if deformed.normals.is_some() {
        mesh.normals = deformed.normals;
    }

    let scene = RenderScene::build(&desc);
    let mut tracer = CpuTracer::new();
    let batch = 8;
    let mut done = 0;
    while done < spp {
        let n = batch.min(spp - done);
        let settings = FrameSettings::new(WIDTH, HEIGHT, n, 7, &desc.render).continuing(done);
        let uniforms = frame_uniforms(
            &desc.camera,
            desc.sun.as_ref(),
            &desc.sky,
            &settings,
            &scene.header(),
        );
        tracer.render(&scene, &uniforms)?;
        done += n;
    }
    let film = tracer.film()?;
    write_png(
        &out,
        film.width,
        film.height,
        &film.mean,
        &TonemapSettings::default(),
    )?;
    println!("{}: {WIDTH}×{HEIGHT}, {spp} spp", out.display());
    Ok(())
}
