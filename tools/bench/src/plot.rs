//! Charts of `bench chart`: one PNG per scene and tracer, one panel per curve family
//! (estimators, bounce caps, BVH builds), each relative MSE against wall time on log–log axes
//! with one line per curve (plotters, text in the system's DejaVu Sans). All panels of a
//! figure share their axis ranges so they can be read against each other.
//!
//! Owns: drawing only. Must not: measure.

use std::path::Path;

use plotters::prelude::*;

use super::chart::Point;

/// Registers a TrueType font for chart text; without one the charts still draw, unlabelled.
pub fn register_font() -> bool {
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

/// One panel: a title, its points and its curves in legend order.
pub struct PanelData<'a> {
    pub title: &'a str,
    pub points: Vec<&'a Point>,
    pub methods: Vec<&'a str>,
}

/// Draws a figure of `panels` side by side into `path`.
pub fn figure(path: &Path, title: &str, panels: &[PanelData<'_>]) -> anyhow::Result<()> {
    let fonts = register_font();
    let width = 700 * panels.len().max(1) as u32;
    let root = BitMapBackend::new(path, (width, 720)).into_drawing_area();
    root.fill(&WHITE)?;
    let body = if fonts {
        root.titled(title, ("sans-serif", 26))?
    } else {
        root.clone()
    };
    let (mut t0, mut t1, mut e0, mut e1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for p in panels.iter().flat_map(|p| &p.points) {
        if p.rel_mse > 0.0 && p.seconds > 0.0 {
            t0 = t0.min(p.seconds);
            t1 = t1.max(p.seconds);
            e0 = e0.min(p.rel_mse);
            e1 = e1.max(p.rel_mse);
        }
    }
    if t0 > t1 {
        anyhow::bail!("{title}: nothing to plot");
    }
    let areas = body.split_evenly((1, panels.len().max(1)));
    for (area, panel) in areas.iter().zip(panels) {
        draw_panel(
            area,
            panel,
            (t0 * 0.8, t1 * 1.25),
            (e0 * 0.8, e1 * 1.25),
            fonts,
        )?;
    }
    root.present()?;
    Ok(())
}

/// A log axis label only at 1, 2 and 5 times a power of ten (plotters puts a key point at
/// every step of a short range, whose labels would overlap).
fn decade_label(x: &f64) -> String {
    if *x <= 0.0 {
        return String::new();
    }
    let mantissa = x / 10f64.powf(x.log10().floor());
    if [1.0, 2.0, 5.0, 10.0]
        .iter()
        .any(|m| (mantissa - m).abs() < 1e-3)
    {
        format!("{x}")
    } else {
        String::new()
    }
}

fn draw_panel(
    area: &DrawingArea<BitMapBackend<'_>, plotters::coord::Shift>,
    panel: &PanelData<'_>,
    time: (f64, f64),
    error: (f64, f64),
    fonts: bool,
) -> anyhow::Result<()> {
    let mut builder = ChartBuilder::on(area);
    builder
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(70);
    if fonts {
        builder.caption(panel.title, ("sans-serif", 20));
    }
    let mut chart =
        builder.build_cartesian_2d((time.0..time.1).log_scale(), (error.0..error.1).log_scale())?;
    let mut mesh = chart.configure_mesh();
    if fonts {
        mesh.x_desc("wall time, seconds (log)")
            .y_desc("relative MSE (log)")
            .x_label_formatter(&decade_label)
            .y_label_formatter(&|y| format!("{y:.0e}"))
            .label_style(("sans-serif", 14));
    } else {
        mesh.disable_x_mesh().disable_y_mesh();
    }
    mesh.draw()?;
    for (i, method) in panel.methods.iter().enumerate() {
        let color = Palette99::pick(i).to_rgba();
        let series: Vec<(f64, f64)> = panel
            .points
            .iter()
            .filter(|p| p.method == *method && p.rel_mse > 0.0 && p.seconds > 0.0)
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
            .label_font(("sans-serif", 13))
            .position(SeriesLabelPosition::UpperRight)
            .draw()?;
    }
    Ok(())
}
