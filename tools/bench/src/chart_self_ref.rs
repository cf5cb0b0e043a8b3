//! Self-references for scenes without an external one: the engine's own CPU render at a high
//! sample count, cached on disk.
//!
//! Owns: rendering it ([`BATCHES`] independent batches with a seed no curve uses, so that a
//! curve's samples are not the reference's first samples), its per-pixel standard error from
//! the batch spread, and the cache: `<refs>/<scene>_<size>px_<spp>spp_<key>/` holding
//! `reference.exr` and `reference_stderr.exr` (the layout of Mitsuba's references, so both
//! load the same way) and `about.txt`, written last as the "complete" mark. The key hashes
//! what the image depends on in the scene (geometry, materials, lights, camera, sun, sky,
//! bounce settings), the size, the sample count and the seed. Engine code is not in the key:
//! after a change to the integrators, pass `--refresh-refs`.
//!
//! Why `target/`: the cache is derived data that the command can always remake (about a
//! minute per scene on two cores) and goes stale with the engine; committing EXRs would grow
//! the repository with every refresh. Must not: decide which scenes need one.

use std::path::{Path, PathBuf};

use candela::assets::SceneDesc;
use candela::layout::METHOD_DEFAULT;
use candela::render::cpu::CpuTracer;
use candela::render::film::write_exr;
use candela::render::{FrameSettings, Tracer, frame_uniforms};
use candela::scene::RenderScene;
use glam::Vec3;

/// Seed of the self-reference renders; the curves use 7 (see `chart.rs`).
pub const REF_SEED: u32 = 0x5EED_C0DE;
/// Independent batches of a self-reference: their spread gives each pixel's standard error.
pub const BATCHES: u32 = 16;
/// Bumped when the way references are made changes.
const CACHE_VERSION: u64 = 1;

/// FNV-1a, 64 bit: a stable hash for cache keys (std's hasher may change between releases).
struct Fnv(u64);

impl Fnv {
    fn new() -> Self {
        Fnv(0xcbf2_9ce4_8422_2325)
    }
    fn bytes(&mut self, bytes: &[u8]) -> &mut Self {
        for &b in bytes {
            self.0 = (self.0 ^ b as u64).wrapping_mul(0x0000_0100_0000_01b3);
        }
        self
    }
}

/// The cache key of a self-reference of `scene` (built from `desc`) at `size × size`, `spp`.
pub fn key(scene: &RenderScene, desc: &SceneDesc, size: u32, spp: u32) -> u64 {
    let mut h = Fnv::new();
    h.bytes(&CACHE_VERSION.to_le_bytes())
        .bytes(bytemuck::cast_slice(&scene.vertices))
        .bytes(bytemuck::cast_slice(&scene.triangles))
        .bytes(bytemuck::cast_slice(&scene.materials))
        .bytes(bytemuck::cast_slice(&scene.textures))
        .bytes(bytemuck::cast_slice(&scene.texels))
        .bytes(bytemuck::cast_slice(&scene.lights.lights))
        .bytes(bytemuck::cast_slice(&scene.instances))
        .bytes(format!("{:?}", (&desc.camera, &desc.sun, &desc.sky, &desc.render)).as_bytes())
        .bytes(
            &[size, spp, REF_SEED, METHOD_DEFAULT]
                .map(u32::to_le_bytes)
                .concat(),
        );
    h.0
}

/// Per-pixel mean of `batches` (equal-sized images of equal sample counts) and the standard
/// error of that mean, from the spread of the batch means: sqrt(Σ (bₖ − m)² / (K (K − 1))).
pub fn batch_stats(batches: &[Vec<Vec3>]) -> (Vec<Vec3>, Vec<Vec3>) {
    let k = batches.len().max(1) as f32;
    let pixels = batches.first().map_or(0, Vec::len);
    let mut mean = vec![Vec3::ZERO; pixels];
    for b in batches {
        for (m, v) in mean.iter_mut().zip(b) {
            *m += *v / k;
        }
    }
    let mut var = vec![Vec3::ZERO; pixels];
    for b in batches {
        for ((s, v), m) in var.iter_mut().zip(b).zip(&mean) {
            *s += (*v - *m) * (*v - *m);
        }
    }
    let denominator = (k * (k - 1.0)).max(1.0);
    let stderr = var
        .iter()
        .map(|s| (*s / denominator).map(f32::sqrt))
        .collect();
    (mean, stderr)
}

/// The folder of a cached self-reference, rendering it with `render` (returning the image
/// edge, the mean and the standard-error image) when it is missing or `refresh` is set.
/// Returns the folder and whether it was rendered now.
pub fn cached(
    refs: &Path,
    label: &str,
    key: u64,
    refresh: bool,
    render: impl FnOnce() -> anyhow::Result<(u32, Vec<Vec3>, Vec<Vec3>)>,
) -> anyhow::Result<(PathBuf, bool)> {
    let dir = refs.join(format!("{label}_{key:016x}"));
    let about = dir.join("about.txt");
    if about.is_file() && !refresh {
        return Ok((dir, false));
    }
    let (size, mean, stderr) = render()?;
    std::fs::create_dir_all(&dir)?;
    write_exr(&dir.join("reference.exr"), size, size, &mean)?;
    write_exr(&dir.join("reference_stderr.exr"), size, size, &stderr)?;
    std::fs::write(
        &about,
        format!(
            "bench chart self-reference {label}: Candela's CPU tracer, default estimator, \
             the level's bounce settings, {BATCHES} batches, seed {REF_SEED:#x}\n"
        ),
    )?;
    Ok((dir, true))
}

/// Where self-references are cached and how they are made.
#[derive(Clone, Copy, Debug)]
pub struct RefSettings<'a> {
    /// The cache folder (`--refs`).
    pub refs: &'a Path,
    /// Samples per pixel of a self-reference (`--ref-spp`).
    pub spp: u32,
    /// Render again even when cached (`--refresh-refs`).
    pub refresh: bool,
}

/// The self-reference of `desc` at `size × size` (rendered on the CPU with the default BLAS
/// build `scene`, or read from the cache).
pub fn ensure(
    settings: RefSettings<'_>,
    name: &str,
    desc: &SceneDesc,
    scene: &RenderScene,
    size: u32,
    progress: &indicatif::ProgressBar,
) -> anyhow::Result<(PathBuf, bool)> {
    let RefSettings { refs, spp, refresh } = settings;
    let label = format!("{name}_{size}px_{spp}spp");
    let key = key(scene, desc, size, spp);
    cached(refs, &label, key, refresh, || {
        let per_batch = (spp / BATCHES).max(1);
        let mut tracer = CpuTracer::new();
        let mut batches = Vec::new();
        for b in 0..BATCHES {
            progress.set_message(format!(
                "{name}: self-reference, batch {}/{BATCHES} of {per_batch} spp",
                b + 1
            ));
            tracer.clear();
            let mut s = FrameSettings::new(size, size, per_batch, REF_SEED, &desc.render);
            s.sample_base = b * per_batch;
            let u = frame_uniforms(
                &desc.camera,
                desc.sun.as_ref(),
                &desc.sky,
                &s,
                &scene.header(),
            );
            tracer.render(scene, &u)?;
            batches.push(tracer.film()?.mean);
        }
        let (mean, stderr) = batch_stats(&batches);
        Ok((size, mean, stderr))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn batch_stats_give_the_standard_error_of_the_mean() {
        let batches = vec![vec![Vec3::splat(1.0)], vec![Vec3::splat(3.0)]];
        let (mean, se) = batch_stats(&batches);
        assert_eq!(mean[0], Vec3::splat(2.0));
        // Σ (b − m)² = 2, K (K − 1) = 2: standard error 1.
        assert!((se[0].x - 1.0).abs() < 1e-6);
    }

    #[test]
    fn the_cache_renders_once_per_key() -> anyhow::Result<()> {
        let refs = std::env::temp_dir().join(format!("bench-self-ref-{}", std::process::id()));
        let image = || Ok((2, vec![Vec3::ONE; 4], vec![Vec3::ZERO; 4]));
        let (dir, fresh) = cached(&refs, "s", 1, false, image)?;
        assert!(fresh && dir.join("reference.exr").is_file());
        let (again, fresh) = cached(&refs, "s", 1, false, || anyhow::bail!("not again"))?;
        assert!(!fresh && again == dir);
        let (_, fresh) = cached(&refs, "s", 1, true, image)?;
        assert!(fresh, "--refresh-refs renders again");
        let (other, fresh) = cached(&refs, "s", 2, false, image)?;
        assert!(fresh && other != dir);
        let r = super::super::chart_reference::Reference::load(&dir, 1)?;
        assert_eq!(r.mean[0], Vec3::ONE);
        std::fs::remove_dir_all(&refs)?;
        Ok(())
    }

    #[test]
    fn the_key_follows_size_samples_and_settings() -> anyhow::Result<()> {
        let repo = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        let root = candela::assets::AssetRoot::new(repo.join("assets/test_scenes"))?;
        let mut desc =
            candela::assets::load_scene(&repo.join("assets/test_scenes/cornell_box.ron"), &root)?;
        let scene = RenderScene::build(&desc);
        let k = key(&scene, &desc, 64, 1024);
        assert_eq!(k, key(&scene, &desc, 64, 1024));
        assert_ne!(k, key(&scene, &desc, 32, 1024));
        assert_ne!(k, key(&scene, &desc, 64, 2048));
        desc.render.max_bounces += 1;
        assert_ne!(k, key(&scene, &desc, 64, 1024));
        Ok(())
    }
}
