//! `bench instance-merge`: what a Reflect chamber's two-level scene (TLAS over instances, one
//! BLAS per mesh) costs in traversal against the same triangles merged into one world-space BLAS,
//! on the same rays. It decides whether merging a level's static instances is worth building.
//!
//! The chamber's view is captured as `bench chamber-rays` does. Rays, all in render space: one
//! camera ray per pixel of the traced size; from every camera hit a bounce ray in a random
//! direction on the camera's side of the hit (origin pulled back 1 mm along the camera ray),
//! and a shadow ray from that point to another pixel's hit point. Each set is traced through
//! both structures, interleaved, `--rounds` times; the hits are compared (same distance within
//! 10⁻⁴ relative) so both sides answer the same question.
//!
//! Owns: [`run`]. Main thread, one thread (traversal only, no shading). Must not: change the
//! scene it measures.

use std::time::Instant;

use candela::accel::build_blas;
use candela::scene::RenderScene;
use candela::trace::{Ray, TraceScene, closest_blas, occluded_blas};
use clap::Parser;
use glam::{Vec3, Vec4};

use super::chamber_rays::{ChamberRaysArgs, capture};
use super::machine::median;

#[derive(Parser, Debug)]
pub struct InstanceMergeArgs {
    /// Chamber number, from 1.
    #[arg(long, default_value_t = 1)]
    pub chamber: usize,
    /// Camera rays per row.
    #[arg(long, default_value_t = 320)]
    pub width: u32,
    /// Rows of camera rays.
    #[arg(long, default_value_t = 180)]
    pub height: u32,
    /// Timed passes over each ray set per structure.
    #[arg(long, default_value_t = 7)]
    pub rounds: u32,
}

/// Every instance's triangles in render space, as one position and index list.
fn merged_triangles(scene: &RenderScene) -> (Vec<Vec3>, Vec<[u32; 3]>) {
    // A mesh's triangles run from its `triangle_base` to the next mesh's.
    let mut bases: Vec<u32> = scene.instances.iter().map(|i| i.triangle_base).collect();
    bases.push(scene.triangles.len() as u32);
    bases.sort_unstable();
    bases.dedup();
    let (mut positions, mut triangles) = (Vec::new(), Vec::new());
    for inst in &scene.instances {
        let start = inst.triangle_base;
        let end = bases.iter().copied().find(|&b| b > start).unwrap_or(start);
        let m = inst.world_from_object;
        let rows = m.map(Vec4::from_array);
        for tri in scene
            .triangles
            .get(start as usize..end as usize)
            .unwrap_or(&[])
        {
            let mut out = [0u32; 3];
            for (k, &i) in tri.indices.iter().enumerate() {
                let Some(v) = scene.vertices.get((inst.vertex_base + i) as usize) else {
                    continue;
                };
                let p = Vec4::from((Vec3::from_array(v.position), 1.0));
                out[k] = positions.len() as u32;
                positions.push(Vec3::new(rows[0].dot(p), rows[1].dot(p), rows[2].dot(p)));
            }
            triangles.push(out);
        }
    }
    (positions, triangles)
}

/// A small deterministic generator (xorshift), for ray directions and shadow targets.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f32 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 40) as f32 / (1u64 << 24) as f32
    }
}

pub fn run(args: &InstanceMergeArgs) -> anyhow::Result<()> {
    let (scene, u) = capture(&ChamberRaysArgs {
        chamber: args.chamber,
        width: args.width,
        height: args.height,
        frames: 1,
        rounds: 1,
        threads: 1,
        warm_frames: 4,
        light_tree: false,
        indirect_every: 1,
    })?;
    let two_level = scene.trace_scene();
    let (positions, triangles) = merged_triangles(&scene);
    let build = Instant::now();
    let merged = build_blas(&positions, &triangles);
    let build_ms = build.elapsed().as_secs_f64() * 1e3;
    println!(
        "chamber {}: {} instances, {} placed triangles merged into one BLAS of {} nodes ({:.1} ms \
         to build); two-level: {} nodes in all",
        args.chamber,
        scene.instances.len(),
        triangles.len(),
        merged.nodes.len(),
        build_ms,
        scene.nodes.len()
    );

    // Camera rays over the image plane.
    let origin = Vec3::from_array(u.camera_position);
    let (right, up, forward) = (
        Vec3::from_array(u.camera_right),
        Vec3::from_array(u.camera_up),
        Vec3::from_array(u.camera_forward),
    );
    let mut camera = Vec::new();
    for y in 0..args.height {
        for x in 0..args.width {
            let sx = (x as f32 + 0.5) / args.width as f32 * 2.0 - 1.0;
            let sy = 1.0 - (y as f32 + 0.5) / args.height as f32 * 2.0;
            let d = (forward + right * sx + up * sy).normalize();
            camera.push(Ray::new(origin, d));
        }
    }
    let points: Vec<Vec3> = camera
        .iter()
        .filter_map(|r| {
            two_level
                .closest(r)
                .map(|h| r.origin + r.direction * h.t - r.direction * 1e-3)
        })
        .collect();
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let mut bounce = Vec::with_capacity(points.len());
    let mut shadow = Vec::with_capacity(points.len());
    for (i, &p) in points.iter().enumerate() {
        let z = rng.next() * 2.0 - 1.0;
        let phi = rng.next() * std::f32::consts::TAU;
        let s = (1.0 - z * z).max(0.0).sqrt();
        let mut d = Vec3::new(s * phi.cos(), s * phi.sin(), z);
        if d.dot(p - origin) > 0.0 {
            d = -d;
        }
        bounce.push(Ray::new(p, d));
        let target = points[(i * 7919 + 13) % points.len()];
        let to = target - p;
        let len = to.length();
        if len > 1e-3 {
            shadow.push(Ray {
                t_max: len * 0.999,
                ..Ray::new(p, to / len)
            });
        }
    }

    println!(
        "| rays | count | two-level Mrays/s | merged Mrays/s | merged ÷ two-level | answers differ |\n|---|---:|---:|---:|---:|---:|"
    );
    for (name, rays, any) in [
        ("camera (closest)", &camera, false),
        ("bounce (closest)", &bounce, false),
        ("shadow (any hit)", &shadow, true),
    ] {
        let (mut a_ms, mut b_ms) = (Vec::new(), Vec::new());
        let mut differ = 0usize;
        for round in 0..args.rounds {
            let start = Instant::now();
            let a = trace_all(&two_level, None, rays, any);
            a_ms.push(start.elapsed().as_secs_f64());
            let start = Instant::now();
            let b = trace_all(&two_level, Some((&merged.nodes, &merged.blocks)), rays, any);
            b_ms.push(start.elapsed().as_secs_f64());
            if round == 0 {
                differ = a
                    .iter()
                    .zip(&b)
                    .filter(|(x, y)| (*x - *y).abs() > 1e-4 * x.abs().max(1.0))
                    .count();
            }
        }
        let rate = |s: &[f64]| rays.len() as f64 / median(s) / 1e6;
        println!(
            "| {name} | {} | {:.2} | {:.2} | {:.2}× | {differ} |",
            rays.len(),
            rate(&a_ms),
            rate(&b_ms),
            rate(&b_ms) / rate(&a_ms)
        );
    }
    Ok(())
}

/// Each ray's answer: the hit distance (closest), 1 or 0 (any hit), +inf for a miss.
fn trace_all(
    two_level: &TraceScene,
    merged: Option<(&[candela::layout::GpuBvh8Node], &[candela::layout::GpuTri4])>,
    rays: &[Ray],
    any: bool,
) -> Vec<f32> {
    rays.iter()
        .map(|r| match (merged, any) {
            (None, false) => two_level.closest(r).map_or(f32::INFINITY, |h| h.t),
            (None, true) => f32::from(u8::from(two_level.occluded(r))),
            (Some((n, b)), false) => closest_blas(n, b, r).map_or(f32::INFINITY, |h| h.t),
            (Some((n, b)), true) => f32::from(u8::from(occluded_blas(n, b, r))),
        })
        .collect()
}
