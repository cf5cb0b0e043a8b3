//! The chart of `bench two-lights`: one panel per view, relative MSE of the running mean against
//! cumulative wall time on log–log axes, one line per estimator (plotters, text in the system's
//! DejaVu Sans via `plot::register_font`). Each panel has its own axis ranges: a night view's
//! error and a day view's differ by orders of magnitude.
//!
//! Owns: drawing only. Must not: measure.

use std::path::Path;

use plotters::prelude::*;

use super::plot::register_font;

/// One estimator's curve: (cumulative seconds, relative MSE) points in time order.
pub struct Curve {
    pub name: &'static str,
    pub points: Vec<(f64, f64)>,
}

/// Draws `panels` (title, curves) side by side into `path` (PNG).
pub fn figure(path: &Path, title: &str, panels: &[(&str, Vec<Curve>)]) -> anyhow::Result<()> {
    let fonts = register_font();
    let width = 700 * panels.len().max(1) as u32;
    let root = BitMapBackend::new(path, (width, 620)).into_drawing_area();
    root.fill(&WHITE)?;
    let body = if fonts {
        root.titled(title, ("sans-serif", 22))?
    } else {
        root.clone()
    };
    let areas = body.split_evenly((1, panels.len().max(1)));
    for (area, (panel_title, curves)) in areas.iter().zip(panels) {
        let points = curves
            .iter()
            .flat_map(|c| &c.points)
            .filter(|(t, e)| *t > 0.0 && *e > 0.0);
        let (mut t0, mut t1, mut e0, mut e1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
        for &(t, e) in points {
            (t0, t1, e0, e1) = (t0.min(t), t1.max(t), e0.min(e), e1.max(e));
        }
        if t0 > t1 {
            anyhow::bail!("{panel_title}: nothing to plot");
        }
        let mut builder = ChartBuilder::on(area);
        builder
            .margin(15)
            .x_label_area_size(45)
            .y_label_area_size(70);
        if fonts {
            builder.caption(*panel_title, ("sans-serif", 18));
        }
        let mut chart = builder.build_cartesian_2d(
            (t0 * 0.8..t1 * 1.25).log_scale(),
            (e0 * 0.8..e1 * 1.25).log_scale(),
        )?;
        let mut mesh = chart.configure_mesh();
        if fonts {
            mesh.x_desc("cumulative wall time, seconds (log)")
                .y_desc("relative MSE of the mean (log)")
                .x_label_formatter(&|x| format!("{x:.2}"))
                .y_label_formatter(&|y| format!("{y:.0e}"))
                .label_style(("sans-serif", 14));
        } else {
            mesh.disable_x_mesh().disable_y_mesh();
        }
        mesh.draw()?;
        for (i, curve) in curves.iter().enumerate() {
            let color = Palette99::pick(i).to_rgba();
            let series: Vec<(f64, f64)> = curve
                .points
                .iter()
                .copied()
                .filter(|(t, e)| *t > 0.0 && *e > 0.0)
                .collect();
            let line = chart.draw_series(LineSeries::new(series, color.stroke_width(2)))?;
            if fonts {
                line.label(curve.name).legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
                });
            }
        }
        if fonts {
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.8))
                .border_style(BLACK)
                .label_font(("sans-serif", 14))
                .draw()?;
        }
    }
    root.present()?;
    Ok(())
}
