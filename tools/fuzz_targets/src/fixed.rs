//! The files the model targets load beside their input, in memory: the fixed OBJ and MTLs
//! that make the `obj`, `mtl` and `texture` targets reach their format, and [`files`], the
//! in-memory folder every model target resolves references in (the same layout as the
//! scratch asset root on disk, so a reference to `textures/t.png` finds a file either way).
//!
//! Owns: those constants and [`files`]. Runs on the calling thread. Must not: touch the file
//! system (only `asset_path` and `level` need the scratch folder on disk, see `scratch`).

use candela::assets::MemoryFiles;

/// A one-triangle OBJ that uses material `m` from `fuzz.mtl`.
pub const FIXED_OBJ: &[u8] = b"mtllib fuzz.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\nusemtl m\nf 1/1/1 2/2/1 3/3/1\n";

/// An MTL whose material `m` takes its colour from `fuzz_texture` (the texture target's file).
pub const TEXTURE_MTL: &[u8] = b"newmtl m\nKd 1 1 1\nmap_Kd fuzz_texture\n";

/// An MTL with one plain material `m` (for the OBJ target).
pub const PLAIN_MTL: &[u8] = b"newmtl m\nKd 0.5 0.5 0.5\n";

/// A file that claims to be a PNG and is not (`textures/t.png`).
pub const NOT_A_PNG: &[u8] = b"not really a png";

/// The in-memory folder a model target's input sits in: `models/box.obj`, `textures/t.png`
/// and `level.ron`, plus `extra` (path, bytes) files, such as the MTL beside the input OBJ.
pub fn files(extra: &[(&str, &[u8])]) -> MemoryFiles {
    let mut files = MemoryFiles::new()
        .with("models/box.obj", FIXED_OBJ)
        .with("textures/t.png", NOT_A_PNG)
        .with("level.ron", &b"()"[..]);
    for (path, bytes) in extra {
        files.insert(path, *bytes);
    }
    files
}
