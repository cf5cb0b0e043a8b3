//! The chart of `bench denoise`: RMSE against the converged reference at 1, 2 and 4 spp with
//! and without the denoiser (error bars: the spread over seeds), and the converged image's
//! RMSE with and without it (the bias the denoiser adds) as horizontal lines (plotters, PNG).
//!
//! Owns: drawing only. Must not: measure.

use std::path::Path;

use plotters::prelude::*;

use super::denoise::ErrorRow;
use super::plot::register_font;

/// (legend, colour, which figure of a row).
type Series = (&'static str, RGBColor, fn(&ErrorRow) -> (f64, f64));

pub fn chart(path: &Path, rows: &[ErrorRow], converged: (f64, f64)) -> anyhow::Result<()> {
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir)?;
    }
    let fonts = register_font();
    let root = BitMapBackend::new(path, (900, 600)).into_drawing_area();
    root.fill(&WHITE)?;
    let top = rows
        .iter()
        .map(|r| r.noisy.0 + r.noisy.1)
        .fold(0.0f64, f64::max)
        * 1.3;
    let mut builder = ChartBuilder::on(&root);
    builder
        .margin(20)
        .x_label_area_size(50)
        .y_label_area_size(70);
    if fonts {
        builder.caption(
            "Cornell box 160×90, away from the lamp: RMSE against 2048 spp",
            ("sans-serif", 24),
        );
    }
    let mut chart = builder.build_cartesian_2d(0.5f64..4.5f64, 0.0f64..top)?;
    let mut mesh = chart.configure_mesh();
    if fonts {
        mesh.x_desc("samples per pixel (one frame)")
            .y_desc("RMSE (linear radiance)")
            .label_style(("sans-serif", 15));
    }
    mesh.draw()?;
    let series: [Series; 2] = [
        ("without denoiser", RGBColor(200, 60, 40), |r| r.noisy),
        ("SVGF (CPU; GPU within 2e-3)", RGBColor(40, 90, 200), |r| {
            r.denoised
        }),
    ];
    for (name, colour, get) in series {
        let points: Vec<(f64, f64)> = rows.iter().map(|r| (r.spp as f64, get(r).0)).collect();
        chart
            .draw_series(LineSeries::new(points.clone(), colour.stroke_width(3)))?
            .label(name)
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(3))
            });
        chart.draw_series(points.iter().map(|&p| Circle::new(p, 5, colour.filled())))?;
        chart.draw_series(rows.iter().map(|r| {
            let (m, s) = get(r);
            PathElement::new(
                vec![(r.spp as f64, m - s), (r.spp as f64, m + s)],
                colour.stroke_width(2),
            )
        }))?;
    }
    for (name, value, colour) in [
        (
            "1024 spp, without (its noise)",
            converged.0,
            RGBColor(120, 120, 120),
        ),
        (
            "1024 spp, denoised (noise + bias)",
            converged.1,
            RGBColor(20, 150, 90),
        ),
    ] {
        chart
            .draw_series(LineSeries::new(
                vec![(0.5, value), (4.5, value)],
                colour.stroke_width(2),
            ))?
            .label(name)
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2))
            });
    }
    if fonts {
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font(("sans-serif", 15))
            .draw()?;
    }
    root.present()?;
    Ok(())
}
