//! Reading glTF accessors with every bound checked, dense and sparse.
//!
//! Written here instead of using `gltf::mesh::Reader` because that reader trusts the file: it
//! subtracts 1 from `count` unchecked, multiplies offsets without overflow checks, asserts
//! on component sizes (so KHR_mesh_quantization data panics a debug build) and unwraps
//! sparse values. Here, every byte range is checked against its buffer view and buffer with
//! 64-bit arithmetic, `count` is bounded by [`MAX_ACCESSOR_ELEMENTS`] before allocating, and
//! a sparse index must lie below `count`.
//! Values: floats as they are; integers as their value, or mapped to [0, 1] / [-1, 1] when
//! `normalized` (glTF 2.0 §3.11). Of the matrix types only MAT4 is read (skins' inverse bind
//! matrices), column-major as stored: its columns never need the padding glTF 2.0 §3.6.2.4
//! asks of MAT2/MAT3 with small components. Output is flat: `count × components` values.
//! Must not: interpret what the values mean (`mesh` does).

use gltf::json;
use gltf::json::accessor::{ComponentType, Type};
use gltf::json::validation::Checked;

use super::super::context::LoadContext;
use super::super::error::{AssetError, AssetResult};
use super::super::limits::MAX_ACCESSOR_ELEMENTS;
use super::document::GltfFile;

/// Reads accessors and buffer views of one glTF file.
pub(crate) struct Reader<'a> {
    pub context: &'a LoadContext<'a>,
    pub file: &'a GltfFile,
}

/// An accessor's layout, checked.
struct Layout {
    component: ComponentType,
    components: usize,
    component_size: usize,
    count: usize,
}

impl Reader<'_> {
    /// The bytes of buffer view `view`, and its byte stride if set.
    pub fn view_bytes(&self, view: usize) -> AssetResult<(&[u8], Option<usize>)> {
        let error = |m: String| self.context.gltf_error(format!("buffer view {view}: {m}"));
        let json = self.file.document.as_json();
        let view_json = json
            .buffer_views
            .get(view)
            .ok_or_else(|| error("does not exist".into()))?;
        let buffer = self
            .file
            .buffers
            .get(view_json.buffer.value())
            .ok_or_else(|| error("its buffer does not exist".into()))?
            .as_ref()
            .ok_or_else(|| {
                error(format!(
                    "buffer {} has no data (no uri, and not the GLB's BIN chunk)",
                    view_json.buffer.value()
                ))
            })?;
        let start = view_json.byte_offset.map_or(0, |o| o.0);
        let end = start.checked_add(view_json.byte_length.0);
        match end {
            Some(end) if end <= buffer.len() as u64 => Ok((
                &buffer[start as usize..end as usize],
                view_json.byte_stride.map(|s| s.0),
            )),
            _ => Err(error(format!(
                "bytes {start}+{} lie outside buffer {} ({} bytes)",
                view_json.byte_length.0,
                view_json.buffer.value(),
                buffer.len()
            ))),
        }
    }

    /// Reads accessor `index` as floats; its type must be one of `types`. Returns the values
    /// and the component count per element.
    pub fn read_floats(
        &self,
        index: usize,
        types: &[Type],
        what: &str,
    ) -> AssetResult<(Vec<f32>, usize)> {
        let (accessor, layout) = self.layout(index, what)?;
        if !types
            .iter()
            .any(|&t| components_of(t) == Some(layout.components))
        {
            return Err(self.error(
                index,
                what,
                format!("has {} components, expected {types:?}", layout.components),
            ));
        }
        let normalized = accessor.normalized;
        let values = self.read(index, what, accessor, &layout, |component, bytes| {
            decode_float(component, bytes, normalized)
        })?;
        Ok((values, layout.components))
    }

    /// Reads accessor `index` as vertex indices (unsigned integer scalars).
    pub fn read_indices(&self, index: usize) -> AssetResult<Vec<u32>> {
        let what = "indices";
        let (accessor, layout) = self.layout(index, what)?;
        if layout.components != 1
            || !matches!(
                layout.component,
                ComponentType::U8 | ComponentType::U16 | ComponentType::U32
            )
        {
            return Err(self.error(index, what, "must be unsigned integer scalars".to_string()));
        }
        self.read(
            index,
            what,
            accessor,
            &layout,
            |component, bytes| match component {
                ComponentType::U8 => u32::from(bytes[0]),
                ComponentType::U16 => u32::from(u16::from_le_bytes([bytes[0], bytes[1]])),
                _ => u32::from_le_bytes([bytes[0], bytes[1], bytes[2], bytes[3]]),
            },
        )
    }

    fn error(&self, index: usize, what: &str, message: String) -> AssetError {
        self.context
            .gltf_error(format!("accessor {index} ({what}) {message}"))
    }

    /// Checks the accessor's type and count.
    fn layout(&self, index: usize, what: &str) -> AssetResult<(&json::Accessor, Layout)> {
        let accessor = self
            .file
            .document
            .as_json()
            .accessors
            .get(index)
            .ok_or_else(|| self.error(index, what, "does not exist".to_string()))?;
        let (Checked::Valid(component), Checked::Valid(kind)) =
            (&accessor.component_type, &accessor.type_)
        else {
            return Err(self.error(index, what, "has an unknown type".to_string()));
        };
        let component = component.0;
        let components = components_of(*kind).ok_or_else(|| {
            self.error(
                index,
                what,
                "is a MAT2 or MAT3, which is not read here".to_string(),
            )
        })?;
        let count = accessor.count.0;
        if count > MAX_ACCESSOR_ELEMENTS {
            return Err(self.context.too_large(
                format!("accessor {index} ({what}) element count"),
                count,
                MAX_ACCESSOR_ELEMENTS,
            ));
        }
        let component_size = match component {
            ComponentType::I8 | ComponentType::U8 => 1,
            ComponentType::I16 | ComponentType::U16 => 2,
            ComponentType::U32 | ComponentType::F32 => 4,
        };
        Ok((
            accessor,
            Layout {
                component,
                components,
                component_size,
                count: count as usize,
            },
        ))
    }

    /// Reads the dense part (zeros without a buffer view), then applies the sparse part.
    fn read<T: Copy + Default>(
        &self,
        index: usize,
        what: &str,
        accessor: &json::Accessor,
        layout: &Layout,
        decode: impl Fn(ComponentType, &[u8]) -> T,
    ) -> AssetResult<Vec<T>> {
        let fail = |m: String| self.error(index, what, m);
        let element_size = layout.component_size * layout.components;
        let mut values = vec![T::default(); layout.count * layout.components];
        let read_element = |data: &[u8], at: usize, out: &mut [T]| {
            for (c, value) in out.iter_mut().enumerate() {
                let start = at + c * layout.component_size;
                *value = decode(
                    layout.component,
                    &data[start..start + layout.component_size],
                );
            }
        };
        if let Some(view) = accessor.buffer_view {
            let (data, stride) = self.view_bytes(view.value())?;
            let stride = stride.unwrap_or(element_size);
            if stride < element_size {
                return Err(fail(format!(
                    "byte stride {stride} is below the element size {element_size}"
                )));
            }
            let offset = accessor.byte_offset.map_or(0, |o| o.0);
            check_range(data.len(), offset, stride, layout.count, element_size).map_err(&fail)?;
            for (element, out) in values.chunks_exact_mut(layout.components).enumerate() {
                read_element(data, offset as usize + element * stride, out);
            }
        }
        if let Some(sparse) = &accessor.sparse {
            let count = sparse.count.0;
            if count > layout.count as u64 {
                return Err(fail(format!(
                    "sparse count {count} exceeds the count {}",
                    layout.count
                )));
            }
            let count = count as usize;
            let Checked::Valid(index_type) = sparse.indices.component_type else {
                return Err(fail("has an unknown sparse index type".to_string()));
            };
            let index_size = match index_type.0 {
                ComponentType::U8 => 1,
                ComponentType::U16 => 2,
                ComponentType::U32 => 4,
                _ => return Err(fail("sparse indices must be unsigned integers".to_string())),
            };
            let (index_data, _) = self.view_bytes(sparse.indices.buffer_view.value())?;
            let index_offset = sparse.indices.byte_offset.0;
            check_range(
                index_data.len(),
                index_offset,
                index_size,
                count,
                index_size,
            )
            .map_err(&fail)?;
            let (value_data, _) = self.view_bytes(sparse.values.buffer_view.value())?;
            let value_offset = sparse.values.byte_offset.0;
            check_range(
                value_data.len(),
                value_offset,
                element_size,
                count,
                element_size,
            )
            .map_err(&fail)?;
            for k in 0..count {
                let at = index_offset as usize + k * index_size;
                let bytes = &index_data[at..at + index_size];
                let target = match index_size {
                    1 => bytes[0] as usize,
                    2 => u16::from_le_bytes([bytes[0], bytes[1]]) as usize,
                    _ => u32::from_le_bytes([bytes[0], bytes[1], bytes[2], bytes[3]]) as usize,
                };
                if target >= layout.count {
                    return Err(fail(format!(
                        "sparse index {target} is out of range (count {})",
                        layout.count
                    )));
                }
                let out = &mut values[target * layout.components..(target + 1) * layout.components];
                read_element(value_data, value_offset as usize + k * element_size, out);
            }
        }
        Ok(values)
    }
}

/// Components per element of a type the reader supports (MAT2 and MAT3 are not).
fn components_of(kind: Type) -> Option<usize> {
    match kind {
        Type::Scalar => Some(1),
        Type::Vec2 => Some(2),
        Type::Vec3 => Some(3),
        Type::Vec4 => Some(4),
        Type::Mat4 => Some(16),
        Type::Mat2 | Type::Mat3 => None,
    }
}

/// Checks that `count` elements of `size` bytes, `stride` apart from `offset`, fit in `length`.
fn check_range(
    length: usize,
    offset: u64,
    stride: usize,
    count: usize,
    size: usize,
) -> Result<(), String> {
    if count == 0 {
        return Ok(());
    }
    let end = (stride as u64)
        .checked_mul(count as u64 - 1)
        .and_then(|span| span.checked_add(offset))
        .and_then(|start| start.checked_add(size as u64));
    match end {
        Some(end) if end <= length as u64 => Ok(()),
        _ => Err(format!(
            "needs {count} elements of {size} bytes every {stride} bytes from byte {offset}, \
             but its buffer view has {length} bytes"
        )),
    }
}

/// One component as a float, normalized to [0, 1] or [-1, 1] when asked.
fn decode_float(component: ComponentType, bytes: &[u8], normalized: bool) -> f32 {
    match component {
        ComponentType::F32 => f32::from_le_bytes([bytes[0], bytes[1], bytes[2], bytes[3]]),
        ComponentType::I8 => {
            let value = f32::from(bytes[0] as i8);
            if normalized {
                (value / 127.0).max(-1.0)
            } else {
                value
            }
        }
        ComponentType::U8 => {
            let value = f32::from(bytes[0]);
            if normalized { value / 255.0 } else { value }
        }
        ComponentType::I16 => {
            let value = f32::from(i16::from_le_bytes([bytes[0], bytes[1]]));
            if normalized {
                (value / 32767.0).max(-1.0)
            } else {
                value
            }
        }
        ComponentType::U16 => {
            let value = f32::from(u16::from_le_bytes([bytes[0], bytes[1]]));
            if normalized { value / 65535.0 } else { value }
        }
        ComponentType::U32 => {
            let value = u32::from_le_bytes([bytes[0], bytes[1], bytes[2], bytes[3]]) as f32;
            if normalized {
                value / u32::MAX as f32
            } else {
                value
            }
        }
    }
}
