//! A tracer that traces only the frames a measurement needs: [`Skipping`] wraps another
//! tracer (`bench picture-ruins` wraps `picture_tracer::ReferencingTracer`) and hands it the
//! frames in its `live` set; every other frame costs nothing but a black film of the frame's
//! size. Long replays are then played to their measured frames at the cost of the game's
//! fixed steps; the caller cuts the camera (`Engine::cut`) at the start of each traced window,
//! so no black frame reaches the history a compared frame is built from.
//!
//! Owns: [`Skipping`]. Render thread (the engine's). Must not: change a traced frame: a live
//! frame is the inner tracer's, untouched.

use std::collections::BTreeSet;

use candela::layout::GpuFrameUniforms;
use candela::render::film::Film;
use candela::render::{FilmView, OpenTracer, RenderError, RenderStats, Tracer};
use candela::scene::RenderScene;

/// The frame number of `u`: the first sample's index over the samples per pixel (fixed size,
/// no workload scaling: `sample_base` is the commit's frame times `spp`).
pub fn frame_of(u: &GpuFrameUniforms) -> u64 {
    u64::from(u.sample_base / u.spp.max(1))
}

/// Traces the frames in `live` with the inner tracer; skips the rest.
pub struct Skipping {
    inner: Box<dyn Tracer>,
    live: BTreeSet<u64>,
    /// Whether the last frame was traced, and its film's size (pixels).
    traced: bool,
    size: (u32, u32),
}

impl Skipping {
    /// An `OpenTracer` for `Engine::with_tracer`, around the one `inner` opens.
    pub fn open(inner: OpenTracer, live: BTreeSet<u64>) -> OpenTracer {
        Box::new(move |context, scene| {
            Ok(Box::new(Skipping {
                inner: inner(context, scene)?,
                live,
                traced: false,
                size: (0, 0),
            }) as Box<dyn Tracer>)
        })
    }
}

impl Tracer for Skipping {
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
        self.size = (u.width, u.height);
        self.traced = self.live.contains(&frame_of(u));
        if self.traced {
            self.inner.render(scene, u)
        } else {
            Ok(RenderStats::default())
        }
    }

    fn update(
        &mut self,
        scene: &RenderScene,
        writes: &[candela::scene::SceneWrite],
    ) -> Result<(), RenderError> {
        self.inner.update(scene, writes)
    }

    fn film(&mut self) -> Result<Film, RenderError> {
        if self.traced {
            self.inner.film()
        } else {
            Ok(Film::new(self.size.0, self.size.1))
        }
    }

    fn film_view(&self) -> Option<FilmView<'_>> {
        self.traced.then(|| self.inner.film_view()).flatten()
    }

    fn clear(&mut self) {
        self.inner.clear()
    }

    fn record_guides(&mut self, on: bool) {
        self.inner.record_guides(on)
    }

    fn take_guides(&mut self) -> Option<candela::render::denoise::Guides> {
        self.traced.then(|| self.inner.take_guides()).flatten()
    }
}
