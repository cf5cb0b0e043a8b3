//! Readers of the peer benchmark's shared files (little-endian, formats in
//! `shared/peers/README.md`): `scene.tri` (magic "TRIS", triangle soup) and `*.rays`
//! (magic "RAYS", `ox oy oz tnear dx dy dz tfar` per ray). Errors name the file.

use anyhow::{Context, Result, bail, ensure};
use glam::Vec3;

/// One ray record as stored.
#[derive(Clone, Copy, Debug)]
pub struct RayRecord {
    pub origin: [f32; 3],
    pub t_near: f32,
    pub direction: [f32; 3],
    pub t_far: f32,
}

/// The body after a 16-byte header with `magic`, version 1 and a count of `stride`-byte records.
fn body(path: &str, magic: u32, stride: usize) -> Result<(usize, Vec<f32>)> {
    let bytes = std::fs::read(path).with_context(|| format!("cannot read {path}"))?;
    let word = |i: usize| -> Result<u32> {
        let b = bytes
            .get(4 * i..4 * i + 4)
            .with_context(|| format!("{path}: short header"))?;
        Ok(u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
    };
    if word(0)? != magic || word(1)? != 1 {
        bail!("{path}: not a version-1 file with magic {magic:#x}");
    }
    let count = word(2)? as usize;
    let data = bytes
        .get(16..16 + count * stride)
        .with_context(|| format!("{path}: {count} records announced, file too short"))?;
    let floats = data
        .chunks_exact(4)
        .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]))
        .collect();
    Ok((count, floats))
}

/// The soup as positions (3 per triangle) and index triples `[3i, 3i+1, 3i+2]`.
pub fn load_triangles(path: &str) -> Result<(Vec<Vec3>, Vec<[u32; 3]>)> {
    let (count, f) = body(path, 0x5349_5254, 36)?;
    ensure!(
        count < (u32::MAX / 3) as usize,
        "{path}: too many triangles"
    );
    let positions = f.chunks_exact(3).map(Vec3::from_slice).collect();
    let triangles = (0..count as u32)
        .map(|i| [3 * i, 3 * i + 1, 3 * i + 2])
        .collect();
    Ok((positions, triangles))
}

/// All ray records of a `.rays` file.
pub fn load_rays(path: &str) -> Result<Vec<RayRecord>> {
    let (_, f) = body(path, 0x5359_4152, 32)?;
    Ok(f.chunks_exact(8)
        .map(|r| RayRecord {
            origin: [r[0], r[1], r[2]],
            t_near: r[3],
            direction: [r[4], r[5], r[6]],
            t_far: r[7],
        })
        .collect())
}
