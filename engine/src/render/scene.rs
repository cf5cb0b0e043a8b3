//! The render-side scene both tracers read: a [`SceneDesc`] flattened into `layout` buffers.
//!
//! Owns: the [`RenderScene`] container — one BLAS per mesh (shared by every placement of that
//! mesh), the TLAS over all instances, global material/texture/vertex/triangle tables and the
//! emissive-triangle light list — and the one-shot build from a [`SceneDesc`], which runs the
//! same `accel::Upkeep` a game runs frame by frame. The GPU tracer uploads these vectors
//! unchanged; the CPU tracer walks them in place; commits change them by `SceneWrite`s.
//! Must not: read files (assets did that) or talk to the GPU.

use glam::Vec3;

use super::lights::LightTable;
use crate::accel::{Aabb, BlasParams};
use crate::assets::{Model, SceneDesc};
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
}

impl RenderScene {
    /// Flattens `desc` in one go, through the same [`Upkeep`](crate::accel::Upkeep) path a
    /// running game uses frame by frame (so a one-shot build and an incremental one agree).
    /// Render space's origin is snapped near the camera (camera-relative rendering, see
    /// `accel::origin`).
    pub fn build(desc: &SceneDesc) -> RenderScene {
        let origin = crate::accel::origin::snap_origin(Vec3::from(desc.camera.position));
        Self::build_with_origin(desc, origin)
    }

    /// [`RenderScene::build`] with render space's origin at `origin` (world metres, snapped to
    /// `accel::origin::ORIGIN_GRID`); `Vec3::ZERO` renders in world space as it is.
    pub fn build_with_origin(desc: &SceneDesc, origin: Vec3) -> RenderScene {
        Self::build_from(desc, origin, BlasParams::default())
    }

    /// [`RenderScene::build`] with every BLAS built with `params` (a build preset or leaf size
    /// other than the default, for measurements such as `bench chart`). Both tracers read the
    /// result like any other scene: the image is the same, only the traversal speed differs.
    pub fn build_with_blas_params(desc: &SceneDesc, params: BlasParams) -> RenderScene {
        let origin = crate::accel::origin::snap_origin(Vec3::from(desc.camera.position));
        Self::build_from(desc, origin, params)
    }

    fn build_from(desc: &SceneDesc, origin: Vec3, params: BlasParams) -> RenderScene {
        let started = std::time::Instant::now();
        let mut upkeep = crate::accel::Upkeep::with_blas_params(params);
        upkeep.set_origin(origin);
        upkeep.add_level_materials(&desc.level_materials);
        let handles: Vec<_> = desc.models.iter().map(|m| upkeep.add_model(m)).collect();
        let blas_build_seconds = started.elapsed().as_secs_f64();
        let mut ids = hecs::World::new();
        for instance in &desc.instances {
            let Some(&model) = handles.get(instance.model) else {
                continue;
            };
            let entity = ids.spawn(());
            let material_override = instance.material_override.map(|m| m as u32);
            upkeep.set_instance(
                entity,
                model,
                instance.world_from_model,
                material_override,
                None,
            );
        }
        let started = std::time::Instant::now();
        upkeep.finish_frame();
        let tlas_build_seconds = started.elapsed().as_secs_f64();
        let mut scene = upkeep.into_scene();
        scene.stats = SceneStats {
            meshes: desc.models.iter().map(|m| m.meshes.len()).sum(),
            unique_triangles: desc
                .models
                .iter()
                .flat_map(|m| m.meshes.iter())
                .map(|m| m.triangles.len())
                .sum(),
            instanced_triangles: desc
                .instances
                .iter()
                .filter_map(|i| desc.models.get(i.model))
                .map(model_triangles)
                .sum(),
            instances: scene.instances.len(),
            lights: scene.lights.count as usize,
            blas_build_seconds,
            tlas_build_seconds,
        };
        scene
    }

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
