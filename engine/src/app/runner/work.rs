//! [`FrameWork`]: what the engine computed for one frame, so that "model no more than a scene
//! needs" (DESIGN.md, Speed and accuracy) can be checked rather than assumed: a static scene
//! does no BVH work after its first frame, switched-off light groups leave the sampling
//! distribution, a rigid mover costs a TLAS build and no BLAS work, a deforming mesh costs
//! refits (and now and then a rebuild).
//!
//! Owns: the per-frame counts and their totals over a run ([`WorkTotals`]). Main thread.
//! Must not: time anything (the [`super::FrameReport`] does) or change the world.

use hecs::{Entity, World};

use crate::accel::{Upkeep, UpkeepStats};
use crate::assets::RenderSettings;
use crate::ecs::{Renderable, Static};

/// Counts of one frame's work. Instance counts are instance rows (one per placement of an
/// entity's model) as of the end of the frame.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FrameWork {
    /// Rows of entities marked [`Static`]: written once, never compared again.
    pub static_instances: u32,
    /// Rows of entities without [`Static`]: compared every frame, rewritten when they move.
    pub dynamic_instances: u32,
    /// Instance rows written this frame.
    pub instances_written: u32,
    pub blas_refits: u32,
    pub blas_rebuilds: u32,
    /// 0 or 1: the TLAS is rebuilt once in a frame where any instance changed.
    pub tlas_builds: u32,
    /// 0 or 1: the emissive-triangle table and its alias table.
    pub light_table_builds: u32,
    /// Bytes of geometry (BVH nodes, triangle blocks, triangles, vertices) the commit carries.
    pub geometry_bytes: usize,
    /// Emissive triangles in the light sampling distribution the render thread will use.
    pub lights: u32,
    /// Maximum scattering events per path (the level's render settings).
    pub max_bounces: u32,
    /// Physics bodies simulated this frame. Always 0: physics (rapier) is not built yet; the
    /// field is here so that sleeping bodies can be shown to cost nothing once it is.
    pub awake_bodies: u32,
}

impl FrameWork {
    /// The work of the frame whose upkeep returned `stats`.
    pub fn of(
        world: &World,
        upkeep: &Upkeep,
        stats: &UpkeepStats,
        render: &RenderSettings,
    ) -> Self {
        let (mut static_instances, mut dynamic_instances) = (0u32, 0u32);
        for (entity, is_static) in world
            .query::<(Entity, &Renderable, Option<&Static>)>()
            .iter()
            .map(|(e, _, s)| (e, s.is_some()))
        {
            let rows = upkeep.instance_rows(entity) as u32;
            if is_static {
                static_instances += rows;
            } else {
                dynamic_instances += rows;
            }
        }
        Self {
            static_instances,
            dynamic_instances,
            instances_written: stats.instances_written,
            blas_refits: stats.blas_refits,
            blas_rebuilds: stats.blas_rebuilds,
            tlas_builds: stats.tlas_builds,
            light_table_builds: stats.light_table_builds,
            geometry_bytes: stats.geometry_bytes,
            lights: upkeep.light_count(),
            max_bounces: render.max_bounces,
            awake_bodies: 0,
        }
    }
}

/// Sums and ranges of [`FrameWork`] over a run (for per-level summaries).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WorkTotals {
    pub frames: u32,
    /// Instance rows at the last frame.
    pub static_instances: u32,
    pub dynamic_instances: u32,
    pub instances_written: u64,
    pub blas_refits: u64,
    pub blas_rebuilds: u64,
    pub tlas_builds: u64,
    pub light_table_builds: u64,
    pub geometry_bytes: u64,
    /// Fewest and most lights in the sampling distribution over the run.
    pub lights_min: u32,
    pub lights_max: u32,
    pub max_bounces: u32,
    pub awake_bodies_max: u32,
}

impl WorkTotals {
    /// Adds one frame.
    pub fn add(&mut self, w: &FrameWork) {
        if self.frames == 0 {
            self.lights_min = w.lights;
        }
        self.frames += 1;
        self.static_instances = w.static_instances;
        self.dynamic_instances = w.dynamic_instances;
        self.instances_written += w.instances_written as u64;
        self.blas_refits += w.blas_refits as u64;
        self.blas_rebuilds += w.blas_rebuilds as u64;
        self.tlas_builds += w.tlas_builds as u64;
        self.light_table_builds += w.light_table_builds as u64;
        self.geometry_bytes += w.geometry_bytes as u64;
        self.lights_min = self.lights_min.min(w.lights);
        self.lights_max = self.lights_max.max(w.lights);
        self.max_bounces = w.max_bounces;
        self.awake_bodies_max = self.awake_bodies_max.max(w.awake_bodies);
    }

    /// Totals of `frames`.
    pub fn of<'a>(frames: impl IntoIterator<Item = &'a FrameWork>) -> Self {
        let mut t = Self::default();
        for w in frames {
            t.add(w);
        }
        t
    }
}

impl std::fmt::Display for WorkTotals {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        writeln!(
            f,
            "work over {} frames: instances {} static + {} dynamic, {} instance rows written",
            self.frames, self.static_instances, self.dynamic_instances, self.instances_written
        )?;
        writeln!(
            f,
            "  BVH: {} BLAS refits, {} BLAS rebuilds, {} TLAS builds; {} light table builds; \
             {} geometry bytes committed",
            self.blas_refits,
            self.blas_rebuilds,
            self.tlas_builds,
            self.light_table_builds,
            self.geometry_bytes
        )?;
        write!(
            f,
            "  lights sampled {}..={}, max bounces {}, awake physics bodies (most) {}",
            self.lights_min, self.lights_max, self.max_bounces, self.awake_bodies_max
        )
    }
}
