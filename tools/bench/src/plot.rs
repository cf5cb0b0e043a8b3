//! Charts of `bench chart`: relative MSE against wall time, log–log, one line per method, one
//! PNG per scene and tracer (plotters, text in the system's DejaVu Sans).
//!
//! Owns: drawing only. Must not: measure.

use std::path::Path;

use plotters::prelude::*;

use super::chart::Point;

/// Registers a TrueType font for chart text; without one the charts still draw, unlabelled.
fn register_font() -> bool {
    for path in [
        "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
        "/usr/share/fonts/TTF/DejaVuSans.ttf",
        "/usr/share/fonts/dejavu/DejaVuSans.ttf",
    ] {
        if let Ok(bytes) = std::fs::read(path) {
            let bytes: &'static [u8] = Box::leak(bytes.into_boxed_slice());
            if plotters::style::register_font("sans-serif", FontStyle::Normal, bytes).is_ok() {
                return true;
            }
        }
    }
    false
}

/// Draws `points` (one scene, one tracer) into `path`.
pub fn chart(path: &Path, title: &str, points: &[&Point], methods: &[&str]) -> anyhow::Result<()> {
    let fonts = register_font();
    let root = BitMapBackend::new(path, (1100, 700)).into_drawing_area();
    root.fill(&WHITE)?;
    let positive: Vec<&&Point> = points
        .iter()
        .filter(|p| p.rel_mse > 0.0 && p.seconds > 0.0)
        .collect();
    let (mut t0, mut t1, mut e0, mut e1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for p in &positive {
        t0 = t0.min(p.seconds);
        t1 = t1.max(p.seconds);
        e0 = e0.min(p.rel_mse);
        e1 = e1.max(p.rel_mse);
    }
    if positive.is_empty() {
        anyhow::bail!("{title}: nothing to plot");
    }
    let mut builder = ChartBuilder::on(&root);
    builder
        .margin(20)
        .x_label_area_size(50)
        .y_label_area_size(80);
    if fonts {
        builder.caption(title, ("sans-serif", 24));
    }
    let mut chart = builder.build_cartesian_2d(
        (t0 * 0.8..t1 * 1.25).log_scale(),
        (e0 * 0.8..e1 * 1.25).log_scale(),
    )?;
    let mut mesh = chart.configure_mesh();
    if fonts {
        mesh.x_desc("wall time, seconds (log)")
            .y_desc("relative MSE against the reference (log)")
            .x_label_formatter(&|x| format!("{x:.3}"))
            .y_label_formatter(&|y| format!("{y:.0e}"))
            .label_style(("sans-serif", 15));
    } else {
        mesh.disable_x_mesh().disable_y_mesh();
    }
    mesh.draw()?;
    for (i, method) in methods.iter().enumerate() {
        let color = Palette99::pick(i).to_rgba();
        let series: Vec<(f64, f64)> = positive
            .iter()
            .filter(|p| p.method == *method)
            .map(|p| (p.seconds, p.rel_mse))
            .collect();
        if series.is_empty() {
            continue;
        }
        let line = chart.draw_series(LineSeries::new(series.clone(), color.stroke_width(2)))?;
        if fonts {
            line.label(*method).legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
            });
        }
        chart.draw_series(
            series
                .iter()
                .map(|&(x, y)| Circle::new((x, y), 3, color.filled())),
        )?;
    }
    if fonts {
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font(("sans-serif", 14))
            .position(SeriesLabelPosition::UpperRight)
            .draw()?;
    }
    root.present()?;
    Ok(())
}
