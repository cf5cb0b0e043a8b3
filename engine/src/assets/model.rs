//! What every loader produces: a [`Model`] of meshes, materials, textures and placed mesh
//! instances, in the engine's conventions (right-handed, +Y up, metres; linear colour).
//!
//! Owns: the in-memory, loader-independent description of loaded art. Loaders (`obj`, `gltf`)
//! fill it; `accel` flattens it into the `layout` buffers of `scene::RenderScene`.
//! Must not: know any file format, or anything about BVHs or GPUs.

use glam::{Mat4, Vec2, Vec3, Vec4};
use half::f16;

/// Loaded art: meshes, the materials and textures they use, and where the meshes are placed.
#[derive(Clone, Debug, Default)]
pub struct Model {
    /// Where it came from (the file path as given, for messages).
    pub name: String,
    pub meshes: Vec<Mesh>,
    pub materials: Vec<Material>,
    pub textures: Vec<Texture>,
    /// Placed meshes, with transforms from mesh space to the model's space (glTF: the node's
    /// global transform in the default scene; OBJ: one identity placement per mesh).
    pub placements: Vec<Placement>,
    /// What the loader did that a user should know (generated normals or tangents, skipped
    /// primitives, clamped values). Also logged with `log::info!`/`log::warn!`.
    pub notes: Vec<String>,
}

/// A triangle mesh in its own space (metres).
#[derive(Clone, Debug, Default)]
pub struct Mesh {
    pub name: String,
    pub positions: Vec<Vec3>,
    /// Per-vertex unit normals; `None` means flat shading with geometric normals. A zero
    /// vector at a vertex means the same there (loaders write it for missing or broken
    /// normals; see `mesh_check`).
    pub normals: Option<Vec<Vec3>>,
    /// Per-vertex texture coordinates (glTF convention: v down the image, origin top-left).
    pub uvs: Option<Vec<Vec2>>,
    /// Per-vertex tangents, `w` = bitangent sign (MikkTSpace convention: bitangent =
    /// `w · normal × tangent`). A zero `xyz` means no normal mapping at that vertex.
    pub tangents: Option<Vec<Vec4>>,
    /// Vertex indices, counter-clockwise seen from the front (geometric normal = (v1-v0)×(v2-v0)).
    pub triangles: Vec<[u32; 3]>,
    /// Per-triangle index into [`Model::materials`].
    pub triangle_materials: Vec<u32>,
}

/// One placed mesh: `model_from_mesh` maps mesh space into the model's space.
#[derive(Clone, Copy, Debug)]
pub struct Placement {
    pub mesh: usize,
    pub model_from_mesh: Mat4,
}

/// How a surface scatters light. See `layout::GpuMaterial` for the evaluated form.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum MaterialKind {
    /// Lambertian, two-sided.
    Diffuse,
    /// Metal: GGX microfacets, a perfect mirror at roughness 0; `base_color` is F0.
    Conductor,
    /// Glass-like: Fresnel reflection and refraction, Beer–Lambert absorption inside.
    Dielectric,
    /// glTF metallic-roughness (diffuse under a dielectric coat, mixed with metal by `metallic`).
    MetalRough,
}

/// A reference to a texture of the same [`Model`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TextureRef(pub usize);

/// A material in engine terms (all colours linear RGB).
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    pub name: String,
    pub kind: MaterialKind,
    /// Albedo (diffuse), F0 (conductor) or transmission tint (dielectric).
    pub base_color: Vec3,
    pub base_color_texture: Option<TextureRef>,
    /// Emitted radiance (W·sr⁻¹·m⁻²), strength already multiplied in.
    pub emission: Vec3,
    pub emission_texture: Option<TextureRef>,
    /// Emits from both faces (glTF `doubleSided`), otherwise along the geometric normal only.
    pub two_sided_emission: bool,
    /// A thin line emitter (a laser beam): seen from the camera as a prefiltered line, so it
    /// stays a continuous line at any resolution (`layout::MATERIAL_FLAG_LINE`). Only for
    /// emitters whose mesh is the unit beam prism (`sim::triggers::beam_model`).
    pub line: bool,
    /// Perceptual roughness in [0, 1] (GGX α = roughness²).
    pub roughness: f32,
    pub metallic: f32,
    /// glTF metallic-roughness texture (roughness in G, metallic in B).
    pub metal_rough_texture: Option<TextureRef>,
    pub normal_texture: Option<TextureRef>,
    pub normal_scale: f32,
    /// Index of refraction (dielectric inside, or the coat of MetalRough).
    pub ior: f32,
    /// glTF `KHR_materials_transmission` factor (MetalRough only).
    pub transmission: f32,
    /// Beer–Lambert: colour left after `attenuation_distance` metres inside (linear RGB).
    pub attenuation_color: Vec3,
    /// Metres; `f32::INFINITY` means no absorption.
    pub attenuation_distance: f32,
}

impl Default for Material {
    fn default() -> Self {
        Self {
            name: String::new(),
            kind: MaterialKind::Diffuse,
            base_color: Vec3::splat(0.8),
            base_color_texture: None,
            emission: Vec3::ZERO,
            emission_texture: None,
            two_sided_emission: false,
            line: false,
            roughness: 1.0,
            metallic: 0.0,
            metal_rough_texture: None,
            normal_texture: None,
            normal_scale: 1.0,
            ior: 1.5,
            transmission: 0.0,
            attenuation_color: Vec3::ONE,
            attenuation_distance: f32::INFINITY,
        }
    }
}

/// How texture coordinates outside [0, 1] are treated.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Wrap {
    #[default]
    Repeat,
    Clamp,
    Mirror,
}

/// A decoded texture: linear RGBA as f16, rows top to bottom.
#[derive(Clone, Debug, Default)]
pub struct Texture {
    /// Source, for messages (a file path or "`model` image #i").
    pub name: String,
    pub width: u32,
    pub height: u32,
    /// `width * height` texels, linear (sRGB sources are decoded by the loader).
    pub texels: Vec<[f16; 4]>,
    pub wrap_u: Wrap,
    pub wrap_v: Wrap,
    /// Nearest filtering instead of bilinear.
    pub nearest: bool,
}
