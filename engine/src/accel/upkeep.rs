//! The game side's flattened scene and its upkeep: what changed this frame becomes buffer
//! writes for the commit (Brigade §4.4).
//!
//! Owns: [`Upkeep`] — the authoritative copy of the flattened scene on the main thread (ray
//! queries read it), per-mesh slots in the node/block/vertex buffers, the instance table and
//! which entity owns which instance, light groups, and the policy: rigid movers change only
//! their instance rows; a deforming mesh is refitted every frame it changes and rebuilt when its
//! SAH cost exceeds [`REBUILD_RATIO`] × the estimated cost of a fresh build of its current
//! shape (at most its cost at the last build; see `refit::rebuild_bound`); the TLAS is rebuilt every
//! frame an instance changed; the light table every frame an emitter changed. Only what changed
//! is written. Main thread. Must not: talk to the GPU or the render thread (the commit carries
//! the writes).
//!
//! Instance operations live in `upkeep_instances.rs`, level materials in
//! `upkeep_materials.rs`.

use std::collections::{HashMap, HashSet};

use glam::Mat4;
use rayon::prelude::*;

use super::blas::{Blas, BlasParams, build_blas_with_params};
use super::refit::{sah_cost, triangle_area_ratio};
use super::tlas::build_tlas;
use crate::assets::{Material, Model};
use crate::ecs::ModelHandle;
use crate::layout::{GpuBvh8Node, GpuTriangle, GpuVertex};
use crate::scene::Aabb;
use crate::scene::lights::build_lights;
use crate::scene::materials::{pack_textures, to_gpu_material};
use crate::scene::{RenderScene, mesh_vertices};
use crate::scene::{SceneHeader, SceneWrite};
use crate::trace::TraceBuffer;

/// Rebuild a deforming mesh's BLAS when its SAH cost after refitting exceeds this multiple of
/// the estimated cost of a fresh build (`refit::rebuild_bound`). Chosen by measurement: see
/// `docs/PERFORMANCE.md` ("The frame pipeline on the demo level", rebuild threshold; `bench
/// pipeline --only refit`); a refit is 15–20× cheaper than a rebuild, and traversal slows
/// roughly in proportion to the SAH cost.
pub const REBUILD_RATIO: f32 = 1.5;

/// Where one mesh lives in the flattened buffers.
#[derive(Clone, Debug)]
pub(super) struct MeshSlot {
    pub(super) blas: Blas,
    pub(super) node_base: u32,
    pub(super) node_capacity: u32,
    pub(super) block_base: u32,
    pub(super) block_capacity: u32,
    pub(super) triangle_base: u32,
    pub(super) vertex_base: u32,
    pub(super) vertex_count: u32,
    pub(super) triangles: Vec<[u32; 3]>,
    /// SAH cost right after the last (re)build.
    pub(super) built_cost: f32,
    /// [`triangle_area_ratio`] right after the last (re)build.
    pub(super) built_area: f32,
    /// Any of its triangles' materials emits.
    pub(super) emissive: bool,
}

/// A registered model: its meshes' slots and where each is placed.
#[derive(Clone, Debug)]
pub(super) struct ModelRecord {
    pub(super) meshes: Vec<usize>,
    pub(super) placements: Vec<(usize, Mat4)>,
}

/// What the upkeep did in one frame (for the stats overlay and the "model no more than a scene
/// needs" report).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct UpkeepStats {
    pub instances_written: u32,
    pub blas_refits: u32,
    pub blas_rebuilds: u32,
    pub tlas_builds: u32,
    pub light_table_builds: u32,
    /// Frames whose moved emitters only refitted the light table and tree
    /// (`scene::light_refit`) instead of rebuilding them.
    pub light_refits: u32,
    /// Bytes of all writes of the frame.
    pub bytes: usize,
    /// Bytes of the frame's geometry writes (BVH nodes and triangle blocks, vertices,
    /// triangles): zero in a frame where nothing moved or deformed.
    pub geometry_bytes: usize,
    /// Seconds spent in refits, rebuilds and the TLAS.
    pub seconds: f64,
}

/// The game side's flattened scene.
pub struct Upkeep {
    pub(super) scene: RenderScene,
    pub(super) models: Vec<ModelRecord>,
    pub(super) meshes: Vec<MeshSlot>,
    /// Owner entity and mesh slot of every row of `scene.instances`.
    pub(super) rows: Vec<(hecs::Entity, usize)>,
    /// Rows of every entity, and its light group.
    pub(super) entities: HashMap<hecs::Entity, (Vec<u32>, Option<u32>)>,
    pub(super) groups_off: HashSet<u32>,
    /// The light groups next-event estimation samples (`None`: every group; set from the
    /// render area the camera is in, see [`Upkeep::set_sampled_groups`]).
    pub(super) groups_sampled: Option<HashSet<u32>>,
    /// The level's render areas (`assets::RenderArea`), which pick `groups_sampled` from the
    /// camera's position ([`Upkeep::sample_from`]).
    pub(super) render_areas: Vec<crate::assets::RenderArea>,
    pub(super) level_material_base: u32,
    /// Table rows reserved for level materials at `level_material_base` (`None`: no level
    /// has registered any yet; see `upkeep_materials.rs`).
    pub(super) level_material_slots: Option<u32>,
    /// End of the BLAS part of the node buffer; the TLAS follows.
    pub(super) blas_node_end: u32,
    pub(super) pending: Vec<SceneWrite>,
    pub(super) tlas_dirty: bool,
    pub(super) lights_dirty: bool,
    /// Rows of emissive instances moved since the last commit (refitted when nothing else
    /// dirtied the light table, see `scene::light_refit`).
    pub(super) lights_moved: Vec<u32>,
    pub(super) stats: UpkeepStats,
    /// The far-from-origin warning was given (see `origin.rs`).
    pub(super) precision_warned: bool,
    /// How every BLAS is built and rebuilt ([`BlasParams::default`] unless a measurement asks
    /// for another layout, see [`Upkeep::with_blas_params`]).
    pub(super) blas_params: BlasParams,
}

impl Default for Upkeep {
    fn default() -> Self {
        Self::new()
    }
}

impl Upkeep {
    /// An empty scene.
    pub fn new() -> Self {
        let scene = RenderScene {
            nodes: TraceBuffer::from_slice(&[GpuBvh8Node::EMPTY]),
            lights: build_lights(&[], &[], &[], &[], &[]),
            ..RenderScene::empty()
        };
        Self {
            scene,
            models: Vec::new(),
            meshes: Vec::new(),
            rows: Vec::new(),
            entities: HashMap::new(),
            groups_off: HashSet::new(),
            groups_sampled: None,
            render_areas: Vec::new(),
            level_material_base: 0,
            level_material_slots: None,
            blas_node_end: 0,
            pending: vec![SceneWrite::Nodes {
                first: 0,
                data: vec![GpuBvh8Node::EMPTY],
            }],
            tlas_dirty: true,
            lights_dirty: true,
            lights_moved: Vec::new(),
            stats: UpkeepStats::default(),
            precision_warned: false,
            blas_params: BlasParams::default(),
        }
    }

    /// An empty scene whose BLAS are built (and rebuilt after deformation) with `params`
    /// instead of the default: a build preset or leaf size for measurements (`bench chart`
    /// compares them). Traversal reads every variant the same way; only speed differs.
    pub fn with_blas_params(params: BlasParams) -> Self {
        Self {
            blas_params: params,
            ..Self::new()
        }
    }

    /// The scene as of the last [`Upkeep::finish_frame`] (what ray queries read).
    pub fn scene(&self) -> &RenderScene {
        &self.scene
    }

    /// Registers `model`: builds every mesh's BLAS (in parallel) and appends its geometry,
    /// materials and textures. Its instances come later, one per entity.
    pub fn add_model(&mut self, model: &Model) -> ModelHandle {
        let started = std::time::Instant::now();
        let (textures, texels, _, means) = pack_textures(std::slice::from_ref(model));
        let texture_base = self.scene.textures.len() as u32;
        let texel_base = self.scene.texels.len() as u32;
        let textures: Vec<_> = textures
            .into_iter()
            .map(|mut t| {
                t.texel_offset += texel_base;
                t
            })
            .collect();
        let mut global_means = vec![1.0; texture_base as usize];
        global_means.extend(means);
        let material_base = self.scene.materials.len() as u32;
        let default = [Material::default()];
        let source = if model.materials.is_empty() {
            &default[..]
        } else {
            &model.materials[..]
        };
        let materials: Vec<_> = source
            .iter()
            .map(|m| to_gpu_material(m, texture_base, &global_means))
            .collect();
        let material_count = materials.len() as u32;
        if !textures.is_empty() {
            self.push(SceneWrite::Textures {
                first: texture_base,
                data: textures,
            });
            self.push(SceneWrite::Texels {
                first: texel_base,
                data: texels,
            });
        }
        let emissive: Vec<bool> = materials.iter().map(|m| m.emission[3] > 0.0).collect();
        self.push(SceneWrite::Materials {
            first: material_base,
            data: materials,
        });
        let params = self.blas_params;
        let built: Vec<Blas> = model
            .meshes
            .par_iter()
            .map(|m| build_blas_with_params(&m.positions, &m.triangles, params))
            .collect();
        let mut mesh_slots = Vec::new();
        for (mesh, blas) in model.meshes.iter().zip(built) {
            let triangle_base = self.scene.triangles.len() as u32;
            let vertex_base = self.scene.vertices.len() as u32;
            let triangles: Vec<GpuTriangle> = mesh
                .triangles
                .iter()
                .enumerate()
                .map(|(i, t)| GpuTriangle {
                    indices: *t,
                    material: material_base
                        + mesh
                            .triangle_materials
                            .get(i)
                            .copied()
                            .filter(|&m| m < material_count)
                            .unwrap_or(0),
                })
                .collect();
            let vertices: Vec<GpuVertex> = mesh_vertices(mesh).collect();
            let vertex_count = vertices.len() as u32;
            self.push(SceneWrite::Triangles {
                first: triangle_base,
                data: triangles,
            });
            self.push(SceneWrite::Vertices {
                first: vertex_base,
                data: vertices,
            });
            let slot_emissive = mesh
                .triangle_materials
                .iter()
                .any(|&m| emissive.get(m as usize).copied().unwrap_or(false));
            let built_cost = sah_cost(&blas.nodes, &blas.blocks);
            let built_area = triangle_area_ratio(&blas);
            let mut slot = MeshSlot {
                node_base: 0,
                node_capacity: blas.nodes.len() as u32,
                block_base: self.scene.blocks.len() as u32,
                block_capacity: blas.blocks.len() as u32,
                triangle_base,
                vertex_base,
                vertex_count,
                triangles: mesh.triangles.clone(),
                built_cost,
                built_area,
                emissive: slot_emissive,
                blas,
            };
            self.place_blas(&mut slot, true);
            mesh_slots.push(self.meshes.len());
            self.meshes.push(slot);
        }
        self.models.push(ModelRecord {
            meshes: mesh_slots,
            placements: model
                .placements
                .iter()
                .filter(|p| p.mesh < model.meshes.len())
                .map(|p| (p.mesh, p.model_from_mesh))
                .collect(),
        });
        self.stats.seconds += started.elapsed().as_secs_f64();
        ModelHandle(self.models.len() as u32 - 1)
    }

    /// Writes `slot.blas` into the node and block buffers: in place when it fits the slot's
    /// capacity, else at the end of the BLAS area (the TLAS moves behind it).
    pub(super) fn place_blas(&mut self, slot: &mut MeshSlot, new: bool) {
        let nodes = slot.blas.nodes.len() as u32;
        let blocks = slot.blas.blocks.len() as u32;
        if new || nodes > slot.node_capacity {
            slot.node_base = self.blas_node_end;
            slot.node_capacity = nodes;
            self.blas_node_end += nodes;
            self.tlas_dirty = true;
        }
        if new || blocks > slot.block_capacity {
            slot.block_base = self.scene.blocks.len() as u32;
            slot.block_capacity = blocks;
        }
        let (node_base, block_base) = (slot.node_base, slot.block_base);
        self.push(SceneWrite::Nodes {
            first: node_base,
            data: slot.blas.nodes.clone(),
        });
        self.push(SceneWrite::Blocks {
            first: block_base,
            data: slot.blas.blocks.clone(),
        });
    }

    /// Switches a light group on or off.
    pub fn set_light_group(&mut self, group: u32, on: bool) {
        let changed = if on {
            self.groups_off.remove(&group)
        } else {
            self.groups_off.insert(group)
        };
        if changed {
            self.apply_group_flags(group);
        }
    }

    /// The light groups switched off, in increasing order.
    pub fn light_groups_off(&self) -> Vec<u32> {
        let mut off: Vec<u32> = self.groups_off.iter().copied().collect();
        off.sort_unstable();
        off
    }

    /// Whether light group `group` is on (groups are on until switched off).
    pub fn light_group_on(&self, group: u32) -> bool {
        !self.groups_off.contains(&group)
    }

    /// Rebuilds the TLAS if instances changed, so that queries see every change applied so
    /// far; the writes stay pending for [`Upkeep::finish_frame`] (the light table too: queries
    /// do not read it). For fixed steps between two commits (`Engine::frame`).
    pub fn settle_queries(&mut self) {
        if self.tlas_dirty {
            puffin::profile_scope!("TLAS");
            let started = std::time::Instant::now();
            let bounds: Vec<Aabb> = self
                .rows
                .iter()
                .enumerate()
                .map(|(i, _)| self.row_bounds(i))
                .collect();
            let tlas = build_tlas(&bounds);
            self.scene.bounds = bounds.iter().fold(Aabb::EMPTY, |a, b| a.union(*b));
            self.scene.tlas_root = self.blas_node_end;
            self.push(SceneWrite::Nodes {
                first: self.blas_node_end,
                data: tlas,
            });
            self.stats.tlas_builds += 1;
            self.stats.seconds += started.elapsed().as_secs_f64();
            self.tlas_dirty = false;
        }
    }

    /// Ends the frame: rebuilds the TLAS and the light table if needed, and returns the
    /// frame's writes (every write since the last call, in order), the header and the
    /// statistics. The scene is then what queries read.
    pub fn finish_frame(&mut self) -> (Vec<SceneWrite>, SceneHeader, UpkeepStats) {
        self.settle_queries();
        self.finish_lights();
        self.scene.stats.instances = self.rows.len();
        self.scene.stats.lights = self.scene.lights.count as usize;
        let writes = std::mem::take(&mut self.pending);
        let mut stats = std::mem::take(&mut self.stats);
        stats.bytes = writes.iter().map(SceneWrite::bytes).sum();
        stats.geometry_bytes = writes
            .iter()
            .filter(|w| w.is_geometry())
            .map(SceneWrite::bytes)
            .sum();
        (writes, self.scene.header(), stats)
    }

    /// The flattened scene, giving up the upkeep (for one-shot builds).
    pub fn into_scene(self) -> RenderScene {
        self.scene
    }

    /// Records a write and applies it to the game-side copy. A pending write that this one
    /// covers is dropped (`SceneWrite::supersedes`): a frame of several settled steps refits
    /// the same BLAS and rebuilds the TLAS once per step, and the commit carries the last.
    pub(super) fn push(&mut self, write: SceneWrite) {
        let header = self.scene.header();
        self.scene.apply(std::slice::from_ref(&write), &header);
        self.push_applied(write);
    }

    /// [`Self::push`] of a write the caller has already made to the game-side copy (the same
    /// bytes in the same range): only recorded for the commit.
    pub(super) fn push_applied(&mut self, write: SceneWrite) {
        self.pending.retain(|earlier| !write.supersedes(earlier));
        self.pending.push(write);
    }
}
