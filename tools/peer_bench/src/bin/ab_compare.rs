//! ab_compare: A/B of BLAS build parameters on the peer benchmark's rays, in one process. Each
//! variant is a [`BlasParams`] (`name:key=value,...` over the defaults; keys `block_cost`,
//! `node_cost`, `max_leaf_blocks`); the variants take turns, one untimed and `--passes` timed
//! passes per kind each, for `--rounds` rounds, timed with this thread's CPU clock, so a slow
//! minute on this shared machine hits every variant alike. Prints median and minimum ms per pass
//! and the speed-up over the first variant. One thread, the fastest kernel, huge-page buffers.
//!
//! Usage: `ab_compare DIR --variant new: --variant old:block_cost=1,max_leaf_blocks=1`.

#[path = "../load.rs"]
mod load;

use anyhow::{Context, Result, bail};
use candela::accel::{BlasParams, build_blas_with_params};
use candela::trace::{Ray, TraceBuffer, closest_blas, occluded_blas};
use clap::Parser;
use load::{load_rays, load_triangles};

#[derive(Parser)]
struct Args {
    dir: String,
    /// `name:key=value,key=value` (repeatable; the first is the reference).
    #[arg(long)]
    variant: Vec<String>,
    #[arg(long, default_value_t = 30)]
    rounds: usize,
    /// Timed passes per variant and round (after one untimed pass).
    #[arg(long, default_value_t = 2)]
    passes: usize,
    #[arg(long, default_value = "primary,shadow,bounce")]
    kinds: String,
}

fn thread_cpu_seconds() -> f64 {
    let mut ts = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: a valid out-pointer to a timespec.
    unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut ts) };
    ts.tv_sec as f64 + ts.tv_nsec as f64 * 1e-9
}

fn main() -> Result<()> {
    let args = Args::parse();
    let (positions, triangles) = load_triangles(&format!("{}/scene.tri", args.dir))?;
    let mut variants = Vec::new();
    for spec in &args.variant {
        let (name, vars) = spec.split_once(':').context("variant needs name:")?;
        let mut params = BlasParams::default();
        for kv in vars.split(',').filter(|s| !s.is_empty()) {
            let (key, value) = kv.split_once('=').context("key=value")?;
            let number: f32 = value.parse().with_context(|| format!("value of {key}"))?;
            match key {
                "block_cost" => params.block_cost = number,
                "node_cost" => params.node_cost = number,
                "max_leaf_blocks" => params.max_leaf_blocks = number as u32,
                _ => bail!("unknown key {key}"),
            }
        }
        let t0 = std::time::Instant::now();
        let blas = build_blas_with_params(&positions, &triangles, params);
        let ms = t0.elapsed().as_secs_f64() * 1e3;
        println!(
            "{name}: {} nodes, {} blocks, SAH {:.3}, build {ms:.0} ms",
            blas.nodes.len(),
            blas.blocks.len(),
            blas.sah_cost
        );
        variants.push((
            name.to_string(),
            TraceBuffer::from_slice(&blas.nodes),
            TraceBuffer::from_slice(&blas.blocks),
        ));
    }
    for kind in args.kinds.split(',') {
        let rays = load_rays(&format!("{}/{kind}.rays", args.dir))?;
        let rays: Vec<Ray> = rays
            .iter()
            .map(|r| Ray::with_range(r.origin.into(), r.direction.into(), r.t_near, r.t_far))
            .collect();
        let any = kind == "shadow";
        let mut times = vec![Vec::new(); variants.len()];
        let mut hits = vec![0u64; variants.len()];
        for round in 0..args.rounds + 1 {
            for i in 0..variants.len() {
                let v = (i + round) % variants.len();
                let (_, nodes, blocks) = &variants[v];
                // One untimed pass to bring this variant's tree back into the caches.
                for pass in 0..1 + args.passes {
                    let t0 = thread_cpu_seconds();
                    let mut h = 0u64;
                    for r in &rays {
                        h += u64::from(if any {
                            occluded_blas(nodes, blocks, r)
                        } else {
                            closest_blas(nodes, blocks, r).is_some()
                        });
                    }
                    let dt = thread_cpu_seconds() - t0;
                    hits[v] = h;
                    if round > 0 && pass > 0 {
                        times[v].push(dt * 1e3);
                    }
                }
            }
        }
        let stat = |t: &Vec<f64>| {
            let mut t = t.clone();
            t.sort_by(f64::total_cmp);
            (t[t.len() / 2], t[0])
        };
        let (base_med, base_min) = stat(&times[0]);
        for (v, (name, _, _)) in variants.iter().enumerate() {
            let (med, min) = stat(&times[v]);
            println!(
                "{kind:8} {name:12} median {med:7.3} ms ({:+5.1} %)  min {min:7.3} ms ({:+5.1} %)  hits {}",
                (base_med / med - 1.0) * 100.0,
                (base_min / min - 1.0) * 100.0,
                hits[v]
            );
        }
    }
    Ok(())
}
