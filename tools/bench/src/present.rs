//! `bench present`: the cost of presenting the CPU tracer's film in a 1280×720 window, without
//! a window. Times the CPU compose (`render::present::HostCompose`: Catmull-Rom upscale,
//! tonemap, sRGB, 8-bit BGRA) of 160×90, 320×180 and 480×270 films, the F3 stats overlay drawn
//! over the frame on the CPU (`CpuOverlay`), and a copy of the frame's bytes (what
//! `queue.write_texture` does first), each at 1 and 2 threads, medians of many runs. Beside each,
//! the code as it was before (`present_reference.rs`, `present_overlay_reference.rs`), timed
//! in the same run, alternating with the new, and the largest byte difference between the two.
//! One-thread figures are the thread's CPU time (load-independent), two-thread ones wall time.
//!
//! Owns: the measurement. Must not: open a window or touch a device.

use std::time::Instant;

use candela::commit::Overlay;
use candela::render::film::{Film, TonemapSettings};
use candela::render::present::{CpuOverlay, HostCompose};
use clap::Args;
use glam::Vec3;

use super::present_overlay_reference::ReferenceOverlay;
use super::present_reference::compose_reference;

#[derive(Args, Debug)]
pub struct PresentArgs {
    /// Timed runs of each figure (the median is reported).
    #[arg(long, default_value_t = 61)]
    pub runs: usize,
    /// Thread counts to time at.
    #[arg(long, value_delimiter = ',', default_value = "1,2")]
    pub threads: Vec<usize>,
    /// The window's size.
    #[arg(long, default_value_t = 1280)]
    pub width: u32,
    #[arg(long, default_value_t = 720)]
    pub height: u32,
}

/// A film of `w`×`h` with smooth gradients, per-pixel noise (a 1-spp look), values above 1,
/// one NaN and one infinite pixel. Linear radiance.
fn test_film(w: u32, h: u32) -> Film {
    let mut film = Film::new(w, h);
    let mut state = 0x9e37_79b9_u32;
    for (i, p) in film.mean.iter_mut().enumerate() {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        let noise = (state >> 8) as f32 / (1 << 24) as f32;
        let (x, y) = (
            (i as u32 % w) as f32 / w as f32,
            (i as u32 / w) as f32 / h as f32,
        );
        *p = Vec3::new(x * 1.5, y, 0.3 + 0.2 * (x * 9.0).sin()) * (0.25 + 1.5 * noise);
    }
    film.mean[w as usize + 1] = Vec3::new(f32::NAN, 0.5, 0.5);
    film.mean[2 * w as usize + 3] = Vec3::new(f32::INFINITY, 2.0, -1.0);
    film
}

/// The stats window the F3 overlay draws (`candela::app::stats_window`) with 22 label–value
/// rows, run until its layout settles, at 1 pixel per point.
fn stats_overlay(size: (u32, u32)) -> Overlay {
    let context = egui::Context::default();
    let mut textures = egui::TexturesDelta::default();
    let mut last = None;
    for _ in 0..3 {
        let input = egui::RawInput {
            screen_rect: Some(egui::Rect::from_min_size(
                egui::Pos2::ZERO,
                egui::vec2(size.0 as f32, size.1 as f32),
            )),
            ..Default::default()
        };
        let rows: Vec<(String, String)> = (0..22)
            .map(|i| (format!("phase {i}"), format!("{:.2} ms", 1.234 * i as f32)))
            .collect();
        let mut output = context.run_pass(input, |ctx| candela::app::stats_window(ctx, &rows));
        textures.append(std::mem::take(&mut output.textures_delta));
        last = Some(output);
    }
    let output = last.unwrap_or_default();
    Overlay {
        primitives: context.tessellate(output.shapes, output.pixels_per_point),
        textures_delta: textures,
        pixels_per_point: output.pixels_per_point,
    }
}

/// This thread's CPU time in milliseconds (`CLOCK_THREAD_CPUTIME_ID`): unlike the wall clock,
/// it does not count the time other processes held the core, so one-thread figures taken on a
/// loaded machine stay comparable.
fn thread_cpu_ms() -> f64 {
    let mut t = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `t` is a valid timespec for the call to fill.
    let ok = unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut t) } == 0;
    if ok {
        t.tv_sec as f64 * 1e3 + t.tv_nsec as f64 * 1e-6
    } else {
        f64::NAN
    }
}

/// Milliseconds of one call of `f`: wall clock, or this thread's CPU time when `cpu`.
fn time_with(cpu: bool, f: impl FnOnce()) -> f64 {
    if cpu {
        let started = thread_cpu_ms();
        f();
        return thread_cpu_ms() - started;
    }
    let started = Instant::now();
    f();
    started.elapsed().as_secs_f64() * 1e3
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v.get(v.len() / 2).copied().unwrap_or(f64::NAN)
}

/// The 1-minute load average (`/proc/loadavg`), for reading the times: other work on the
/// machine's cores stretches every figure.
fn load() -> String {
    std::fs::read_to_string("/proc/loadavg")
        .ok()
        .and_then(|s| s.split_whitespace().next().map(str::to_owned))
        .unwrap_or_else(|| "unknown".into())
}

fn largest_difference(a: &[u8], b: &[u8]) -> u8 {
    if a.len() != b.len() {
        return u8::MAX;
    }
    a.iter()
        .zip(b)
        .map(|(x, y)| x.abs_diff(*y))
        .max()
        .unwrap_or(0)
}

pub fn run(args: &PresentArgs) -> anyhow::Result<()> {
    let size = (args.width, args.height);
    let tonemap = TonemapSettings::default();
    let overlay = stats_overlay(size);
    let mut new_overlay = CpuOverlay::default();
    new_overlay.apply(&overlay.textures_delta);
    let mut old_overlay = ReferenceOverlay::default();
    old_overlay.apply(&overlay.textures_delta);
    let triangles: usize = overlay
        .primitives
        .iter()
        .map(|p| match &p.primitive {
            egui::epaint::Primitive::Mesh(m) => m.indices.len() / 3,
            _ => 0,
        })
        .sum();
    println!(
        "\n`bench present`: into {}×{} (BGRA), median of {} runs each; stats overlay of {triangles} triangles; load average {}\n",
        size.0,
        size.1,
        args.runs,
        load()
    );
    println!(
        "| threads | film | compose before, ms | compose now, ms | speed-up | overlay before, ms | overlay now, ms | copy, ms | now: compose + overlay + copy, ms | largest difference |"
    );
    println!("|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|");
    for &threads in &args.threads {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()?;
        for (fw, fh) in [(160u32, 90u32), (320, 180), (480, 270)] {
            let film = test_film(fw, fh);
            pool.install(|| {
                let mut compose = HostCompose::default();
                let (mut before, mut now) = (Vec::new(), Vec::new());
                let (mut overlay_before, mut overlay_now, mut copy) =
                    (Vec::new(), Vec::new(), Vec::new());
                let reference = compose_reference(&film, size, &tonemap, true);
                let mut frame_old = reference.clone();
                let mut frame_new = reference.clone();
                let mut target = vec![0u8; reference.len()];
                // One thread: the pool's thread does all the work, so its CPU time is the cost.
                let time = |f: &mut dyn FnMut()| time_with(threads == 1, f);
                for _ in 0..args.runs {
                    before.push(time(&mut || {
                        std::hint::black_box(compose_reference(&film, size, &tonemap, true));
                    }));
                    now.push(time(&mut || {
                        std::hint::black_box(compose.compose(&film, size, &tonemap, true));
                    }));
                    frame_old.copy_from_slice(&reference);
                    overlay_before.push(time(&mut || {
                        old_overlay.draw(&mut frame_old, size, true, &overlay);
                    }));
                    frame_new.copy_from_slice(&reference);
                    overlay_now.push(time(&mut || {
                        new_overlay.draw(&mut frame_new, size, true, &overlay);
                    }));
                    copy.push(time(&mut || {
                        target.copy_from_slice(std::hint::black_box(&frame_new))
                    }));
                }
                let composed = compose.compose(&film, size, &tonemap, true).to_vec();
                let difference = largest_difference(&reference, &composed)
                    .max(largest_difference(&frame_old, &frame_new));
                let (b, n) = (median(before), median(now));
                let (ob, on, c) = (median(overlay_before), median(overlay_now), median(copy));
                println!(
                    "| {threads} | {fw}×{fh} | {b:.2} | {n:.2} | {:.1}× | {ob:.2} | {on:.2} | {c:.2} | {:.2} | {difference} |",
                    b / n,
                    n + on + c
                );
            });
        }
    }
    println!(
        "\n(largest difference: of 255, between the old and the new code's bytes, compose and overlay; load average at the end {})",
        load()
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The new compose and overlay give the old code's bytes (the bench's "largest
    /// difference" column, held): films of several scales with bad values, both tonemaps,
    /// BGRA and RGBA, the stats overlay drawn over the frame.
    #[test]
    fn the_new_compose_and_overlay_give_the_old_bytes() {
        let size = (640u32, 360u32);
        let overlay = stats_overlay(size);
        let mut new_overlay = CpuOverlay::default();
        new_overlay.apply(&overlay.textures_delta);
        let mut old_overlay = ReferenceOverlay::default();
        old_overlay.apply(&overlay.textures_delta);
        let mut compose = HostCompose::default();
        for (fw, fh) in [(160u32, 90u32), (321, 180), (7, 3), (640, 360)] {
            let film = test_film(fw, fh);
            for (filmic, bgra) in [(false, true), (true, false)] {
                let tonemap = TonemapSettings {
                    exposure_ev: -0.3,
                    filmic,
                };
                let mut old = compose_reference(&film, size, &tonemap, bgra);
                let new = compose.compose(&film, size, &tonemap, bgra);
                assert_eq!(
                    largest_difference(&old, new),
                    0,
                    "{fw}×{fh} filmic {filmic}"
                );
                old_overlay.draw(&mut old, size, bgra, &overlay);
                new_overlay.draw(new, size, bgra, &overlay);
                assert_eq!(largest_difference(&old, new), 0, "overlay over {fw}×{fh}");
            }
        }
    }
}
