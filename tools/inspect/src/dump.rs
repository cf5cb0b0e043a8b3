//! Writing animated world-space vertex positions as little-endian float32 x y z.
//!
//! Owns: [`write`]. Must not: print (the caller reports).

use std::io::Write;
use std::path::Path;

use anyhow::{Context, Result};
use candela::sim::animation::{AnimatedModel, world_positions};

/// Evaluates `clip` (the rest pose when `None`) at `time_seconds` and writes every vertex
/// of the default scene to `out`; returns the vertex count.
pub fn write(
    model: &AnimatedModel,
    clip: Option<usize>,
    time_seconds: f64,
    out: &Path,
) -> Result<usize> {
    let pose = match clip {
        Some(clip) => model.pose_at(clip, time_seconds),
        None => model.rest_pose(),
    };
    let positions = world_positions(model, &pose);
    let mut bytes = Vec::with_capacity(positions.len() * 12);
    for p in &positions {
        for c in p.to_array() {
            bytes.extend_from_slice(&c.to_le_bytes());
        }
    }
    let mut file =
        std::fs::File::create(out).with_context(|| format!("creating {}", out.display()))?;
    file.write_all(&bytes)
        .with_context(|| format!("writing {}", out.display()))?;
    Ok(positions.len())
}
