//! Interleaved indirect light (twin: `shaders/shared/interleave.wgsl`): which pixels trace a
//! path's first diffuse or glossy bounce this sample, and the weight that keeps the estimate
//! unbiased ([`METHOD_INDIRECT_HALF`], [`METHOD_INDIRECT_QUARTER`]).
//!
//! Owns: [`indirect_weight`]. The choice is a fixed pattern over the pixel grid that turns with
//! the sample index: with one pixel in `k` chosen per sample (k = 2: a checkerboard; k = 4: one
//! pixel of each 2×2 block), any `k` consecutive samples of a pixel hold exactly one chosen
//! sample, weighted ×k, so their mean is the mean of the full estimator's (stratified, not
//! random: no extra variance beyond the one path's). Neighbouring pixels take turns, so each
//! frame of one sample still spreads indirect estimates evenly over the picture for the
//! denoiser to join. Any thread (a pure function).
//! Must not: trace, or draw random numbers (the path's random sequence is the same whether or
//! not its bounce is traced).

use crate::layout::{METHOD_INDIRECT_HALF, METHOD_INDIRECT_QUARTER};

/// The order in which a 2×2 block's pixels (index `x % 2 + 2 · (y % 2)`) take their turn:
/// diagonal neighbours one sample apart, so two consecutive samples cover a checkerboard.
const QUARTER_ORDER: [u32; 4] = [0, 3, 1, 2];

/// The weight of pixel (px, py)'s first diffuse or glossy bounce at sample index `sample`
/// under `method`: 1 without interleaving, 0 when this pixel skips it this sample, and 2 or 4
/// when it traces it for its neighbours.
#[inline]
pub fn indirect_weight(method: u32, px: u32, py: u32, sample: u32) -> f32 {
    if method & METHOD_INDIRECT_QUARTER != 0 {
        let cell = (px & 1) + 2 * (py & 1);
        if cell == QUARTER_ORDER[(sample & 3) as usize] {
            4.0
        } else {
            0.0
        }
    } else if method & METHOD_INDIRECT_HALF != 0 {
        if (px + py + sample) & 1 == 0 {
            2.0
        } else {
            0.0
        }
    } else {
        1.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every pixel traces exactly one of any `k` consecutive samples, weighted ×k: the mean
    /// weight over those samples is 1 at every pixel (the estimate is unbiased).
    #[test]
    fn each_pixel_takes_exactly_one_turn_in_k_samples() {
        for (method, k) in [
            (0u32, 1u32),
            (METHOD_INDIRECT_HALF, 2),
            (METHOD_INDIRECT_QUARTER, 4),
        ] {
            for py in 0..6 {
                for px in 0..6 {
                    for start in 0..9 {
                        let w: Vec<f32> = (start..start + k)
                            .map(|s| indirect_weight(method, px, py, s))
                            .collect();
                        let turns = w.iter().filter(|&&x| x > 0.0).count();
                        assert_eq!(
                            turns, 1,
                            "method {method:#x} pixel ({px}, {py}) from {start}"
                        );
                        assert_eq!(w.iter().sum::<f32>(), k as f32);
                    }
                }
            }
        }
    }

    /// In one sample every 2×2 block holds its share of chosen pixels: one (a quarter) or two
    /// (a half, diagonal), so the indirect estimates are spread evenly over the picture.
    #[test]
    fn one_sample_spreads_its_turns_over_every_block() {
        for s in 0..8 {
            for (by, bx) in [(0u32, 0u32), (2, 4), (6, 2)] {
                let block = |m| {
                    (0..4)
                        .filter(|i| indirect_weight(m, bx + i % 2, by + i / 2, s) > 0.0)
                        .count()
                };
                assert_eq!(block(METHOD_INDIRECT_QUARTER), 1, "sample {s}");
                assert_eq!(block(METHOD_INDIRECT_HALF), 2, "sample {s}");
            }
        }
    }
}
