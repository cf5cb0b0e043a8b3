//! OBJ bump maps: turns a height map into a tangent-space normal map, because the tracers
//! read normal maps only.
//!
//! Input: linear RGBA texels whose red channel is a height in [0, 1] (one height unit = the
//! full 0–255 range). Output: a normal map in the glTF convention (+X towards +u, +Y towards
//! the top of the image, +Z out of the surface; stored as `n * 0.5 + 0.5`, alpha 1).
//! The slope is the Sobel height difference per texel (edges wrap, as textures repeat), so a
//! full-range step over one texel tilts the normal by about 27°; the MTL `-bm` multiplier is
//! applied later as the material's `normal_scale`, which scales exactly this slope.
//! Must not: decide whether an image is a height map (the texture module does).

use half::f16;

/// Converts a height map (red channel) of `width` × `height` texels to a normal map.
pub(crate) fn height_to_normal(width: u32, height: u32, heights: &[[f16; 4]]) -> Vec<[f16; 4]> {
    let (w, h) = (width as usize, height as usize);
    if w == 0 || h == 0 || heights.len() != w * h {
        return heights.to_vec();
    }
    let at = |x: usize, y: usize| heights[y * w + x][0].to_f32();
    let mut normals = Vec::with_capacity(w * h);
    for y in 0..h {
        let up = (y + h - 1) % h;
        let down = (y + 1) % h;
        for x in 0..w {
            let left = (x + w - 1) % w;
            let right = (x + 1) % w;
            // Sobel: derivative along +x (columns) and along +row (down the image).
            let d_right = (at(right, up) + 2.0 * at(right, y) + at(right, down)
                - at(left, up)
                - 2.0 * at(left, y)
                - at(left, down))
                / 8.0;
            let d_down = (at(left, down) + 2.0 * at(x, down) + at(right, down)
                - at(left, up)
                - 2.0 * at(x, up)
                - at(right, up))
                / 8.0;
            // Height field z = h(x, y_up) with y_up = -row: normal ∝ (-∂h/∂x, -∂h/∂y_up, 1).
            let (nx, ny, nz) = (-d_right, d_down, 1.0_f32);
            let length = (nx * nx + ny * ny + nz * nz).sqrt();
            let encode = |c: f32| f16::from_f32(c / length * 0.5 + 0.5);
            normals.push([encode(nx), encode(ny), encode(nz), f16::ONE]);
        }
    }
    normals
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flat_height_gives_up_normal_and_a_ramp_tilts_towards_lower_heights() {
        let flat = vec![[f16::from_f32(0.5); 4]; 16];
        for n in height_to_normal(4, 4, &flat) {
            assert_eq!(
                [n[0].to_f32(), n[1].to_f32(), n[2].to_f32()],
                [0.5, 0.5, 1.0]
            );
        }
        // Height rises to the right (+u) in the middle columns: the normal leans to -x.
        let ramp: Vec<[f16; 4]> = (0..16)
            .map(|i| [f16::from_f32((i % 4) as f32 / 4.0); 4])
            .collect();
        let normals = height_to_normal(4, 4, &ramp);
        let n = normals[4 + 1];
        assert!(n[0].to_f32() < 0.5, "x = {}", n[0]);
        assert!((n[1].to_f32() - 0.5).abs() < 1e-3, "y = {}", n[1]);
    }
}
