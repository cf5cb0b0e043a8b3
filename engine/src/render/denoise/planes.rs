//! The CPU denoiser's working layout: planes (one `f32` per pixel, rows top to bottom) that the
//! row kernels of `variance` and `atrous` sweep a whole image row at a time, so that the
//! compiler vectorises their per-tap loops (SSE2, or AVX2 / AVX-512 where the CPU has them,
//! see [`Simd`]), and the exponential those kernels share ([`exp_neg`]).
//!
//! Owns: [`GuidePlanes`] (the sanitized guides, the depth gradient and the demodulation
//! factors, built once per frame), [`ColourPlanes`] (a pass's rows: illumination rgb, variance,
//! luminance), [`RowSums`] (one rayon task's accumulators), [`exp_neg`], the choice of vector
//! width ([`Simd`], [`dispatch`]) and [`FlushDenormals`]. The values are those the per-pixel
//! reference functions (`weights`, `variance_pixel`, `atrous_pixel`) compute, bit for bit,
//! except the exponential (a few ULP from `f32::exp`), the luminance term (a product with the
//! reciprocal of its scale rather than a quotient, 1 ULP) and subnormal values (flushed to 0).
//! Render thread, rows on rayon's pool.
//! Must not: filter (the passes do) or keep anything between frames beyond reused storage.

use glam::{Vec3, Vec4};
use rayon::prelude::*;

use super::guides::Guides;
use super::weights::{
    DEPTH_EPS_REL, NORMAL_SQUARINGS, axis_gradient, demodulator, luminance, normal_depth,
};

/// e^x for x ≤ 0 (the edge-stopping weights' exponent), by Cephes' `expf` polynomial on a
/// range reduced by powers of two (n = x·log₂e rounded to nearest): relative error within about
/// 2·10⁻⁷ (a few ULP) of the exact value for −87 ≤ x ≤ 0, 0 below −87 (where e^x < 2⁻¹²⁵, a
/// weight that cannot count against the kernel's centre). Plain arithmetic, branch-free, so
/// loops over it vectorise. Not meant for x > 0.
#[inline(always)]
pub fn exp_neg(x: f32) -> f32 {
    const LIMIT: f32 = -87.0;
    // 1.5·2²³: adding it rounds to an integer n held in the low mantissa bits (|n| < 2²²).
    const ROUND: f32 = 12_582_912.0;
    let xc = x.max(LIMIT);
    let t = xc * std::f32::consts::LOG2_E + ROUND;
    let nf = t - ROUND;
    // r = x − n·ln 2 in two parts (Cody–Waite), |r| ≤ ln 2 / 2.
    let r = xc - nf * 0.693_359_4 - nf * -2.121_944_4e-4;
    let p = ((((1.987_569_2e-4 * r + 1.398_2e-3) * r + 8.333_452e-3) * r + 4.166_579_6e-2) * r
        + 1.666_666_5e-1)
        * r
        + 0.5;
    let e = p * (r * r) + r + 1.0;
    // 2ⁿ, −126 ≤ n ≤ 0: a normal float built from its exponent bits (integer lanes only; a
    // float-to-integer cast would not vectorise).
    let n = t.to_bits().wrapping_sub(ROUND.to_bits());
    let two_n = f32::from_bits(n.wrapping_add(127) << 23);
    if x < LIMIT { 0.0 } else { e * two_n }
}

/// [`edge_weight`](super::weights::edge_weight) for a neighbour at depth `qz` > 0 (the
/// caller masks the others), lane form: `dot` is n_p·n_q, `slope` |∇z·offset| (metres), `dl`
/// the luminance term (0 without one). Same operations in the same order, [`exp_neg`] for
/// the exponential.
#[inline(always)]
pub fn lane_weight(dot: f32, pz: f32, qz: f32, slope: f32, sigma_z: f32, dl: f32) -> f32 {
    let mut wn = dot.max(0.0);
    for _ in 0..NORMAL_SQUARINGS {
        wn *= wn;
    }
    let dz = (pz - qz).abs() / (sigma_z * slope + DEPTH_EPS_REL * pz);
    wn * exp_neg(-(dz + dl))
}

/// The widest vector instructions this CPU runs, detected once per call (cached by `std`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Simd {
    /// AVX-512 (F, VL): 32 vector registers, so the kernels' constants stay in registers.
    Avx512,
    Avx2,
    /// As compiled (SSE2 on x86-64).
    Baseline,
}

impl Simd {
    pub fn detect() -> Self {
        #[cfg(target_arch = "x86_64")]
        {
            if std::arch::is_x86_feature_detected!("avx512f")
                && std::arch::is_x86_feature_detected!("avx512vl")
            {
                return Simd::Avx512;
            }
            if std::arch::is_x86_feature_detected!("avx2") {
                return Simd::Avx2;
            }
        }
        Simd::Baseline
    }
}

/// While it lives, this thread's SSE/AVX arithmetic flushes subnormal results and inputs to
/// zero (MXCSR FTZ and DAZ), as GPUs may: a kernel's tiny weights (below 2⁻¹²⁶) would otherwise
/// take the CPU's slow subnormal path. Dropping it restores the thread's previous mode, so the
/// tracer sharing rayon's threads is unaffected.
pub struct FlushDenormals {
    #[cfg(target_arch = "x86_64")]
    saved: u32,
}

impl FlushDenormals {
    /// FTZ (bit 15) and DAZ (bit 6) of MXCSR.
    #[cfg(target_arch = "x86_64")]
    const BITS: u32 = (1 << 15) | (1 << 6);

    #[inline(always)]
    #[allow(clippy::new_without_default)]
    pub fn new() -> Self {
        #[cfg(target_arch = "x86_64")]
        {
            let mut saved = 0u32;
            // SAFETY: stores MXCSR into a local and loads it back with FTZ and DAZ set; both
            // bits are defined on every x86-64 CPU with SSE2, and no memory but `saved` and
            // `mode` is touched.
            unsafe {
                std::arch::asm!("stmxcsr [{}]", in(reg) &mut saved, options(nostack));
                let mode = saved | Self::BITS;
                std::arch::asm!("ldmxcsr [{}]", in(reg) &mode, options(nostack));
            }
            Self { saved }
        }
        #[cfg(not(target_arch = "x86_64"))]
        Self {}
    }
}

impl Drop for FlushDenormals {
    #[inline(always)]
    fn drop(&mut self) {
        #[cfg(target_arch = "x86_64")]
        // SAFETY: restores the MXCSR value read in `new`.
        unsafe {
            std::arch::asm!("ldmxcsr [{}]", in(reg) &self.saved, options(nostack));
        }
    }
}

/// Defines `$name`, which runs the `#[inline(always)]` kernel `$kernel` compiled for the
/// widest [`Simd`] level the CPU has (its loops vectorise for that width).
macro_rules! dispatch {
    ($(#[$doc:meta])* $vis:vis fn $name:ident => $kernel:ident ($($arg:ident : $ty:ty),* $(,)?)) => {
        $(#[$doc])*
        $vis fn $name(simd: $crate::render::denoise::planes::Simd, $($arg: $ty),*) {
            #[cfg(target_arch = "x86_64")]
            #[target_feature(enable = "avx512f,avx512vl,avx2")]
            fn avx512($($arg: $ty),*) {
                let _ftz = $crate::render::denoise::planes::FlushDenormals::new();
                $kernel($($arg),*)
            }
            #[cfg(target_arch = "x86_64")]
            #[target_feature(enable = "avx2")]
            fn avx2($($arg: $ty),*) {
                let _ftz = $crate::render::denoise::planes::FlushDenormals::new();
                $kernel($($arg),*)
            }
            match simd {
                // SAFETY: `Simd::detect` found these features on this CPU.
                #[cfg(target_arch = "x86_64")]
                $crate::render::denoise::planes::Simd::Avx512 => unsafe { avx512($($arg),*) },
                // SAFETY: as above.
                #[cfg(target_arch = "x86_64")]
                $crate::render::denoise::planes::Simd::Avx2 => unsafe { avx2($($arg),*) },
                _ => $kernel($($arg),*),
            }
        }
    };
}
pub(crate) use dispatch;

/// The guides as planes: sanitized normal and depth (`weights::normal_depth`: zero where there
/// is no surface, an emissive pixel included) and the depth gradient (metres per pixel, x
/// right, y down; `weights::depth_gradient`) and the demodulation factors.
#[derive(Clone, Debug, Default)]
pub struct GuidePlanes {
    pub width: usize,
    pub height: usize,
    pub nx: Vec<f32>,
    pub ny: Vec<f32>,
    pub nz: Vec<f32>,
    /// Metres along the camera ray; 0 = no surface.
    pub z: Vec<f32>,
    pub gx: Vec<f32>,
    pub gy: Vec<f32>,
    /// The demodulation factors (`weights::demodulator` of the albedo), per channel.
    pub dr: Vec<f32>,
    pub dg: Vec<f32>,
    pub db: Vec<f32>,
}

impl GuidePlanes {
    /// Refills the planes from `guides` (which must be consistent), reusing their storage.
    pub fn fill(&mut self, guides: &Guides) {
        let (w, h) = (guides.width as usize, guides.height as usize);
        let n = w * h;
        self.width = w;
        self.height = h;
        for plane in [
            &mut self.nx,
            &mut self.ny,
            &mut self.nz,
            &mut self.z,
            &mut self.gx,
            &mut self.gy,
            &mut self.dr,
            &mut self.dg,
            &mut self.db,
        ] {
            // Every value is written below: only the size is set.
            plane.resize(n, 0.0);
        }
        let w1 = w.max(1);
        (self.nx.par_chunks_mut(w1))
            .zip(self.ny.par_chunks_mut(w1))
            .zip(self.nz.par_chunks_mut(w1))
            .zip(self.z.par_chunks_mut(w1))
            .zip(self.dr.par_chunks_mut(w1))
            .zip(self.dg.par_chunks_mut(w1))
            .zip(self.db.par_chunks_mut(w1))
            .enumerate()
            .for_each(|(y, ((((((nx, ny), nz), zs), dr), dg), db))| {
                for x in 0..nx.len() {
                    let i = y * w + x;
                    let z = if guides.emissive[i] {
                        -guides.depth[i]
                    } else {
                        guides.depth[i]
                    };
                    let g = normal_depth(guides.normal[i].extend(z));
                    nx[x] = g.x;
                    ny[x] = g.y;
                    nz[x] = g.z;
                    zs[x] = g.w;
                    let d = demodulator(guides.albedo[i]);
                    dr[x] = d.x;
                    dg[x] = d.y;
                    db[x] = d.z;
                }
            });
        let z = &self.z;
        self.gx
            .par_chunks_mut(w.max(1))
            .zip(self.gy.par_chunks_mut(w.max(1)))
            .enumerate()
            .for_each(|(y, (gx, gy))| {
                let at = |x: usize, y: usize| z[y * w + x];
                for x in 0..w {
                    let zc = at(x, y);
                    let left = if x > 0 { at(x - 1, y) } else { 0.0 };
                    let right = if x + 1 < w { at(x + 1, y) } else { 0.0 };
                    let up = if y > 0 { at(x, y - 1) } else { 0.0 };
                    let down = if y + 1 < h { at(x, y + 1) } else { 0.0 };
                    gx[x] = axis_gradient(zc, left, right);
                    gy[x] = axis_gradient(zc, up, down);
                }
            });
    }
}

/// A pass's rows as planes: illumination rgb, variance (−1: no valid sample) and the rgb's
/// luminance (`weights::luminance`, for the next pass's taps).
#[derive(Clone, Debug, Default)]
pub struct ColourPlanes {
    pub r: Vec<f32>,
    pub g: Vec<f32>,
    pub b: Vec<f32>,
    pub v: Vec<f32>,
    pub l: Vec<f32>,
}

impl ColourPlanes {
    /// Makes room for `n` pixels (contents unspecified until a pass writes them).
    pub fn resize(&mut self, n: usize) {
        for plane in [
            &mut self.r,
            &mut self.g,
            &mut self.b,
            &mut self.v,
            &mut self.l,
        ] {
            plane.resize(n, 0.0);
        }
    }

    /// The rgb of every pixel.
    pub fn rgb(&self) -> Vec<Vec3> {
        (0..self.r.len())
            .map(|i| Vec3::new(self.r[i], self.g[i], self.b[i]))
            .collect()
    }

    /// Row `y` (`width` pixels) of each plane, writable, for one rayon task per row.
    pub fn rows_mut(
        &mut self,
        width: usize,
    ) -> impl IndexedParallelIterator<Item = (usize, OutRow<'_>)> {
        let w = width.max(1);
        self.r
            .par_chunks_mut(w)
            .zip(self.g.par_chunks_mut(w))
            .zip(self.b.par_chunks_mut(w))
            .zip(self.v.par_chunks_mut(w))
            .zip(self.l.par_chunks_mut(w))
            .map(|((((r, g), b), v), l)| OutRow { r, g, b, v, l })
            .enumerate()
    }
}

/// One output row of a [`ColourPlanes`].
pub struct OutRow<'a> {
    pub r: &'a mut [f32],
    pub g: &'a mut [f32],
    pub b: &'a mut [f32],
    pub v: &'a mut [f32],
    pub l: &'a mut [f32],
}

impl OutRow<'_> {
    /// Writes pixel `x` of the row (and its luminance).
    #[inline]
    pub fn set(&mut self, x: usize, value: Vec4) {
        self.r[x] = value.x;
        self.g[x] = value.y;
        self.b[x] = value.z;
        self.v[x] = value.w;
        self.l[x] = luminance(value.truncate());
    }
}

/// One rayon task's per-row accumulators (weighted rgb, variance and weight sums) and per-row
/// centre values (luminance, the reciprocal of the luminance weight's scale).
#[derive(Clone, Debug, Default)]
pub struct RowSums {
    pub r: Vec<f32>,
    pub g: Vec<f32>,
    pub b: Vec<f32>,
    pub v: Vec<f32>,
    pub w: Vec<f32>,
    pub lum: Vec<f32>,
    pub scale: Vec<f32>,
}

impl RowSums {
    pub fn new(width: usize) -> Self {
        let z = vec![0.0; width];
        Self {
            r: z.clone(),
            g: z.clone(),
            b: z.clone(),
            v: z.clone(),
            w: z.clone(),
            lum: z.clone(),
            scale: z,
        }
    }

    /// Zeroes the sums.
    pub fn clear(&mut self) {
        for s in [
            &mut self.r,
            &mut self.g,
            &mut self.b,
            &mut self.v,
            &mut self.w,
        ] {
            s.fill(0.0);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exp_neg_is_within_a_few_ulp() {
        let mut worst = 0.0f64;
        let mut x = 0.0f32;
        while x > -87.0 {
            let exact = (x as f64).exp();
            let rel = ((exp_neg(x) as f64 - exact) / exact).abs();
            worst = worst.max(rel);
            x -= 0.000_37;
        }
        assert!(worst < 3e-7, "worst relative error {worst:e}");
        assert_eq!(exp_neg(0.0), 1.0);
        assert_eq!(exp_neg(-100.0), 0.0);
        assert_eq!(exp_neg(f32::NEG_INFINITY), 0.0);
    }
}
