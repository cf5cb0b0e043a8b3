//! Acceleration structures: BLAS per mesh, TLAS over instances, in the 8-wide layout of
//! [`crate::layout::GpuBvh8Node`] / [`crate::layout::GpuTri4`] that both tracers read.
//!
//! Inputs: mesh positions and triangles (BLAS), instance bounds (TLAS). Outputs: node and block
//! vectors whose indices are relative to their own first element; the caller concatenates them
//! into the frame's buffers. Main thread; no shared state. Must not: trace rays (see
//! [`crate::trace`]) or know about materials and lights.
//!
//! Phases (one file each): [`bounds`] (the box type), `bvh2` (binary PLOC build with obvhs),
//! `collapse` (SAH-optimal 8-wide collapse and the per-octant child orders), [`blas`] (triangle
//! blocks), [`tlas`] (instances).

mod binned;
pub mod blas;
pub mod bounds;
mod bvh2;
mod collapse;
pub mod tlas;

pub use blas::{Blas, build_blas, build_blas_with};
pub use bounds::Aabb;
pub use bvh2::BuildQuality;
pub use tlas::build_tlas;

/// Deepest tree (levels of 8-wide nodes) the builders emit and the tracers' fixed stacks hold.
/// A traversal pushes at most 7 entries per level plus 8 at the deepest node, so
/// `7 · (MAX_DEPTH - 1) + 8` entries (239) fit the 256-entry stacks of [`crate::trace`] with
/// room for one 8-lane vector store. Builds that would be deeper fall back to a balanced
/// binary tree, whose depth is at most `log2(primitives) + 1` (at most 33 for `u32` counts).
pub const MAX_DEPTH: u32 = 34;
