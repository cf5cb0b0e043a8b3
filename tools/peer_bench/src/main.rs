//! engine_bench: Candela's row in the CPU ray-traversal peer benchmark (`shared/peers/README.md`,
//! "Adding the engine"). Reads `DIR/scene.tri` and `DIR/{primary,shadow,bounce}.rays` written by
//! `embree_bench --dump DIR`, builds a BLAS from the triangle soup with
//! [`candela::accel::build_blas_with`] (timed: median of `--reps` builds, soup in memory to a
//! traceable structure), then traces every kind: closest hit for primary and bounce rays,
//! any hit for shadow rays, one [`Ray`] made from each record inside the timed loop.
//!
//! Timing: one warm-up pass, one calibration pass fixing `passes = ceil(min_ms / pass_time)`,
//! then `--reps` measurements of `passes` full passes; reported Mrays/s = rays / median per-pass
//! time. Threads: a rayon pool of `--threads`; every thread takes chunks of 64 consecutive
//! rays from a shared atomic counter (dynamic scheduling, like the C peers' OpenMP loops).
//!
//! stdout: `scene,<peer>,<kind>,<threads>,<mrays_per_s>,<build_ms>`; stderr: `# …` diagnostics,
//! one `# check` line per kind (rays, hits, mean hit distance, per-pass ms).

mod load;

use std::io::Write;
use std::time::Instant;

use anyhow::{Context, Result, bail};
use candela::accel::{BuildQuality, build_blas_with};
use candela::layout::{GpuBvh8Node, GpuTri4};
use candela::trace::{Kernel, Ray, TraceBuffer, closest_blas_with, occluded_blas_with};
use clap::{Parser, ValueEnum};
use std::sync::atomic::{AtomicUsize, Ordering};

use load::{RayRecord, load_rays, load_triangles};

/// Rays per work item handed to a thread.
const CHUNK: usize = 64;

#[derive(Parser, Debug)]
#[command(about = "Candela CPU traversal on the shared peer-benchmark rays")]
struct Args {
    /// Folder with scene.tri and {primary,shadow,bounce}.rays.
    dir: String,
    #[arg(long, default_value_t = 1)]
    threads: usize,
    #[arg(long, default_value_t = 5)]
    reps: usize,
    /// Least duration of one measurement, milliseconds.
    #[arg(long, default_value_t = 100.0)]
    min_ms: f64,
    #[arg(long, default_value = "scene")]
    scene: String,
    /// Peer name in the CSV.
    #[arg(long, default_value = "candela")]
    peer: String,
    /// Binary-build preset.
    #[arg(long, value_enum, default_value_t = Quality::BinnedSah)]
    quality: Quality,
    /// Traversal kernel (default: the fastest this CPU supports).
    #[arg(long, value_enum)]
    kernel: Option<KernelArg>,
    /// Only these kinds (comma separated: primary,shadow,bounce).
    #[arg(long, default_value = "primary,shadow,bounce")]
    kinds: String,
    /// Time with the CPU time of this process's threads (/proc/self/task/*/schedstat)
    /// instead of wall time: a development aid for comparing variants on a busy machine. The
    /// peer table always uses wall time.
    #[arg(long)]
    cpu_time: bool,
    /// Trace from the build's plain vectors instead of the huge-page buffers the renderer
    /// uses ([`TraceBuffer`]): a development aid to measure what huge pages give.
    #[arg(long)]
    plain_memory: bool,
}

/// Seconds on the CPU summed over this process's threads (Linux schedstat, ns resolution).
fn process_cpu_seconds() -> f64 {
    let Ok(tasks) = std::fs::read_dir("/proc/self/task") else {
        return 0.0;
    };
    tasks
        .filter_map(|t| std::fs::read_to_string(t.ok()?.path().join("schedstat")).ok())
        .filter_map(|s| s.split_whitespace().next()?.parse::<f64>().ok())
        .sum::<f64>()
        * 1e-9
}

/// A stopwatch over wall time or process CPU time.
struct Clock(bool);

impl Clock {
    fn now(&self) -> f64 {
        if self.0 {
            process_cpu_seconds()
        } else {
            static START: std::sync::OnceLock<Instant> = std::sync::OnceLock::new();
            START.get_or_init(Instant::now).elapsed().as_secs_f64()
        }
    }
}

#[derive(Clone, Copy, Debug, ValueEnum)]
enum Quality {
    Fastest,
    VeryFast,
    Fast,
    Medium,
    Slow,
    VerySlow,
    BinnedSah,
}

#[derive(Clone, Copy, Debug, ValueEnum)]
enum KernelArg {
    Scalar,
    Avx2,
    Avx512,
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

#[inline(always)]
fn make_ray(r: &RayRecord) -> Ray {
    Ray::with_range(r.origin.into(), r.direction.into(), r.t_near, r.t_far)
}

/// One pass over all rays: (hits, sum of hit t). Every pool thread takes chunks of `CHUNK`
/// consecutive rays from a shared counter until none are left (dynamic scheduling with chunk
/// size 64, as the C peers' OpenMP loops do), so there is no task splitting per pass.
fn trace(
    pool: &rayon::ThreadPool,
    kernel: Kernel,
    nodes: &[GpuBvh8Node],
    blocks: &[GpuTri4],
    rays: &[RayRecord],
    occlusion: bool,
) -> (u64, f64) {
    let next = AtomicUsize::new(0);
    let chunks = rays.len().div_ceil(CHUNK);
    let partial = pool.broadcast(|_| {
        let (mut hits, mut sum_t) = (0u64, 0f64);
        loop {
            let c = next.fetch_add(1, Ordering::Relaxed);
            if c >= chunks {
                break;
            }
            for r in &rays[c * CHUNK..((c + 1) * CHUNK).min(rays.len())] {
                let ray = make_ray(r);
                if occlusion {
                    hits += u64::from(occluded_blas_with(kernel, nodes, blocks, &ray));
                } else if let Some(hit) = closest_blas_with(kernel, nodes, blocks, &ray) {
                    hits += 1;
                    sum_t += f64::from(hit.t);
                }
            }
        }
        (hits, sum_t)
    });
    partial
        .into_iter()
        .fold((0, 0.0), |a, b| (a.0 + b.0, a.1 + b.1))
}

fn main() -> Result<()> {
    let args = Args::parse();
    if args.threads < 1 || args.reps < 1 {
        bail!("--threads and --reps must be at least 1");
    }
    let quality = match args.quality {
        Quality::Fastest => BuildQuality::Fastest,
        Quality::VeryFast => BuildQuality::VeryFast,
        Quality::Fast => BuildQuality::Fast,
        Quality::Medium => BuildQuality::Medium,
        Quality::Slow => BuildQuality::Slow,
        Quality::VerySlow => BuildQuality::VerySlow,
        Quality::BinnedSah => BuildQuality::BinnedSah,
    };
    let kernel = match args.kernel {
        None => Kernel::best(),
        Some(KernelArg::Scalar) => Kernel::Scalar,
        Some(KernelArg::Avx2) => Kernel::Avx2,
        Some(KernelArg::Avx512) => Kernel::Avx512,
    };
    if !Kernel::available().contains(&kernel) {
        bail!("kernel {kernel:?} is not supported by this CPU");
    }
    let dir = &args.dir;
    let (positions, triangles) = load_triangles(&format!("{dir}/scene.tri"))?;
    let mut sets = Vec::new();
    for (kind, occlusion) in [("primary", false), ("shadow", true), ("bounce", false)] {
        if args.kinds.split(',').any(|k| k == kind) {
            sets.push((kind, load_rays(&format!("{dir}/{kind}.rays"))?, occlusion));
        }
    }
    eprintln!(
        "# candela {} ({kernel:?} kernel, {quality:?} build), {} triangles, threads {}",
        env!("CARGO_PKG_VERSION"),
        triangles.len(),
        args.threads
    );
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(args.threads)
        .build()
        .context("rayon pool")?;

    // Build: soup in memory -> traceable BLAS, median of reps (single-threaded builder).
    let mut times = Vec::new();
    let mut built = None;
    for _ in 0..args.reps {
        drop(built.take());
        let t0 = Instant::now();
        let blas = pool.install(|| build_blas_with(&positions, &triangles, quality));
        times.push(t0.elapsed().as_secs_f64() * 1e3);
        built = Some(blas);
    }
    let blas = built.context("no build")?;
    let (bmin, bmax) = (
        times.iter().copied().fold(f64::INFINITY, f64::min),
        times.iter().copied().fold(0.0, f64::max),
    );
    let build_ms = median(times);
    eprintln!(
        "# candela build: {} nodes, {} blocks, SAH {:.3}, median {build_ms:.2} ms (min {bmin:.2} max {bmax:.2}) over {}",
        blas.nodes.len(),
        blas.blocks.len(),
        blas.sah_cost,
        args.reps
    );

    // The renderer's storage (`RenderScene`): huge-page buffers; copied outside the build time.
    let (nodes, blocks) = (
        TraceBuffer::from_slice(&blas.nodes),
        TraceBuffer::from_slice(&blas.blocks),
    );
    let (nodes, blocks): (&[GpuBvh8Node], &[GpuTri4]) = if args.plain_memory {
        (&blas.nodes, &blas.blocks)
    } else {
        (&nodes, &blocks)
    };
    eprintln!(
        "# candela memory: {} (nodes {} KiB, blocks {} KiB)",
        if args.plain_memory {
            "plain"
        } else {
            "huge-page buffers"
        },
        size_of_val(nodes) / 1024,
        size_of_val(blocks) / 1024
    );
    let out = std::io::stdout();
    let clock = Clock(args.cpu_time);
    for (kind, rays, occlusion) in &sets {
        let run = || trace(&pool, kernel, nodes, blocks, rays, *occlusion);
        let check = run();
        let t0 = clock.now();
        run();
        let calibration = clock.now() - t0;
        let passes = ((args.min_ms * 1e-3 / calibration.max(1e-9)).ceil() as usize).max(1);
        let mut per_pass = Vec::new();
        for _ in 0..args.reps {
            let t0 = clock.now();
            for _ in 0..passes {
                if run().0 != check.0 {
                    eprintln!("# WARNING: hit count changed between passes");
                }
            }
            per_pass.push((clock.now() - t0) / passes as f64);
        }
        let (tmin, tmax) = (
            per_pass.iter().copied().fold(f64::INFINITY, f64::min),
            per_pass.iter().copied().fold(0.0, f64::max),
        );
        let t = median(per_pass);
        let mut o = out.lock();
        writeln!(
            o,
            "{},{},{kind},{},{:.3},{build_ms:.2}",
            args.scene,
            args.peer,
            args.threads,
            rays.len() as f64 / t * 1e-6
        )?;
        o.flush()?;
        eprintln!(
            "# check {},{},{kind},{}: rays={} hits={} mean_t={:.6} pass_ms={:.3} (min {:.3} max {:.3}) passes_per_measurement={passes}",
            args.scene,
            args.peer,
            args.threads,
            rays.len(),
            check.0,
            if check.0 > 0 {
                check.1 / check.0 as f64
            } else {
                0.0
            },
            t * 1e3,
            tmin * 1e3,
            tmax * 1e3
        );
    }
    Ok(())
}
