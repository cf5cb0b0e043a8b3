//! The counter-based random number generator both tracers use (twin: `shaders/shared/rng.wgsl`).
//!
//! Owns: turning (pixel, sample index, seed, draw counter) into uniform numbers. Stateless
//! apart from the draw counter, so any sample of any pixel can be reproduced alone, on any
//! thread, by either tracer. Hash: `pcg4d` (Jarzynski & Olano, "Hash Functions for GPU
//! Rendering", JCGT 2020); all arithmetic is wrapping u32, exactly as WGSL does it.
//! Must not: hold global state.

/// One path's random stream: pixel (x, y), global sample index, and seed + block counter.
/// Each hash gives four numbers: draw `k` is lane `k % 4` of the hash of block `k / 4`.
#[derive(Clone, Copy, Debug)]
pub struct Rng {
    pixel_x: u32,
    pixel_y: u32,
    sample: u32,
    stream: u32,
    block: [u32; 4],
    /// Lanes of `block` already used (4: none left).
    used: u32,
}

/// Golden-ratio constant that spreads seeds far apart on the counter lane.
const SEED_SPREAD: u32 = 0x9e37_79b9;

#[inline]
fn mix(v: &mut [u32; 4]) {
    v[0] = v[0].wrapping_add(v[1].wrapping_mul(v[3]));
    v[1] = v[1].wrapping_add(v[2].wrapping_mul(v[0]));
    v[2] = v[2].wrapping_add(v[0].wrapping_mul(v[1]));
    v[3] = v[3].wrapping_add(v[1].wrapping_mul(v[2]));
}

/// `pcg4d`: a 4×u32 → 4×u32 hash with good avalanche in every output lane.
#[inline]
pub fn pcg4d(mut v: [u32; 4]) -> [u32; 4] {
    for x in &mut v {
        *x = x.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
    }
    mix(&mut v);
    for x in &mut v {
        *x ^= *x >> 16;
    }
    mix(&mut v);
    v
}

impl Rng {
    /// The stream of sample `sample` (global index, across frames) of pixel (x, y).
    #[inline]
    pub fn new(pixel_x: u32, pixel_y: u32, sample: u32, seed: u32) -> Self {
        Self {
            pixel_x,
            pixel_y,
            sample,
            stream: seed.wrapping_mul(SEED_SPREAD),
            block: [0; 4],
            used: 4,
        }
    }

    /// Next uniform number in [0, 1) with 24 bits of resolution.
    #[inline]
    pub fn next_f32(&mut self) -> f32 {
        if self.used == 4 {
            self.block = pcg4d([self.pixel_x, self.pixel_y, self.sample, self.stream]);
            self.stream = self.stream.wrapping_add(1);
            self.used = 0;
        }
        let x = self.block[self.used as usize];
        self.used += 1;
        (x >> 8) as f32 * (1.0 / 16_777_216.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uniform_and_reproducible() {
        let mut a = Rng::new(3, 7, 11, 1);
        let mut b = Rng::new(3, 7, 11, 1);
        let n = 100_000;
        let mut sum = 0.0f64;
        let mut buckets = [0u32; 16];
        for _ in 0..n {
            let x = a.next_f32();
            assert_eq!(x, b.next_f32());
            assert!((0.0..1.0).contains(&x));
            sum += x as f64;
            buckets[(x * 16.0) as usize] += 1;
        }
        // Mean of n uniforms: standard error 1/sqrt(12 n) ≈ 0.0009; allow 5 sigma.
        assert!((sum / n as f64 - 0.5).abs() < 5.0 * (1.0 / (12.0 * n as f64)).sqrt());
        // Each bucket holds n/16 ± 5 sqrt(n/16 · 15/16).
        let expected = n as f64 / 16.0;
        let sigma = (expected * 15.0 / 16.0).sqrt();
        for count in buckets {
            assert!((count as f64 - expected).abs() < 5.0 * sigma, "{buckets:?}");
        }
        // Neighbouring pixels, samples and seeds give different streams.
        let first = |x, y, s, seed| Rng::new(x, y, s, seed).next_f32();
        let base = first(3, 7, 11, 1);
        for other in [
            first(4, 7, 11, 1),
            first(3, 8, 11, 1),
            first(3, 7, 12, 1),
            first(3, 7, 11, 2),
        ] {
            assert_ne!(base, other);
        }
    }
}
