//! The engine's built-in deformer: travelling waves on a grid ([`crate::assets::WaveDesc`]),
//! run every frame in the pose phase on every entity with [`Waves`] and [`Deformable`]; on a
//! water with a [`WaterSim`] the simulated ripples (stepped in the fixed steps,
//! `sim::water`) are added on top of the swell.
//!
//! Owns: the swell's height field, its analytic normals, and on simulated waters the total
//! height's normals by central differences. Main thread, pose phase.
//! Must not: touch the BVH (the upkeep refits from the `Deformable` it marks dirty), or step
//! the simulation (the fixed steps do).

use glam::Vec3;
use hecs::World;

use crate::assets::WaveDesc;
use crate::ecs::Deformable;
use crate::sim::water::{GridLayout, WaterSim};

/// Waves on a mesh whose rest positions are `base` (object space, metres).
#[derive(Clone, Debug, PartialEq)]
pub struct Waves {
    pub desc: WaveDesc,
    pub base: Vec<Vec3>,
}

impl Waves {
    pub fn new(desc: WaveDesc, base: Vec<Vec3>) -> Self {
        Self { desc, base }
    }

    /// Height and its x/z slopes at rest position `p`, time `t` seconds.
    fn height(&self, p: Vec3, t: f32) -> (f32, f32, f32) {
        let k = std::f32::consts::TAU / self.desc.wavelength.max(1e-3);
        let w = k * self.desc.speed;
        let a = self.desc.amplitude;
        let phase1 = k * p.x - w * t;
        let k2 = 0.7 * k;
        let phase2 = k2 * (p.x + p.z) - 1.3 * w * t;
        let h = a * phase1.sin() + 0.5 * a * phase2.sin();
        let dx = a * k * phase1.cos() + 0.5 * a * k2 * phase2.cos();
        let dz = 0.5 * a * k2 * phase2.cos();
        (h, dx, dz)
    }
}

/// Moves every waving mesh to time `t` (seconds since the start): the swell, plus the
/// simulated ripples where the water has a [`WaterSim`].
pub fn waves_system(world: &mut World, t: f64) {
    let t = t as f32;
    for (waves, deformable, sim) in
        world.query_mut::<(&Waves, &mut Deformable, Option<&WaterSim>)>()
    {
        let sim = sim.filter(|s| s.field.layout.len() == waves.base.len());
        let normals = match sim {
            Some(sim) => simulated(waves, &mut deformable.positions, sim, t),
            None => swell(waves, &mut deformable.positions, t),
        };
        deformable.normals = Some(normals);
        deformable.dirty = true;
    }
}

/// The swell alone, with its analytic normals.
fn swell(waves: &Waves, positions: &mut [Vec3], t: f32) -> Vec<Vec3> {
    let mut normals = Vec::with_capacity(waves.base.len());
    for (i, p) in waves.base.iter().enumerate() {
        let (h, dx, dz) = waves.height(*p, t);
        if let Some(out) = positions.get_mut(i) {
            *out = Vec3::new(p.x, p.y + h, p.z);
        }
        normals.push(Vec3::new(-dx, 1.0, -dz).normalize());
    }
    normals
}

/// Swell plus simulated heights; normals by central differences of that total height
/// (one-sided on the edges).
fn simulated(waves: &Waves, positions: &mut [Vec3], sim: &WaterSim, t: f32) -> Vec<Vec3> {
    let ripples = sim.field.heights();
    let total: Vec<f32> = (waves.base.iter().zip(ripples))
        .map(|(p, r)| waves.height(*p, t).0 + r)
        .collect();
    for ((out, p), h) in positions.iter_mut().zip(&waves.base).zip(&total) {
        *out = Vec3::new(p.x, p.y + h, p.z);
    }
    let GridLayout {
        columns,
        rows,
        dx,
        dz,
        ..
    } = sim.field.layout;
    let mut normals = Vec::with_capacity(total.len());
    for iz in 0..rows {
        for ix in 0..columns {
            let (x0, x1) = (ix.saturating_sub(1), (ix + 1).min(columns - 1));
            let (z0, z1) = (iz.saturating_sub(1), (iz + 1).min(rows - 1));
            let slope_x =
                (total[x1 + iz * columns] - total[x0 + iz * columns]) / ((x1 - x0) as f32 * dx);
            let slope_z =
                (total[ix + z1 * columns] - total[ix + z0 * columns]) / ((z1 - z0) as f32 * dz);
            normals.push(Vec3::new(-slope_x, 1.0, -slope_z).normalize());
        }
    }
    normals
}
