//! `bench chamber-rays`: rays per second of the CPU path tracer on one view of a Reflect
//! chamber, at a fixed camera, as the game renders it (the game's own scene and frame uniforms:
//! 1 spp, its light sampling, roulette and bounce cap), at a fixed traced size.
//!
//! The chamber is started at its file's camera with nothing pressed and run through the real
//! frame loop for a few frames; the scene and uniforms of the last of them are kept, then the
//! engine's [`CpuTracer`] renders that frame `--frames` times (sample bases 0, 1, …) and every
//! render is timed. The printed film hash is a function of the traced paths only, so two
//! binaries whose traversal differs only in speed print the same hash: run two builds one after
//! the other, interleaved (`--rounds`, or a shell loop over two binaries), for an A/B. After
//! each render the denoiser's guide pass (`cpu::guides`) traces the same view, timed apart
//! (wall clock, outside the CPU seconds of the rays).
//!
//! Owns: [`run`]. Main thread; the render thread only while the chamber warms up, the rayon
//! pool (`--threads`) for the timed renders. Must not: change the game or the tracer.

use std::hash::{DefaultHasher, Hash, Hasher};
use std::sync::{Arc, Mutex};

use candela::app::{Engine, Game};
use candela::assets::Level;
use candela::layout::{
    GpuFrameUniforms, METHOD_INDIRECT_HALF, METHOD_INDIRECT_QUARTER, METHOD_LIGHT_TREE,
    METHOD_LIGHTS_BY_POWER,
};
use candela::render::cpu::CpuTracer;
use candela::render::cpu::guides::trace_guides;
use candela::render::{FilmView, OpenTracer, RenderConfig, RenderError, RenderStats, Tracer};
use candela::scene::RenderScene;
use clap::Parser;
use reflect::game::ReflectGame;
use reflect::world::ReflectWorld;

use super::machine::median;

#[derive(Parser, Debug)]
pub struct ChamberRaysArgs {
    /// Chamber number, from 1.
    #[arg(long, default_value_t = 1)]
    pub chamber: usize,
    /// Traced width in pixels.
    #[arg(long, default_value_t = 320)]
    pub width: u32,
    /// Traced height in pixels.
    #[arg(long, default_value_t = 180)]
    pub height: u32,
    /// Timed renders (one sample per pixel each) per round.
    #[arg(long, default_value_t = 30)]
    pub frames: u32,
    /// Rounds (one line each).
    #[arg(long, default_value_t = 3)]
    pub rounds: u32,
    /// Rayon threads for the timed renders (0: all cores).
    #[arg(long, default_value_t = 0)]
    pub threads: usize,
    /// Game frames run before the view is kept.
    #[arg(long, default_value_t = 4)]
    pub warm_frames: u32,
    /// Pick lights by the light tree instead of the game's own light sampling.
    #[arg(long)]
    pub light_tree: bool,
    /// Interleaved indirect light: 1 (every pixel, the default), 2 or 4 pixels per traced
    /// first bounce (`render/cpu/interleave.rs`).
    #[arg(long, default_value_t = 1)]
    pub indirect_every: u32,
}

/// The scene and uniforms of the latest frame rendered.
type Kept = Arc<Mutex<Option<(RenderScene, GpuFrameUniforms)>>>;

/// The engine's CPU tracer, keeping a copy of each frame it renders.
struct KeepingTracer {
    inner: CpuTracer,
    kept: Kept,
}

impl Tracer for KeepingTracer {
    fn name(&self) -> &'static str {
        self.inner.name()
    }
    fn device(&self) -> String {
        self.inner.device()
    }
    fn render(
        &mut self,
        scene: &RenderScene,
        u: &GpuFrameUniforms,
    ) -> Result<RenderStats, RenderError> {
        *self.kept.lock().expect("kept lock") = Some((scene.clone(), *u));
        self.inner.render(scene, u)
    }
    fn update(
        &mut self,
        scene: &RenderScene,
        writes: &[candela::scene::SceneWrite],
    ) -> Result<(), RenderError> {
        self.inner.update(scene, writes)
    }
    fn film(&mut self) -> Result<candela::render::film::Film, RenderError> {
        self.inner.film()
    }
    fn film_view(&self) -> Option<FilmView<'_>> {
        self.inner.film_view()
    }
    fn clear(&mut self) {
        self.inner.clear()
    }

    fn record_guides(&mut self, on: bool) {
        self.inner.record_guides(on)
    }

    fn take_guides(&mut self) -> Option<candela::render::denoise::Guides> {
        self.inner.take_guides()
    }
}

/// Runs chamber `args.chamber` (from 1) for `warm_frames` frames; the last frame's scene and
/// uniforms.
pub fn capture(args: &ChamberRaysArgs) -> anyhow::Result<(RenderScene, GpuFrameUniforms)> {
    let (path, root) = reflect::cli::locate(None)?;
    let world = ReflectWorld::load(&path, &root)?;
    let chamber = args.chamber.max(1) - 1;
    let file = world
        .files
        .get(chamber + 1)
        .ok_or_else(|| anyhow::anyhow!("no chamber {}", args.chamber))?;
    let camera = Level::read(file)?.camera;
    let mut game = ReflectGame::new(world.clone(), chamber);
    game.start_at_view(&candela::extract::RenderCamera::from_desc(&camera));
    let kept: Kept = Arc::new(Mutex::new(None));
    let k = kept.clone();
    let open: OpenTracer = Box::new(move |_, _| {
        Ok(Box::new(KeepingTracer {
            inner: CpuTracer::new(),
            kept: k,
        }) as Box<dyn Tracer>)
    });
    let render = RenderConfig::cpu(args.width, args.height);
    let mut engine = Engine::with_tracer(render, game.inner().environment(), open)?;
    game.setup(&mut engine)
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    for _ in 0..args.warm_frames.max(1) {
        engine.frame(1.0 / 30.0, &mut game)?;
    }
    for r in engine.shutdown() {
        r?;
    }
    let kept = kept.lock().expect("kept lock").take();
    kept.ok_or_else(|| anyhow::anyhow!("no frame was rendered"))
}

pub fn run(args: &ChamberRaysArgs) -> anyhow::Result<()> {
    let (scene, mut u) = capture(args)?;
    if args.light_tree {
        u.method = (u.method & !METHOD_LIGHTS_BY_POWER) | METHOD_LIGHT_TREE;
    }
    u.method |= match args.indirect_every {
        2 => METHOD_INDIRECT_HALF,
        4 => METHOD_INDIRECT_QUARTER,
        _ => 0,
    };
    let threads = if args.threads == 0 {
        rayon::current_num_threads()
    } else {
        args.threads
    };
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()?;
    println!(
        "chamber {} at its file's camera, {}×{}, {} spp per render, method {:#x}, max bounces {}, \
         roulette from {} (scale {}), {} threads",
        args.chamber,
        u.width,
        u.height,
        u.spp,
        u.method,
        u.max_bounces,
        u.roulette_start,
        u.roulette_scale,
        threads
    );
    let mib = |bytes: usize| bytes as f64 / (1u64 << 20) as f64;
    println!(
        "scene: {} instances, {} triangles, {} emissive in the light table, {:.1} MiB of nodes, \
         {:.1} MiB of triangle blocks, {:.1} MiB of texels",
        scene.instances.len(),
        scene.triangles.len(),
        scene.lights.lights.len(),
        mib(scene.nodes.len() * size_of::<candela::layout::GpuBvh8Node>()),
        mib(scene.blocks.len() * size_of::<candela::layout::GpuTri4>()),
        mib(scene.texels.len() * 8)
    );
    // The light tree's shape: a pick evaluates two nodes' importance per level it descends.
    let tree = &scene.lights.tree.nodes;
    let mut depth = vec![0u32; tree.len()];
    let (mut leaves, mut leaf_depths, mut deepest) = (0u64, 0u64, 0u32);
    for (i, node) in tree.iter().enumerate() {
        if let Some(&d) = depth.get(node.parent as usize) {
            depth[i] = d + 1;
        }
        if node.flags & candela::layout::LIGHT_NODE_LEAF != 0 {
            leaves += 1;
            leaf_depths += u64::from(depth[i]);
            deepest = deepest.max(depth[i]);
        }
    }
    println!(
        "light tree: {} nodes, leaf depth mean {:.1}, max {deepest}",
        tree.len(),
        leaf_depths as f64 / leaves.max(1) as f64
    );
    println!(
        "| round | renders | rays | camera | shadow | bounce | ms per render (median) | Mrays/s (wall) | Mrays per CPU second | film hash | guide pass ms (median) |\n|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|"
    );
    let mut tracer = CpuTracer::new();
    for round in 0..args.rounds {
        let (mut ms, mut rays, mut seconds) = (Vec::new(), [0u64; 3], 0.0);
        let mut guide_ms = Vec::new();
        let mut cpu_total = 0.0;
        let mut hasher = DefaultHasher::new();
        for f in 0..args.frames {
            let frame = GpuFrameUniforms {
                sample_base: f * u.spp.max(1),
                film_blend: 1.0,
                ..u
            };
            tracer.clear();
            let cpu = cpu_seconds();
            let stats = pool.install(|| tracer.render(&scene, &frame))?;
            cpu_total += cpu_seconds() - cpu;
            ms.push(stats.seconds * 1e3);
            seconds += stats.seconds;
            rays[0] += stats.counts.camera;
            rays[1] += stats.counts.shadow;
            rays[2] += stats.counts.bounce;
            for p in &tracer.film()?.mean {
                p.to_array().map(f32::to_bits).hash(&mut hasher);
            }
            // The denoiser's guide pass over the same view, as the game runs it beside the trace.
            let start = std::time::Instant::now();
            let guides = pool.install(|| trace_guides(&scene, &frame));
            guide_ms.push(start.elapsed().as_secs_f64() * 1e3);
            std::hint::black_box(&guides);
        }
        let total: u64 = rays.iter().sum();
        println!(
            "| {} | {} | {} | {} | {} | {} | {:.2} | {:.3} | {:.3} | {:016x} | {:.2} |",
            round + 1,
            args.frames,
            total,
            rays[0],
            rays[1],
            rays[2],
            median(&ms),
            total as f64 / seconds.max(1e-9) / 1e6,
            total as f64 / cpu_total.max(1e-9) / 1e6,
            hasher.finish(),
            median(&guide_ms)
        );
    }
    Ok(())
}

/// CPU seconds this process has run so far, all threads (user + system; Linux
/// `/proc/self/stat`, in clock ticks of 1/100 s), or 0 where that cannot be read. On a machine
/// shared with other work this counts only our own time, unlike the wall clock.
pub(crate) fn cpu_seconds() -> f64 {
    let Ok(stat) = std::fs::read_to_string("/proc/self/stat") else {
        return 0.0;
    };
    // Fields after the command name (which is in parentheses and may hold spaces).
    let Some(rest) = stat.rfind(')').map(|i| &stat[i + 1..]) else {
        return 0.0;
    };
    let fields: Vec<&str> = rest.split_whitespace().collect();
    // utime and stime are fields 14 and 15 of the whole line, 12 and 13 after the name.
    let tick = |i: usize| {
        fields
            .get(i)
            .and_then(|f| f.parse::<f64>().ok())
            .unwrap_or(0.0)
    };
    (tick(11) + tick(12)) / 100.0
}
