//! Texture lookups of the CPU tracer (twin: `shaders/shared/texture.wgsl`).
//!
//! Owns: wrapping, nearest and bilinear filtering over the packed f16 texel buffer, and the
//! mip level a ray cone's [`Lod`] picks (Akenine-Möller et al., "Texture Level of Detail
//! Strategies for Real-Time Ray Tracing", Ray Tracing Gems ch. 20): level ⌊λ⌋ or ⌊λ⌋ + 1,
//! chosen at random in proportion to λ's fraction, then bilinear — trilinear in expectation.
//! Texture coordinates follow glTF: (0, 0) is the top-left of the image, v grows downward.
//! Must not: decode image files or build mip chains (`scene/mips.rs`).

use glam::{Vec2, Vec4};
use half::f16;

use crate::layout::{
    GpuTexture, TEXTURE_FLAG_NEAREST, TEXTURE_LEVELS_MASK, TEXTURE_LEVELS_SHIFT, WRAP_CLAMP,
    WRAP_MIRROR,
};
use crate::scene::mips::level_size;

/// Where a lookup's footprint lies on the mip chain, before the texture's own size is known.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lod {
    /// log2 of the footprint in texture space, in units of the whole texture's side: λ of a
    /// `w × h` texture is `footprint + ½·log2(w·h)`. −∞ reads level 0.
    pub footprint: f32,
    /// Uniform in [0, 1): picks between the two nearest levels.
    pub random: f32,
}

impl Lod {
    /// Always level 0 (light sampling, the denoiser's guides, tests).
    pub const FINEST: Lod = Lod {
        footprint: f32::NEG_INFINITY,
        random: 0.0,
    };

    /// The level of texture `t` (`levels` of them): ⌊λ⌋ or ⌊λ⌋ + 1 with probability frac(λ).
    pub fn level(&self, t: &GpuTexture, levels: u32) -> u32 {
        let lambda = self.footprint + 0.5 * ((t.width as f32) * (t.height as f32)).log2();
        if lambda.is_nan() || lambda <= 0.0 || levels <= 1 {
            return 0;
        }
        let top = (levels - 1) as f32;
        if lambda >= top {
            return levels - 1;
        }
        let floor = lambda.floor();
        floor as u32 + u32::from(self.random < lambda - floor)
    }
}

/// Number of mip levels of `t` (at least 1).
pub fn levels(t: &GpuTexture) -> u32 {
    ((t.flags >> TEXTURE_LEVELS_SHIFT) & TEXTURE_LEVELS_MASK).max(1)
}

fn unpack(t: [u32; 2]) -> Vec4 {
    let h = |bits: u32| f16::from_bits(bits as u16).to_f32();
    Vec4::new(
        h(t[0] & 0xffff),
        h(t[0] >> 16),
        h(t[1] & 0xffff),
        h(t[1] >> 16),
    )
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

/// Samples texture `index` at `uv` on the level `lod` picks (nearest textures: level 0);
/// returns opaque white for `INVALID` or a broken index.
pub fn sample(
    textures: &[GpuTexture],
    texels: &[[u32; 2]],
    index: u32,
    uv: Vec2,
    lod: Lod,
) -> Vec4 {
    let Some(t) = textures.get(index as usize) else {
        return Vec4::ONE;
    };
    if t.width == 0 || t.height == 0 {
        return Vec4::ONE;
    }
    let uv = if uv.is_finite() { uv } else { Vec2::ZERO };
    let level = if t.flags & TEXTURE_FLAG_NEAREST != 0 {
        0
    } else {
        lod.level(t, levels(t))
    };
    // Levels lie one after the other from `texel_offset`.
    let mut base = t.texel_offset as usize;
    for l in 0..level {
        let (lw, lh) = level_size(t.width, t.height, l);
        base += lw as usize * lh as usize;
    }
    let (w, h) = level_size(t.width, t.height, level);
    let (w, h) = (w as i32, h as i32);
    let (wrap_u, wrap_v) = (t.flags & 3, (t.flags >> 2) & 3);
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
    use crate::layout::WRAP_REPEAT;
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
            sample(
                std::slice::from_ref(t),
                &texels,
                0,
                Vec2::new(u, 0.5),
                Lod::FINEST,
            )
            .x
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
        assert_eq!(sample(&[], &texels, 0, Vec2::ZERO, Lod::FINEST), Vec4::ONE);
    }
}
