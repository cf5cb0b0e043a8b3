//! Scene deltas at the level of the flattened buffers: what a commit carries to the render
//! thread, and applying them to a [`RenderScene`].
//!
//! Owns: [`SceneWrite`] (a typed range write or truncation of one buffer) and
//! [`SceneHeader`] (the few scalars that change with the buffers), and
//! `RenderScene::apply`. The GPU tracer replays the same writes into its buffers
//! (`Tracer::update`), so both sides stay byte-identical.
//! Must not: decide what changed (the game side's upkeep does).

use super::flattened::RenderScene;
use super::lights::LightTable;
use crate::layout::{
    GpuBvh8Node, GpuInstance, GpuLight, GpuLightNode, GpuMaterial, GpuTexture, GpuTri4,
    GpuTriangle, GpuVertex,
};

/// One delta to one flattened buffer: `data` replaces the elements from `first` on (the buffer
/// grows when the range ends past its length), or the buffer is cut to `len` elements.
#[derive(Clone, Debug)]
pub enum SceneWrite {
    Nodes {
        first: u32,
        data: Vec<GpuBvh8Node>,
    },
    Blocks {
        first: u32,
        data: Vec<GpuTri4>,
    },
    Instances {
        first: u32,
        data: Vec<GpuInstance>,
    },
    Triangles {
        first: u32,
        data: Vec<GpuTriangle>,
    },
    Vertices {
        first: u32,
        data: Vec<GpuVertex>,
    },
    Materials {
        first: u32,
        data: Vec<GpuMaterial>,
    },
    Textures {
        first: u32,
        data: Vec<GpuTexture>,
    },
    Texels {
        first: u32,
        data: Vec<[u32; 2]>,
    },
    Lights {
        first: u32,
        data: Vec<GpuLight>,
    },
    /// The light tree's nodes (`LightTree::nodes`).
    LightNodes {
        first: u32,
        data: Vec<GpuLightNode>,
    },
    /// The light tree's hit lookup (`LightTree::lookup`).
    LightLookup {
        first: u32,
        data: Vec<u32>,
    },
    /// Keep only the first `len` instances (despawned entities at the end of the table).
    TruncateInstances {
        len: u32,
    },
}

impl SceneWrite {
    /// Bytes this write carries (for commit statistics).
    pub fn bytes(&self) -> usize {
        fn n<T>(v: &[T]) -> usize {
            std::mem::size_of_val(v)
        }
        match self {
            SceneWrite::Nodes { data, .. } => n(data),
            SceneWrite::Blocks { data, .. } => n(data),
            SceneWrite::Instances { data, .. } => n(data),
            SceneWrite::Triangles { data, .. } => n(data),
            SceneWrite::Vertices { data, .. } => n(data),
            SceneWrite::Materials { data, .. } => n(data),
            SceneWrite::Textures { data, .. } => n(data),
            SceneWrite::Texels { data, .. } => n(data),
            SceneWrite::Lights { data, .. } => n(data),
            SceneWrite::LightNodes { data, .. } => n(data),
            SceneWrite::LightLookup { data, .. } => n(data),
            SceneWrite::TruncateInstances { .. } => 0,
        }
    }

    /// Whether this write carries geometry: BVH nodes (BLAS or TLAS), triangle blocks,
    /// triangles or vertices.
    pub fn is_geometry(&self) -> bool {
        matches!(
            self,
            SceneWrite::Nodes { .. }
                | SceneWrite::Blocks { .. }
                | SceneWrite::Triangles { .. }
                | SceneWrite::Vertices { .. }
        )
    }
}

/// The scalars of a scene that change together with its buffers.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SceneHeader {
    pub tlas_root: u32,
    pub light_count: u32,
    pub light_weight_total: f32,
    /// World position of render space's origin (metres; see `RenderScene::origin`).
    pub origin: glam::Vec3,
}

fn write_range<T: Copy + bytemuck::Zeroable>(target: &mut Vec<T>, first: u32, data: &[T]) {
    let first = first as usize;
    let end = first + data.len();
    if target.len() < end {
        target.resize(end, T::zeroed());
    }
    target[first..end].copy_from_slice(data);
}

impl RenderScene {
    /// The header of this scene.
    pub fn header(&self) -> SceneHeader {
        SceneHeader {
            tlas_root: self.tlas_root,
            light_count: self.lights.count,
            light_weight_total: self.lights.weight_total,
            origin: self.origin,
        }
    }

    /// Applies `writes` in order, then `header`.
    pub fn apply(&mut self, writes: &[SceneWrite], header: &SceneHeader) {
        for w in writes {
            match w {
                SceneWrite::Nodes { first, data } => self.nodes.write_range(*first as usize, data),
                SceneWrite::Blocks { first, data } => {
                    self.blocks.write_range(*first as usize, data)
                }
                SceneWrite::Instances { first, data } => {
                    write_range(&mut self.instances, *first, data)
                }
                SceneWrite::Triangles { first, data } => {
                    write_range(&mut self.triangles, *first, data)
                }
                SceneWrite::Vertices { first, data } => {
                    write_range(&mut self.vertices, *first, data)
                }
                SceneWrite::Materials { first, data } => {
                    write_range(&mut self.materials, *first, data)
                }
                SceneWrite::Textures { first, data } => {
                    write_range(&mut self.textures, *first, data)
                }
                SceneWrite::Texels { first, data } => write_range(&mut self.texels, *first, data),
                SceneWrite::Lights { first, data } => {
                    write_range(&mut self.lights.lights, *first, data)
                }
                SceneWrite::LightNodes { first, data } => {
                    write_range(&mut self.lights.tree.nodes, *first, data)
                }
                SceneWrite::LightLookup { first, data } => {
                    write_range(&mut self.lights.tree.lookup, *first, data)
                }
                SceneWrite::TruncateInstances { len } => self.instances.truncate(*len as usize),
            }
        }
        self.tlas_root = header.tlas_root;
        self.origin = header.origin;
        self.lights = LightTable {
            lights: std::mem::take(&mut self.lights.lights),
            count: header.light_count,
            weight_total: header.light_weight_total,
            tree: std::mem::take(&mut self.lights.tree),
        };
    }
}
