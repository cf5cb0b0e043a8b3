//! The chart of `bench memory`: one stacked bar per scene (triangles, BVH, textures, the rest,
//! in MB) and Brigade's published figures beside them (plotters, DejaVu Sans).
//!
//! Owns: drawing only. Must not: measure.

use std::path::Path;

use plotters::prelude::*;

use super::memory::Row;

/// Draws `rows` and Brigade's 737 MB into `path`.
pub fn draw(path: &Path, rows: &[Row]) -> anyhow::Result<()> {
    let fonts = super::plot::register_font();
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir)?;
    }
    let mb = |b: usize| b as f64 / 1e6;
    // (name, [triangles, BVH, textures, rest]) in MB.
    let mut bars: Vec<(String, [f64; 4])> = rows
        .iter()
        .map(|r| {
            let m = &r.memory;
            let rest = m.instances + m.lights + m.other;
            (
                r.name.clone(),
                [mb(m.triangles), mb(m.bvh), mb(m.textures), mb(rest)],
            )
        })
        .collect();
    bars.push((
        "Brigade, 1.4 M tri (paper)".into(),
        [175.0, 42.0, 520.0, 0.0],
    ));
    let top = bars
        .iter()
        .map(|(_, v)| v.iter().sum::<f64>())
        .fold(1.0, f64::max)
        * 1.1;
    let root = BitMapBackend::new(path, (1100, 520)).into_drawing_area();
    root.fill(&WHITE)?;
    let n = bars.len() as i32;
    let mut builder = ChartBuilder::on(&root);
    builder
        .margin(16)
        .x_label_area_size(40)
        .y_label_area_size(220);
    if fonts {
        builder.caption("Scene memory by kind (MB)", ("sans-serif", 24));
    }
    let mut chart = builder.build_cartesian_2d(0.0..top, (0..n - 1).into_segmented())?;
    if fonts {
        let names: Vec<String> = bars.iter().map(|(name, _)| name.clone()).collect();
        chart
            .configure_mesh()
            .disable_y_mesh()
            .x_desc("MB")
            .y_label_formatter(&|y| match y {
                SegmentValue::CenterOf(i) => names.get(*i as usize).cloned().unwrap_or_default(),
                _ => String::new(),
            })
            .draw()?;
    }
    let kinds = [
        ("triangles", RGBColor(70, 110, 180)),
        ("BVH", RGBColor(220, 140, 50)),
        ("textures", RGBColor(90, 160, 90)),
        ("instances, lights, materials, sky", RGBColor(150, 150, 150)),
    ];
    for (k, (label, color)) in kinds.iter().enumerate() {
        let rects = bars.iter().enumerate().map(|(i, (_, v))| {
            let from: f64 = v[..k].iter().sum();
            let i = i as i32;
            Rectangle::new(
                [
                    (from, SegmentValue::Exact(i)),
                    (from + v[k], SegmentValue::Exact(i + 1)),
                ],
                color.filled(),
            )
        });
        let series = chart.draw_series(rects)?;
        if fonts {
            let c = *color;
            series
                .label(*label)
                .legend(move |(x, y)| Rectangle::new([(x, y - 5), (x + 12, y + 5)], c.filled()));
        }
    }
    if fonts {
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .position(SeriesLabelPosition::LowerRight)
            .draw()?;
    }
    root.present()?;
    Ok(())
}
