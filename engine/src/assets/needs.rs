//! What a level needs from the renderer: [`Needs`], declared in the level file or derived from
//! its content ("model no more than a scene needs", DESIGN.md).
//!
//! Owns: the feature set, deriving it from a loaded [`SceneDesc`] (only materials that placed
//! triangles use count), and comparing it with a level's declaration. A level that declares
//! `needs` may not use a feature it did not declare (`level_load` refuses it, naming the
//! feature); a level without a declaration gets the derived set, which tools report. The
//! bounce count is declared separately, in `render: (max_bounces: …)`.
//! Must not: load files or change what the renderer does (it only states and checks).
//!
//! Why the renderer does not read it: the work a feature costs is already switched off by the
//! data itself, in both integrators (`render/cpu/integrator.rs`, `shaders/trace.wgsl`):
//! next-event estimation over emissive triangles runs only when the light table is non-empty
//! (`light_count > 0`), the sun's only when there is a sun (`sun_solid_angle >= 0`), and a
//! texture or normal map is fetched only for a material that names one. A flag from `needs`
//! would skip nothing more (checked 2026-11-22), so it stays a declaration and a check.

use serde::{Deserialize, Serialize};

use super::level::SkyDesc;
use super::model::{Material, MaterialKind};
use super::scene_desc::SceneDesc;

/// Renderer features a level uses. All `false` by default: a level that declares
/// `needs: ()` may use only untextured, opaque, non-emissive materials under a black sky.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Needs {
    /// Base-colour, emission or metal-roughness textures.
    pub textures: bool,
    /// Normal maps (tangent-space, so generated tangents).
    pub normal_maps: bool,
    /// Refraction: dielectric materials or glTF transmission.
    pub glass: bool,
    /// Emissive triangles (the light table and next-event estimation over it).
    pub emitters: bool,
    /// A sun with non-zero irradiance.
    pub sun: bool,
    /// A sky that is not black.
    pub sky: bool,
    /// Meshes that deform at run time (BLAS refits and rebuilds).
    pub deforming: bool,
}

fn material_needs(m: &Material, n: &mut Needs) {
    n.textures |= m.base_color_texture.is_some()
        || m.emission_texture.is_some()
        || m.metal_rough_texture.is_some();
    n.normal_maps |= m.normal_texture.is_some();
    n.glass |= m.kind == MaterialKind::Dielectric || m.transmission > 0.0;
    n.emitters |= m.emission.max_element() > 0.0;
}

impl Needs {
    /// Adds what the level materials `switched_to` (indices into `desc.level_materials`:
    /// those gameplay rules switch instances to at run time, a wall that becomes a mirror or a
    /// lamp) use.
    pub fn add_switched_materials(
        &mut self,
        desc: &SceneDesc,
        switched_to: impl IntoIterator<Item = usize>,
    ) {
        for m in switched_to {
            if let Some(m) = desc.level_materials.get(m) {
                material_needs(m, self);
            }
        }
    }

    /// The features `desc`'s placed content uses.
    pub fn of_scene(desc: &SceneDesc) -> Needs {
        let mut n = Needs::default();
        for instance in &desc.instances {
            if let Some(m) = instance
                .material_override
                .and_then(|m| desc.level_materials.get(m))
            {
                material_needs(m, &mut n);
            } else if let Some(model) = desc.models.get(instance.model) {
                for mesh in &model.meshes {
                    let mut used: Vec<u32> = mesh.triangle_materials.clone();
                    used.sort_unstable();
                    used.dedup();
                    if used.is_empty() && !mesh.triangles.is_empty() {
                        used.push(0);
                    }
                    for m in used.iter().filter_map(|&m| model.materials.get(m as usize)) {
                        material_needs(m, &mut n);
                    }
                }
            }
            n.deforming |= instance.waves.is_some();
        }
        n.sun = desc
            .sun
            .is_some_and(|s| s.irradiance.iter().any(|&e| e > 0.0));
        n.sky = match desc.sky {
            SkyDesc::Constant(c) => c.iter().any(|&v| v > 0.0),
            SkyDesc::Gradient {
                zenith,
                horizon,
                ground,
            } => zenith
                .iter()
                .chain(&horizon)
                .chain(&ground)
                .any(|&v| v > 0.0),
            SkyDesc::Physical(_) => true,
        };
        n.sun |= matches!(desc.sky, SkyDesc::Physical(_));
        n
    }

    /// Names of the features, in declaration order, paired with whether each is set.
    pub fn features(&self) -> [(&'static str, bool); 7] {
        [
            ("textures", self.textures),
            ("normal_maps", self.normal_maps),
            ("glass", self.glass),
            ("emitters", self.emitters),
            ("sun", self.sun),
            ("sky", self.sky),
            ("deforming", self.deforming),
        ]
    }

    /// Features `used` has that `self` (a declaration) lacks.
    pub fn undeclared(&self, used: &Needs) -> Vec<&'static str> {
        self.features()
            .iter()
            .zip(used.features())
            .filter(|((_, declared), (_, uses))| *uses && !*declared)
            .map(|((name, _), _)| *name)
            .collect()
    }
}

impl std::fmt::Display for Needs {
    /// The set features, comma-separated ("none" when empty).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let set: Vec<&str> = self
            .features()
            .iter()
            .filter(|(_, on)| *on)
            .map(|(name, _)| *name)
            .collect();
        if set.is_empty() {
            write!(f, "none")
        } else {
            write!(f, "{}", set.join(", "))
        }
    }
}
