//! [`FrameStats`]: the figures the stats overlay shows, smoothed over recent frames.
//!
//! Owns: exponential averages of the main thread's [`FrameReport`]s (update, BVH upkeep,
//! hand-off, commit bytes) and the render thread's [`Rendered`] results (commit apply, render,
//! present, rays per second) plus the latest workload (spp, roulette scale, film size), and
//! their text lines. Main thread. Must not: draw (the overlay does) or time anything itself
//! except the wall time between frames it is given.

use super::phase::{FrameReport, Phase};
use crate::render::Rendered;

/// Weight of the newest frame in the running averages (≈ the last 10 frames count).
const SMOOTHING: f64 = 0.1;

fn smooth(average: &mut Option<f64>, value: f64) {
    *average = Some(match *average {
        Some(a) => a + (value - a) * SMOOTHING,
        None => value,
    });
}

/// Smoothed per-frame figures. Seconds unless named otherwise.
#[derive(Clone, Debug, Default)]
pub struct FrameStats {
    /// Which tracer renders and on what ("cpu", "gpu on llvmpipe", …).
    pub tracer: String,
    pub frame: Option<f64>,
    /// Per main-thread [`Phase`], in `Phase::ALL` order.
    pub phases: [Option<f64>; Phase::ALL.len()],
    pub commit_bytes: Option<f64>,
    pub overlay_bytes: Option<f64>,
    pub apply: Option<f64>,
    pub render: Option<f64>,
    pub present: Option<f64>,
    pub rays_per_second: Option<f64>,
    /// The latest workload and film.
    pub spp: u32,
    pub roulette_scale: f32,
    pub film_size: (u32, u32),
    /// The output (window) size the film is shown at.
    pub output_size: (u32, u32),
    /// The latest converging blend factor (1: the image restarted).
    pub blend: f32,
    pub frames_rendered: u64,
}

impl FrameStats {
    /// Adds the main thread's figures of one frame and its wall time.
    pub fn observe_frame(&mut self, report: &FrameReport, frame_seconds: f64) {
        smooth(&mut self.frame, frame_seconds);
        for (average, (_, seconds)) in self.phases.iter_mut().zip(report.phases.iter()) {
            smooth(average, seconds);
        }
        smooth(&mut self.commit_bytes, report.commit_bytes as f64);
        smooth(&mut self.overlay_bytes, report.overlay_bytes as f64);
    }

    /// Adds the render thread's figures of one frame.
    pub fn observe_rendered(&mut self, rendered: &Rendered) {
        if self.tracer == "auto" {
            self.tracer = format!("auto: {}", rendered.tracer);
        }
        smooth(&mut self.apply, rendered.apply_seconds);
        smooth(&mut self.render, rendered.render_seconds);
        smooth(&mut self.present, rendered.present_seconds);
        if rendered.render_seconds > 0.0 {
            smooth(
                &mut self.rays_per_second,
                rendered.stats.rays() as f64 / rendered.render_seconds,
            );
        }
        self.spp = rendered.spp;
        self.roulette_scale = rendered.roulette_scale;
        self.film_size = rendered.film_size;
        self.blend = rendered.blend;
        self.frames_rendered += 1;
    }

    /// What workload scaling settled on, for the player (the settings screen shows it next to
    /// the target frame rate): traced size, output size, samples per pixel and the frame rate
    /// reached, e.g. "160×90 traced for 1280×720, 1 spp, 29.8 fps". `None` before the first
    /// rendered frame.
    pub fn workload_summary(&self) -> Option<String> {
        if self.frames_rendered == 0 {
            return None;
        }
        let fps = self
            .frame
            .filter(|s| *s > 0.0)
            .map_or(String::new(), |s| format!(", {:.1} fps", 1.0 / s));
        Some(format!(
            "{}×{} traced for {}×{}, {} spp{fps}",
            self.film_size.0, self.film_size.1, self.output_size.0, self.output_size.1, self.spp
        ))
    }

    /// (label, value) lines for the overlay, in frame order: the main thread's phases as
    /// [`Phase::name`] labels them, then the render thread's figures.
    pub fn lines(&self) -> Vec<(&'static str, String)> {
        let ms = |s: Option<f64>| s.map_or("–".into(), |s| format!("{:.2} ms", s * 1e3));
        let kib = |b: Option<f64>| b.map_or("–".into(), |b| format!("{:.1} KiB", b / 1024.0));
        let fps = self
            .frame
            .filter(|s| *s > 0.0)
            .map_or("–".into(), |s| format!("{:.1} fps", 1.0 / s));
        let mut lines = vec![
            ("tracer", self.tracer.clone()),
            ("frame", format!("{} ({fps})", ms(self.frame))),
        ];
        for (phase, average) in Phase::ALL.iter().zip(&self.phases) {
            lines.push((phase.name(), ms(*average)));
        }
        lines.extend([
            ("commit apply", ms(self.apply)),
            ("commit size", kib(self.commit_bytes)),
            ("overlay size", kib(self.overlay_bytes)),
            ("render", ms(self.render)),
            ("present", ms(self.present)),
            (
                "rays/s",
                self.rays_per_second
                    .map_or("–".into(), |r| format!("{:.2} M", r / 1e6)),
            ),
            ("spp", self.spp.to_string()),
            ("roulette scale", format!("{:.2}", self.roulette_scale)),
            (
                "resolution",
                format!(
                    "{}×{} of {}×{}",
                    self.film_size.0, self.film_size.1, self.output_size.0, self.output_size.1
                ),
            ),
            ("converging", format!("blend {:.3}", self.blend)),
        ]);
        lines
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn averages_and_lines() {
        let mut stats = FrameStats::default();
        let mut report = FrameReport {
            commit_bytes: 2048,
            ..Default::default()
        };
        report.phases.add(Phase::Steps, 0.002);
        stats.observe_frame(&report, 0.020);
        report.phases.add(Phase::Steps, 0.010);
        stats.observe_frame(&report, 0.020);
        assert!((stats.phases[1].unwrap_or(0.0) - 0.003).abs() < 1e-12);
        let lines = stats.lines();
        let get = |label: &str| {
            lines
                .iter()
                .find(|(l, _)| *l == label)
                .map(|(_, v)| v.clone())
                .unwrap_or_default()
        };
        assert_eq!(get("frame"), "20.00 ms (50.0 fps)");
        assert_eq!(get(Phase::Steps.name()), "3.00 ms");
        assert_eq!(get("commit size"), "2.0 KiB");
        assert_eq!(get("render"), "–");
    }

    #[test]
    fn the_workload_summary_says_what_scaling_settled_on() {
        let mut stats = FrameStats::default();
        assert_eq!(stats.workload_summary(), None, "nothing rendered yet");
        stats.observe_frame(&FrameReport::default(), 0.040);
        stats.spp = 2;
        stats.film_size = (160, 90);
        stats.output_size = (1280, 720);
        stats.frames_rendered = 1;
        assert_eq!(
            stats.workload_summary().as_deref(),
            Some("160×90 traced for 1280×720, 2 spp, 25.0 fps")
        );
    }
}
