//! The flattened scene both tracers read: a level's `SceneDesc` into `layout` buffers.
//!
//! Owns: the [`RenderScene`] container — one BLAS per mesh (shared by every placement of that
//! mesh), the TLAS over all instances, global material/texture/vertex/triangle tables and the
//! emissive-triangle light list. Both sides use it: the main thread's `accel::Upkeep` keeps the
//! authoritative copy (ray queries read it) and builds it (`RenderScene::build` lives in
//! `accel/flatten.rs`); the render thread keeps its own copy, changed only by the commit's
//! [`SceneWrite`](super::SceneWrite)s. The GPU tracer uploads these vectors unchanged; the CPU
//! tracer walks them in place. Any thread (plain data).
//! Must not: read files (assets did that), build trees (accel does) or talk to the GPU.

use glam::Vec3;

use super::bounds::Aabb;
use super::lights::LightTable;
use crate::assets::Model;
use crate::layout::{
    GpuBvh8Node, GpuInstance, GpuMaterial, GpuTexture, GpuTri4, GpuTriangle, GpuVertex,
};
use crate::trace::TraceBuffer;

/// Counts of what was built, for logs and tools.
#[derive(Clone, Copy, Debug, Default)]
pub struct SceneStats {
    pub meshes: usize,
    /// Triangles stored (each mesh once).
    pub unique_triangles: usize,
    /// Triangles placed in the world (counting every instance).
    pub instanced_triangles: usize,
    pub instances: usize,
    pub lights: usize,
    pub blas_build_seconds: f64,
    pub tlas_build_seconds: f64,
}

/// The flattened scene. Vectors are in `layout` form, ready to upload or trace.
#[derive(Clone, Debug)]
pub struct RenderScene {
    /// Every BLAS, then the TLAS from `tlas_root`. Huge-page buffers ([`TraceBuffer`]): the CPU
    /// tracer walks them for every ray.
    pub nodes: TraceBuffer<GpuBvh8Node>,
    pub blocks: TraceBuffer<GpuTri4>,
    pub instances: Vec<GpuInstance>,
    pub triangles: Vec<GpuTriangle>,
    pub vertices: Vec<GpuVertex>,
    pub materials: Vec<GpuMaterial>,
    pub textures: Vec<GpuTexture>,
    /// Linear RGBA f16 texels, two per u32 pair (see `GpuTexture`).
    pub texels: Vec<[u32; 2]>,
    pub lights: LightTable,
    pub tlas_root: u32,
    /// Where render space's origin lies in world space (metres). Instances, lights and bounds
    /// are stored in render space = world − `origin`, so that coordinates near the camera stay
    /// small and keep f32 precision far from the world origin (see `accel::origin`).
    pub origin: Vec3,
    /// Render-space bounds of everything.
    pub bounds: Aabb,
    pub stats: SceneStats,
    /// The physical sky's sky-view table (empty for constant and gradient skies).
    pub sky: super::SkyTable,
}

impl RenderScene {
    /// A scene with nothing in it (the render thread's copy before the first commit).
    pub fn empty() -> RenderScene {
        RenderScene {
            nodes: TraceBuffer::default(),
            blocks: TraceBuffer::default(),
            instances: Vec::new(),
            triangles: Vec::new(),
            vertices: Vec::new(),
            materials: Vec::new(),
            textures: Vec::new(),
            texels: Vec::new(),
            lights: LightTable::default(),
            tlas_root: 0,
            origin: Vec3::ZERO,
            bounds: Aabb::EMPTY,
            stats: SceneStats::default(),
            sky: super::SkyTable::default(),
        }
    }

    /// A view for the CPU traversal kernels.
    pub fn trace_scene(&self) -> crate::trace::TraceScene<'_> {
        crate::trace::TraceScene {
            nodes: &self.nodes,
            blocks: &self.blocks,
            instances: &self.instances,
            tlas_root: self.tlas_root,
        }
    }
}

/// A mesh's vertices in `GpuVertex` form (missing attributes become zeros: flat shading, no UVs,
/// no tangent frame).
pub(crate) fn mesh_vertices(mesh: &crate::assets::Mesh) -> impl Iterator<Item = GpuVertex> + '_ {
    (0..mesh.positions.len()).map(move |i| {
        let p = mesh.positions[i];
        let n = mesh
            .normals
            .as_ref()
            .and_then(|n| n.get(i).copied())
            .filter(|n| n.is_finite())
            .unwrap_or(Vec3::ZERO);
        let uv = mesh
            .uvs
            .as_ref()
            .and_then(|t| t.get(i).copied())
            .unwrap_or_default();
        let tangent = mesh
            .tangents
            .as_ref()
            .and_then(|t| t.get(i).copied())
            .unwrap_or_default();
        GpuVertex {
            position: p.to_array(),
            u: uv.x,
            normal: n.to_array(),
            v: uv.y,
            tangent: tangent.to_array(),
        }
    })
}

/// Count of placed triangles of a model (for tools).
pub fn model_triangles(model: &Model) -> usize {
    model
        .placements
        .iter()
        .filter_map(|p| model.meshes.get(p.mesh))
        .map(|m| m.triangles.len())
        .sum()
}
