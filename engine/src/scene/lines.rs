//! The thin line emitters of a scene (laser beams) as the camera sees them: one [`GpuLine`]
//! per instance whose material is a line emitter ([`MATERIAL_FLAG_LINE`]).
//!
//! Owns: [`RenderScene::lines`], gathered from the instance table on each render (a scene has a
//! few dozen beam pieces among a few hundred instances; gathering costs microseconds). The unit
//! beam prism runs from the object's origin to +z with x, y in [−½, ½]
//! (`sim::triggers::beam_model`), so the line is the instance's origin → its +z end and its
//! half-width half the length of its x axis. Pieces hidden by a zero scale and instances whose
//! light group is off are left out. Any thread (a pure function of the scene).
//! Must not: trace or shade (the tracers do, `render/cpu/lines.rs` and its WGSL twin).
//! Units: metres in render space (world − `RenderScene::origin`); radiance linear RGB.

use glam::Vec3;

use super::RenderScene;
use crate::layout::{GpuLine, INSTANCE_FLAG_EMISSION_OFF, INVALID, MATERIAL_FLAG_LINE};

/// Most lines a render sees; further ones are left out (the GPU binds a fixed array).
pub const MAX_LINES: usize = 256;

impl RenderScene {
    /// The line emitters the camera sees, at most [`MAX_LINES`], in instance order.
    pub fn lines(&self) -> Vec<GpuLine> {
        let mut lines = Vec::new();
        for instance in &self.instances {
            if instance.flags & INSTANCE_FLAG_EMISSION_OFF != 0 {
                continue;
            }
            let material = if instance.material_override != INVALID {
                instance.material_override
            } else {
                match self.triangles.get(instance.triangle_base as usize) {
                    Some(t) => t.material,
                    None => continue,
                }
            };
            let Some(m) = self.materials.get(material as usize) else {
                continue;
            };
            if m.flags & MATERIAL_FLAG_LINE == 0 {
                continue;
            }
            let row = |k: usize| {
                Vec3::new(
                    instance.world_from_object[0][k],
                    instance.world_from_object[1][k],
                    instance.world_from_object[2][k],
                )
            };
            let (across, along, start) = (row(0), row(2), row(3));
            let radius = 0.5 * across.length();
            if !(radius > 0.0 && along.length_squared() > 0.0) || !start.is_finite() {
                continue;
            }
            let radiance = Vec3::from_slice(&m.emission[..3]);
            if radiance == Vec3::ZERO {
                continue;
            }
            lines.push(GpuLine {
                start: start.to_array(),
                radius,
                end: (start + along).to_array(),
                _padding: 0,
                radiance: radiance.extend(0.0).to_array(),
            });
            if lines.len() == MAX_LINES {
                break;
            }
        }
        lines
    }
}
