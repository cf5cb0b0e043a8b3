//! `bench pipeline --only queries`: game-side ray queries (`Upkeep::queries()`) on the demo —
//! what lasers, picking, line of sight and ground probes cost.
//!
//! Scene: the demo level placed in an `Upkeep` as the engine does (one commit's state). Rays:
//! * `pick` (closest hit): 320 × 180 camera rays through pixel centres of the level camera —
//!   mouse picks and lasers;
//! * `sun` (occluded): from each camera-ray hit, just off the surface, towards the sun —
//!   "is this point in shadow";
//! * `sight` (occluded): 57,600 segments between random points 1.7 m above the streets of the
//!   city, up to 150 m apart — line of sight between characters.
//!
//! Single: `closest`/`occluded` called ray by ray on the calling thread. Batch:
//! `closest_batch`/`occluded_batch` inside a rayon pool of 1 thread and of all threads. Median
//! of `--reps` measurements of ≥ 100 ms each.

use std::time::Instant;

use candela::accel::Upkeep;
use candela::app::Environment;
use candela::assets::SceneDesc;
use candela::query::Queries;
use candela::render::cpu::rng::Rng;
use candela::render::cpu::surface::offset_origin;
use candela::trace::Ray;
use glam::Vec3;

use super::pipeline::{PipelineArgs, write_csv};
use crate::machine::median;

fn upkeep_of(desc: &SceneDesc) -> Upkeep {
    let mut upkeep = Upkeep::new();
    upkeep.add_level_materials(&desc.level_materials);
    let handles: Vec<_> = desc.models.iter().map(|m| upkeep.add_model(m)).collect();
    let mut ids = hecs::World::new();
    for instance in &desc.instances {
        let entity = ids.spawn(());
        upkeep.set_instance(
            entity,
            handles[instance.model],
            instance.world_from_model,
            instance.material_override.map(|m| m as u32),
            instance.light_group,
        );
    }
    upkeep.finish_frame();
    upkeep
}

fn camera_rays(desc: &SceneDesc) -> Vec<Ray> {
    let env = Environment::of(desc);
    let c = env.default_camera;
    let (w, h) = (320u32, 180u32);
    let eye = Vec3::from(c.position);
    let forward = (Vec3::from(c.look_at) - eye).normalize();
    let right = forward.cross(Vec3::Y).normalize();
    let up = right.cross(forward);
    let half = (c.vertical_fov_deg.to_radians() * 0.5).tan();
    (0..w * h)
        .map(|i| {
            let sx = (2.0 * ((i % w) as f32 + 0.5) / w as f32 - 1.0) * half * w as f32 / h as f32;
            let sy = (1.0 - 2.0 * ((i / w) as f32 + 0.5) / h as f32) * half;
            Ray::new(eye, (forward + right * sx + up * sy).normalize())
        })
        .collect()
}

/// Median Mrays/s of `pass` over `rays` rays (passes repeated to ≥ 100 ms per measurement).
fn rate(reps: usize, rays: usize, mut pass: impl FnMut() -> usize) -> (f64, usize) {
    let hits = pass();
    let started = Instant::now();
    std::hint::black_box(pass());
    let passes = (0.1 / started.elapsed().as_secs_f64().max(1e-6))
        .ceil()
        .max(1.0) as usize;
    let times: Vec<f64> = (0..reps)
        .map(|_| {
            let started = Instant::now();
            for _ in 0..passes {
                std::hint::black_box(pass());
            }
            started.elapsed().as_secs_f64() / passes as f64
        })
        .collect();
    (rays as f64 / median(&times) / 1e6, hits)
}

pub fn run(desc: &SceneDesc, args: &PipelineArgs) -> anyhow::Result<()> {
    println!("## Ray queries on the demo (`Upkeep::queries()`)\n");
    let upkeep = upkeep_of(desc);
    let queries: Queries<'_> = upkeep.queries();
    let pick = camera_rays(desc);
    let sun = desc
        .sun
        .map(|s| Vec3::from(s.direction).normalize())
        .unwrap_or(Vec3::Y);
    let shadow: Vec<Ray> = queries
        .closest_batch(&pick)
        .into_iter()
        .flatten()
        .map(|hit| {
            let n = hit.geometric_normal;
            let n = if n.dot(sun) < 0.0 { -n } else { n };
            Ray::new(offset_origin(hit.position, n), sun)
        })
        .collect();
    let mut rng = Rng::new(3, 5, 7, 9);
    let mut u = || rng.next_f32();
    let sight: Vec<Ray> = (0..57_600)
        .map(|_| {
            let a = Vec3::new((u() - 0.5) * 300.0, 1.7, (u() - 0.5) * 300.0);
            let b = a + Vec3::new((u() - 0.5) * 212.0, 0.0, (u() - 0.5) * 212.0);
            let d = b - a;
            let length = d.length().max(1e-3);
            Ray::with_range(a, d / length, 0.0, length)
        })
        .collect();
    let all = rayon::current_num_threads();
    let pools = [
        (1, rayon::ThreadPoolBuilder::new().num_threads(1).build()?),
        (
            all,
            rayon::ThreadPoolBuilder::new().num_threads(all).build()?,
        ),
    ];
    println!(
        "| rays | kind | mode | threads | rays | hits | Mrays/s |\n|---|---|---|---:|---:|---:|---:|"
    );
    let mut csv = String::from("rays,kind,mode,threads,count,hits,mrays_per_s\n");
    let sets: [(&str, &[Ray], bool); 3] = [
        ("pick", &pick, false),
        ("sun", &shadow, true),
        ("sight", &sight, true),
    ];
    for (name, rays, occluded) in sets {
        let kind = if occluded { "occluded" } else { "closest" };
        let mut row = |mode: &str, threads: usize, (mrays, hits): (f64, usize)| {
            println!(
                "| {name} | {kind} | {mode} | {threads} | {} | {hits} | {mrays:.3} |",
                rays.len()
            );
            csv += &format!(
                "{name},{kind},{mode},{threads},{},{hits},{mrays:.4}\n",
                rays.len()
            );
        };
        let single = rate(args.reps, rays.len(), || {
            if occluded {
                rays.iter().filter(|r| queries.occluded(r)).count()
            } else {
                rays.iter().filter(|r| queries.closest(r).is_some()).count()
            }
        });
        row("single", 1, single);
        for (threads, pool) in &pools {
            let batch = rate(args.reps, rays.len(), || {
                pool.install(|| {
                    if occluded {
                        queries
                            .occluded_batch(rays)
                            .into_iter()
                            .filter(|h| *h)
                            .count()
                    } else {
                        queries.closest_batch(rays).iter().flatten().count()
                    }
                })
            });
            row("batch", *threads, batch);
        }
    }
    println!();
    write_csv(&args.out_dir, "queries.csv", &csv)
}
