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

    /// The buffer this write targets (an index per variant) and its element range
    /// `first..end`; `None` for a truncation.
    fn target_range(&self) -> Option<(u8, u32, u32)> {
        let r = |kind: u8, first: u32, len: usize| Some((kind, first, first + len as u32));
        match self {
            SceneWrite::Nodes { first, data } => r(0, *first, data.len()),
            SceneWrite::Blocks { first, data } => r(1, *first, data.len()),
            SceneWrite::Instances { first, data } => r(2, *first, data.len()),
            SceneWrite::Triangles { first, data } => r(3, *first, data.len()),
            SceneWrite::Vertices { first, data } => r(4, *first, data.len()),
            SceneWrite::Materials { first, data } => r(5, *first, data.len()),
            SceneWrite::Textures { first, data } => r(6, *first, data.len()),
            SceneWrite::Texels { first, data } => r(7, *first, data.len()),
            SceneWrite::Lights { first, data } => r(8, *first, data.len()),
            SceneWrite::LightNodes { first, data } => r(9, *first, data.len()),
            SceneWrite::LightLookup { first, data } => r(10, *first, data.len()),
            SceneWrite::TruncateInstances { .. } => None,
        }
    }

    /// Whether this write, applied after `earlier`, leaves nothing of it: the same buffer and
    /// a range that covers `earlier`'s. Whatever was applied between them, every element
    /// `earlier` wrote is written again, and the buffer grows at least as far, so `earlier`
    /// can be dropped from a list of pending writes without changing what the list makes.
    pub fn supersedes(&self, earlier: &SceneWrite) -> bool {
        match (self.target_range(), earlier.target_range()) {
            (Some((kind, first, end)), Some((k, f, e))) => kind == k && first <= f && e <= end,
            _ => false,
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

#[cfg(test)]
mod tests {
    use super::*;

    fn nodes(first: u32, len: usize) -> SceneWrite {
        SceneWrite::Nodes {
            first,
            data: vec![bytemuck::Zeroable::zeroed(); len],
        }
    }

    #[test]
    fn a_write_supersedes_only_what_it_covers_in_the_same_buffer() {
        assert!(nodes(10, 5).supersedes(&nodes(10, 5)));
        assert!(nodes(8, 10).supersedes(&nodes(10, 5)));
        assert!(!nodes(11, 5).supersedes(&nodes(10, 5)), "a part left");
        assert!(!nodes(10, 5).supersedes(&nodes(10, 6)), "an end left");
        let other = SceneWrite::Lights {
            first: 10,
            data: vec![bytemuck::Zeroable::zeroed(); 5],
        };
        assert!(!nodes(10, 5).supersedes(&other), "another buffer");
        let cut = SceneWrite::TruncateInstances { len: 3 };
        assert!(!nodes(0, 100).supersedes(&cut) && !cut.supersedes(&nodes(0, 1)));
    }
}
