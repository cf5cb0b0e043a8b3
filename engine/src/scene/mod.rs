//! The flattened scene: the one data model both sides of the hand-off share. The main thread's
//! upkeep (`accel`) builds and changes it, the render thread applies the same changes to its
//! copy, and both tracers and the game's ray queries read it.
//!
//! Owns: [`RenderScene`] (the `layout` buffers of one scene), [`SceneWrite`] / [`SceneHeader`]
//! (the deltas a commit carries, and applying them), the light table ([`lights`]: emissive
//! triangles, alias table, light groups, sun and sky; [`discs`]: the physical sky's sun, moon and night in the uniforms; [`light_tree`]: the light BVH; [`light_refit`]: both refitted after emitters moved rigidly), material and texture packing
//! (`materials`), the thin line emitters the camera sees prefiltered (`lines`), what a surface does to a laser (`optics`), the physical sky's table ([`SkyTable`]), what it holds in bytes ([`SceneMemory`]) and the box type [`Aabb`].
//! Any thread (plain data and pure functions).
//! Must not: build trees (`accel`), trace rays (`trace`), or know about the ECS, the commit or
//! either thread.

mod bounds;
pub mod discs;
mod flattened;
pub mod light_refit;
pub mod light_tree;
pub mod lights;
mod lines;
pub(crate) mod materials;
mod memory;
pub mod mips;
pub(crate) mod optics;
mod sky_table;
pub(crate) mod surface;
mod writes;

pub use bounds::Aabb;
pub(crate) use flattened::mesh_vertices;
pub use flattened::{RenderScene, SceneStats, model_triangles};
pub use lights::LightTable;
pub use lines::MAX_LINES;
pub use materials::luminance;
pub use memory::SceneMemory;
pub use optics::{Optics, optics_of};
pub use sky_table::{SkyRebuild, SkyTable};
pub use writes::{SceneHeader, SceneWrite};
