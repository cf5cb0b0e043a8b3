//! What a flattened scene holds in memory, by kind: the figures Brigade's paper gives for its
//! 1.4 M-triangle scene (§6.2: 175 MB triangles, 42 MB BVH, 520 MB textures of 737 MB).
//!
//! Owns: [`SceneMemory`] and [`RenderScene::memory`]. Counts the bytes of the vectors the
//! tracers read (lengths × element sizes; capacity slack and allocator overhead are not
//! counted, nor the main thread's own copy of the same data). Any thread (plain data).
//! Must not: allocate or change the scene.

use super::flattened::RenderScene;

/// Bytes of a [`RenderScene`] by kind.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SceneMemory {
    /// Triangles the tracers intersect and shade: the BVH leaves' packed triangle blocks,
    /// the shading triangles (vertex indices, material) and the vertices.
    pub triangles: usize,
    /// BVH nodes: every BLAS and the TLAS.
    pub bvh: usize,
    /// The instance table (transforms both ways, BLAS roots, material offsets).
    pub instances: usize,
    /// Texture headers and texels (linear RGBA, f16).
    pub textures: usize,
    /// The emissive-triangle light table and the light tree with its lookup.
    pub lights: usize,
    /// Materials and the physical sky's sky-view table.
    pub other: usize,
}

impl SceneMemory {
    /// Every kind together.
    pub fn total(&self) -> usize {
        self.triangles + self.bvh + self.instances + self.textures + self.lights + self.other
    }
}

fn bytes<T>(items: &[T]) -> usize {
    std::mem::size_of_val(items)
}

impl RenderScene {
    /// The bytes this scene's vectors hold, by kind.
    pub fn memory(&self) -> SceneMemory {
        let tree = &self.lights.tree;
        SceneMemory {
            triangles: bytes(&self.blocks) + bytes(&self.triangles) + bytes(&self.vertices),
            bvh: bytes(&self.nodes),
            instances: bytes(&self.instances),
            textures: bytes(&self.textures) + bytes(&self.texels),
            lights: bytes(&self.lights.lights) + bytes(&tree.nodes) + bytes(&tree.lookup),
            other: bytes(&self.materials) + bytes(self.sky.texels.as_slice()),
        }
    }
}
