//! `bench picture --worst N --dump-dir DIR`: where a displayed frame's error comes from. Ranks
//! a compared frame's pixels by their share of the relative MSE (`picture_metrics::rel_mse`'s
//! per pixel sum over channels) and writes the displayed frame and its reference as PNGs
//! (linear radiance through the game's tonemap, each pixel blown up to a square of
//! [`ZOOM`]×[`ZOOM`]), so that a few outlying pixels can be found and looked at.
//!
//! Owns: arithmetic and file writing only. Main thread. Must not: render or change a figure.

use std::path::{Path, PathBuf};

use candela::render::film::{TonemapSettings, write_png};
use glam::Vec3;

/// Each pixel of a dumped picture becomes a square this many pixels wide.
pub const ZOOM: usize = 8;

/// The offset in the relative MSE's denominator (`picture_metrics`'s).
const REL_EPSILON: f64 = 0.01;

/// One pixel's part of a frame's relative MSE.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Outlier {
    pub x: u32,
    pub y: u32,
    pub shown: Vec3,
    pub reference: Vec3,
    /// Its share of the frame's relative MSE (0–1).
    pub share: f64,
}

/// The `n` pixels of `shown` (rows of `width`) that add most to its relative MSE against
/// `reference`, worst first.
pub fn worst_pixels(shown: &[Vec3], reference: &[Vec3], width: u32, n: usize) -> Vec<Outlier> {
    let error = |a: Vec3, b: Vec3| -> f64 {
        (0..3)
            .map(|c| {
                let (a, b) = (f64::from(a[c]), f64::from(b[c]));
                (a - b).powi(2) / (b * b + REL_EPSILON)
            })
            .sum()
    };
    let errors: Vec<f64> = shown
        .iter()
        .zip(reference)
        .map(|(&a, &b)| error(a, b))
        .collect();
    let total: f64 = errors.iter().sum::<f64>().max(f64::MIN_POSITIVE);
    let mut order: Vec<usize> = (0..errors.len()).collect();
    order.sort_by(|&a, &b| errors[b].total_cmp(&errors[a]));
    let width = width.max(1) as usize;
    order
        .into_iter()
        .take(n)
        .map(|i| Outlier {
            x: (i % width) as u32,
            y: (i / width) as u32,
            shown: shown[i],
            reference: reference[i],
            share: errors[i] / total,
        })
        .collect()
}

/// The outliers as lines of text, under a heading naming the frame.
pub fn describe(heading: &str, outliers: &[Outlier]) -> String {
    let mut text =
        format!("{heading}: worst pixels (x, y: shown / reference, share of rel. MSE)\n");
    for o in outliers {
        text += &format!(
            "  {:4}, {:4}: ({:.3}, {:.3}, {:.3}) / ({:.3}, {:.3}, {:.3}), {:.1} %\n",
            o.x,
            o.y,
            o.shown.x,
            o.shown.y,
            o.shown.z,
            o.reference.x,
            o.reference.y,
            o.reference.z,
            o.share * 100.0
        );
    }
    text
}

/// Writes `image` (rows of `width`, linear radiance) as `dir/name.png`, zoomed; returns the path.
pub fn dump(dir: &Path, name: &str, image: &[Vec3], width: u32) -> anyhow::Result<PathBuf> {
    let width = width.max(1) as usize;
    let height = image.len() / width;
    let zoomed: Vec<Vec3> = (0..height * ZOOM)
        .flat_map(|y| (0..width * ZOOM).map(move |x| (x / ZOOM, y / ZOOM)))
        .map(|(x, y)| image[y * width + x])
        .collect();
    let safe: String = name
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect();
    let path = dir.join(format!("{safe}.png"));
    write_png(
        &path,
        (width * ZOOM) as u32,
        (height * ZOOM) as u32,
        &zoomed,
        &TonemapSettings::default(),
    )?;
    Ok(path)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_outlying_pixel_comes_first_with_its_share() {
        let reference = vec![Vec3::splat(0.5); 6];
        let mut shown = reference.clone();
        shown[4] = Vec3::splat(6.0);
        shown[1] = Vec3::splat(0.6);
        let worst = worst_pixels(&shown, &reference, 3, 2);
        assert_eq!((worst[0].x, worst[0].y), (1, 1));
        assert_eq!((worst[1].x, worst[1].y), (1, 0));
        assert!(worst[0].share > 0.99 && worst[0].share < 1.0, "{worst:?}");
        assert!(describe("frame", &worst).contains("1,    1"));
    }
}
