//! Presenting without a window (lavapipe without a GPU): what the window would show is composed
//! offscreen by the same `FrameComposer` the window's presenter uses, and read back.
//!
//! * The present pass tonemaps exactly like the CPU (`linear_to_srgb8`, which writes capture
//!   PNGs): exposure, the filmic curve, NaN/inf/negative inputs, for an sRGB target (hardware
//!   encoding) and a plain one (the shader encodes). Tolerance: 1 of 255 per channel, for the
//!   float-to-8-bit rounding of the GPU's sRGB encoder and `pow`, which the WGSL spec lets
//!   differ by a few ulp; at least 90 % of the channels must match exactly (lavapipe: 94.4 %).
//! * A film on the device (the GPU tracer's buffer, read in place) and the same film in host
//!   memory (the CPU tracer's, uploaded) give the same bytes.
//! * A film smaller than the window (workload scaling lowered the resolution) is upscaled
//!   by a Catmull-Rom bicubic with clamped edges: every pixel within 1 of 255 of a CPU
//!   bicubic reference (the edge pixels repeat beyond the film, never wrap).
//! * The CPU compose of a host film (what the window shows of the CPU tracer's film) matches
//!   the present pass within 1 of 255.
//! * The egui overlay changes the frame inside the overlay's own rectangle and nowhere else.

use candela::commit::Overlay;
use candela::render::FilmView;
use candela::render::film::{Film, TonemapSettings, linear_to_srgb8};
use candela::render::gpu::GpuContext;
use candela::render::present::{
    CpuOverlay, FrameComposer, HostCompose, PixelLayout, Screenshot, catmull_rom, compose_host_film,
};
use glam::Vec3;
use wgpu::util::DeviceExt;

fn composer(format: wgpu::TextureFormat) -> FrameComposer {
    let context = GpuContext::headless().expect("a GPU adapter (lavapipe without a GPU)");
    FrameComposer::new(context, format).expect("present pipeline")
}

/// A film with a ramp over [−0.2, 2.2] per channel (different per channel) and a few bad
/// values (NaN, infinity, negative).
fn test_film(width: u32, height: u32) -> Film {
    let mut film = Film::new(width, height);
    let n = film.mean.len() as f32;
    for (i, p) in film.mean.iter_mut().enumerate() {
        let t = i as f32 / n;
        *p = Vec3::new(t * 2.4 - 0.2, (1.0 - t) * 1.3, (t * 7.0).fract() * 0.9);
    }
    film.mean[3] = Vec3::new(f32::NAN, 0.5, 0.5);
    film.mean[5] = Vec3::new(f32::INFINITY, -1.0, 0.25);
    film
}

/// Per channel: (largest difference, fraction exactly equal) against the CPU tonemap.
fn compare(shot: &Screenshot, expected: impl Fn(u32, u32) -> [u8; 3]) -> (u8, f64) {
    let (mut worst, mut equal, mut total) = (0u8, 0usize, 0usize);
    for y in 0..shot.height {
        for x in 0..shot.width {
            let got = shot.rgb(x, y).expect("inside");
            let want = expected(x, y);
            for c in 0..3 {
                worst = worst.max(got[c].abs_diff(want[c]));
                equal += (got[c] == want[c]) as usize;
                total += 1;
            }
        }
    }
    (worst, equal as f64 / total as f64)
}

#[test]
fn the_present_pass_tonemaps_like_the_cpu_on_host_and_device_films() {
    let (width, height) = (37, 23);
    let film = test_film(width, height);
    let settings = [
        TonemapSettings::default(),
        TonemapSettings {
            exposure_ev: 1.0,
            filmic: false,
        },
        TonemapSettings {
            exposure_ev: -0.5,
            filmic: true,
        },
    ];
    for format in [
        wgpu::TextureFormat::Rgba8UnormSrgb,
        wgpu::TextureFormat::Bgra8Unorm,
    ] {
        let mut composer = composer(format);
        for tonemap in &settings {
            let shot = composer
                .compose_offscreen(Some(FilmView::Host(&film)), (width, height), tonemap, None)
                .expect("compose");
            assert_eq!((shot.width, shot.height), (width, height));
            let (worst, exact) = compare(&shot, |x, y| {
                linear_to_srgb8(film.mean[(y * width + x) as usize], tonemap)
            });
            assert!(
                worst <= 1 && exact >= 0.9,
                "{format:?} {tonemap:?}: worst {worst}, exact {exact:.3}"
            );
        }
        // The same film in a device buffer (as the GPU tracer keeps it) gives the same bytes.
        let texels: Vec<[f32; 4]> = film.mean.iter().map(|c| [c.x, c.y, c.z, 0.0]).collect();
        let buffer =
            composer
                .context()
                .device
                .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                    label: Some("device film"),
                    contents: bytemuck::cast_slice(&texels),
                    usage: wgpu::BufferUsages::STORAGE,
                });
        let view = FilmView::Device {
            buffer: &buffer,
            width,
            height,
        };
        let tonemap = TonemapSettings::default();
        let device = composer
            .compose_offscreen(Some(view), (width, height), &tonemap, None)
            .expect("compose");
        let host = composer
            .compose_offscreen(Some(FilmView::Host(&film)), (width, height), &tonemap, None)
            .expect("compose");
        assert_eq!(device, host, "{format:?}: device and host films differ");
        // Nothing rendered yet: black.
        let empty = composer
            .compose_offscreen(None, (4, 4), &tonemap, None)
            .expect("compose");
        assert!(empty.rgba.chunks(4).all(|p| p[..3] == [0, 0, 0]));
    }
}

#[test]
fn a_smaller_film_is_upscaled_bicubically_with_clamped_edges() {
    let (fw, fh) = (3u32, 2u32);
    let mut film = Film::new(fw, fh);
    for (i, p) in film.mean.iter_mut().enumerate() {
        *p = Vec3::new(
            0.1 * i as f32,
            0.9 - 0.15 * i as f32,
            if i % 2 == 0 { 0.8 } else { 0.05 },
        );
    }
    let (tw, th) = (12u32, 7u32);
    let texel = |x: i32, y: i32| {
        film.mean
            [(y.clamp(0, fh as i32 - 1) as u32 * fw + x.clamp(0, fw as i32 - 1) as u32) as usize]
    };
    let tonemap = TonemapSettings::default();
    let mut composer = composer(wgpu::TextureFormat::Rgba8UnormSrgb);
    let shot = composer
        .compose_offscreen(Some(FilmView::Host(&film)), (tw, th), &tonemap, None)
        .expect("compose");
    let (worst, _) = compare(&shot, |x, y| {
        let fx = (x as f32 + 0.5) * fw as f32 / tw as f32 - 0.5;
        let fy = (y as f32 + 0.5) * fh as f32 / th as f32 - 0.5;
        let (bx, by) = (fx.floor(), fy.floor());
        let (wx, wy) = (catmull_rom(fx - bx), catmull_rom(fy - by));
        let (bx, by) = (bx as i32, by as i32);
        let mut c = Vec3::ZERO;
        for (j, wj) in wy.iter().enumerate() {
            for (i, wi) in wx.iter().enumerate() {
                c += texel(bx - 1 + i as i32, by - 1 + j as i32) * (wi * wj);
            }
        }
        linear_to_srgb8(c, &tonemap)
    });
    assert!(worst <= 1, "upscaled pixels differ by up to {worst}");
}

#[test]
fn the_cpu_compose_of_a_host_film_matches_the_present_pass() {
    // What the window shows of the CPU tracer's film (composed on the CPU and copied into the
    // surface, `render/present/cpu_compose.rs`) against the present shader's offscreen frame:
    // an upscaled film with bad values, exposure and the filmic curve. Tolerance: 1 of 255,
    // the shader's own rounding (see the first test) plus the CPU's sRGB table (one step).
    let film = test_film(40, 23);
    for filmic in [false, true] {
        let tonemap = TonemapSettings {
            exposure_ev: 0.7,
            filmic,
        };
        let size = (97, 61);
        let mut composer = composer(wgpu::TextureFormat::Rgba8Unorm);
        let shot = composer
            .compose_offscreen(Some(FilmView::Host(&film)), size, &tonemap, None)
            .expect("compose");
        let cpu = compose_host_film(&film, size, &tonemap, false);
        let (worst, _) = compare(&shot, |x, y| {
            let i = ((y * size.0 + x) * 4) as usize;
            [cpu[i], cpu[i + 1], cpu[i + 2]]
        });
        assert!(
            worst <= 1,
            "filmic {filmic}: CPU compose differs by up to {worst}"
        );
    }
}

/// A stats-like egui window, run until its layout settles; the overlay carries every
/// texture change of those passes.
fn overlay(size: (u32, u32)) -> (Overlay, egui::Rect) {
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
        let output = context.run_pass(input, |ctx| {
            egui::Window::new("stats")
                .fixed_pos([10.0, 10.0])
                .show(ctx, |ui| {
                    ui.label("render 12.34 ms");
                    ui.label("rays/s 1.23 M");
                });
        });
        let mut output = output;
        textures.append(std::mem::take(&mut output.textures_delta));
        last = Some(output);
    }
    let output = last.expect("three passes ran");
    let primitives = context.tessellate(output.shapes, output.pixels_per_point);
    let mut bounds = egui::Rect::NOTHING;
    for p in &primitives {
        if let egui::epaint::Primitive::Mesh(mesh) = &p.primitive {
            for v in &mesh.vertices {
                bounds.extend_with(v.pos);
            }
        }
    }
    let overlay = Overlay {
        primitives,
        textures_delta: textures,
        pixels_per_point: output.pixels_per_point,
    };
    (overlay, bounds)
}

#[test]
fn the_overlay_draws_over_the_frame_inside_its_rectangle_only() {
    let size = (240u32, 160u32);
    let mut film = Film::new(size.0, size.1);
    film.mean.fill(Vec3::new(0.2, 0.4, 0.1));
    let tonemap = TonemapSettings::default();
    let mut composer = composer(wgpu::TextureFormat::Bgra8UnormSrgb);
    let (mut overlay, bounds) = overlay(size);
    assert!(
        bounds.width() > 20.0 && bounds.height() > 20.0,
        "{bounds:?}"
    );
    let with = composer
        .compose_offscreen(
            Some(FilmView::Host(&film)),
            size,
            &tonemap,
            Some(&mut overlay),
        )
        .expect("compose with overlay");
    assert!(
        overlay.textures_delta.is_empty(),
        "texture changes were applied"
    );
    let without = composer
        .compose_offscreen(Some(FilmView::Host(&film)), size, &tonemap, None)
        .expect("compose without overlay");
    let (mut inside_changed, mut outside_changed) = (0, 0);
    for y in 0..size.1 {
        for x in 0..size.0 {
            if with.rgb(x, y) != without.rgb(x, y) {
                // Anti-aliased edges may touch the pixel just outside the vertex bounds.
                let p = egui::pos2(x as f32 + 0.5, y as f32 + 0.5);
                if bounds.expand(1.0).contains(p) {
                    inside_changed += 1;
                } else {
                    outside_changed += 1;
                }
            }
        }
    }
    let area = bounds.width() * bounds.height();
    assert!(
        inside_changed as f32 > 0.5 * area,
        "the overlay covers its rectangle ({inside_changed} of {area} pixels changed)"
    );
    assert_eq!(outside_changed, 0, "pixels outside the overlay changed");
}

#[test]
fn the_cpu_overlay_draws_like_the_device_painter() {
    // The overlay rasterised on the CPU (the CPU tracer's present path, gamma-space surface)
    // against egui-wgpu on the device, over the same composed frame. The two sample the font
    // atlas with different bilinear arithmetic and round differently, so single pixels may
    // differ by a few steps on glyph edges; the mean difference over the overlay's pixels
    // must stay below half a step, and no pixel may differ by more than 16 of 255 (a glyph
    // edge pixel taken by one rasteriser and not the other would differ by far more).
    let size = (240u32, 160u32);
    let mut film = Film::new(size.0, size.1);
    film.mean.fill(Vec3::new(0.2, 0.4, 0.1));
    let tonemap = TonemapSettings::default();
    let mut composer = composer(wgpu::TextureFormat::Rgba8Unorm);
    let (mut gpu_overlay, bounds) = overlay(size);
    let cpu_overlay = gpu_overlay.clone();
    let gpu = composer
        .compose_offscreen(
            Some(FilmView::Host(&film)),
            size,
            &tonemap,
            Some(&mut gpu_overlay),
        )
        .expect("compose with overlay");
    let mut painter = CpuOverlay::default();
    painter.apply(&cpu_overlay.textures_delta);
    let mut cpu = compose_host_film(&film, size, &tonemap, false);
    let plain = cpu.clone();
    painter.draw(&mut cpu, size, false, &cpu_overlay);
    let (mut sum, mut count, mut worst, mut changed) = (0u64, 0u64, 0u8, 0usize);
    for y in 0..size.1 {
        for x in 0..size.0 {
            let i = ((y * size.0 + x) * 4) as usize;
            let got = gpu.rgb(x, y).expect("inside");
            if cpu[i..i + 3] != plain[i..i + 3] {
                changed += 1;
            }
            if !bounds
                .expand(1.0)
                .contains(egui::pos2(x as f32 + 0.5, y as f32 + 0.5))
            {
                assert_eq!(
                    &cpu[i..i + 3],
                    &plain[i..i + 3],
                    "CPU overlay outside at ({x}, {y})"
                );
                continue;
            }
            for c in 0..3 {
                let d = got[c].abs_diff(cpu[i + c]);
                worst = worst.max(d);
                sum += d as u64;
                count += 1;
            }
        }
    }
    eprintln!(
        "CPU overlay against the device: mean {} worst {worst}",
        sum as f64 / count as f64
    );
    assert!(
        changed as f32 > 0.5 * bounds.width() * bounds.height(),
        "{changed} pixels drawn"
    );
    let mean = sum as f64 / count as f64;
    assert!(
        mean < 0.5 && worst <= 16,
        "mean difference {mean}, worst {worst}"
    );
}

#[test]
fn the_softbuffer_layout_carries_the_same_colours_under_the_overlay() {
    // The window's softbuffer path composes into `0RGB` words (B, G, R, 0 in a little-endian
    // machine's memory) and draws the overlay over them as over BGRA: every pixel must carry
    // the RGBA path's colours, overlay included, with the fourth byte left 0.
    let size = (203u32, 157u32);
    let film = test_film(64, 48);
    let tonemap = TonemapSettings::default();
    let (overlay, _) = overlay(size);
    let mut painter = CpuOverlay::default();
    painter.apply(&overlay.textures_delta);
    let mut rgba = compose_host_film(&film, size, &tonemap, false);
    let plain = rgba.clone();
    painter.draw(&mut rgba, size, false, &overlay);
    let mut xrgb = vec![0xaau8; (size.0 * size.1 * 4) as usize];
    HostCompose::default().compose_into(&film, size, &tonemap, PixelLayout::Xrgb32, &mut xrgb);
    painter.draw(&mut xrgb, size, true, &overlay);
    let mut drawn = 0;
    for (i, (x, p)) in xrgb.chunks_exact(4).zip(rgba.chunks_exact(4)).enumerate() {
        let word = u32::from_le_bytes([x[0], x[1], x[2], x[3]]);
        let want = ((p[0] as u32) << 16) | ((p[1] as u32) << 8) | p[2] as u32;
        assert_eq!(word, want, "pixel {i}: {word:08x} against RGBA {p:?}");
        drawn += (p != &plain[i * 4..i * 4 + 4]) as usize;
    }
    assert!(drawn > 1000, "the overlay drew {drawn} pixels");
}
