//! Tonemapping: linear radiance to displayable 8-bit sRGB.
//!
//! Owns: exposure (in stops), the tone curve and the sRGB transfer function.
//! Must not: accumulate samples.

use glam::Vec3;

pub use crate::commit::TonemapSettings;

fn srgb_encode(c: f32) -> f32 {
    if c <= 0.003_130_8 {
        12.92 * c
    } else {
        1.055 * c.powf(1.0 / 2.4) - 0.055
    }
}

/// Linear radiance → 8-bit sRGB with `settings` (NaN maps to black).
pub fn linear_to_srgb8(c: Vec3, settings: &TonemapSettings) -> [u8; 3] {
    let mut c = c * settings.exposure_ev.exp2();
    if settings.filmic {
        let (a, b, cc, d, e) = (2.51, 0.03, 2.43, 0.59, 0.14);
        c = (c * (a * c + b)) / (c * (cc * c + d) + e);
    }
    c.to_array().map(|x| {
        let x = if x.is_nan() { 0.0 } else { x.clamp(0.0, 1.0) };
        (srgb_encode(x) * 255.0 + 0.5) as u8
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn srgb_curve_points() {
        let s = TonemapSettings::default();
        assert_eq!(linear_to_srgb8(Vec3::ZERO, &s), [0, 0, 0]);
        assert_eq!(linear_to_srgb8(Vec3::ONE, &s), [255, 255, 255]);
        // 18% grey is sRGB 118.
        assert_eq!(linear_to_srgb8(Vec3::splat(0.18), &s)[0], 118);
        assert_eq!(linear_to_srgb8(Vec3::splat(f32::NAN), &s), [0, 0, 0]);
        let bright = TonemapSettings {
            exposure_ev: 1.0,
            filmic: false,
        };
        assert_eq!(linear_to_srgb8(Vec3::splat(0.5), &bright), [255, 255, 255]);
    }
}
