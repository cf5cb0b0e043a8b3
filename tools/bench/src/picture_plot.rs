//! The chart of `bench picture`: the error of the displayed picture against the frame time of
//! each configuration, relative MSE on linear radiance (left) and RMSE of the sRGB picture
//! (right), one labelled point per configuration, lines joining each size's denoiser off and on
//! (plotters, PNG).
//!
//! Owns: drawing only. Must not: measure.

use std::path::Path;

use plotters::prelude::*;

use super::picture::Outcome;
use super::picture_report::summary;
use super::plot::register_font;

const COLOURS: [RGBColor; 4] = [
    RGBColor(200, 60, 40),
    RGBColor(40, 90, 200),
    RGBColor(230, 140, 30),
    RGBColor(20, 150, 90),
];

pub fn chart(path: &Path, outcome: &Outcome) -> anyhow::Result<()> {
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir)?;
    }
    let fonts = register_font();
    let root = BitMapBackend::new(path, (1400, 620)).into_drawing_area();
    root.fill(&WHITE)?;
    let body = if fonts {
        root.titled(
            "Reflect, the displayed picture against a converged render of the same view",
            ("sans-serif", 24),
        )?
    } else {
        root.clone()
    };
    let panels = body.split_evenly((1, 2));
    let points: Vec<(f64, [f64; 4])> = outcome
        .configs
        .iter()
        .zip(&outcome.frame_ms)
        .map(|(c, ms)| (*ms, summary(outcome, c)))
        .collect();
    let t1 = points.iter().map(|p| p.0).fold(1.0, f64::max) * 1.25;
    for (panel, (which, name)) in panels.iter().zip([
        (0, "relative MSE (linear radiance)"),
        (1, "RMSE (tonemapped sRGB, 0–1)"),
    ]) {
        let top = points.iter().map(|p| p.1[which]).fold(1e-6, f64::max) * 1.25;
        let mut builder = ChartBuilder::on(panel);
        builder
            .margin(20)
            .x_label_area_size(50)
            .y_label_area_size(80);
        let mut chart = builder.build_cartesian_2d(0.0..t1, 0.0..top)?;
        let mut mesh = chart.configure_mesh();
        if fonts {
            mesh.x_desc("frame time, ms (trace + denoise, median)")
                .y_desc(name)
                .label_style(("sans-serif", 15));
        }
        mesh.draw()?;
        for pair in points.chunks(2) {
            let line: Vec<(f64, f64)> = pair.iter().map(|p| (p.0, p.1[which])).collect();
            chart.draw_series(LineSeries::new(line, BLACK.mix(0.3).stroke_width(1)))?;
        }
        for ((ms, figures), (config, colour)) in points
            .iter()
            .zip(outcome.configs.iter().zip(COLOURS.iter().cycle()))
        {
            let colour = *colour;
            chart
                .draw_series([Circle::new((*ms, figures[which]), 7, colour.filled())])?
                .label(config.label())
                .legend(move |(x, y)| Circle::new((x + 10, y), 6, colour.filled()));
            // The reference's own noise, the floor under the point.
            chart.draw_series([PathElement::new(
                vec![
                    (ms * 0.97, figures[which + 2]),
                    (ms * 1.03, figures[which + 2]),
                ],
                colour.stroke_width(2),
            )])?;
        }
        if fonts {
            chart
                .configure_series_labels()
                .position(SeriesLabelPosition::UpperRight)
                .background_style(WHITE.mix(0.85))
                .border_style(BLACK)
                .label_font(("sans-serif", 15))
                .draw()?;
        }
    }
    root.present()?;
    Ok(())
}
