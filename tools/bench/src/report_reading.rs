//! The automatic readings of `bench chart`: a few sentences per scene × tracer, one per panel,
//! generated from the measured numbers so that they stay true when the figures change.
//!
//! Owns: time to a target error (log–log interpolation), and the readings of the estimator,
//! bounce and BVH panels. Must not: measure or write files.

use std::fmt::Write as _;

use super::chart::Point;
use super::chart_methods::{DEFAULT_NAME, Layout, Panel, in_panel};

/// Seconds until the curve first reaches `target` relative MSE (log-log interpolation between
/// the two measured points around it); `None` if it never does within the measured range.
pub fn time_to(points: &[&Point], target: f64) -> Option<f64> {
    let mut previous: Option<&Point> = None;
    for p in points {
        if p.rel_mse <= target {
            return Some(match previous {
                Some(q) if q.rel_mse > target && p.rel_mse > 0.0 => {
                    let f = (q.rel_mse.ln() - target.ln()) / (q.rel_mse.ln() - p.rel_mse.ln());
                    (q.seconds.ln() + f * (p.seconds.ln() - q.seconds.ln())).exp()
                }
                _ => p.seconds,
            });
        }
        previous = Some(p);
    }
    None
}

/// The points of one curve, in sample order.
fn curve<'a>(group: &[&'a Point], name: &str) -> Vec<&'a Point> {
    group.iter().copied().filter(|p| p.method == name).collect()
}

/// Mean bias of a point over the three channels, relative to the reference's image mean.
fn relative_bias(p: &Point) -> f64 {
    let mean: f64 = p.ref_mean.iter().sum();
    p.bias.iter().sum::<f64>() / mean.max(1e-12)
}

/// Whether a curve stopped falling: its last doubling of samples gained less than 25 %.
fn flattens(points: &[&Point]) -> bool {
    matches!(points, [.., a, b] if b.rel_mse > 0.75 * a.rel_mse)
}

/// The reading of the estimator panel, and the default's time to a relative MSE of 1e-2.
pub fn estimators(group: &[&Point]) -> (Option<f64>, String) {
    let reach: Vec<(&str, Option<f64>)> = in_panel(Panel::Estimators)
        .filter(|m| !curve(group, m.name).is_empty())
        .map(|m| (m.name, time_to(&curve(group, m.name), 1e-2)))
        .collect();
    let default = reach
        .iter()
        .find(|(n, _)| *n == DEFAULT_NAME)
        .and_then(|(_, t)| *t);
    if reach.is_empty() {
        return (default, String::new());
    }
    let mut out = String::from("Reading, estimators: ");
    let best = reach
        .iter()
        .filter_map(|(n, t)| t.map(|t| (*n, t)))
        .min_by(|a, b| a.1.total_cmp(&b.1));
    if let Some((best, t)) = best {
        let _ = write!(out, "fastest to a relative MSE of 1e-2: {best} ({t:.2} s)");
        if let Some(d) = default {
            let _ = write!(out, "; the default takes {d:.2} s ({:.2}×)", d / t);
        }
        out.push_str(". ");
    } else {
        out.push_str("no estimator reached a relative MSE of 1e-2 in the measured range. ");
    }
    let missed: Vec<&str> = reach
        .iter()
        .filter(|(_, t)| t.is_none())
        .map(|(n, _)| *n)
        .collect();
    if !missed.is_empty() && best.is_some() {
        let _ = write!(out, "Did not reach 1e-2: {}. ", missed.join("; "));
    }
    let flat: Vec<&str> = reach
        .iter()
        .filter(|(n, _)| flattens(&curve(group, n)))
        .map(|(n, _)| *n)
        .collect();
    if !flat.is_empty() {
        let _ = write!(
            out,
            "Flattening at the end (too noisy to tell, or biased): {}.",
            flat.join("; ")
        );
    }
    out.push_str("\n\n");
    (default, out)
}

/// The reading of the bounce panel: the bias each cap leaves, and the fastest cap to 1e-2.
pub fn bounces(group: &[&Point], default_reach: Option<f64>) -> String {
    let caps: Vec<(&str, u32, Vec<&Point>)> = in_panel(Panel::Bounces)
        .map(|m| (m.name, m.max_bounces.unwrap_or(0), curve(group, m.name)))
        .filter(|(_, _, c)| !c.is_empty())
        .collect();
    if caps.is_empty() {
        return String::new();
    }
    let mut out = String::from(
        "Reading, bounces: mean bias of the final image per cap, % of the image mean: ",
    );
    let biases: Vec<String> = caps
        .iter()
        .filter_map(|(_, b, c)| {
            c.last()
                .map(|p| format!("{b}: {:+.1}", 100.0 * relative_bias(p)))
        })
        .collect();
    out.push_str(&biases.join(", "));
    out.push_str(". ");
    if let Some((_, b, _)) = caps.iter().find(|(_, _, c)| {
        c.last()
            .is_some_and(|p| relative_bias(p).abs() < 0.01 && !flattens(c))
    }) {
        let _ = write!(
            out,
            "The lowest cap within 1 % of the reference's brightness that still converges: {b}. "
        );
    }
    let best = caps
        .iter()
        .filter_map(|(_, b, c)| time_to(c, 1e-2).map(|t| (*b, t)))
        .min_by(|a, b| a.1.total_cmp(&b.1));
    match (best, default_reach) {
        (Some((b, t)), Some(d)) => {
            let _ = write!(
                out,
                "Fastest to 1e-2: max {b} bounces ({t:.2} s; the level's default {d:.2} s)."
            );
        }
        (Some((b, t)), None) => {
            let _ = write!(out, "Fastest to 1e-2: max {b} bounces ({t:.2} s).");
        }
        (None, _) => out.push_str("No cap reached 1e-2 in the measured range."),
    }
    out.push_str("\n\n");
    out
}

/// The reading of the BVH panel: time and rays per second of each build against the default
/// at the final sample count (the images are the same).
pub fn layouts(group: &[&Point]) -> String {
    let Some(default) = curve(group, DEFAULT_NAME).last().copied() else {
        return String::new();
    };
    let rate = |p: &Point| p.rays as f64 / p.seconds.max(1e-9) / 1e6;
    let mut parts = Vec::new();
    for m in in_panel(Panel::Layouts).filter(|m| m.layout != Layout::Default) {
        if let Some(p) = curve(group, m.name).last() {
            parts.push(format!(
                "{} takes {:.2}× the default's time ({:.2} against {:.2} Mrays/s; final \
                 relative MSE {:.2e} against {:.2e})",
                m.name,
                p.seconds / default.seconds.max(1e-9),
                rate(p),
                rate(default),
                p.rel_mse,
                default.rel_mse
            ));
        }
    }
    if parts.is_empty() {
        return String::new();
    }
    format!("Reading, BVH builds: {}.\n\n", parts.join("; "))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chart_scenes::RefKind;

    fn point(seconds: f64, rel_mse: f64) -> Point {
        Point {
            scene: "s",
            reference: RefKind::Mitsuba,
            tracer: "cpu",
            method: DEFAULT_NAME,
            same_as: None,
            spp: 1,
            seconds,
            rays: 1,
            rel_mse,
            rmse: 0.0,
            bias: [-0.1, -0.2, -0.3],
            bias_floor: [0.0; 3],
            ref_mean: [1.0, 2.0, 3.0],
        }
    }

    #[test]
    fn time_to_interpolates_on_log_log_axes() {
        let (a, b) = (point(1.0, 1e-1), point(4.0, 1e-3));
        let t = time_to(&[&a, &b], 1e-2);
        assert!(t.is_some_and(|t| (t - 2.0).abs() < 1e-9));
        assert_eq!(time_to(&[&a, &b], 1e-4), None);
        assert_eq!(time_to(&[&a], 1.0), Some(1.0));
        assert!((relative_bias(&a) + 0.1).abs() < 1e-12);
        assert!(flattens(&[&a, &point(2.0, 0.09)]) && !flattens(&[&a, &b]));
    }
}
