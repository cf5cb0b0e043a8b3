//! layout_compare: single-thread traversal throughput of obvhs 0.4's own layouts (BVH2 and
//! CWBVH, `medium_build`, triangles re-ordered into BVH order as obvhs's examples do) against
//! Candela's 8-wide SoA layout, on the peer benchmark's ray files (same rays, same process,
//! interleaved). It produced the figures in `engine/src/accel/mod.rs` that justify the layout.
//!
//! Usage: `layout_compare DIR [--min-ms MS] [--reps R]`; prints one line per layout and kind.

#[path = "../load.rs"]
mod load;

use std::time::{Duration, Instant};

use anyhow::Result;
use candela::accel::build_blas;
use candela::trace::{Ray, closest_blas, occluded_blas};
use clap::Parser;
use glam::Vec3A;
use load::{RayRecord, load_rays, load_triangles};
use obvhs::{
    BvhBuildParams,
    bvh2::builder::build_bvh2_from_tris,
    cwbvh::builder::build_cwbvh_from_tris,
    ray::{Ray as ObRay, RayHit},
    rt_triangle::RtTriangle,
    triangle::Triangle,
};

#[derive(Parser)]
struct Args {
    dir: String,
    #[arg(long, default_value_t = 200.0)]
    min_ms: f64,
    #[arg(long, default_value_t = 5)]
    reps: usize,
}

/// Median Mrays/s of `reps` measurements of at least `min_ms` each; returns (Mrays/s, hits).
fn measure(
    rays: &[RayRecord],
    args: &Args,
    mut trace: impl FnMut(&RayRecord) -> bool,
) -> (f64, u64) {
    let hits = rays.iter().filter(|r| trace(r)).count() as u64;
    let mut rates = Vec::new();
    for _ in 0..args.reps {
        let (t0, mut n) = (Instant::now(), 0usize);
        while t0.elapsed().as_secs_f64() * 1e3 < args.min_ms {
            for r in rays {
                std::hint::black_box(trace(r));
            }
            n += rays.len();
        }
        rates.push(n as f64 / t0.elapsed().as_secs_f64() * 1e-6);
    }
    rates.sort_by(f64::total_cmp);
    (rates[rates.len() / 2], hits)
}

fn main() -> Result<()> {
    let args = Args::parse();
    let (positions, triangles) = load_triangles(&format!("{}/scene.tri", args.dir))?;
    let tris: Vec<Triangle> = triangles
        .iter()
        .map(|t| Triangle {
            v0: Vec3A::from(positions[t[0] as usize]),
            v1: Vec3A::from(positions[t[1] as usize]),
            v2: Vec3A::from(positions[t[2] as usize]),
        })
        .collect();
    let params = BvhBuildParams::medium_build();
    let bvh2 = build_bvh2_from_tris(&tris, params, &mut Duration::default());
    let bvh2_tris: Vec<RtTriangle> = bvh2
        .primitive_indices
        .iter()
        .map(|&i| RtTriangle::from(&tris[i as usize]))
        .collect();
    let cwbvh = build_cwbvh_from_tris(&tris, params, &mut Duration::default());
    let cw_tris: Vec<RtTriangle> = cwbvh
        .primitive_indices
        .iter()
        .map(|&i| RtTriangle::from(&tris[i as usize]))
        .collect();
    let blas = build_blas(&positions, &triangles);
    let ob_ray = |r: &RayRecord| {
        ObRay::new(
            Vec3A::from(r.origin),
            Vec3A::from(r.direction),
            r.t_near,
            r.t_far,
        )
    };
    let ray =
        |r: &RayRecord| Ray::with_range(r.origin.into(), r.direction.into(), r.t_near, r.t_far);
    for kind in ["primary", "shadow", "bounce"] {
        let rays = load_rays(&format!("{}/{kind}.rays", args.dir))?;
        let any = kind == "shadow";
        let results = [
            (
                "obvhs_bvh2",
                measure(&rays, &args, |r| {
                    if any {
                        !bvh2.ray_traverse_miss(ob_ray(r), |ray, id| bvh2_tris[id].intersect(ray))
                    } else {
                        let mut hit = RayHit::none();
                        bvh2.ray_traverse(ob_ray(r), &mut hit, |ray, id| {
                            bvh2_tris[id].intersect(ray)
                        })
                    }
                }),
            ),
            (
                "obvhs_cwbvh",
                measure(&rays, &args, |r| {
                    if any {
                        !cwbvh.ray_traverse_miss(ob_ray(r), |ray, id| cw_tris[id].intersect(ray))
                    } else {
                        let mut hit = RayHit::none();
                        cwbvh
                            .ray_traverse(ob_ray(r), &mut hit, |ray, id| cw_tris[id].intersect(ray))
                    }
                }),
            ),
            (
                "candela_bvh8_soa",
                measure(&rays, &args, |r| {
                    if any {
                        occluded_blas(&blas.nodes, &blas.blocks, &ray(r))
                    } else {
                        closest_blas(&blas.nodes, &blas.blocks, &ray(r)).is_some()
                    }
                }),
            ),
        ];
        for (name, (rate, hits)) in results {
            println!("{kind},{name},{rate:.3},{hits}");
        }
    }
    Ok(())
}
