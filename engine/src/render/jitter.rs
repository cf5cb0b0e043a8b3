//! The sub-pixel jitter of the traced grid for temporal upscaling (`denoise::upscale`): one
//! offset per frame, shared by every pixel, from the Halton (2, 3) sequence over
//! [`JITTER_FRAMES`] frames, deterministic from the frame number (replays and captures repeat).
//!
//! Owns: [`frame_jitter`] and the packing of an offset into `GpuFrameUniforms::pixel_jitter`
//! ([`pack`], [`unpack`]): 0 means "no fixed offset" (each sample uniform in its pixel, the box
//! filter); otherwise bit 31 is set and bits 0–14 and 15–29 hold x and y in 1/32768 of a traced
//! pixel (x right, y down, from the pixel's top left corner). Any thread.
//! Must not: trace or accumulate.

/// Frames before the jitter sequence repeats.
pub const JITTER_FRAMES: u64 = 16;

/// Steps of a packed offset per traced pixel.
const STEPS: f32 = 32768.0;
const FLAG: u32 = 1 << 31;

/// The radical inverse of `index` in `base` (the Halton sequence's `index`-th value, in [0, 1)).
pub fn halton(mut index: u64, base: u64) -> f32 {
    let (mut f, mut r) = (1.0f64, 0.0f64);
    while index > 0 {
        f /= base as f64;
        r += f * (index % base) as f64;
        index /= base;
    }
    r as f32
}

/// The offset of frame `frame`'s samples inside their pixels (traced pixels, [0, 1)², already
/// quantized as [`pack`] stores it).
pub fn frame_jitter(frame: u64) -> (f32, f32) {
    let k = frame % JITTER_FRAMES + 1;
    let q = |v: f32| (v * STEPS).floor().min(STEPS - 1.0) / STEPS;
    (q(halton(k, 2)), q(halton(k, 3)))
}

/// The uniforms' word for offset (x, y) (traced pixels, each clamped to [0, 1)).
pub fn pack((x, y): (f32, f32)) -> u32 {
    let q = |v: f32| (v.clamp(0.0, 1.0) * STEPS).floor().min(STEPS - 1.0) as u32;
    FLAG | q(x) | (q(y) << 15)
}

/// The offset a uniforms' word holds (`None`: the samples are uniform in their pixels).
pub fn unpack(word: u32) -> Option<(f32, f32)> {
    (word & FLAG != 0).then(|| {
        let x = (word & 0x7fff) as f32 / STEPS;
        let y = ((word >> 15) & 0x7fff) as f32 / STEPS;
        (x, y)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn halton_starts_as_published() {
        assert_eq!(halton(1, 2), 0.5);
        assert_eq!(halton(2, 2), 0.25);
        assert_eq!(halton(3, 2), 0.75);
        assert!((halton(1, 3) - 1.0 / 3.0).abs() < 1e-7);
        assert!((halton(2, 3) - 2.0 / 3.0).abs() < 1e-7);
        assert!((halton(4, 3) - 4.0 / 9.0).abs() < 1e-7);
    }

    #[test]
    fn jitter_is_deterministic_periodic_and_packs_exactly() {
        let first: Vec<_> = (0..JITTER_FRAMES).map(frame_jitter).collect();
        let again: Vec<_> = (JITTER_FRAMES..2 * JITTER_FRAMES)
            .map(frame_jitter)
            .collect();
        assert_eq!(first, again);
        let distinct: std::collections::BTreeSet<_> = first
            .iter()
            .map(|&(x, y)| ((x * STEPS) as u32, (y * STEPS) as u32))
            .collect();
        assert_eq!(distinct.len() as u64, JITTER_FRAMES);
        for &j in &first {
            assert!(
                (0.0..1.0).contains(&j.0) && (0.0..1.0).contains(&j.1),
                "{j:?}"
            );
            assert_eq!(unpack(pack(j)), Some(j));
        }
        // Every quarter of the pixel gets 3 to 5 of the 16 frames (2× upscaling sees all four;
        // Halton's base 3 does not split in halves evenly).
        for qx in 0..2 {
            for qy in 0..2 {
                let n = first
                    .iter()
                    .filter(|&&(x, y)| (x * 2.0) as i32 == qx && (y * 2.0) as i32 == qy)
                    .count();
                assert!((3..=5).contains(&n), "quarter ({qx}, {qy}): {n} frames");
            }
        }
        assert_eq!(unpack(0), None);
    }
}
