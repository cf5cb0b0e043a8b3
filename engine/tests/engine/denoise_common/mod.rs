//! Shared by the denoiser tests: the Cornell box at a small size, frames and guides from the
//! CPU tracer, a converged reference, error measures and synthetic inputs.

#![allow(dead_code)]

use std::path::Path;

use candela::assets::{AssetRoot, SceneDesc, load_scene};
use candela::render::cpu::CpuTracer;
use candela::render::cpu::guides::trace_guides;
use candela::render::denoise::Guides;
use candela::render::{FrameSettings, Tracer, frame_uniforms};
use candela::scene::RenderScene;
use glam::Vec3;

pub struct Cornell {
    pub desc: SceneDesc,
    pub scene: RenderScene,
    pub width: u32,
    pub height: u32,
}

impl Cornell {
    pub fn load(width: u32, height: u32) -> anyhow::Result<Self> {
        let assets = Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/test_scenes");
        let desc = load_scene(&assets.join("cornell_box.ron"), &AssetRoot::new(&assets)?)?;
        let scene = RenderScene::build(&desc);
        Ok(Self {
            desc,
            scene,
            width,
            height,
        })
    }

    fn uniforms(&self, spp: u32, seed: u32, sample_base: u32) -> candela::layout::GpuFrameUniforms {
        let mut s = FrameSettings::new(self.width, self.height, spp, seed, &self.desc.render);
        s.sample_base = sample_base;
        frame_uniforms(
            &self.desc.camera,
            self.desc.sun.as_ref(),
            &self.desc.sky,
            &s,
            &self.scene.header(),
        )
    }

    /// One frame's mean radiance at `spp` samples per pixel (samples from `sample_base`).
    pub fn frame(&self, spp: u32, seed: u32, sample_base: u32) -> anyhow::Result<Vec<Vec3>> {
        let mut tracer = CpuTracer::new();
        tracer.render(&self.scene, &self.uniforms(spp, seed, sample_base))?;
        Ok(tracer.film()?.mean)
    }

    pub fn guides(&self) -> Guides {
        trace_guides(&self.scene, &self.uniforms(1, 0, 0))
    }

    /// A converged image: `spp` samples with a seed no test frame uses.
    pub fn reference(&self, spp: u32) -> anyhow::Result<Vec<Vec3>> {
        self.frame(spp, 9_999, 0)
    }
}

/// Root mean square error over pixels and channels.
pub fn rmse(a: &[Vec3], b: &[Vec3]) -> f64 {
    let sum: f64 = a
        .iter()
        .zip(b)
        .map(|(x, y)| (*x - *y).length_squared() as f64)
        .sum();
    (sum / (3 * a.len().max(1)) as f64).sqrt()
}

/// Pixels that neither see a lamp nor touch one (3×3): the lamp's edge pixels hold a
/// fraction of its radiance set by where the jittered samples fall (0 or 17 W·sr⁻¹·m⁻² at
/// 1 spp), an error the denoiser leaves alone by design (it would blur the lamp) and that would
/// otherwise dominate every RMSE.
pub fn away_from_lamps(guides: &Guides) -> Vec<bool> {
    let (w, h) = (guides.width as i32, guides.height as i32);
    (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|(x, y)| {
            !(-1..=1).any(|dy| {
                (-1..=1).any(|dx| {
                    let (qx, qy) = (x + dx, y + dy);
                    qx >= 0
                        && qy >= 0
                        && qx < w
                        && qy < h
                        && guides.emissive[(qy * w + qx) as usize]
                })
            })
        })
        .collect()
}

/// RMSE over the pixels where `keep` is true.
pub fn rmse_where(a: &[Vec3], b: &[Vec3], keep: &[bool]) -> f64 {
    let (mut sum, mut n) = (0.0f64, 0usize);
    for ((x, y), k) in a.iter().zip(b).zip(keep) {
        if *k {
            sum += (*x - *y).length_squared() as f64;
            n += 1;
        }
    }
    (sum / (3 * n.max(1)) as f64).sqrt()
}

/// Mean and sample standard deviation.
pub fn mean_std(v: &[f64]) -> (f64, f64) {
    let n = v.len() as f64;
    let mean = v.iter().sum::<f64>() / n;
    let var = v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0).max(1.0);
    (mean, var.sqrt())
}

/// A small deterministic generator for synthetic noise (xorshift32 → uniform [0, 1)).
pub struct Noise(pub u32);

impl Noise {
    pub fn next(&mut self) -> f32 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 17;
        self.0 ^= self.0 << 5;
        (self.0 >> 8) as f32 / (1u32 << 24) as f32
    }
}

/// Flat guides: every pixel a surface facing the camera at `depth` metres with `albedo`.
pub fn flat_guides(width: u32, height: u32, depth: f32, albedo: Vec3) -> Guides {
    let mut g = Guides::sky(width, height);
    for i in 0..g.len() {
        g.normal[i] = Vec3::Z;
        g.depth[i] = depth;
        g.albedo[i] = albedo;
        g.instance[i] = 0;
    }
    g
}
