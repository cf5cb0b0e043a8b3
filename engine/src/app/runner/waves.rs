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
    /// The mesh was last written still (no swell, simulated water still): nothing to rewrite
    /// or refit until the water moves again.
    pub written_still: bool,
    /// The time (seconds) and the simulated water's step count the mesh was last written at:
    /// a frame with neither changed (the engine paused, or no fixed step since) rewrites and
    /// refits nothing.
    pub written_at: Option<(f32, u64)>,
}

impl Waves {
    pub fn new(desc: WaveDesc, base: Vec<Vec3>) -> Self {
        Self {
            desc,
            base,
            written_still: false,
            written_at: None,
        }
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
/// simulated ripples where the water has a [`WaterSim`]. A simulated water without swell
/// whose surface is still ([`crate::sim::water::HeightField::is_still`]) is written once and
/// then left alone (no refit, nothing committed) until it moves.
pub fn waves_system(world: &mut World, t: f64) {
    let t = t as f32;
    for (waves, deformable, sim) in
        world.query_mut::<(&mut Waves, &mut Deformable, Option<&WaterSim>)>()
    {
        let sim = sim.filter(|s| s.field.layout.len() == waves.base.len());
        let still = waves.desc.amplitude == 0.0 && sim.is_some_and(|s| s.field.is_still());
        if still && waves.written_still {
            continue;
        }
        let at = (t, sim.map_or(0, |s| s.field.steps()));
        if waves.written_at == Some(at) {
            continue;
        }
        waves.written_at = Some(at);
        waves.written_still = still;
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assets::WaterSimDesc;

    fn grid(n: usize) -> Vec<Vec3> {
        (0..n * n)
            .map(|i| Vec3::new((i % n) as f32 * 0.1, 0.0, (i / n) as f32 * 0.1))
            .collect()
    }

    /// A still simulated water without swell is written once, then left alone (no refit)
    /// until a ripple moves it; with a swell it is written every frame.
    #[test]
    fn a_still_water_is_not_rewritten_until_it_moves() {
        let base = grid(8);
        let sim_desc = WaterSimDesc {
            wave_speed: 1.0,
            damping: 0.5,
            substeps: 1,
            push: 0.1,
            start_at_rest: false,
        };
        let desc = |amplitude| WaveDesc {
            amplitude,
            wavelength: 2.0,
            speed: 0.5,
            simulate: Some(sim_desc),
        };
        let mut world = World::new();
        let mut spawn = |amplitude: f32| {
            let sim = WaterSim::on_grid(&base, sim_desc).expect("a grid");
            let deformable = Deformable {
                mesh: 0,
                positions: base.clone(),
                normals: None,
                dirty: false,
            };
            world.spawn((Waves::new(desc(amplitude), base.clone()), deformable, sim))
        };
        let (calm, swell) = (spawn(0.0), spawn(0.02));
        let dirty = |world: &mut World, e| {
            let mut d = world.get::<&mut Deformable>(e).expect("deformable");
            std::mem::replace(&mut d.dirty, false)
        };
        waves_system(&mut world, 0.0);
        assert!(dirty(&mut world, calm) && dirty(&mut world, swell));
        waves_system(&mut world, 0.1);
        assert!(!dirty(&mut world, calm), "a still water was rewritten");
        assert!(dirty(&mut world, swell), "a swell must move every frame");
        if let Ok(mut sim) = world.get::<&mut WaterSim>(calm) {
            sim.field.raise(3, 3, 0.05);
        }
        waves_system(&mut world, 0.2);
        assert!(dirty(&mut world, calm), "a ripple did not reach the mesh");
        let p = world
            .get::<&Deformable>(calm)
            .expect("deformable")
            .positions[3 + 3 * 8];
        assert!((p.y - 0.05).abs() < 1e-6, "{p}");
    }

    /// On a simulated water the analytic swell stays the base: each vertex is its rest
    /// position raised by the swell plus the ripple, and the normals are the central
    /// differences of that total height (one-sided on the edges), not the swell's analytic
    /// normals.
    #[test]
    fn ripples_ride_on_the_swell_with_central_difference_normals() {
        let n = 8;
        let base = grid(n);
        let sim_desc = WaterSimDesc {
            wave_speed: 1.0,
            damping: 0.5,
            substeps: 1,
            push: 0.1,
            start_at_rest: false,
        };
        let desc = WaveDesc {
            amplitude: 0.02,
            wavelength: 0.7,
            speed: 0.5,
            simulate: Some(sim_desc),
        };
        let mut sim = WaterSim::on_grid(&base, sim_desc).expect("a grid");
        sim.field.raise(3, 4, 0.05);
        let ripples = sim.field.heights().to_vec();
        let waves = Waves::new(desc, base.clone());
        let deformable = Deformable {
            mesh: 0,
            positions: base.clone(),
            normals: None,
            dirty: false,
        };
        let mut world = World::new();
        let e = world.spawn((waves.clone(), deformable, sim));
        let t = 0.37;
        waves_system(&mut world, f64::from(t));
        let d = world.get::<&Deformable>(e).expect("deformable");
        let normals = d.normals.as_ref().expect("normals written");
        let total = |ix: usize, iz: usize| {
            let i = ix + iz * n;
            waves.height(base[i], t).0 + ripples[i]
        };
        for (i, p) in d.positions.iter().enumerate() {
            let expected = base[i].y + total(i % n, i / n);
            assert!(
                (p.y - expected).abs() < 1e-6,
                "vertex {i}: {p} vs {expected}"
            );
            assert_eq!(
                (p.x, p.z),
                (base[i].x, base[i].z),
                "vertex {i} moved sideways"
            );
        }
        // An interior vertex beside the ripple, and a corner (one-sided).
        let h = 0.1;
        for (ix, iz, x0, x1, z0, z1) in [(2, 4, 1, 3, 3, 5), (0, 0, 0, 1, 0, 1)] {
            let slope_x = (total(x1, iz) - total(x0, iz)) / ((x1 - x0) as f32 * h);
            let slope_z = (total(ix, z1) - total(ix, z0)) / ((z1 - z0) as f32 * h);
            let expected = Vec3::new(-slope_x, 1.0, -slope_z).normalize();
            let got = normals[ix + iz * n];
            assert!(
                got.abs_diff_eq(expected, 1e-5),
                "normal at ({ix}, {iz}): {got} vs {expected}"
            );
        }
    }
}
