//! The GLB container: splits a binary glTF file into its JSON chunk and its optional BIN chunk.
//!
//! Written here rather than taken from the `gltf` crate because that one subtracts the header
//! size from the declared length unchecked (a GLB whose length field is under 12 panics a
//! debug build). Layout (glTF 2.0 §4.4): a 12-byte header (`glTF`, version 2, total length),
//! then chunks of (length, type, data), each length a multiple of 4; the first chunk is JSON,
//! an optional second one BIN. Unknown chunk types after them are skipped, as the
//! specification asks.
//! Must not: parse the JSON.

/// The chunks of a GLB file.
pub(crate) struct Glb<'a> {
    pub json: &'a [u8],
    pub bin: Option<&'a [u8]>,
    /// Oddities that did not stop loading (for notes).
    pub notes: Vec<String>,
}

const MAGIC: &[u8; 4] = b"glTF";
const CHUNK_JSON: u32 = 0x4E4F_534A;
const CHUNK_BIN: u32 = 0x004E_4942;

/// Whether `bytes` start like a GLB file.
pub(crate) fn is_glb(bytes: &[u8]) -> bool {
    bytes.starts_with(MAGIC)
}

/// Splits `bytes` (a whole GLB file); errors describe the first structural problem.
pub(crate) fn split_glb(bytes: &[u8]) -> Result<Glb<'_>, String> {
    let (Some(version), Some(length)) = (word(bytes, 4), word(bytes, 8)) else {
        return Err(format!("GLB header truncated ({} bytes)", bytes.len()));
    };
    if version != 2 {
        return Err(format!("GLB version {version} (only 2 is supported)"));
    }
    let mut notes = Vec::new();
    let length = length as usize;
    if length < 12 {
        return Err(format!("GLB length {length} is smaller than its header"));
    }
    if length > bytes.len() {
        return Err(format!(
            "GLB declares {length} bytes but the file has {}",
            bytes.len()
        ));
    }
    if length < bytes.len() {
        notes.push(format!(
            "{} bytes after the GLB's declared length ignored",
            bytes.len() - length
        ));
    }
    let bytes = &bytes[..length];
    let mut at = 12;
    let mut json: Option<&[u8]> = None;
    let mut bin: Option<&[u8]> = None;
    while at < bytes.len() {
        let (Some(chunk_length), Some(chunk_type)) = (word(bytes, at), word(bytes, at + 4)) else {
            return Err(format!("GLB chunk header at byte {at} truncated"));
        };
        let start = at + 8;
        let end = start
            .checked_add(chunk_length as usize)
            .filter(|&end| end <= bytes.len())
            .ok_or_else(|| {
                format!(
                    "GLB chunk at byte {at} declares {chunk_length} bytes past the end of the file"
                )
            })?;
        let data = &bytes[start..end];
        match chunk_type {
            CHUNK_JSON if json.is_none() && at == 12 => json = Some(data),
            CHUNK_JSON => return Err("a GLB may hold only one JSON chunk, first".to_string()),
            _ if json.is_none() => return Err("the first GLB chunk is not JSON".to_string()),
            CHUNK_BIN if bin.is_none() => bin = Some(data),
            CHUNK_BIN => return Err("a GLB may hold only one BIN chunk".to_string()),
            other => notes.push(format!("unknown GLB chunk type {other:#010x} skipped")),
        }
        if chunk_length % 4 != 0 {
            notes.push(format!("GLB chunk at byte {at} is not 4-byte aligned"));
        }
        at = end;
    }
    let json = json.ok_or("the GLB has no JSON chunk")?;
    Ok(Glb { json, bin, notes })
}

/// The little-endian `u32` at byte `at`, if the slice holds it.
fn word(bytes: &[u8], at: usize) -> Option<u32> {
    let slice = bytes.get(at..at.checked_add(4)?)?;
    Some(u32::from_le_bytes([slice[0], slice[1], slice[2], slice[3]]))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn glb(chunks: &[(u32, &[u8])], length_delta: i64) -> Vec<u8> {
        let mut body = Vec::new();
        for (kind, data) in chunks {
            body.extend((data.len() as u32).to_le_bytes());
            body.extend(kind.to_le_bytes());
            body.extend(*data);
        }
        let length = (12 + body.len()) as i64 + length_delta;
        let mut bytes = b"glTF".to_vec();
        bytes.extend(2u32.to_le_bytes());
        bytes.extend((length as u32).to_le_bytes());
        bytes.extend(body);
        bytes
    }

    #[test]
    fn splits_valid_files_and_refuses_broken_ones() -> Result<(), String> {
        let good = glb(&[(CHUNK_JSON, b"{}  "), (CHUNK_BIN, b"abcd")], 0);
        let split = split_glb(&good)?;
        assert_eq!((split.json, split.bin), (&b"{}  "[..], Some(&b"abcd"[..])));
        for (bad, why) in [
            (glb(&[(CHUNK_JSON, b"{}  ")], 4), "too long"),
            (glb(&[(CHUNK_BIN, b"abcd")], 0), "BIN first"),
            (glb(&[], 0), "no chunk"),
            (
                b"glTF\x02\0\0\0\x04\0\0\0".to_vec(),
                "length under the header",
            ),
            (b"glTF\x02\0".to_vec(), "truncated header"),
        ] {
            assert!(split_glb(&bad).is_err(), "{why}: accepted");
        }
        Ok(())
    }
}
