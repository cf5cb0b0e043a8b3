//! Helpers shared by the cross-crate tests: test data locations, procedural meshes, rendering in
//! independent batches, and image statistics with noise-derived tolerances.
//!
//! Statistics: a render is split into `batches` independent passes (disjoint sample ranges of
//! the same RNG). For every pixel the spread of its batch means estimates its variance; the
//! standard error of any region mean then follows from summing those variances, with thousands
//! of pixels × (batches − 1) degrees of freedom, so the error estimate itself is precise.

pub mod alone;
pub mod furnace_bound;
pub mod xvfb;

/// The single-scatter GGX albedo by quadrature, shared with the engine's BSDF tests (one
/// file, test-only, independent of the scattering code it bounds).
#[path = "../../engine/src/render/cpu/reference_albedo.rs"]
pub mod reference_albedo;

use std::path::PathBuf;

use candela::assets::{CameraDesc, Material, Mesh, Model, Placement, SceneDesc};
use candela::render::{FrameSettings, Tracer, frame_uniforms};
use candela::scene::RenderScene;
use glam::{Mat4, Vec3};

/// `../shared/external` beside the repository (test data made by others; never copied in).
pub fn external() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../shared/external")
}

/// The repository root.
pub fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// Which tracer a test renders with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Which {
    Cpu,
    Gpu,
}

/// Opens a tracer over `scene`.
pub fn open(which: Which, scene: &RenderScene) -> anyhow::Result<Box<dyn Tracer>> {
    Ok(match which {
        Which::Cpu => Box::new(candela::render::cpu::CpuTracer::new()),
        Which::Gpu => {
            let context = candela::render::gpu::GpuContext::headless()?;
            Box::new(candela::render::gpu::GpuTracer::new(context, scene)?)
        }
    })
}

/// A render split into independent batches: per-batch mean radiance per pixel.
pub struct Batches {
    pub width: u32,
    pub height: u32,
    /// `batches[b][pixel]`: mean of batch b's samples for that pixel.
    pub batches: Vec<Vec<Vec3>>,
    pub spp_per_batch: u32,
}

/// Renders `desc` with `which`: `batches` passes of `spp` samples each, `width × height`; each
/// pass replaces the film (`film_blend = 1`), so the film after it is that batch's mean.
pub fn render_batches(
    which: Which,
    desc: &SceneDesc,
    width: u32,
    height: u32,
    spp: u32,
    batches: u32,
    seed: u32,
) -> anyhow::Result<Batches> {
    render_batches_with(
        which,
        desc,
        width,
        height,
        spp,
        batches,
        seed,
        candela::layout::METHOD_DEFAULT,
    )
}

/// [`render_batches`] with an estimator other than the default (`layout::METHOD_*` bits).
#[allow(clippy::too_many_arguments)]
pub fn render_batches_with(
    which: Which,
    desc: &SceneDesc,
    width: u32,
    height: u32,
    spp: u32,
    batches: u32,
    seed: u32,
    method: u32,
) -> anyhow::Result<Batches> {
    let scene = RenderScene::build(desc);
    render_scene_batches_with(
        which, desc, &scene, width, height, spp, batches, seed, method,
    )
}

/// [`render_batches`] of an already built `scene` (camera, sun, sky and settings from `desc`).
#[allow(clippy::too_many_arguments)]
pub fn render_scene_batches(
    which: Which,
    desc: &SceneDesc,
    scene: &RenderScene,
    width: u32,
    height: u32,
    spp: u32,
    batches: u32,
    seed: u32,
) -> anyhow::Result<Batches> {
    let method = candela::layout::METHOD_DEFAULT;
    render_scene_batches_with(
        which, desc, scene, width, height, spp, batches, seed, method,
    )
}

/// [`render_scene_batches`] with an estimator other than the default (`layout::METHOD_*` bits).
#[allow(clippy::too_many_arguments)]
pub fn render_scene_batches_with(
    which: Which,
    desc: &SceneDesc,
    scene: &RenderScene,
    width: u32,
    height: u32,
    spp: u32,
    batches: u32,
    seed: u32,
    method: u32,
) -> anyhow::Result<Batches> {
    let mut tracer = open(which, scene)?;
    let mut out = Vec::new();
    for b in 0..batches {
        let uniforms = uniforms_with(desc, scene, (width, height), spp, seed, method, b * spp);
        tracer.render(scene, &uniforms)?;
        out.push(tracer.film()?.mean);
    }
    Ok(Batches {
        width,
        height,
        batches: out,
        spp_per_batch: spp,
    })
}

/// The frame uniforms of `spp` samples per pixel from `sample_base` of `desc`'s camera, sun,
/// sky and render settings over `scene`, at `size` pixels, with estimator `method`.
pub fn uniforms_with(
    desc: &SceneDesc,
    scene: &RenderScene,
    size: (u32, u32),
    spp: u32,
    seed: u32,
    method: u32,
    sample_base: u32,
) -> candela::layout::GpuFrameUniforms {
    let mut settings = FrameSettings::new(size.0, size.1, spp, seed, &desc.render);
    settings.sample_base = sample_base;
    settings.method = method;
    frame_uniforms(
        &desc.camera,
        desc.sun.as_ref(),
        &desc.sky,
        &settings,
        &scene.header(),
    )
}

/// Mean and standard error (per channel) of a set of pixels.
#[derive(Clone, Copy, Debug)]
pub struct RegionStat {
    pub mean: [f64; 3],
    pub std_error: [f64; 3],
}

impl Batches {
    /// Mean over all batches per pixel.
    pub fn mean(&self) -> Vec<Vec3> {
        let k = self.batches.len() as f32;
        (0..self.batches[0].len())
            .map(|p| self.batches.iter().map(|b| b[p]).sum::<Vec3>() / k)
            .collect()
    }

    /// Unbiased estimate of the variance of each pixel's overall mean (batch spread / K).
    pub fn variance_of_mean(&self) -> Vec<[f64; 3]> {
        let k = self.batches.len() as f64;
        let mean = self.mean();
        (0..mean.len())
            .map(|p| {
                let mut v = [0.0f64; 3];
                for b in &self.batches {
                    for c in 0..3 {
                        let d = (b[p][c] - mean[p][c]) as f64;
                        v[c] += d * d;
                    }
                }
                v.map(|x| x / (k - 1.0) / k)
            })
            .collect()
    }

    /// Mean and standard error over the pixels `keep` selects (x, y).
    pub fn region(&self, keep: impl Fn(u32, u32) -> bool) -> RegionStat {
        let mean = self.mean();
        let var = self.variance_of_mean();
        region_stat(self.width, &mean, &var, keep)
    }
}

/// Region statistics of an image given per-pixel means and variances of those means.
pub fn region_stat(
    width: u32,
    mean: &[Vec3],
    var: &[[f64; 3]],
    keep: impl Fn(u32, u32) -> bool,
) -> RegionStat {
    let mut sum = [0.0f64; 3];
    let mut var_sum = [0.0f64; 3];
    let mut n = 0.0f64;
    for (i, (m, v)) in mean.iter().zip(var).enumerate() {
        let (x, y) = (i as u32 % width, i as u32 / width);
        if keep(x, y) {
            n += 1.0;
            for c in 0..3 {
                sum[c] += m[c] as f64;
                var_sum[c] += v[c];
            }
        }
    }
    RegionStat {
        mean: sum.map(|s| s / n.max(1.0)),
        std_error: var_sum.map(|v| v.sqrt() / n.max(1.0)),
    }
}

/// An icosphere of `radius` around `center` with `subdivisions` levels (20·4^s triangles),
/// wound outward (or inward when `inward`), without vertex normals (flat shading).
pub fn icosphere(center: Vec3, radius: f32, subdivisions: u32, inward: bool) -> Mesh {
    let t = (1.0 + 5.0f32.sqrt()) / 2.0;
    let mut positions: Vec<Vec3> = [
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
    let mut faces: Vec<[u32; 3]> = vec![
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
    for _ in 0..subdivisions {
        let mut cache = std::collections::HashMap::new();
        let mut midpoint = |a: u32, b: u32, positions: &mut Vec<Vec3>| {
            *cache.entry((a.min(b), a.max(b))).or_insert_with(|| {
                positions.push(((positions[a as usize] + positions[b as usize]) * 0.5).normalize());
                positions.len() as u32 - 1
            })
        };
        let mut next = Vec::with_capacity(faces.len() * 4);
        for [a, b, c] in faces {
            let ab = midpoint(a, b, &mut positions);
            let bc = midpoint(b, c, &mut positions);
            let ca = midpoint(c, a, &mut positions);
            next.extend([[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]);
        }
        faces = next;
    }
    if inward {
        for f in &mut faces {
            f.swap(1, 2);
        }
    }
    let count = faces.len();
    Mesh {
        name: "icosphere".into(),
        positions: positions.iter().map(|p| center + *p * radius).collect(),
        normals: None,
        uvs: None,
        tangents: None,
        triangles: faces,
        triangle_materials: vec![0; count],
    }
}

/// A model of one mesh with one material, placed once.
pub fn single_mesh_model(mesh: Mesh, material: Material) -> Model {
    Model {
        name: "procedural".into(),
        meshes: vec![mesh],
        materials: vec![material],
        textures: Vec::new(),
        placements: vec![Placement {
            mesh: 0,
            model_from_mesh: Mat4::IDENTITY,
        }],
        notes: Vec::new(),
    }
}

/// A pinhole camera at `position` looking at `look_at`.
pub fn camera(position: Vec3, look_at: Vec3, vertical_fov_deg: f32) -> CameraDesc {
    CameraDesc {
        position: position.to_array(),
        look_at: look_at.to_array(),
        up: [0.0, 1.0, 0.0],
        vertical_fov_deg,
        aperture_radius: 0.0,
        focus_distance: None,
    }
}
