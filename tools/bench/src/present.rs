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

use super::present_before::BeforeCompose;
use super::present_overlay_before::BeforeOverlay;
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
    /// Time only the code as it is now (no reference runs): for `perf record`, whose profile
    /// then holds the new code alone.
    #[arg(long)]
    pub now_only: bool,
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
/// rows, run until its layout settles, at 1 pixel per point. With `menu`, under it what the
/// shell's menu screens draw over the whole picture: the title's top shade (a full-width
/// gradient over 45 % of the height, `theme::top_shade`) and the dim of every menu
/// (`theme::DIM`, black at alpha 130 over the whole window).
fn stats_overlay(size: (u32, u32), menu: bool) -> Overlay {
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
        let mut output = context.run_pass(input, |ctx| {
            if menu {
                menu_layers(ctx);
            }
            candela::app::stats_window(ctx, &rows)
        });
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

/// The menus' full-window layers (see [`stats_overlay`]).
fn menu_layers(ctx: &egui::Context) {
    let rect = ctx.content_rect();
    let painter = ctx.layer_painter(egui::LayerId::background());
    painter.rect_filled(
        rect,
        egui::CornerRadius::ZERO,
        egui::Color32::from_rgba_premultiplied(0, 0, 0, 130),
    );
    let bottom = rect.top() + rect.height() * 0.45;
    let mut mesh = egui::Mesh::default();
    let (top, clear) = (
        egui::Color32::from_black_alpha(190),
        egui::Color32::TRANSPARENT,
    );
    mesh.colored_vertex(rect.left_top(), top);
    mesh.colored_vertex(rect.right_top(), top);
    mesh.colored_vertex(egui::pos2(rect.right(), bottom), clear);
    mesh.colored_vertex(egui::pos2(rect.left(), bottom), clear);
    mesh.add_triangle(0, 1, 2);
    mesh.add_triangle(0, 2, 3);
    painter.add(egui::Shape::mesh(mesh));
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

/// Milliseconds of `f`: the median of `samples`.
fn median_of(samples: &[f64]) -> f64 {
    median(samples.to_vec())
}

pub fn run(args: &PresentArgs) -> anyhow::Result<()> {
    let size = (args.width, args.height);
    let tonemap = TonemapSettings::default();
    let stats = stats_overlay(size, false);
    let menu = stats_overlay(size, true);
    // Every overlay's textures (the font atlas) in each rasteriser; the two passes built
    // their own contexts with the same text, so the same atlas under the same id.
    let (mut new_overlay, mut before_overlay, mut reference_overlay) = (
        CpuOverlay::default(),
        BeforeOverlay::default(),
        ReferenceOverlay::default(),
    );
    let mut apply = |o: &Overlay| {
        new_overlay.apply(&o.textures_delta);
        before_overlay.apply(&o.textures_delta);
        reference_overlay.apply(&o.textures_delta);
    };
    apply(&stats);
    apply(&menu);
    let triangles = |o: &Overlay| -> usize {
        o.primitives
            .iter()
            .map(|p| match &p.primitive {
                egui::epaint::Primitive::Mesh(m) => m.indices.len() / 3,
                _ => 0,
            })
            .sum()
    };
    println!(
        "\n`bench present`: into {}×{} (BGRA), median of {} runs each; F3 stats overlay of {} triangles, menu overlay (the same over a full-window dim and top shade) of {}; load average {}\n",
        size.0,
        size.1,
        args.runs,
        triangles(&stats),
        triangles(&menu),
        load()
    );
    println!(
        "| threads | film | compose before, ms | compose now, ms | F3 overlay before, ms | F3 overlay now, ms | menu overlay before, ms | menu overlay now, ms | copy, ms | now: compose + copy, ms | now: + F3 overlay, ms | largest difference |"
    );
    println!("|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for &threads in &args.threads {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()?;
        for (fw, fh) in [(160u32, 90u32), (320, 180), (480, 270)] {
            let film = test_film(fw, fh);
            pool.install(|| {
                let (mut compose, mut compose_before) =
                    (HostCompose::default(), BeforeCompose::default());
                // Timed samples: compose before/now, F3 overlay before/now, menu overlay
                // before/now, copy.
                let mut t: [Vec<f64>; 7] = Default::default();
                let reference = compose_reference(&film, size, &tonemap, true);
                let mut frame = reference.clone();
                let mut target = vec![0u8; reference.len()];
                // One thread: the pool's thread does all the work, so its CPU time is the cost.
                let time = |f: &mut dyn FnMut()| time_with(threads == 1, f);
                for _ in 0..args.runs {
                    if !args.now_only {
                        t[0].push(time(&mut || {
                            std::hint::black_box(compose_before.compose(&film, size, &tonemap, true));
                        }));
                    }
                    t[1].push(time(&mut || {
                        std::hint::black_box(compose.compose(&film, size, &tonemap, true));
                    }));
                    for (k, o) in [(2, &stats), (4, &menu)] {
                        if !args.now_only {
                            frame.copy_from_slice(&reference);
                            t[k].push(time(&mut || before_overlay.draw(&mut frame, size, true, o)));
                        }
                        frame.copy_from_slice(&reference);
                        t[k + 1].push(time(&mut || new_overlay.draw(&mut frame, size, true, o)));
                    }
                    t[6].push(time(&mut || {
                        target.copy_from_slice(std::hint::black_box(&frame))
                    }));
                }
                // The bytes: the new code against the code at 4c2b644 (`present_reference.rs`).
                let mut difference = largest_difference(
                    &reference,
                    compose.compose(&film, size, &tonemap, true),
                );
                for o in [&stats, &menu] {
                    let (mut old, mut new) = (reference.clone(), reference.clone());
                    reference_overlay.draw(&mut old, size, true, o);
                    new_overlay.draw(&mut new, size, true, o);
                    difference = difference.max(largest_difference(&old, &new));
                }
                let m = t.each_ref().map(|v| median_of(v));
                println!(
                    "| {threads} | {fw}×{fh} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2} | {difference} |",
                    m[0],
                    m[1],
                    m[2],
                    m[3],
                    m[4],
                    m[5],
                    m[6],
                    m[1] + m[6],
                    m[1] + m[3] + m[6],
                );
            });
        }
    }
    println!(
        "\n(before: the code at 8f10f79, timed alternately with the new in the same run; largest difference: of 255, between the new code's bytes and the code's at 4c2b644, compose and both overlays; load average at the end {})",
        load()
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The new compose and overlays give the old code's bytes (the bench's "largest
    /// difference" column, held): films of several scales with bad values, both tonemaps,
    /// BGRA and RGBA, windows whose width is and is not a multiple of four (the vector
    /// encoding's remainder), the F3 stats overlay and the menu overlay (full-window dim and
    /// gradient: the exact runs' interiors) drawn over the frame.
    #[test]
    fn the_new_compose_and_overlay_give_the_old_bytes() {
        for size in [(640u32, 360u32), (333, 201)] {
            let mut compose = HostCompose::default();
            for menu in [false, true] {
                let overlay = stats_overlay(size, menu);
                let mut new_overlay = CpuOverlay::default();
                new_overlay.apply(&overlay.textures_delta);
                let mut old_overlay = ReferenceOverlay::default();
                old_overlay.apply(&overlay.textures_delta);
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
                            "{fw}×{fh} into {size:?} filmic {filmic}"
                        );
                        old_overlay.draw(&mut old, size, bgra, &overlay);
                        new_overlay.draw(new, size, bgra, &overlay);
                        assert_eq!(
                            largest_difference(&old, new),
                            0,
                            "overlay (menu {menu}) over {fw}×{fh} into {size:?}"
                        );
                    }
                }
            }
        }
    }
}
