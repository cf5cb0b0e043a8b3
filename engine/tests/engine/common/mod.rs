//! Shared helpers of the acceleration / traversal tests: a small deterministic RNG, procedural
//! meshes, random rays, scene assembly and the agreement check (tree kernels vs brute force);
//! the file walk of the robustness tests; the third-party data's folder; the mean and its standard error of a set of estimates.
#![allow(dead_code)]

use candela::accel::{Aabb, Blas, build_blas, build_tlas};
use candela::layout::{GpuBvh8Node, GpuInstance, GpuTri4, INSTANCE_FLAG_IDENTITY};
use candela::trace::brute::{BruteInstance, BruteMesh, closest_brute, closest_brute_mesh};
use candela::trace::{Hit, Kernel, Ray, TraceScene, closest_blas_with, occluded_blas_with};
use std::path::{Path, PathBuf};

use glam::{Mat4, Quat, Vec3};

/// `relative` inside the third-party test data, `../shared/external` (read in place).
pub fn external(relative: &str) -> PathBuf {
    Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../shared/external"
    ))
    .join(relative)
}

/// Mean and variance of the mean of `values` (sample variance / n).
pub fn mean_and_error(values: &[f64]) -> (f64, f64) {
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    let var = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0);
    (mean, var / n)
}

/// PCG32 (O'Neill 2014): deterministic across platforms.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Self(
            seed.wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407),
        )
    }
    pub fn next_u32(&mut self) -> u32 {
        let old = self.0;
        self.0 = old
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        let xorshifted = (((old >> 18) ^ old) >> 27) as u32;
        xorshifted.rotate_right((old >> 59) as u32)
    }
    /// Uniform in [0, 1).
    pub fn f32(&mut self) -> f32 {
        (self.next_u32() >> 8) as f32 * (1.0 / (1u32 << 24) as f32)
    }
    pub fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.f32()
    }
    pub fn vec3(&mut self, lo: Vec3, hi: Vec3) -> Vec3 {
        Vec3::new(
            self.range(lo.x, hi.x),
            self.range(lo.y, hi.y),
            self.range(lo.z, hi.z),
        )
    }
    pub fn unit(&mut self) -> Vec3 {
        loop {
            let v = self.vec3(Vec3::splat(-1.0), Vec3::ONE);
            let l = v.length_squared();
            if l > 1e-4 && l <= 1.0 {
                return v / l.sqrt();
            }
        }
    }
}

/// A mesh: positions and index triples.
#[derive(Clone, Debug, Default)]
pub struct Mesh {
    pub positions: Vec<Vec3>,
    pub triangles: Vec<[u32; 3]>,
}

impl Mesh {
    pub fn brute(&self) -> BruteMesh<'_> {
        BruteMesh {
            positions: &self.positions,
            triangles: &self.triangles,
        }
    }
    pub fn bounds(&self) -> Aabb {
        Aabb::from_points(self.positions.iter().copied())
    }
    pub fn push_tri(&mut self, a: Vec3, b: Vec3, c: Vec3) {
        let i = self.positions.len() as u32;
        self.positions.extend([a, b, c]);
        self.triangles.push([i, i + 1, i + 2]);
    }
}

/// A UV sphere (shared vertices, degenerate triangles at the poles included).
pub fn sphere(center: Vec3, radius: f32, rings: u32, segments: u32) -> Mesh {
    let mut m = Mesh::default();
    for r in 0..=rings {
        let theta = std::f32::consts::PI * r as f32 / rings as f32;
        for s in 0..=segments {
            let phi = std::f32::consts::TAU * s as f32 / segments as f32;
            m.positions.push(
                center
                    + radius
                        * Vec3::new(
                            theta.sin() * phi.cos(),
                            theta.cos(),
                            theta.sin() * phi.sin(),
                        ),
            );
        }
    }
    let w = segments + 1;
    for r in 0..rings {
        for s in 0..segments {
            let (a, b, c, d) = (
                r * w + s,
                r * w + s + 1,
                (r + 1) * w + s,
                (r + 1) * w + s + 1,
            );
            m.triangles.push([a, c, b]);
            m.triangles.push([b, c, d]);
        }
    }
    m
}

/// A bumpy height-field grid in the xz plane (`flat`: all y = 0, an axis-aligned flat mesh).
pub fn grid(n: u32, size: f32, flat: bool) -> Mesh {
    let mut m = Mesh::default();
    for z in 0..=n {
        for x in 0..=n {
            let (fx, fz) = (x as f32 / n as f32, z as f32 / n as f32);
            let y = if flat {
                0.0
            } else {
                0.1 * size * ((fx * 9.0).sin() * (fz * 7.0).cos())
            };
            m.positions
                .push(Vec3::new((fx - 0.5) * size, y, (fz - 0.5) * size));
        }
    }
    for z in 0..n {
        for x in 0..n {
            let i = z * (n + 1) + x;
            m.triangles.push([i, i + 1, i + n + 1]);
            m.triangles.push([i + 1, i + n + 2, i + n + 1]);
        }
    }
    m
}

/// Random triangles of random sizes in a box: long thin ones, overlapping, all orientations.
pub fn soup(rng: &mut Rng, count: usize, extent: f32) -> Mesh {
    let mut m = Mesh::default();
    for _ in 0..count {
        let c = rng.vec3(Vec3::splat(-extent), Vec3::splat(extent));
        let size = extent * 0.2 * rng.f32().powi(3);
        m.push_tri(
            c + rng.unit() * size,
            c + rng.unit() * size,
            c + rng.unit() * size * rng.range(0.1, 3.0),
        );
    }
    m
}

/// Random rays aimed at `bounds` (most hit, some miss, some start inside); a few have a
/// limited `t` range; `zero_components` zeroes one or two direction components of every
/// second ray (including `-0.0`).
pub fn rays(rng: &mut Rng, bounds: Aabb, count: usize, zero_components: bool) -> Vec<Ray> {
    let c = bounds.center();
    let e = (bounds.max - bounds.min).max(Vec3::splat(1e-3));
    let mut out = Vec::with_capacity(count);
    for i in 0..count {
        let origin = if i % 5 == 0 {
            rng.vec3(bounds.min, bounds.max)
        } else {
            c + rng.unit() * e.length() * rng.range(0.6, 2.0)
        };
        let target = rng.vec3(c - e * 0.6, c + e * 0.6);
        let mut direction = (target - origin) * rng.range(0.1, 3.0);
        if zero_components && i % 2 == 0 {
            let axis = (rng.next_u32() % 3) as usize;
            direction[axis] = if rng.next_u32().is_multiple_of(2) {
                0.0
            } else {
                -0.0
            };
            if i % 6 == 0 {
                let other = (axis + 1) % 3;
                direction[other] = 0.0;
            }
        }
        let (t_min, t_max) = match i % 7 {
            0 => (0.0, rng.range(0.1, 2.0)),
            1 => (rng.range(0.0, 0.5), f32::INFINITY),
            _ => (0.0, f32::INFINITY),
        };
        out.push(Ray::with_range(origin, direction, t_min, t_max));
    }
    out
}

/// Compares a tree hit with the brute-force hit: same `t` bit for bit; the same triangle and
/// `(u, v)` unless another triangle has exactly the same `t` (a tie may pick either).
pub fn same_hit(tree: Option<Hit>, brute: Option<Hit>) -> Result<(), String> {
    match (tree, brute) {
        (None, None) => Ok(()),
        (Some(a), Some(b)) if a.t == b.t => {
            if (a.instance, a.triangle) == (b.instance, b.triangle) && (a.u, a.v) != (b.u, b.v) {
                Err(format!("same triangle, different (u, v): {a:?} vs {b:?}"))
            } else {
                Ok(())
            }
        }
        (a, b) => Err(format!("tree {a:?} vs brute {b:?}")),
    }
}

/// Every kernel against brute force on one BLAS; returns the number of hits, or the first
/// disagreements.
pub fn check_blas(blas: &Blas, mesh: &Mesh, rays: &[Ray]) -> Result<usize, String> {
    let mut errors = Vec::new();
    let mut hits = 0;
    for (i, ray) in rays.iter().enumerate() {
        let brute = closest_brute_mesh(&mesh.brute(), ray);
        hits += usize::from(brute.is_some());
        for kernel in Kernel::available() {
            let tree = closest_blas_with(kernel, &blas.nodes, &blas.blocks, ray);
            if let Err(e) = same_hit(tree, brute) {
                errors.push(format!("ray {i} {ray:?} {kernel:?} closest: {e}"));
            }
            let occluded = occluded_blas_with(kernel, &blas.nodes, &blas.blocks, ray);
            if occluded != brute.is_some() {
                errors.push(format!("ray {i} {ray:?} {kernel:?} occluded {occluded}"));
            }
        }
        if errors.len() > 5 {
            break;
        }
    }
    if errors.is_empty() {
        Ok(hits)
    } else {
        Err(errors.join("\n"))
    }
}

/// A flattened scene: BLAS per mesh, instances, TLAS at the end of the node buffer.
pub struct Scene {
    pub nodes: Vec<GpuBvh8Node>,
    pub blocks: Vec<GpuTri4>,
    pub instances: Vec<GpuInstance>,
    pub tlas_root: u32,
    pub brute: Vec<BruteInstance>,
    pub world_bounds: Aabb,
    pub instance_bounds: Vec<Aabb>,
}

impl Scene {
    pub fn trace(&self) -> TraceScene<'_> {
        TraceScene {
            nodes: &self.nodes,
            blocks: &self.blocks,
            instances: &self.instances,
            tlas_root: self.tlas_root,
        }
    }
}

/// Rows of the 3×4 affine part of `m`.
pub fn rows(m: &Mat4) -> [[f32; 4]; 3] {
    let r = m.transpose();
    [
        r.x_axis.to_array(),
        r.y_axis.to_array(),
        r.z_axis.to_array(),
    ]
}

/// Builds every mesh and places `placements` (mesh index, world_from_object; `None` = identity
/// with the identity flag).
pub fn assemble(meshes: &[Mesh], placements: &[(usize, Option<Mat4>)]) -> Scene {
    let mut nodes = Vec::new();
    let mut blocks = Vec::new();
    let mut bases = Vec::new();
    let mut mesh_bounds = Vec::new();
    for mesh in meshes {
        let blas = build_blas(&mesh.positions, &mesh.triangles);
        bases.push((nodes.len() as u32, blocks.len() as u32));
        mesh_bounds.push(blas.bounds);
        nodes.extend_from_slice(&blas.nodes);
        blocks.extend_from_slice(&blas.blocks);
    }
    let mut instances = Vec::new();
    let mut brute = Vec::new();
    let mut bounds = Vec::new();
    for &(mesh, transform) in placements {
        let m = transform.unwrap_or(Mat4::IDENTITY);
        let inst = GpuInstance {
            world_from_object: rows(&m),
            object_from_world: rows(&m.inverse()),
            node_base: bases[mesh].0,
            block_base: bases[mesh].1,
            triangle_base: 0,
            vertex_base: 0,
            material_override: u32::MAX,
            flags: if transform.is_none() {
                INSTANCE_FLAG_IDENTITY
            } else {
                0
            },
            _padding: [0; 2],
        };
        instances.push(inst);
        brute.push(BruteInstance {
            instance: inst,
            mesh,
        });
        bounds.push(mesh_bounds[mesh].transformed(&m));
    }
    let tlas = build_tlas(&bounds);
    let tlas_root = nodes.len() as u32;
    nodes.extend_from_slice(&tlas);
    let world_bounds = bounds.iter().fold(Aabb::EMPTY, |a, b| a.union(*b));
    Scene {
        nodes,
        blocks,
        instances,
        tlas_root,
        brute,
        world_bounds,
        instance_bounds: bounds,
    }
}

/// Every kernel against brute force on a whole scene.
pub fn check_scene(scene: &Scene, meshes: &[Mesh], rays: &[Ray]) -> Result<usize, String> {
    let brute_meshes: Vec<BruteMesh> = meshes.iter().map(Mesh::brute).collect();
    let trace = scene.trace();
    let mut errors = Vec::new();
    let mut hits = 0;
    for (i, ray) in rays.iter().enumerate() {
        let brute = closest_brute(&brute_meshes, &scene.brute, ray);
        hits += usize::from(brute.is_some());
        for kernel in Kernel::available() {
            if let Err(e) = same_hit(trace.closest_with(kernel, ray), brute) {
                errors.push(format!("ray {i} {ray:?} {kernel:?} closest: {e}"));
            }
            let occluded = trace.occluded_with(kernel, ray);
            if occluded != brute.is_some() {
                errors.push(format!("ray {i} {ray:?} {kernel:?} occluded {occluded}"));
            }
        }
        if errors.len() > 5 {
            break;
        }
    }
    if errors.is_empty() {
        Ok(hits)
    } else {
        Err(errors.join("\n"))
    }
}

/// A rotation, a non-uniform scale and a translation.
pub fn messy_transform(rng: &mut Rng) -> Mat4 {
    Mat4::from_scale_rotation_translation(
        rng.vec3(Vec3::splat(0.3), Vec3::splat(2.5)),
        Quat::from_axis_angle(rng.unit(), rng.range(0.0, std::f32::consts::TAU)),
        rng.vec3(Vec3::splat(-20.0), Vec3::splat(20.0)),
    )
}

/// Every file under `dir` whose extension is one of `extensions`, sorted.
pub fn files_under(dir: &Path, extensions: &[&str]) -> Vec<PathBuf> {
    let mut found = Vec::new();
    let mut pending = vec![dir.to_path_buf()];
    while let Some(dir) = pending.pop() {
        let Ok(entries) = std::fs::read_dir(&dir) else {
            continue;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            if path.is_dir() {
                pending.push(path);
            } else if path
                .extension()
                .and_then(|e| e.to_str())
                .is_some_and(|e| extensions.contains(&e.to_ascii_lowercase().as_str()))
            {
                found.push(path);
            }
        }
    }
    found.sort();
    found
}
