//! [`record_unit_costs`]: the render cost of every work unit of one frame on the CPU tracer.
//!
//! Each unit is rendered whole on one rayon worker with the CPU tracer's own pixel loop
//! ([`trace_rect`]), and timed by that thread's CPU time (`CLOCK_THREAD_CPUTIME_ID`), so other
//! work on a shared machine inflates the figures far less than wall time would. The film is
//! thrown away: this measures, it does not render images.
//! Runs on: the calling thread plus the rayon pool. Must not: change the scene.

use rayon::prelude::*;

use super::split::{unit_count, unit_rows};
use crate::layout::{GpuFrameUniforms, GpuLine};
use crate::render::cpu::integrator::RayCounts;
use crate::render::cpu::trace_rect;
use crate::scene::RenderScene;

/// What one unit cost.
#[derive(Clone, Copy, Debug, Default)]
pub struct UnitCost {
    /// CPU time of the thread that rendered it, seconds.
    pub seconds: f64,
    /// Rays traced (camera + bounce + shadow).
    pub rays: u64,
}

/// CPU time of the calling thread, seconds (0 where the clock is unavailable).
pub(super) fn thread_cpu_seconds() -> f64 {
    let mut ts = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `ts` is a valid, writable timespec for the duration of the call.
    let rc = unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut ts) };
    if rc != 0 {
        return 0.0;
    }
    ts.tv_sec as f64 + ts.tv_nsec as f64 * 1e-9
}

/// One unit rendered whole on the calling thread: its pixel sums (row-major), the rays traced
/// and the thread's CPU seconds. The pool and the recorder both use it; `lines` are the scene's
/// line emitters ([`RenderScene::lines`]), gathered once per frame by the caller.
pub(super) fn trace_unit(
    scene: &RenderScene,
    u: &GpuFrameUniforms,
    lines: &[GpuLine],
    unit: usize,
) -> (Vec<glam::Vec3>, RayCounts, f64) {
    let tracer = scene.trace_scene();
    let mut counts = RayCounts::default();
    let start = thread_cpu_seconds();
    let sums = trace_rect(
        scene,
        &tracer,
        u,
        lines,
        0..u.width,
        unit_rows(unit, u.height),
        &mut counts,
        None,
    );
    (sums, counts, thread_cpu_seconds() - start)
}

/// Renders every unit of the frame `u` describes (all `u.spp` samples of every pixel) and
/// returns each unit's cost, top to bottom.
pub fn record_unit_costs(scene: &RenderScene, u: &GpuFrameUniforms) -> Vec<UnitCost> {
    let lines = &scene.lines();
    (0..unit_count(u.height))
        .into_par_iter()
        .map(|unit| {
            let (sums, counts, seconds) = trace_unit(scene, u, lines, unit);
            std::hint::black_box(sums);
            UnitCost {
                seconds,
                rays: counts.camera + counts.bounce + counts.shadow,
            }
        })
        .collect()
}
