//! The tracer of `bench picture`: the engine's own CPU tracer, which also renders a converged
//! reference of the very frames it is told to, from the frame's own scene and uniforms (the
//! same camera, the same game state, the same render settings: only the seed, the sample count
//! and the blend differ). The reference is two halves of `spp / 2` samples each on seeds of
//! their own, so the noise left in it can be measured (a quarter of their squared difference).
//!
//! Owns: [`ReferencingTracer`] and the [`References`] it fills. Render thread (the engine's).
//! Must not: change what the game sees: the displayed frame is the inner tracer's, untouched.

use std::collections::{BTreeMap, BTreeSet};
use std::sync::{Arc, Mutex};

use candela::layout::GpuFrameUniforms;
use candela::render::cpu::CpuTracer;
use candela::render::film::Film;
use candela::render::{FilmView, OpenTracer, RenderError, RenderStats, Tracer};
use candela::scene::RenderScene;
use glam::Vec3;
use indicatif::ProgressBar;

/// Samples per pixel per reference render call (the progress bar moves by this much).
const CHUNK_SPP: u32 = 32;

/// A converged render of one frame's view.
#[derive(Clone, Debug)]
pub struct Reference {
    pub width: u32,
    pub height: u32,
    /// Mean radiance of each half (`spp / 2` samples each, independent seeds).
    pub halves: [Vec<Vec3>; 2],
    /// The camera it was rendered from (position, right, up, forward).
    pub camera: [f32; 12],
    /// Samples per pixel of both halves together.
    pub spp: u32,
}

impl Reference {
    /// The mean of both halves: the reference image.
    pub fn mean(&self) -> Vec<Vec3> {
        self.halves[0]
            .iter()
            .zip(&self.halves[1])
            .map(|(a, b)| (*a + *b) * 0.5)
            .collect()
    }

    /// This reference at `width` (a whole fraction of its own): each pixel the mean of the
    /// block it covers, which is that pixel's render with the block's samples (box filter).
    pub fn at_width(&self, width: u32) -> Reference {
        let f = (self.width / width.max(1)).max(1) as usize;
        if f == 1 {
            return self.clone();
        }
        let (w, h) = (self.width as usize / f, self.height as usize / f);
        let shrink = |image: &Vec<Vec3>| -> Vec<Vec3> {
            (0..w * h)
                .map(|i| {
                    let (x, y) = (i % w, i / w);
                    let mut sum = Vec3::ZERO;
                    for dy in 0..f {
                        for dx in 0..f {
                            sum += image[(y * f + dy) * self.width as usize + x * f + dx];
                        }
                    }
                    sum / (f * f) as f32
                })
                .collect()
        };
        Reference {
            width: w as u32,
            height: h as u32,
            halves: [shrink(&self.halves[0]), shrink(&self.halves[1])],
            camera: self.camera,
            spp: self.spp * (f * f) as u32,
        }
    }
}

/// Which frames want a reference, and those rendered so far (kept between runs of the same
/// replay at the same size: a later run reuses a reference whose camera matches its own).
#[derive(Default)]
pub struct References {
    /// Frames (the commit's frame number) to render a reference of.
    pub wanted: BTreeSet<u64>,
    pub spp: u32,
    pub done: BTreeMap<u64, Reference>,
    /// References rendered (not reused) since this was made.
    pub rendered: u32,
}

/// The camera of `u` as 12 floats.
fn camera_of(u: &GpuFrameUniforms) -> [f32; 12] {
    let mut c = [0.0; 12];
    for (i, v) in [
        u.camera_position,
        u.camera_right,
        u.camera_up,
        u.camera_forward,
    ]
    .iter()
    .enumerate()
    {
        c[i * 3..i * 3 + 3].copy_from_slice(v);
    }
    c
}

/// The engine's CPU tracer, rendering references on the side.
pub struct ReferencingTracer {
    inner: CpuTracer,
    reference: CpuTracer,
    refs: Arc<Mutex<References>>,
    progress: ProgressBar,
}

impl ReferencingTracer {
    /// An `OpenTracer` for `Engine::with_tracer`.
    pub fn open(refs: Arc<Mutex<References>>, progress: ProgressBar) -> OpenTracer {
        Box::new(move |_, _| {
            Ok(Box::new(ReferencingTracer {
                inner: CpuTracer::new(),
                reference: CpuTracer::new(),
                refs,
                progress,
            }) as Box<dyn Tracer>)
        })
    }

    /// Renders `spp` samples of `u`'s view on seed `seed`, in chunks.
    fn converge(
        &mut self,
        scene: &RenderScene,
        u: &GpuFrameUniforms,
        spp: u32,
        seed: u32,
    ) -> Result<Vec<Vec3>, RenderError> {
        let mut sum = vec![Vec3::ZERO; (u.width * u.height) as usize];
        let mut done = 0;
        while done < spp {
            let n = CHUNK_SPP.min(spp - done);
            let chunk = GpuFrameUniforms {
                spp: n,
                sample_base: done,
                seed,
                film_blend: 1.0,
                ..*u
            };
            self.reference.render(scene, &chunk)?;
            let film = self.reference.film()?;
            for (s, m) in sum.iter_mut().zip(&film.mean) {
                *s += *m * n as f32;
            }
            done += n;
            self.progress
                .inc(u64::from(n) * u64::from(u.width) * u64::from(u.height));
        }
        Ok(sum.into_iter().map(|s| s / spp.max(1) as f32).collect())
    }
}

impl Tracer for ReferencingTracer {
    fn name(&self) -> &'static str {
        self.inner.name()
    }

    fn device(&self) -> String {
        self.inner.device()
    }

    fn render(
        &mut self,
        scene: &RenderScene,
        u: &GpuFrameUniforms,
    ) -> Result<RenderStats, RenderError> {
        let stats = self.inner.render(scene, u)?;
        // One sample per pixel per frame (no scaling): the first sample is the frame number.
        let frame = u64::from(u.sample_base / u.spp.max(1));
        let camera = camera_of(u);
        let spp = {
            let refs = self.refs.lock().expect("references lock");
            // A reference of the same view at a whole multiple of this size serves too (its
            // box-averaged blocks are this size's pixels: the film's pixel filter is a box).
            let cached = refs.done.get(&frame).is_some_and(|r| {
                r.camera == camera
                    && r.width % u.width == 0
                    && r.width / u.width == r.height / u.height
            });
            (refs.wanted.contains(&frame) && !cached).then_some(refs.spp)
        };
        if let Some(spp) = spp {
            // A reference is box-filtered: never at a temporal-upscaling offset.
            let u = &GpuFrameUniforms {
                pixel_jitter: 0,
                ..*u
            };
            // Seeds of their own, the same for every frame (common random numbers): references
            // of consecutive frames differ by the change of the picture, hardly by their noise.
            let seed = u.seed.wrapping_mul(0x9E37_79B9) ^ 0x5EED_0000;
            let a = self.converge(scene, u, spp / 2, seed)?;
            let b = self.converge(scene, u, spp / 2, seed.wrapping_add(0x0101_0101))?;
            let mut refs = self.refs.lock().expect("references lock");
            refs.rendered += 1;
            refs.done.insert(
                frame,
                Reference {
                    width: u.width,
                    height: u.height,
                    halves: [a, b],
                    camera,
                    spp: spp / 2 * 2,
                },
            );
        }
        Ok(stats)
    }

    fn update(
        &mut self,
        scene: &RenderScene,
        writes: &[candela::scene::SceneWrite],
    ) -> Result<(), RenderError> {
        self.inner.update(scene, writes)
    }

    fn film(&mut self) -> Result<Film, RenderError> {
        self.inner.film()
    }

    fn film_view(&self) -> Option<FilmView<'_>> {
        self.inner.film_view()
    }

    fn clear(&mut self) {
        self.inner.clear()
    }

    fn record_guides(&mut self, on: bool) {
        self.inner.record_guides(on)
    }

    fn take_guides(&mut self) -> Option<candela::render::denoise::Guides> {
        self.inner.take_guides()
    }
}
