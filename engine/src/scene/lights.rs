//! Lights: the emissive-triangle list with its alias table and its light tree, and the sun and
//! sky parameters.
//!
//! Owns: finding every emissive triangle of every instance (in world space), the picking
//! distribution (proportional to area × emitted luminance; Vose's alias method, so picking costs
//! O(1)), the light tree over the same triangles (built in `light_tree.rs`, one method beside
//! the table: `LightSampling`), and turning level sun/sky descriptions into frame uniforms.
//! Must not: trace rays or sample directions (the tracers do, from these tables).

use glam::Vec3;

use super::light_tree::{LightTree, build_tree};
use crate::assets::{SkyDesc, SunDesc};
use crate::layout::{
    GpuFrameUniforms, GpuInstance, GpuLight, GpuMaterial, GpuTriangle, GpuVertex, INVALID,
    MATERIAL_FLAG_TWO_SIDED_EMISSION, SKY_CONSTANT, SKY_GRADIENT, SKY_PHYSICAL,
};

/// Emissive triangles, the alias table that picks them by power and the light tree that picks
/// them by importance from a shading point.
#[derive(Clone, Debug, Default)]
pub struct LightTable {
    /// Never empty: a scene without emitters holds one zero-weight placeholder (storage
    /// buffers may not be empty); `count` says how many are real.
    pub lights: Vec<GpuLight>,
    pub count: u32,
    /// Sum of `weight` over all lights.
    pub weight_total: f32,
    /// The light tree over the first `count` lights (leaves name their index in `lights`).
    pub tree: LightTree,
}

/// A point of an instance in world space.
pub fn world_point(instance: &GpuInstance, p: [f32; 3]) -> Vec3 {
    let r = &instance.world_from_object;
    let p = Vec3::from(p).extend(1.0);
    Vec3::new(
        glam::Vec4::from(r[0]).dot(p),
        glam::Vec4::from(r[1]).dot(p),
        glam::Vec4::from(r[2]).dot(p),
    )
}

/// Finds every emissive triangle (material emission weight > 0, area > 0) of every instance;
/// `triangle_counts[i]` is the number of triangles of instance `i`'s mesh.
pub fn build_lights(
    instances: &[GpuInstance],
    triangle_counts: &[u32],
    triangles: &[GpuTriangle],
    vertices: &[GpuVertex],
    materials: &[GpuMaterial],
) -> LightTable {
    let mut lights = Vec::new();
    let mut two_sided = Vec::new();
    for (instance_index, instance) in instances.iter().enumerate() {
        // Off: emits nothing. Unsampled: out of sight of the camera's render area (still
        // emits when hit, with MIS weight 1; see `layout::INSTANCE_FLAG_UNSAMPLED`).
        let left_out =
            crate::layout::INSTANCE_FLAG_EMISSION_OFF | crate::layout::INSTANCE_FLAG_UNSAMPLED;
        if instance.flags & left_out != 0 {
            continue;
        }
        let first = instance.triangle_base as usize;
        let count = triangle_counts.get(instance_index).copied().unwrap_or(0) as usize;
        for local in 0..count {
            let Some(tri) = triangles.get(first + local) else {
                break;
            };
            let material_index = if instance.material_override != INVALID {
                instance.material_override
            } else {
                tri.material
            };
            let Some(material) = materials.get(material_index as usize) else {
                continue;
            };
            let emission_weight = material.emission[3];
            if emission_weight <= 0.0 {
                continue;
            }
            let v = tri.indices.map(|i| {
                vertices
                    .get((instance.vertex_base + i) as usize)
                    .map(|v| world_point(instance, v.position))
                    .unwrap_or(Vec3::ZERO)
            });
            let area = 0.5 * (v[1] - v[0]).cross(v[2] - v[0]).length();
            let weight = area * emission_weight;
            if !(weight > 0.0 && weight.is_finite()) {
                continue;
            }
            two_sided.push(material.flags & MATERIAL_FLAG_TWO_SIDED_EMISSION != 0);
            lights.push(GpuLight {
                p0: v[0].to_array(),
                instance: instance_index as u32,
                p1: v[1].to_array(),
                triangle: local as u32,
                p2: v[2].to_array(),
                weight,
                alias_threshold: 1.0,
                alias_index: 0,
                _padding: [0; 2],
            });
        }
    }
    let count = lights.len() as u32;
    let weight_total = build_alias(&mut lights);
    // A two-sided emitter sends its power out of both faces (PBRT-v4's DiffuseAreaLight).
    let phi: Vec<f32> = lights
        .iter()
        .zip(&two_sided)
        .map(|(l, &two)| if two { 2.0 * l.weight } else { l.weight })
        .collect();
    let tree = build_tree(&lights, &phi, &two_sided, instances.len(), triangle_counts);
    if lights.is_empty() {
        lights.push(GpuLight {
            p0: [0.0; 3],
            instance: INVALID,
            p1: [0.0; 3],
            triangle: INVALID,
            p2: [0.0; 3],
            weight: 0.0,
            alias_threshold: 1.0,
            alias_index: 0,
            _padding: [0; 2],
        });
    }
    LightTable {
        lights,
        count,
        weight_total,
        tree,
    }
}

/// Fills `alias_threshold`/`alias` (Vose 1991) and returns the total weight.
fn build_alias(lights: &mut [GpuLight]) -> f32 {
    let n = lights.len();
    let total: f64 = lights.iter().map(|l| l.weight as f64).sum();
    if n == 0 || total <= 0.0 {
        return 0.0;
    }
    let mut scaled: Vec<f64> = lights
        .iter()
        .map(|l| l.weight as f64 * n as f64 / total)
        .collect();
    let (mut small, mut large): (Vec<usize>, Vec<usize>) = (0..n).partition(|&i| scaled[i] < 1.0);
    while !small.is_empty() && !large.is_empty() {
        let (Some(s), Some(&l)) = (small.pop(), large.last()) else {
            break;
        };
        lights[s].alias_threshold = scaled[s] as f32;
        lights[s].alias_index = l as u32;
        scaled[l] -= 1.0 - scaled[s];
        if scaled[l] < 1.0 {
            large.pop();
            small.push(l);
        }
    }
    for i in small.into_iter().chain(large) {
        lights[i].alias_threshold = 1.0;
        lights[i].alias_index = i as u32;
    }
    total as f32
}

/// Writes the sun and sky into the frame uniforms. A physical sky brings its own sun (a disc
/// of the sun's angular radius whose irradiance is the solar irradiance through the air along
/// its direction) and ignores `sun`; the sky-view table it reads lives in the scene
/// (`RenderScene::sky`).
pub fn fill_sun_and_sky(u: &mut GpuFrameUniforms, sun: Option<&SunDesc>, sky: &SkyDesc) {
    let physical_sun = match sky {
        SkyDesc::Physical(p) => Some(physical_sun(p)),
        _ => None,
    };
    let sun = match &physical_sun {
        Some(s) => s.as_ref(),
        None => sun,
    };
    match sun {
        Some(sun) if Vec3::from(sun.direction).length_squared() > 0.0 => {
            let direction = Vec3::from(sun.direction).normalize();
            let irradiance = Vec3::from(sun.irradiance).max(Vec3::ZERO);
            let radius = sun.angular_radius_deg.to_radians().clamp(0.0, 0.5);
            u.sun_direction = direction.to_array();
            if radius > 0.0 {
                let cos_radius = radius.cos();
                // A uniform disc of radiance L seen face-on gives E = L π sin²θ.
                let sin2 = radius.sin().powi(2);
                u.sun_cos_radius = cos_radius;
                u.sun_sin_radius = ((1.0 - cos_radius) * (1.0 + cos_radius)).sqrt();
                u.sun_solid_angle = 2.0 * std::f32::consts::PI * (1.0 - cos_radius);
                u.sun_radiance = (irradiance / (std::f32::consts::PI * sin2)).to_array();
            } else {
                u.sun_cos_radius = 1.0;
                u.sun_solid_angle = 0.0;
                u.sun_radiance = irradiance.to_array();
            }
        }
        _ => {
            u.sun_direction = [0.0, 1.0, 0.0];
            u.sun_cos_radius = 1.0;
            u.sun_solid_angle = -1.0;
            u.sun_radiance = [0.0; 3];
        }
    }
    match *sky {
        SkyDesc::Constant(c) => {
            u.sky_kind = SKY_CONSTANT;
            u.sky_zenith = Vec3::from(c).extend(0.0).to_array();
            u.sky_horizon = u.sky_zenith;
            u.sky_ground = u.sky_zenith;
        }
        SkyDesc::Gradient {
            zenith,
            horizon,
            ground,
        } => {
            u.sky_kind = SKY_GRADIENT;
            u.sky_zenith = Vec3::from(zenith).extend(0.0).to_array();
            u.sky_horizon = Vec3::from(horizon).extend(0.0).to_array();
            u.sky_ground = Vec3::from(ground).extend(0.0).to_array();
        }
        SkyDesc::Physical(p) => {
            u.sky_kind = SKY_PHYSICAL;
            let azimuth = p.sun_horizontal().map_or(Vec3::NEG_Z, |h| {
                crate::sky::Horizontal {
                    elevation_deg: 0.0,
                    azimuth_deg: h.azimuth_deg,
                }
                .direction()
            });
            u.sky_zenith = [0.0; 4];
            u.sky_horizon = azimuth.extend(0.0).to_array();
            u.sky_ground = [0.0; 4];
            // The sun and the moon, the brighter sampled, and the night (`discs.rs`).
            super::discs::fill_physical(u, &p);
        }
    }
}

/// The sun of a physical sky as a `SunDesc`; none when the sky fails its checks (the level
/// loader refuses those first).
fn physical_sun(sky: &crate::sky::PhysicalSky) -> Option<SunDesc> {
    let horizontal = sky.sun_horizontal().ok()?;
    let irradiance = sky.sun_irradiance().ok()? * sky.sun_scale;
    if irradiance.max_element() <= 0.0 {
        return None;
    }
    Some(SunDesc {
        direction: horizontal.direction().to_array(),
        irradiance: irradiance.to_array(),
        angular_radius_deg: crate::sky::SUN_ANGULAR_RADIUS_DEG,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn alias_table_reproduces_weights() {
        let weights = [1.0f32, 7.0, 0.5, 2.5, 0.0, 4.0];
        let mut lights: Vec<GpuLight> = weights
            .iter()
            .map(|&w| GpuLight {
                p0: [0.0; 3],
                instance: 0,
                p1: [0.0; 3],
                triangle: 0,
                p2: [0.0; 3],
                weight: w,
                alias_threshold: 0.0,
                alias_index: 0,
                _padding: [0; 2],
            })
            .collect();
        let total = build_alias(&mut lights);
        assert_eq!(total, 15.0);
        // Probability of each entry: (threshold_i + Σ_{j: alias_j = i} (1 − threshold_j)) / n.
        let n = lights.len() as f32;
        let mut p = vec![0.0f32; lights.len()];
        for (i, l) in lights.iter().enumerate() {
            p[i] += l.alias_threshold / n;
            p[l.alias_index as usize] += (1.0 - l.alias_threshold) / n;
        }
        for (i, w) in weights.iter().enumerate() {
            assert!(
                (p[i] - w / total).abs() < 1e-6,
                "{i}: {} vs {}",
                p[i],
                w / total
            );
        }
    }
}
