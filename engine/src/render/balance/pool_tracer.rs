//! [`PoolTracer`]: several tracers on one frame, as one [`Tracer`] the render thread runs like
//! any other (`TracerChoice::Pool`). Brigade §4.3: the GPU tracer and CPU tracers of chosen
//! thread counts render the disjoint work units a [`Balancer`] assigns from the previous
//! frame's measurements, and their results are composed into one film that converging,
//! scaling, denoising and presenting treat like a single tracer's.
//!
//! Composition: the pool's film (on the host) is the one that converges. The GPU tracer renders
//! its units with film blend 1 (so its film holds this frame's mean for them) and the pool
//! blends those rows into its film with the frame's blend factor; the CPU tracers blend theirs
//! in place ([`CpuPool::render_part`]). A unit that changes tracer between frames therefore
//! keeps its history. The CPU units get the very samples a single CPU tracer gives them;
//! the GPU's equal the GPU tracer's (the same seeds per pixel, within WGSL's arithmetic).
//!
//! Timing: each tracer's time runs from the common start to its done signal (the GPU's
//! includes reading its film back). The GPU reports no per-unit times, so each of its units is
//! given the GPU's time divided by its unit count; the CPU tracers' units carry their thread
//! CPU time. Render thread only. Must not: change the scene, or know about windows.

use std::time::Instant;

use super::pool::CpuPool;
use super::scheme::{Balancer, SchemeKind};
use super::split::unit_rows;
use super::{FrameTimes, unit_count};
use crate::layout::GpuFrameUniforms;
use crate::render::film::Film;
use crate::render::gpu::{GpuContext, GpuTracer};
use crate::render::tracer::{FilmView, RenderError, RenderStats, Tracer};
use crate::scene::{RenderScene, SceneWrite};

/// What a pool holds and how it splits a frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PoolSpec {
    /// Whether the GPU tracer is tracer 0 of the pool.
    pub gpu: bool,
    /// CPU tracers, after the GPU one.
    pub cpu_tracers: u8,
    /// Threads of each CPU tracer (at least one).
    pub cpu_threads: u8,
    /// The balancing scheme.
    pub scheme: SchemeKind,
}

impl PoolSpec {
    /// Tracers in the pool.
    pub fn tracers(&self) -> usize {
        self.gpu as usize + self.cpu_tracers as usize
    }
}

/// The tracer pool.
pub struct PoolTracer {
    spec: PoolSpec,
    gpu: Option<GpuTracer>,
    cpu: CpuPool,
    /// The scheme, for frames of `units` units (rebuilt when the height changes).
    balancer: Option<(usize, Box<dyn Balancer>)>,
    last: Option<FrameTimes>,
    film: Film,
}

impl PoolTracer {
    /// The pool `spec` describes over `scene`; `context` is the window's device when there is
    /// one (the GPU tracer then shares it), otherwise a headless device is opened when the
    /// pool has a GPU tracer.
    pub fn new(
        spec: PoolSpec,
        context: Option<std::sync::Arc<GpuContext>>,
        scene: &RenderScene,
    ) -> Result<Self, RenderError> {
        if spec.tracers() == 0 {
            return Err(RenderError::Device("a tracer pool needs at least one tracer".into()));
        }
        let gpu = if spec.gpu {
            let context = match context {
                Some(context) => context,
                None => GpuContext::headless()?,
            };
            Some(GpuTracer::new(context, scene)?)
        } else {
            None
        };
        let threads = vec![spec.cpu_threads.max(1) as usize; spec.cpu_tracers as usize];
        let cpu = CpuPool::new(&threads).map_err(|e| RenderError::Device(e.to_string()))?;
        Ok(Self {
            spec,
            gpu,
            cpu,
            balancer: None,
            last: None,
            film: Film::new(0, 0),
        })
    }

    /// What the last frame measured (its split and times).
    pub fn last_times(&self) -> Option<&FrameTimes> {
        self.last.as_ref()
    }

    /// The split for the next frame of `units` units.
    fn next_split(&mut self, units: usize) -> super::Split {
        let tracers = self.spec.tracers();
        let rebuild = !matches!(&self.balancer, Some((n, _)) if *n == units);
        if rebuild {
            self.balancer = Some((units, self.spec.scheme.build(units, tracers)));
            self.last = None;
        }
        let last = self.last.as_ref();
        match &mut self.balancer {
            Some((_, balancer)) => balancer.next(last),
            None => unreachable!("the balancer was just built"),
        }
    }
}

impl Tracer for PoolTracer {
    fn name(&self) -> &'static str {
        "pool"
    }

    fn device(&self) -> String {
        let gpu = match &self.gpu {
            Some(gpu) => format!("gpu ({}) + ", gpu.device()),
            None => String::new(),
        };
        format!(
            "pool: {gpu}{} cpu × {} threads, scheme {:?}",
            self.spec.cpu_tracers, self.spec.cpu_threads, self.spec.scheme
        )
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
        let units = unit_count(u.height);
        if units < self.spec.tracers() {
            return Err(RenderError::BadSize {
                width: u.width,
                height: u.height,
                reason: format!(
                    "{units} work units cannot keep {} tracers busy",
                    self.spec.tracers()
                ),
            });
        }
        let split = self.next_split(units);
        if self.film.width != u.width || self.film.height != u.height {
            self.film = Film::new(u.width, u.height);
        }
        let start = Instant::now();
        let fresh = GpuFrameUniforms {
            film_blend: 1.0,
            ..*u
        };
        let gpu_units: Vec<u32> = match self.gpu {
            Some(_) => split.units_of(0).map(|unit| unit as u32).collect(),
            None => Vec::new(),
        };
        let submitted = match &mut self.gpu {
            Some(gpu) => Some(gpu.submit_units(&fresh, &gpu_units)?),
            None => None,
        };
        let first_cpu = self.spec.gpu as usize;
        let mut unit_seconds = vec![0.0; units];
        let part = self.cpu.render_part(
            scene,
            u,
            &split,
            first_cpu,
            &mut self.film,
            start,
            &mut unit_seconds,
        );
        let mut counts = part.counts;
        let mut tracer_seconds = Vec::with_capacity(self.spec.tracers());
        if let (Some(gpu), Some(started)) = (&mut self.gpu, submitted) {
            let stats = gpu.finish(&fresh, started)?;
            let gpu_film = gpu.film()?;
            let seconds = start.elapsed().as_secs_f64();
            counts += stats.counts;
            let width = u.width as usize;
            for &unit in &gpu_units {
                unit_seconds[unit as usize] = seconds / gpu_units.len().max(1) as f64;
                let rows = unit_rows(unit as usize, u.height);
                let range = rows.start as usize * width..rows.end as usize * width;
                for i in range {
                    let pixel = &mut self.film.mean[i];
                    *pixel += (gpu_film.mean[i] - *pixel) * u.film_blend;
                }
            }
            tracer_seconds.push(seconds);
        }
        tracer_seconds.extend(part.tracer_seconds);
        self.film.samples = if u.film_blend >= 1.0 {
            u.spp
        } else {
            self.film.samples + u.spp
        };
        self.last = Some(FrameTimes {
            split,
            tracer_seconds,
            unit_seconds,
        });
        Ok(RenderStats {
            counts,
            seconds: start.elapsed().as_secs_f64(),
        })
    }

    fn update(&mut self, scene: &RenderScene, writes: &[SceneWrite]) -> Result<(), RenderError> {
        match &mut self.gpu {
            Some(gpu) => gpu.update(scene, writes),
            None => Ok(()),
        }
    }

    fn film(&mut self) -> Result<Film, RenderError> {
        Ok(self.film.clone())
    }

    fn film_view(&self) -> Option<FilmView<'_>> {
        (self.film.width > 0).then_some(FilmView::Host(&self.film))
    }

    fn clear(&mut self) {
        self.film = Film::new(self.film.width, self.film.height);
        if let Some(gpu) = &mut self.gpu {
            gpu.clear();
        }
    }
}
