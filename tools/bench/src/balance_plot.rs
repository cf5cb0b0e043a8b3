//! Figure 9 of `bench balance`: idle share per frame, one line per scheme, one panel per device
//! set and camera (plotters, PNG). The y axis is logarithmic (idle shares run from under 0.1 %
//! for the best schemes to about 50 % without balancing); shares below 0.01 % are drawn at
//! 0.01 %.
//! Owns: drawing only. Must not: simulate.

use std::path::Path;

use candela::render::balance::SimReport;
use plotters::prelude::*;

use super::plot::register_font;

/// One panel: its title and the replays to draw in it.
pub struct Panel<'a> {
    pub title: String,
    pub reports: Vec<&'a SimReport>,
}

/// Floor of the log axis, percent.
const FLOOR_PCT: f64 = 0.01;

/// Draws `panels` in a 2-column grid into `path`.
pub fn figure(path: &Path, title: &str, panels: &[Panel<'_>]) -> anyhow::Result<()> {
    let fonts = register_font();
    let rows = panels.len().div_ceil(2).max(1);
    let root = BitMapBackend::new(path, (1400, 520 * rows as u32)).into_drawing_area();
    root.fill(&WHITE)?;
    let body = if fonts {
        root.titled(title, ("sans-serif", 26))?
    } else {
        root.clone()
    };
    let top = panels
        .iter()
        .flat_map(|p| &p.reports)
        .flat_map(|r| &r.frames)
        .map(|f| f.idle_share * 100.0)
        .fold(1.0, f64::max);
    let frames = panels
        .iter()
        .flat_map(|p| &p.reports)
        .map(|r| r.frames.len())
        .max()
        .unwrap_or(1);
    for (area, panel) in body.split_evenly((rows, 2)).iter().zip(panels) {
        let mut builder = ChartBuilder::on(area);
        builder
            .margin(15)
            .x_label_area_size(40)
            .y_label_area_size(60);
        if fonts {
            builder.caption(&panel.title, ("sans-serif", 20));
        }
        let mut chart =
            builder.build_cartesian_2d(0.0..frames as f64, (FLOOR_PCT..top * 1.3).log_scale())?;
        let mut mesh = chart.configure_mesh();
        if fonts {
            mesh.x_desc("frame")
                .x_label_formatter(&|x| format!("{x:.0}"))
                .y_desc("idle % (log)")
                .y_label_formatter(&|y| format!("{y}"))
                .label_style(("sans-serif", 14));
        } else {
            mesh.disable_x_mesh().disable_y_mesh();
        }
        mesh.draw()?;
        for (i, report) in panel.reports.iter().enumerate() {
            let color = Palette99::pick(i).to_rgba();
            let series: Vec<(f64, f64)> = report
                .frames
                .iter()
                .enumerate()
                .map(|(f, o)| (f as f64, (o.idle_share * 100.0).max(FLOOR_PCT)))
                .collect();
            let width = if report.scheme == "interleaved" || report.scheme == "cost model" {
                3
            } else {
                2
            };
            let line = chart.draw_series(LineSeries::new(series, color.stroke_width(width)))?;
            if fonts {
                let label = format!("{} ({:.1} %)", report.scheme, report.mean_idle() * 100.0);
                line.label(label).legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
                });
            }
        }
        if fonts {
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.85))
                .border_style(BLACK)
                .label_font(("sans-serif", 13))
                .position(SeriesLabelPosition::LowerRight)
                .draw()?;
        }
    }
    root.present()?;
    Ok(())
}
