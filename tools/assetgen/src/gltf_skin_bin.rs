//! The binary side of `gltf_skin`: the buffer with its views and accessors as they are
//! appended (each view padded to four bytes), little-endian `f32` packing, accessor bounds,
//! and the GLB container (glTF 2.0 §4.4: a 12-byte header, the JSON chunk padded with spaces,
//! the BIN chunk padded with zeros). Must not: know what the data means.

use crate::gltf_json::Accessor;
use crate::gltf_skin_json::View;

pub(crate) const ARRAY_BUFFER: u32 = 34962;
pub(crate) const ELEMENT_ARRAY_BUFFER: u32 = 34963;
pub(crate) const UNSIGNED_BYTE: u32 = 5121;
pub(crate) const UNSIGNED_SHORT: u32 = 5123;
pub(crate) const UNSIGNED_INT: u32 = 5125;
pub(crate) const FLOAT: u32 = 5126;

/// The binary buffer and its views and accessors, as they are written.
#[derive(Default)]
pub(crate) struct Bin {
    pub(crate) bytes: Vec<u8>,
    pub(crate) views: Vec<View>,
    pub(crate) accessors: Vec<Accessor>,
}

impl Bin {
    /// Appends `bytes` (padded to 4) as a view and an accessor over it; returns the accessor.
    pub(crate) fn push(
        &mut self,
        bytes: Vec<u8>,
        target: Option<u32>,
        accessor: (u32, usize, &'static str),
        bounds: Option<(Vec<f32>, Vec<f32>)>,
    ) -> usize {
        let offset = self.bytes.len();
        self.bytes.extend_from_slice(&bytes);
        while !self.bytes.len().is_multiple_of(4) {
            self.bytes.push(0);
        }
        self.views.push(View {
            buffer: 0,
            byte_offset: offset,
            byte_length: bytes.len(),
            target,
        });
        let (component_type, count, kind) = accessor;
        let (min, max) = bounds.unzip();
        self.accessors.push(Accessor {
            buffer_view: self.views.len() - 1,
            component_type,
            count,
            kind,
            min,
            max,
        });
        self.accessors.len() - 1
    }
}

pub(crate) fn floats(values: impl IntoIterator<Item = f32>) -> Vec<u8> {
    values.into_iter().flat_map(f32::to_le_bytes).collect()
}

/// Per-component bounds of `values` taken `width` at a time.
pub(crate) fn bounds(values: &[f32], width: usize) -> (Vec<f32>, Vec<f32>) {
    let mut min = vec![f32::INFINITY; width];
    let mut max = vec![f32::NEG_INFINITY; width];
    for chunk in values.chunks_exact(width) {
        for k in 0..width {
            min[k] = min[k].min(chunk[k]);
            max[k] = max[k].max(chunk[k]);
        }
    }
    (min, max)
}

/// The GLB container: header, JSON chunk (space-padded), BIN chunk (zero-padded).
pub(crate) fn glb(mut json: Vec<u8>, mut bin: Vec<u8>) -> Vec<u8> {
    while !json.len().is_multiple_of(4) {
        json.push(b' ');
    }
    while !bin.len().is_multiple_of(4) {
        bin.push(0);
    }
    let total = 12 + 8 + json.len() + 8 + bin.len();
    let mut out = Vec::with_capacity(total);
    out.extend_from_slice(b"glTF");
    out.extend_from_slice(&2u32.to_le_bytes());
    out.extend_from_slice(&(total as u32).to_le_bytes());
    out.extend_from_slice(&(json.len() as u32).to_le_bytes());
    out.extend_from_slice(b"JSON");
    out.extend_from_slice(&json);
    out.extend_from_slice(&(bin.len() as u32).to_le_bytes());
    out.extend_from_slice(b"BIN\0");
    out.extend_from_slice(&bin);
    out
}
