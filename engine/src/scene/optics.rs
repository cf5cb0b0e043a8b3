//! What a surface does to a laser beam (or any other ideal ray game code follows): mirror,
//! glass, or a stop — decided in one place from the packed material, beside the packing
//! ([`super::materials`]) that wrote it, so game code never reads `layout` constants.
//!
//! Owns: [`Optics`] and [`optics_of`]. Any thread, pure. Must not: trace rays or bend them
//! (the caller reflects or refracts).

use crate::layout::{GpuMaterial, MATERIAL_CONDUCTOR, MATERIAL_DIELECTRIC, MATERIAL_METAL_ROUGH};

/// Roughness below which a conductor (or a fully metallic metal-rough material) reflects a
/// beam like a mirror.
pub const MIRROR_ROUGHNESS: f32 = 0.1;

/// What a surface does to an ideal ray.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Optics {
    /// A mirror: the ray reflects.
    Mirror,
    /// Glass of index `ior`: the ray refracts (or reflects totally inside).
    Glass { ior: f32 },
    /// Anything else: the ray stops.
    Opaque,
}

/// The optics of packed material `m`.
pub fn optics_of(m: &GpuMaterial) -> Optics {
    match m.kind {
        MATERIAL_CONDUCTOR if m.roughness < MIRROR_ROUGHNESS => Optics::Mirror,
        MATERIAL_METAL_ROUGH if m.metallic >= 0.9 && m.roughness < MIRROR_ROUGHNESS => {
            Optics::Mirror
        }
        MATERIAL_DIELECTRIC if m.ior.is_finite() && m.ior > 0.0 => Optics::Glass { ior: m.ior },
        _ => Optics::Opaque,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn smooth_metal_mirrors_glass_refracts_rough_stops() {
        let mut m = GpuMaterial {
            kind: MATERIAL_CONDUCTOR,
            roughness: 0.05,
            ..bytemuck::Zeroable::zeroed()
        };
        assert_eq!(optics_of(&m), Optics::Mirror);
        m.roughness = 0.5;
        assert_eq!(optics_of(&m), Optics::Opaque);
        m.kind = MATERIAL_DIELECTRIC;
        m.ior = 1.5;
        assert_eq!(optics_of(&m), Optics::Glass { ior: 1.5 });
        m.ior = f32::NAN;
        assert_eq!(optics_of(&m), Optics::Opaque);
    }
}
