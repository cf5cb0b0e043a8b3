//! The render-side scene both tracers read: a [`SceneDesc`] flattened into `layout` buffers.
//!
//! Owns: building [`RenderScene`] — one BLAS per mesh (built once, shared by every placement
//! of that mesh), the TLAS over all instances, global material/texture/vertex/triangle tables
//! and the emissive-triangle light list. The GPU tracer uploads these vectors unchanged; the
//! CPU tracer walks them in place.
//! Must not: read files (assets did that) or talk to the GPU.

use glam::{Mat4, Vec3};
use rayon::prelude::*;

use super::lights::{LightTable, build_lights};
use super::materials::{pack_textures, to_gpu_material};
use crate::accel::{Aabb, build_blas, build_tlas};
use crate::assets::{Model, SceneDesc};
use crate::layout::{
    GpuBvh8Node, GpuInstance, GpuMaterial, GpuTexture, GpuTri4, GpuTriangle, GpuVertex,
    INSTANCE_FLAG_IDENTITY, INVALID,
};

/// Where one mesh's data starts in the global buffers.
#[derive(Clone, Copy, Debug)]
struct MeshSlot {
    node_base: u32,
    block_base: u32,
    triangle_base: u32,
    vertex_base: u32,
    bounds: Aabb,
}

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
    /// Every BLAS, then the TLAS from `tlas_root`.
    pub nodes: Vec<GpuBvh8Node>,
    pub blocks: Vec<GpuTri4>,
    pub instances: Vec<GpuInstance>,
    pub triangles: Vec<GpuTriangle>,
    pub vertices: Vec<GpuVertex>,
    pub materials: Vec<GpuMaterial>,
    pub textures: Vec<GpuTexture>,
    /// Linear RGBA f16 texels, two per u32 pair (see `GpuTexture`).
    pub texels: Vec<[u32; 2]>,
    pub lights: LightTable,
    pub tlas_root: u32,
    /// World-space bounds of everything.
    pub bounds: Aabb,
    pub stats: SceneStats,
}

fn affine_rows(m: Mat4) -> [[f32; 4]; 3] {
    let r = m.transpose().to_cols_array_2d();
    [r[0], r[1], r[2]]
}

impl RenderScene {
    /// Flattens `desc`: builds the BLAS of every mesh in parallel, then instances, TLAS, lights.
    pub fn build(desc: &SceneDesc) -> RenderScene {
        let mut materials: Vec<GpuMaterial> = Vec::new();
        let mut material_base = Vec::with_capacity(desc.models.len());
        let (textures, texels, texture_base, texture_means) = pack_textures(&desc.models);
        for (model_index, model) in desc.models.iter().enumerate() {
            material_base.push(materials.len() as u32);
            for material in &model.materials {
                materials.push(to_gpu_material(
                    material,
                    texture_base[model_index],
                    &texture_means,
                ));
            }
        }
        let level_material_base = materials.len() as u32;
        for material in &desc.level_materials {
            materials.push(to_gpu_material(material, 0, &texture_means));
        }
        if materials.is_empty() {
            materials.push(to_gpu_material(&Default::default(), 0, &texture_means));
        }

        // BLAS of every mesh of every model, in parallel (rayon), then concatenated.
        let started = std::time::Instant::now();
        let flat: Vec<(usize, &crate::assets::Mesh)> = desc
            .models
            .iter()
            .enumerate()
            .flat_map(|(m, model)| model.meshes.iter().map(move |mesh| (m, mesh)))
            .collect();
        let built: Vec<_> = flat
            .par_iter()
            .map(|(_, mesh)| build_blas(&mesh.positions, &mesh.triangles))
            .collect();
        let blas_build_seconds = started.elapsed().as_secs_f64();

        let mut nodes = Vec::new();
        let mut blocks = Vec::new();
        let mut triangles = Vec::new();
        let mut vertices = Vec::new();
        let mut slots: Vec<Vec<MeshSlot>> = desc.models.iter().map(|_| Vec::new()).collect();
        let mut unique_triangles = 0;
        for ((model_index, mesh), blas) in flat.iter().zip(built) {
            slots[*model_index].push(MeshSlot {
                node_base: nodes.len() as u32,
                block_base: blocks.len() as u32,
                triangle_base: triangles.len() as u32,
                vertex_base: vertices.len() as u32,
                bounds: blas.bounds,
            });
            nodes.extend_from_slice(&blas.nodes);
            blocks.extend_from_slice(&blas.blocks);
            let base = material_base[*model_index];
            triangles.extend(mesh.triangles.iter().enumerate().map(|(i, t)| GpuTriangle {
                indices: *t,
                material: base + mesh.triangle_materials.get(i).copied().unwrap_or(0),
            }));
            vertices.extend(mesh_vertices(mesh));
            unique_triangles += mesh.triangles.len();
        }

        let mut instances = Vec::new();
        let mut instance_bounds = Vec::new();
        let mut instanced_triangles = 0;
        let mut triangle_counts = Vec::new();
        for instance in &desc.instances {
            let Some(model) = desc.models.get(instance.model) else {
                continue;
            };
            let material_override = instance
                .material_override
                .map(|m| level_material_base + m as u32)
                .unwrap_or(INVALID);
            for placement in &model.placements {
                let Some(slot) = slots[instance.model].get(placement.mesh) else {
                    continue;
                };
                let world_from_object = instance.world_from_model * placement.model_from_mesh;
                let flags = if world_from_object == Mat4::IDENTITY {
                    INSTANCE_FLAG_IDENTITY
                } else {
                    0
                };
                instances.push(GpuInstance {
                    world_from_object: affine_rows(world_from_object),
                    object_from_world: affine_rows(world_from_object.inverse()),
                    node_base: slot.node_base,
                    block_base: slot.block_base,
                    triangle_base: slot.triangle_base,
                    vertex_base: slot.vertex_base,
                    material_override,
                    flags,
                    _padding: [0; 2],
                });
                instance_bounds.push(slot.bounds.transformed(&world_from_object));
                let count = model.meshes[placement.mesh].triangles.len();
                instanced_triangles += count;
                triangle_counts.push(count as u32);
            }
        }

        let started = std::time::Instant::now();
        let tlas_root = nodes.len() as u32;
        nodes.extend(build_tlas(&instance_bounds));
        let tlas_build_seconds = started.elapsed().as_secs_f64();
        let bounds = instance_bounds
            .iter()
            .fold(Aabb::EMPTY, |acc, b| acc.union(*b));

        let lights = build_lights(
            &instances,
            &triangle_counts,
            &triangles,
            &vertices,
            &materials,
        );
        let stats = SceneStats {
            meshes: flat.len(),
            unique_triangles,
            instanced_triangles,
            instances: instances.len(),
            lights: lights.lights.len(),
            blas_build_seconds,
            tlas_build_seconds,
        };
        RenderScene {
            nodes,
            blocks,
            instances,
            triangles,
            vertices,
            materials,
            textures,
            texels,
            lights,
            tlas_root,
            bounds,
            stats,
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
fn mesh_vertices(mesh: &crate::assets::Mesh) -> impl Iterator<Item = GpuVertex> + '_ {
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
