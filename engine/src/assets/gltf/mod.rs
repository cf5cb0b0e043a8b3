//! The glTF 2.0 loader (`.gltf` with external or embedded buffers and images, `.glb`).
//! glTF is right-handed, +Y up, metres, linear colour factors: the engine's own conventions,
//! so no axis or unit conversion happens anywhere in this loader.
//!
//! Flow (`load`): `document` opens and validates the file (`glb` splits binaries, `uri`
//! decodes URIs) → `material` converts materials (`texture` loads their images) → `nodes`
//! expands the scene → `mesh` converts the meshes (`accessor` reads their data) →
//! `instancing` expands `EXT_mesh_gpu_instancing` nodes.
//! `sim::animation::gltf_anim` reuses `document` and `accessor` to read clips, skins and morph targets.

pub(crate) mod accessor;
pub(crate) mod document;
mod glb;
mod instancing;
mod load;
mod material;
mod mesh;
mod nodes;
mod texture;
mod uri;

pub(crate) use load::load;
