//! A structural check of RIFF/WAVE files before decoding: every chunk's declared size must fit
//! in the bytes that are there.
//!
//! Owns: [`check_wave`]. The decoder (symphonia, through kira) stops quietly at the end of a
//! short `data` chunk and hands back fewer samples than the header promised; this check turns a
//! cut-off download or a half-written file into a clear [`DecodeProblem::Truncated`] instead.
//! Must not: decode samples or judge anything but sizes and chunk layout; bytes that are not
//! RIFF/WAVE pass through untouched (the decoder judges them).

use super::DecodeProblem;

/// Size of a chunk header: a four-character id and a little-endian `u32` size.
const CHUNK_HEADER_BYTES: usize = 8;
/// `"RIFF"`, the file size minus 8, `"WAVE"`.
const RIFF_HEADER_BYTES: usize = 12;
/// Writers that stream (and never patch the header) leave these sizes in place of a real one.
const UNKNOWN_SIZES: [u32; 2] = [0, u32::MAX];

fn read_u32_le(bytes: &[u8], at: usize) -> Option<u32> {
    let b = bytes.get(at..at + 4)?;
    Some(u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
}

/// Checks the chunk layout of a RIFF/WAVE file held in `bytes`: each chunk in turn (so a file cut
/// inside its samples names the `"data"` chunk), then the RIFF size. Returns `Ok` for anything
/// that is not RIFF/WAVE. Costs one pass over the chunk headers (not the samples).
pub fn check_wave(bytes: &[u8]) -> Result<(), DecodeProblem> {
    if bytes.len() < RIFF_HEADER_BYTES || &bytes[0..4] != b"RIFF" || &bytes[8..12] != b"WAVE" {
        return Ok(());
    }
    let mut at = RIFF_HEADER_BYTES;
    let mut saw_data = false;
    while at + CHUNK_HEADER_BYTES <= bytes.len() {
        let id = String::from_utf8_lossy(&bytes[at..at + 4]).into_owned();
        let Some(size) = read_u32_le(bytes, at + 4) else {
            break;
        };
        let body = at + CHUNK_HEADER_BYTES;
        let present = (bytes.len() - body) as u64;
        let is_data = id == "data";
        saw_data |= is_data;
        if is_data && UNKNOWN_SIZES.contains(&size) {
            // A streamed file: the data runs to the end of the file.
            return Ok(());
        }
        if u64::from(size) > present {
            return Err(DecodeProblem::Truncated {
                chunk: id,
                declared_bytes: size.into(),
                present_bytes: present,
            });
        }
        // Chunks are padded to an even size.
        at = body + size as usize + (size as usize & 1);
    }
    if at < bytes.len() && !saw_data {
        return Err(DecodeProblem::Truncated {
            chunk: "chunk header".into(),
            declared_bytes: CHUNK_HEADER_BYTES as u64,
            present_bytes: (bytes.len() - at) as u64,
        });
    }
    if !saw_data {
        return Err(DecodeProblem::Malformed {
            detail: "a WAVE file without a \"data\" chunk".into(),
        });
    }
    // Every chunk fits, but the file may still have been cut at a chunk boundary.
    let present_after_riff = (bytes.len() - CHUNK_HEADER_BYTES) as u64;
    if let Some(riff_size) = read_u32_le(bytes, 4)
        && !UNKNOWN_SIZES.contains(&riff_size)
        && u64::from(riff_size) > present_after_riff
    {
        return Err(DecodeProblem::Truncated {
            chunk: "RIFF".into(),
            declared_bytes: riff_size.into(),
            present_bytes: present_after_riff,
        });
    }
    Ok(())
}
