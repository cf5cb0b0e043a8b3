//! [`CpuPool`]: several CPU tracers, each with its own thread count, rendering the disjoint
//! units of one frame at once and composing them into one film.
//!
//! Each tracer is a rayon pool of its own; the tracers start together (one scoped thread each)
//! and render their units of the [`Split`] with the CPU tracer's pixel loop (`render::cpu::trace_rect`), so
//! every pixel gets the very samples a single [`crate::render::cpu::CpuTracer`] gives it and the
//! composed film equals its film sample for sample. Each tracer's time is its wall time from the
//! common start; each unit's time is the CPU time of the thread that rendered it.
//! Runs on: the calling thread plus the pools' threads. Must not: change the scene; it is not
//! wired into the render thread.

use std::time::Instant;

use glam::Vec3;
use rayon::prelude::*;

use super::error::BalanceError;
use super::measure::FrameTimes;
use super::record::trace_unit;
use super::split::{Split, unit_rows};
use crate::layout::{GpuFrameUniforms, GpuLine};
use crate::render::film::Film;
use crate::render::tracer::RayCounts;
use crate::scene::RenderScene;

/// Several CPU tracers of chosen thread counts.
pub struct CpuPool {
    pools: Vec<rayon::ThreadPool>,
}

/// One unit's result: its index, its pixel sums (row by row), its rays and its thread CPU time.
type UnitResult = (usize, Vec<Vec3>, RayCounts, f64);

impl CpuPool {
    /// One tracer per entry of `threads`, each with that many threads (at least one).
    pub fn new(threads: &[usize]) -> Result<Self, BalanceError> {
        let pools = threads
            .iter()
            .map(|&n| {
                rayon::ThreadPoolBuilder::new()
                    .num_threads(n.max(1))
                    .build()
                    .map_err(|e| BalanceError::Pool(e.to_string()))
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Self { pools })
    }

    /// Tracers in the pool.
    pub fn tracers(&self) -> usize {
        self.pools.len()
    }

    /// Renders the frame `u` describes with `split` (one tracer per split tracer) and blends
    /// it into `film` as `CpuTracer::render` does (`film = mix(film, mean, u.film_blend)`;
    /// resized and cleared when the size differs). Returns what the frame measured.
    pub fn render(
        &self,
        scene: &RenderScene,
        u: &GpuFrameUniforms,
        split: &Split,
        film: &mut Film,
    ) -> Result<FrameTimes, BalanceError> {
        if split.tracers() != self.pools.len() || split.units() != super::unit_count(u.height) {
            return Err(BalanceError::SplitMismatch {
                units: split.units(),
                tracers: split.tracers(),
                frame_units: super::unit_count(u.height),
                pool_tracers: self.pools.len(),
            });
        }
        if film.width != u.width || film.height != u.height {
            *film = Film::new(u.width, u.height);
        }
        let start = Instant::now();
        let mut unit_seconds = vec![0.0; split.units()];
        let part = self.render_part(scene, u, split, 0, film, start, &mut unit_seconds);
        film.samples = if u.film_blend >= 1.0 {
            u.spp
        } else {
            film.samples + u.spp
        };
        Ok(FrameTimes {
            split: split.clone(),
            tracer_seconds: part.tracer_seconds,
            unit_seconds,
        })
    }

    /// This pool's share of a split that other tracers share too: pool tracer `w` renders the
    /// units of split tracer `first + w`, blending them into `film` (already of the frame's
    /// size) and writing each unit's CPU time into `unit_seconds`. `film.samples` is left to
    /// the caller. Tracer times run from `start`.
    #[allow(clippy::too_many_arguments)] // one frame's inputs and outputs, one each
    pub fn render_part(
        &self,
        scene: &RenderScene,
        u: &GpuFrameUniforms,
        split: &Split,
        first: usize,
        film: &mut Film,
        start: Instant,
        unit_seconds: &mut [f64],
    ) -> PartTimes {
        // The line emitters, gathered once for every unit of the part.
        let lines = &scene.lines();
        let results: Vec<(Vec<UnitResult>, f64)> = std::thread::scope(|s| {
            let handles: Vec<_> = self
                .pools
                .iter()
                .enumerate()
                .map(|(w, pool)| {
                    s.spawn(move || {
                        let units: Vec<usize> = split.units_of(first + w).collect();
                        let done = pool.install(|| {
                            units
                                .par_iter()
                                .map(|&unit| render_unit(scene, u, lines, unit))
                                .collect::<Vec<_>>()
                        });
                        (done, start.elapsed().as_secs_f64())
                    })
                })
                .collect();
            handles
                .into_iter()
                .map(|h| {
                    h.join()
                        .unwrap_or_else(|_| panic!("a pool tracer panicked"))
                })
                .collect()
        });
        let mut part = PartTimes {
            tracer_seconds: vec![0.0; self.pools.len()],
            counts: RayCounts::default(),
        };
        for (w, (units, seconds)) in results.into_iter().enumerate() {
            part.tracer_seconds[w] = seconds;
            for (unit, sums, counts, cpu) in units {
                unit_seconds[unit] = cpu;
                part.counts += counts;
                let y0 = unit_rows(unit, u.height).start as usize * u.width as usize;
                for (i, s) in sums.iter().enumerate() {
                    let pixel = &mut film.mean[y0 + i];
                    let new = *s / u.spp.max(1) as f32;
                    *pixel += (new - *pixel) * u.film_blend;
                }
            }
        }
        part
    }
}

/// What [`CpuPool::render_part`] measured.
#[derive(Clone, Debug, Default)]
pub struct PartTimes {
    /// Seconds per pool tracer, from the common start to its last unit.
    pub tracer_seconds: Vec<f64>,
    /// Rays traced over all units.
    pub counts: RayCounts,
}

/// Renders one unit on the calling thread.
fn render_unit(
    scene: &RenderScene,
    u: &GpuFrameUniforms,
    lines: &[GpuLine],
    unit: usize,
) -> UnitResult {
    let (sums, counts, seconds) = trace_unit(scene, u, lines, unit);
    (unit, sums, counts, seconds)
}
