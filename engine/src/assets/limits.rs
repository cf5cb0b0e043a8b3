//! The sizes past which a loader refuses input instead of allocating for it.
//!
//! Owns: the numeric limits shared by every loader, in one place so that they can be read and
//! defended together. A file that declares more than a limit is refused with
//! [`AssetError::TooLarge`](super::AssetError::TooLarge) *before* anything of that size is
//! allocated, so a corrupt or hostile count cannot exhaust memory.
//! Must not: hold logic.
//!
//! The figures are generous for game art (the largest test mesh, the Stanford dragon at full
//! resolution, has 100 k vertices and 200 k triangles in a 7 MiB OBJ; DamagedHelmet's largest
//! texture is 2048 × 2048) and small enough that the worst accepted file still fits the 24 GiB
//! machines the project runs on.

/// Largest file (OBJ, MTL, glTF JSON, GLB, `.bin` buffer, image) read into memory: 1 GiB.
pub(crate) const MAX_FILE_BYTES: u64 = 1 << 30;

/// Largest glTF buffer (`byteLength`), external, embedded or GLB: 1 GiB.
pub(crate) const MAX_BUFFER_BYTES: u64 = 1 << 30;

/// Most elements one glTF accessor may declare (`count`): 2^24 (16.7 M). This bounds the
/// sparse accessors whose base is all zeros, which need no buffer bytes for their count.
pub(crate) const MAX_ACCESSOR_ELEMENTS: u64 = 1 << 24;

/// Most vertices or triangles in one loaded mesh: 2^24 (16.7 M).
pub(crate) const MAX_MESH_ELEMENTS: u64 = 1 << 24;

/// Most vertices plus triangles in one loaded model, all meshes together: 2^25 (33.5 M;
/// at most about 1.6 GB of vertex data). glTF meshes can reuse one large accessor many times.
pub(crate) const MAX_MODEL_ELEMENTS: u64 = 1 << 25;

/// Widest or tallest texture, in texels: 16384 (the largest 2D texture most GPUs accept).
pub(crate) const MAX_TEXTURE_SIDE: u32 = 16_384;

/// Most texels in one texture: 2^28 (a full 16384 × 16384 image; 2 GiB as RGBA f16).
pub(crate) const MAX_TEXTURE_TEXELS: u64 = 1 << 28;

/// Most bytes an image decoder may allocate at once (passed to `image::Limits::max_alloc`):
/// 4 GiB, enough for the largest accepted image as 16-bit RGBA.
pub(crate) const MAX_DECODE_ALLOC_BYTES: u64 = 1 << 32;

/// Most placed mesh instances one glTF scene may expand to: 2^20. A node graph whose nodes
/// are shared by several parents (invalid glTF, but parseable) can otherwise expand
/// exponentially.
pub(crate) const MAX_PLACEMENTS: usize = 1 << 20;

/// Most node visits while expanding one glTF scene: 2^22. Bounds the same expansion for
/// nodes without meshes.
pub(crate) const MAX_NODE_VISITS: usize = 1 << 22;
