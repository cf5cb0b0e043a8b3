//! Texture lookups of the CPU tracer (twin: `shaders/shared/texture.wgsl`).
//!
//! Owns: wrapping, nearest and bilinear filtering over the packed f16 texel buffer (F16C when
//! the CPU has it, detected at run time), and the cache hints for a lookup to come ([`prefetch`]).
//! Texture coordinates follow glTF: (0, 0) is the top-left of the image, v grows downward.
//! Must not: decode image files.

use glam::{Vec2, Vec4};
use half::f16;

use crate::layout::{GpuTexture, TEXTURE_FLAG_NEAREST, WRAP_CLAMP, WRAP_MIRROR};

#[inline]
fn unpack(t: [u32; 2]) -> Vec4 {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("f16c") {
        // SAFETY: the CPU has F16C (checked just above; `std` caches the detection).
        return unsafe { unpack_f16c(t) };
    }
    let h = |bits: u32| f16::from_bits(bits as u16).to_f32();
    Vec4::new(
        h(t[0] & 0xffff),
        h(t[0] >> 16),
        h(t[1] & 0xffff),
        h(t[1] >> 16),
    )
}

/// [`unpack`] with one F16C conversion of all four halves (exact, as the scalar one: every f16
/// is an f32).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "f16c")]
fn unpack_f16c(t: [u32; 2]) -> Vec4 {
    use std::arch::x86_64::{_mm_cvtph_ps, _mm_cvtsi64_si128, _mm_storeu_ps};
    let bits = (u64::from(t[1]) << 32 | u64::from(t[0])) as i64;
    let mut out = [0.0f32; 4];
    // SAFETY: `out` holds four f32.
    unsafe { _mm_storeu_ps(out.as_mut_ptr(), _mm_cvtph_ps(_mm_cvtsi64_si128(bits))) };
    Vec4::from_array(out)
}

fn wrap(i: i32, size: i32, mode: u32) -> i32 {
    // Inside the image every mode is the identity (the common case: no integer division).
    if (0..size).contains(&i) {
        return i;
    }
    match mode {
        WRAP_CLAMP => i.clamp(0, size - 1),
        WRAP_MIRROR => {
            let m = i.rem_euclid(2 * size);
            if m >= size { 2 * size - 1 - m } else { m }
        }
        _ => i.rem_euclid(size),
    }
}

/// Starts loading the texels [`sample`] will read for texture `index` at `uv` (both rows of the
/// bilinear footprint at its left column, wrapped as [`sample`] wraps them), so that the
/// lookups of one surface's textures miss the cache together rather than one after another.
/// Changes nothing; `INVALID` or a broken index does nothing.
pub fn prefetch(textures: &[GpuTexture], texels: &[[u32; 2]], index: u32, uv: Vec2) {
    let Some(t) = textures.get(index as usize) else {
        return;
    };
    if t.width == 0 || t.height == 0 || !uv.is_finite() {
        return;
    }
    let (w, h) = (t.width as i32, t.height as i32);
    let x = ((uv.x * w as f32).clamp(-1.0e6, 1.0e6) - 0.5).floor() as i32;
    let y = ((uv.y * h as f32).clamp(-1.0e6, 1.0e6) - 0.5).floor() as i32;
    let (wrap_u, wrap_v) = (t.flags & 3, (t.flags >> 2) & 3);
    let (x, y0, y1) = (wrap(x, w, wrap_u), wrap(y, h, wrap_v), wrap(y + 1, h, wrap_v));
    let base = t.texel_offset as usize;
    for row in [y0, y1] {
        if let Some(p) = texels.get(base + (row * w + x) as usize) {
            super::prefetch::line(p);
        }
    }
}

/// Samples texture `index` at `uv`; returns opaque white for `INVALID` or a broken index.
pub fn sample(textures: &[GpuTexture], texels: &[[u32; 2]], index: u32, uv: Vec2) -> Vec4 {
    let Some(t) = textures.get(index as usize) else {
        return Vec4::ONE;
    };
    if t.width == 0 || t.height == 0 {
        return Vec4::ONE;
    }
    let uv = if uv.is_finite() { uv } else { Vec2::ZERO };
    let (w, h) = (t.width as i32, t.height as i32);
    let (wrap_u, wrap_v) = (t.flags & 3, (t.flags >> 2) & 3);
    let base = t.texel_offset as usize;
    // Fetches the texel at wrapped column `x` and wrapped row `y`.
    let fetch = |x: i32, y: i32| {
        let i = base + (y * w + x) as usize;
        texels.get(i).map(|&p| unpack(p)).unwrap_or(Vec4::ONE)
    };
    // Coordinates far outside [0, 1] would overflow i32; wrap them into a safe range first.
    let x = (uv.x * w as f32).clamp(-1.0e6, 1.0e6);
    let y = (uv.y * h as f32).clamp(-1.0e6, 1.0e6);
    if t.flags & TEXTURE_FLAG_NEAREST != 0 {
        return fetch(
            wrap(x.floor() as i32, w, wrap_u),
            wrap(y.floor() as i32, h, wrap_v),
        );
    }
    let (x, y) = (x - 0.5, y - 0.5);
    let (x0, y0) = (x.floor(), y.floor());
    let (fx, fy) = (x - x0, y - y0);
    let (x0, y0) = (x0 as i32, y0 as i32);
    let (xa, xb) = (wrap(x0, w, wrap_u), wrap(x0 + 1, w, wrap_u));
    let (ya, yb) = (wrap(y0, h, wrap_v), wrap(y0 + 1, h, wrap_v));
    let top = fetch(xa, ya) * (1.0 - fx) + fetch(xb, ya) * fx;
    let bottom = fetch(xa, yb) * (1.0 - fx) + fetch(xb, yb) * fx;
    top * (1.0 - fy) + bottom * fy
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::layout::{INVALID, WRAP_REPEAT};
    use crate::scene::materials::pack_texel;

    #[test]
    fn bilinear_and_wrap() {
        let px = |v: f32| pack_texel([f16::from_f32(v); 4]);
        // 2×1 texture: 0 and 1.
        let texels = vec![px(0.0), px(1.0)];
        let mut t = GpuTexture {
            texel_offset: 0,
            width: 2,
            height: 1,
            flags: WRAP_REPEAT,
        };
        let s = |t: &GpuTexture, u: f32| {
            sample(std::slice::from_ref(t), &texels, 0, Vec2::new(u, 0.5)).x
        };
        assert_eq!(s(&t, 0.25), 0.0); // texel centre
        assert_eq!(s(&t, 0.5), 0.5); // half way
        assert_eq!(s(&t, 0.0), 0.5); // repeat: blends texel 1 (wrapped) and texel 0
        t.flags = WRAP_CLAMP;
        assert_eq!(s(&t, 0.0), 0.0);
        t.flags = WRAP_MIRROR;
        assert_eq!(s(&t, -0.25), 0.0);
        assert_eq!(s(&t, 1.25), 1.0);
        t.flags = TEXTURE_FLAG_NEAREST;
        assert_eq!(s(&t, 0.49), 0.0);
        assert_eq!(s(&t, 0.51), 1.0);
        assert_eq!(sample(&[], &texels, 0, Vec2::ZERO), Vec4::ONE);
    }

    /// The F16C unpack returns the scalar conversion's bits for every half in every lane
    /// (normals, subnormals, infinities and NaNs included).
    #[test]
    fn f16c_unpack_matches_scalar() {
        let scalar = |t: [u32; 2]| {
            let h = |bits: u32| f16::from_bits(bits as u16).to_f32().to_bits();
            [t[0] & 0xffff, t[0] >> 16, t[1] & 0xffff, t[1] >> 16].map(h)
        };
        for bits in 0..=u16::MAX as u32 {
            // Each lane sees `bits`, next to neighbours that differ.
            let t = [bits | (bits ^ 0x8001) << 16, (bits ^ 0x7c00) | bits << 16];
            let got = unpack(t).to_array().map(f32::to_bits);
            let want = scalar(t);
            for (g, w) in got.iter().zip(want) {
                // NaN payloads may be quietened differently; a NaN must stay a NaN.
                if f32::from_bits(w).is_nan() {
                    assert!(f32::from_bits(*g).is_nan(), "{t:x?}");
                } else {
                    assert_eq!(*g, w, "{t:x?}");
                }
            }
        }
    }

    /// Prefetching is harmless on any coordinate and texture, broken ones included.
    #[test]
    fn prefetch_any_input() {
        let texels = vec![[0u32; 2]; 4];
        let textures = [
            GpuTexture { texel_offset: 0, width: 2, height: 2, flags: WRAP_REPEAT },
            GpuTexture { texel_offset: 3, width: 2, height: 2, flags: WRAP_MIRROR << 2 },
            GpuTexture { texel_offset: 0, width: 0, height: 2, flags: 0 },
        ];
        for index in [0, 1, 2, 7, INVALID] {
            for uv in [-1e30, -3.7, -0.5, 0.0, 0.49, 1.0, 2.5, 1e30, f32::NAN, f32::INFINITY] {
                prefetch(&textures, &texels, index, Vec2::new(uv, -uv));
            }
        }
    }
}
