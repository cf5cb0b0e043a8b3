//! Mip chains of the packed textures (sampled by `render/cpu/texture.rs` and its twin
//! `shaders/shared/texture.wgsl`, which pick levels by ray cones).
//!
//! Owns: the level sizes (floor halving down to 1×1: level `l` is `max(1, w >> l)` ×
//! `max(1, h >> l)`; an odd size folds its last texel into the last texel of the level below)
//! and the 2×2 box filter in linear values that builds each level from the one above. Levels
//! lie one after the other in the texel buffer, level 0 first, rows top to bottom. Pure, any
//! thread. Must not: decode images or choose levels.

use half::f16;

/// Number of levels of a `width × height` texture: down to 1×1 (1 for an empty one).
pub fn level_count(width: u32, height: u32) -> u32 {
    32 - width.max(height).max(1).leading_zeros()
}

/// Size of level `level` of a `width × height` texture, in texels.
pub fn level_size(width: u32, height: u32, level: u32) -> (u32, u32) {
    let shift = level.min(31);
    ((width >> shift).max(1), (height >> shift).max(1))
}

/// Texels of the whole chain of a `width × height` texture (level 0 included).
pub fn chain_len(width: u32, height: u32) -> usize {
    (0..level_count(width, height))
        .map(|l| {
            let (w, h) = level_size(width, height, l);
            w as usize * h as usize
        })
        .sum()
}

/// Source texels `[first, end)` that texel `i` of a halved axis of `size` covers: two, and
/// three for the last texel of an odd size above 1.
fn span(i: u32, size: u32) -> (u32, u32) {
    let half = (size / 2).max(1);
    let first = (2 * i).min(size - 1);
    let end = if i + 1 == half { size } else { 2 * i + 2 };
    (first, end.max(first + 1))
}

/// One level from the level above (`w × h`, linear RGBA): the box mean of the texels each
/// new texel covers.
fn halve(above: &[[f32; 4]], w: u32, h: u32) -> (Vec<[f32; 4]>, u32, u32) {
    let (nw, nh) = ((w / 2).max(1), (h / 2).max(1));
    let mut out = Vec::with_capacity(nw as usize * nh as usize);
    for y in 0..nh {
        let (y0, y1) = span(y, h);
        for x in 0..nw {
            let (x0, x1) = span(x, w);
            let mut sum = [0.0f32; 4];
            for sy in y0..y1 {
                for sx in x0..x1 {
                    let p = above[(sy * w + sx) as usize];
                    for c in 0..4 {
                        sum[c] += p[c];
                    }
                }
            }
            let n = ((y1 - y0) * (x1 - x0)) as f32;
            out.push(sum.map(|s| s / n));
        }
    }
    (out, nw, nh)
}

/// Levels 1 and below of a `width × height` texture with level-0 `texels` (row-major), in
/// buffer order. Empty for a 1×1 texture or when `texels` does not hold `width × height`.
pub fn lower_levels(width: u32, height: u32, texels: &[[f16; 4]]) -> Vec<[f16; 4]> {
    if width == 0 || height == 0 || texels.len() != width as usize * height as usize {
        return Vec::new();
    }
    let mut out = Vec::with_capacity(chain_len(width, height) - texels.len());
    let mut level: Vec<[f32; 4]> = texels.iter().map(|t| t.map(f16::to_f32)).collect();
    let (mut w, mut h) = (width, height);
    while w > 1 || h > 1 {
        let (next, nw, nh) = halve(&level, w, h);
        out.extend(next.iter().map(|t| t.map(f16::from_f32)));
        (level, w, h) = (next, nw, nh);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grey(v: f32) -> [f16; 4] {
        [f16::from_f32(v); 4]
    }

    #[test]
    fn checker_levels_are_means() {
        // 4×4 checker of 0 and 1: level 1 is 2×2 of 0.5, level 2 is 1×1 of 0.5.
        let texels: Vec<_> = (0..16)
            .map(|i| grey(((i % 4 + i / 4) % 2) as f32))
            .collect();
        assert_eq!(level_count(4, 4), 3);
        assert_eq!(chain_len(4, 4), 16 + 4 + 1);
        let lower = lower_levels(4, 4, &texels);
        assert_eq!(lower.len(), 5);
        for t in &lower {
            assert_eq!(t[0].to_f32(), 0.5);
        }
    }

    #[test]
    fn odd_sizes_fold_the_edge_in() {
        // 3×1 of 0, 3, 6: level 1 is 1×1, the mean of all three (the edge texel folded in).
        let lower = lower_levels(3, 1, &[grey(0.0), grey(3.0), grey(6.0)]);
        assert_eq!(lower.len(), 1);
        assert_eq!(lower[0][0].to_f32(), 3.0);
        // 5×3: 2×1 then 1×1.
        assert_eq!(level_count(5, 3), 3);
        assert_eq!(level_size(5, 3, 1), (2, 1));
        assert_eq!(level_size(5, 3, 2), (1, 1));
        let texels: Vec<_> = (0..15).map(|i| grey(i as f32)).collect();
        let lower = lower_levels(5, 3, &texels);
        assert_eq!(lower.len(), 3);
        assert_eq!(lower[2][0].to_f32(), (5.5 + 8.0) / 2.0);
        // Level 1 texel 0 covers columns 0–1, texel 1 columns 2–4, all rows.
        assert_eq!(lower[0][0].to_f32(), (0 + 1 + 5 + 6 + 10 + 11) as f32 / 6.0);
        assert_eq!(lower[1][0].to_f32(), 8.0); // (2+3+4+7+8+9+12+13+14)/9
        assert_eq!(level_count(1, 1), 1);
        assert!(lower_levels(1, 1, &[grey(1.0)]).is_empty());
        assert!(lower_levels(2, 2, &[grey(1.0)]).is_empty());
    }
}
