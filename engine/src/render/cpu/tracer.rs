//! [`CpuTracer`]: renders a `RenderScene` on all CPU cores.
//!
//! Owns: splitting the image into 16×16 tiles handed to rayon, running the integrator for every
//! sample of every pixel of a tile, and blending each pixel's mean into the film. Sums are
//! formed in sample order inside each pixel, so the film is bit-identical for any thread count.
//! Must not: change the scene (it reads the caller's `RenderScene` in place).

use std::ops::Range;
use std::time::Instant;

use glam::Vec3;
use rayon::prelude::*;

use super::guides::{FirstHit, Guide, fill_at, resolve_first_hit};
use super::integrator::{RayCounts, radiance};
use crate::layout::{GpuFrameUniforms, GpuLine};
use crate::render::denoise::Guides;
use crate::render::film::Film;
use crate::render::tracer::{FilmView, RenderError, RenderStats, Tracer};
use crate::scene::RenderScene;
use crate::trace::TraceScene;

/// Tile edge in pixels.
const TILE: u32 = 16;

/// One tile's index, pixel sums, rays and (when recorded) guides.
type TileResult = (u32, Vec<Vec3>, RayCounts, Vec<Guide>);

/// Sums `u.spp` samples (from `u.sample_base`) of every pixel of the rectangle `xs × ys`, on the
/// calling thread, row by row (left to right, top to bottom). The tile loop below and the
/// workload balancer's recorder and pool (`render/balance/`) share it, so a split frame holds
/// the very sums of a whole one. With `guides`, each pixel's denoiser guide (of its first
/// sample's camera ray, `guides::first_hit`) is pushed there in the same order.
#[allow(clippy::too_many_arguments)] // one frame's inputs and its two outputs
pub fn trace_rect(
    scene: &RenderScene,
    tracer: &TraceScene<'_>,
    u: &GpuFrameUniforms,
    lines: &[GpuLine],
    xs: Range<u32>,
    ys: Range<u32>,
    counts: &mut RayCounts,
    mut guides: Option<&mut Vec<Guide>>,
) -> Vec<Vec3> {
    let mut sums = Vec::with_capacity(xs.len() * ys.len());
    for y in ys {
        for x in xs.clone() {
            let mut sum = Vec3::ZERO;
            let mut first = FirstHit::Open;
            for s in 0..u.spp {
                let record = (s == 0 && guides.is_some()).then_some(&mut first);
                sum += radiance(
                    scene,
                    tracer,
                    u,
                    lines,
                    x,
                    y,
                    u.sample_base + s,
                    counts,
                    record,
                );
            }
            if let Some(g) = guides.as_deref_mut() {
                g.push(resolve_first_hit(scene, tracer, first));
            }
            sums.push(sum);
        }
    }
    sums
}

/// The CPU path tracer. It keeps only the film (and, when asked, the denoiser's guides of the
/// last frame): the scene is read from the caller.
pub struct CpuTracer {
    film: Film,
    /// Take the denoiser's guides from the first hits while tracing ([`Tracer::record_guides`]).
    record_guides: bool,
    guides: Option<Guides>,
}

impl CpuTracer {
    pub fn new() -> Self {
        Self {
            film: Film::new(0, 0),
            record_guides: false,
            guides: None,
        }
    }
}

impl Default for CpuTracer {
    fn default() -> Self {
        Self::new()
    }
}

impl Tracer for CpuTracer {
    fn name(&self) -> &'static str {
        "cpu"
    }

    fn device(&self) -> String {
        format!("CPU, {} threads", rayon::current_num_threads())
    }

    fn render(
        &mut self,
        scene: &RenderScene,
        u: &GpuFrameUniforms,
    ) -> Result<RenderStats, RenderError> {
        if u.width == 0 || u.height == 0 {
            return Err(RenderError::BadSize {
                width: u.width,
                height: u.height,
                reason: "width and height must be positive".into(),
            });
        }
        if self.film.width != u.width || self.film.height != u.height {
            self.film = Film::new(u.width, u.height);
        }
        let started = Instant::now();
        let tiles_x = u.width.div_ceil(TILE);
        let tiles_y = u.height.div_ceil(TILE);
        let tracer = scene.trace_scene();
        let lines = scene.lines();
        // Profiling: the tiles run on rayon's workers, which are not profiled; this scope is
        // the render thread's wait for them.
        // A frame that ends every path before shading its first hit leaves no guide to take.
        let record = self.record_guides && u.max_bounces > 0 && u.spp > 0;
        let tiles = puffin::profile_scope_custom!("trace tiles");
        let results: Vec<TileResult> = (0..tiles_x * tiles_y)
            .into_par_iter()
            .map(|tile| {
                let (x0, y0) = ((tile % tiles_x) * TILE, (tile / tiles_x) * TILE);
                let (x1, y1) = ((x0 + TILE).min(u.width), (y0 + TILE).min(u.height));
                let mut counts = RayCounts::default();
                let mut guides = Vec::new();
                let sums = trace_rect(
                    scene,
                    &tracer,
                    u,
                    &lines,
                    x0..x1,
                    y0..y1,
                    &mut counts,
                    record.then_some(&mut guides),
                );
                (tile, sums, counts, guides)
            })
            .collect();
        drop(tiles);
        puffin::profile_scope!("film blend");
        let mut counts = RayCounts::default();
        let mut guides = Guides::sky(u.width, u.height);
        let mut order = Vec::new();
        for (tile, sums, c, tile_guides) in results {
            counts += c;
            let (x0, y0) = ((tile % tiles_x) * TILE, (tile / tiles_x) * TILE);
            let x1 = (x0 + TILE).min(u.width);
            let w = (x1 - x0) as usize;
            for (i, s) in sums.iter().enumerate() {
                let (x, y) = (x0 as usize + i % w, y0 as usize + i / w);
                let pixel = &mut self.film.mean[y * u.width as usize + x];
                let new = *s / u.spp.max(1) as f32;
                *pixel += (new - *pixel) * u.film_blend;
            }
            if record {
                order.clear();
                order.extend((0..tile_guides.len()).map(|i| {
                    let (x, y) = (x0 as usize + i % w, y0 as usize + i / w);
                    y * u.width as usize + x
                }));
                fill_at(&mut guides, &order, tile_guides);
            }
        }
        self.guides = record.then_some(guides);
        self.film.samples = if u.film_blend >= 1.0 {
            u.spp
        } else {
            self.film.samples + u.spp
        };
        Ok(RenderStats {
            counts,
            seconds: started.elapsed().as_secs_f64(),
        })
    }

    fn update(
        &mut self,
        _scene: &RenderScene,
        _writes: &[crate::scene::SceneWrite],
    ) -> Result<(), RenderError> {
        Ok(())
    }

    fn film(&mut self) -> Result<Film, RenderError> {
        Ok(self.film.clone())
    }

    fn film_view(&self) -> Option<FilmView<'_>> {
        (self.film.width > 0 && self.film.height > 0).then_some(FilmView::Host(&self.film))
    }

    fn clear(&mut self) {
        self.film = Film::new(self.film.width, self.film.height);
    }

    fn record_guides(&mut self, on: bool) {
        self.record_guides = on;
        if !on {
            self.guides = None;
        }
    }

    fn take_guides(&mut self) -> Option<Guides> {
        self.guides.take()
    }
}
