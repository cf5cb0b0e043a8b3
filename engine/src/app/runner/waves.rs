//! The engine's built-in deformer: travelling waves on a grid ([`crate::assets::WaveDesc`]),
//! run every fixed step on every entity with [`Waves`] and [`Deformable`].
//!
//! Owns: the wave height field and its analytic normals. Main thread, inside the fixed steps.
//! Must not: touch the BVH (the upkeep refits from the `Deformable` it marks dirty).

use glam::Vec3;
use hecs::World;

use crate::assets::WaveDesc;
use crate::ecs::Deformable;

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

/// Moves every waving mesh to time `t` (seconds since the start).
pub fn waves_system(world: &mut World, t: f64) {
    for (waves, deformable) in world.query_mut::<(&Waves, &mut Deformable)>() {
        let t = t as f32;
        let mut normals = Vec::with_capacity(waves.base.len());
        for (i, p) in waves.base.iter().enumerate() {
            let (h, dx, dz) = waves.height(*p, t);
            if let Some(out) = deformable.positions.get_mut(i) {
                *out = Vec3::new(p.x, p.y + h, p.z);
            }
            normals.push(Vec3::new(-dx, 1.0, -dz).normalize());
        }
        deformable.normals = Some(normals);
        deformable.dirty = true;
    }
}
