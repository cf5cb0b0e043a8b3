//! The `view` tool in a real window under Xvfb (lavapipe presents; no GPU needed). One window
//! run per process: winit allows one event loop per process, so the test runs alone in its process
//! under any runner (`candela_tests::alone`).
//!
//! It starts `Xvfb :N -screen 0 1280x720x24 -nolisten tcp` on a free display, runs the view
//! tool's library entry on the Cornell box (CPU tracer, 4 frames of 4 spp, 160×120, no overlay)
//! with `--frames 4 --screenshot`, keeps the last frame on screen (`--hold`), grabs the X root
//! window with `xwd -root | /usr/bin/convert`, then sends itself SIGINT — the view tool's Ctrl-C
//! handler sets its stop flag — and checks:
//!
//! * (a) the window opened at the asked size, 4 frames ran, Ctrl-C ended the run (the render
//!   thread joined, the loop returned well before the 60 s hold), and the screenshot is 160×120;
//! * (b) the screenshot matches a headless capture of the same frame (same level, camera, seed,
//!   and the same 16 samples per pixel: frame k traces samples 4k..4k+3 and converges with
//!   weight 1/(k+1), as `capture --spp 16 --batch 4` does). Compared in linear space, per
//!   channel, over a 4×4 grid of regions: |window − capture| ≤ 4.5 σ + q, where σ is the
//!   standard error of the difference of two independent 16-spp region means (from 8
//!   independent 16-spp batches: per-pixel variance, summed over the region; clamping to the
//!   displayable range only shrinks it) and q the 8-bit quantisation: per pixel, half the
//!   linear width of ±1 sRGB step around each PNG value (the GPU's sRGB encoder and the CPU's
//!   may round differently), averaged over the region, for both images. The two renders share
//!   their samples, so in practice they agree far inside this; the test also checks the bound
//!   has power: a black or blank window fails many of these checks;
//! * (c) the root window, cropped at the window's position, shows the same picture (equal
//!   bytes; 24-bit Xvfb keeps 8 bits per channel). Presentation is asynchronous, so three
//!   grabs over 1.5 s are taken and one must match.

use std::process::{Command, Stdio};
use std::sync::atomic::Ordering;
use std::time::{Duration, Instant};

use candela::app::WindowEnd;
use candela::assets::{AssetRoot, load_scene};
use candela_tests::xvfb::{set_environment, start_xvfb};
use candela_tests::{Which, region_stat, render_batches, repo};
use clap::Parser;

const WIDTH: u32 = 160;
const HEIGHT: u32 = 120;

/// The X root window as an RGB image (`xwd -root` through ImageMagick's real `convert`).
fn grab_root(display: &str) -> image::RgbImage {
    let xwd = Command::new("xwd")
        .args(["-root", "-silent", "-display", display])
        .output()
        .expect("xwd runs (Debian package x11-apps; `cargo xtask test` installs it)");
    assert!(xwd.status.success(), "xwd failed: {:?}", xwd.status);
    let mut convert = Command::new("/usr/bin/convert")
        .args(["xwd:-", "png:-"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .expect("/usr/bin/convert runs (Debian package imagemagick)");
    let mut stdin = convert.stdin.take().expect("stdin");
    let writer = std::thread::spawn(move || {
        use std::io::Write;
        stdin.write_all(&xwd.stdout)
    });
    let png = convert.wait_with_output().expect("convert finishes");
    writer.join().expect("writer").expect("xwd data written");
    assert!(png.status.success(), "convert failed: {:?}", png.status);
    image::load_from_memory(&png.stdout)
        .expect("convert wrote a PNG")
        .to_rgb8()
}

fn srgb_to_linear(s: u8) -> f64 {
    let c = s as f64 / 255.0;
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// Half the linear width of ±1 sRGB step around `s`.
fn quantisation(s: u8) -> f64 {
    (srgb_to_linear(s.saturating_add(1)) - srgb_to_linear(s.saturating_sub(1))) / 2.0
}

#[test]
fn view_shows_the_headless_frame_in_an_xvfb_window() {
    // Changes process-wide state: alone in its process under any test runner.
    if !candela_tests::alone::alone_in_process(
        "window::view_shows_the_headless_frame_in_an_xvfb_window",
    ) {
        return;
    }
    let started = Instant::now();
    let scratch = std::env::temp_dir().join(format!("candela_window_{}", std::process::id()));
    std::fs::create_dir_all(&scratch).expect("scratch folder");
    let xvfb = start_xvfb();
    set_environment(&xvfb.display, &scratch);
    let level = repo().join("assets/test_scenes/cornell_box.ron");
    let shot_path = scratch.join("window.png");
    let size = [WIDTH.to_string(), HEIGHT.to_string()];
    let args = view::ViewArgs::parse_from([
        "view",
        &level.display().to_string(),
        "--tracer",
        "cpu",
        "--spp",
        "4",
        "--frames",
        "4",
        "--width",
        &size[0],
        "--height",
        &size[1],
        "--seed",
        "0",
        "--no-stats",
        "--hold",
        "60",
        "--screenshot",
        &shot_path.display().to_string(),
    ]);
    let stop = view::stop_on_ctrl_c().expect("Ctrl-C handler");
    let run = {
        let stop = std::sync::Arc::clone(&stop);
        std::thread::spawn(move || view::run(&args, stop))
    };
    // The screenshot appears once the last frame was presented and read back.
    while !shot_path.exists() {
        if run.is_finished() {
            let outcome = run.join().expect("the view thread did not panic");
            panic!("view ended before its screenshot: {outcome:?}");
        }
        assert!(
            started.elapsed() < Duration::from_secs(90),
            "no screenshot after 90 s"
        );
        std::thread::sleep(Duration::from_millis(20));
    }
    let mut roots = Vec::new();
    for wait_ms in [200, 400, 900] {
        std::thread::sleep(Duration::from_millis(wait_ms));
        roots.push(grab_root(&xvfb.display));
    }
    // Ctrl-C, as a person would press it in the terminal.
    let interrupted = Instant::now();
    let kill = Command::new("kill")
        .args(["-INT", &std::process::id().to_string()])
        .status()
        .expect("kill runs");
    assert!(kill.success());
    let report = run
        .join()
        .expect("the view thread did not panic")
        .expect("view runs in the Xvfb window");
    eprintln!("{}", view::describe(&report));

    // (a) The window, the frames, the screenshot's size.
    assert_eq!(report.ended_by, WindowEnd::Stopped, "Ctrl-C ends the hold");
    assert!(stop.load(Ordering::Relaxed));
    assert!(
        interrupted.elapsed() < Duration::from_secs(10),
        "the run took {:?} to end after Ctrl-C",
        interrupted.elapsed()
    );
    assert_eq!(report.frames, 4);
    assert_eq!(report.inner_size, (WIDTH, HEIGHT));
    assert_eq!(report.screenshot.as_deref(), Some(shot_path.as_path()));
    let window = image::open(&shot_path).expect("screenshot PNG").to_rgb8();
    assert_eq!(window.dimensions(), (WIDTH, HEIGHT));

    // (b) The same frame rendered headless.
    let capture_png = scratch.join("capture.png");
    capture::run(&capture::CaptureArgs::parse_from([
        "capture",
        &level.display().to_string(),
        "--tracer",
        "cpu",
        "--spp",
        "16",
        "--batch",
        "4",
        "--width",
        &size[0],
        "--height",
        &size[1],
        "--seed",
        "0",
        "--quiet",
        "--out",
        &capture_png.display().to_string(),
    ]))
    .expect("headless capture");
    let capture = image::open(&capture_png).expect("capture PNG").to_rgb8();
    let root = AssetRoot::new(repo().join("assets/test_scenes")).expect("asset root");
    let desc = load_scene(&level, &root).expect("level loads");
    let batches = 8;
    let spread = render_batches(Which::Cpu, &desc, WIDTH, HEIGHT, 16, batches, 7).expect("batches");
    // Variance of one 16-spp estimate per pixel (the batches' spread, not their mean's).
    let var_single: Vec<[f64; 3]> = spread
        .variance_of_mean()
        .into_iter()
        .map(|v| v.map(|x| x * batches as f64))
        .collect();
    let linear = |img: &image::RgbImage| -> Vec<glam::Vec3> {
        img.pixels()
            .map(|p| {
                glam::Vec3::new(
                    srgb_to_linear(p[0]) as f32,
                    srgb_to_linear(p[1]) as f32,
                    srgb_to_linear(p[2]) as f32,
                )
            })
            .collect()
    };
    let (window_linear, capture_linear) = (linear(&window), linear(&capture));
    let (cell_w, cell_h) = (WIDTH / 4, HEIGHT / 4);
    let (mut checks, mut powerful, mut worst) = (0, 0, 0.0f64);
    let mut failures = Vec::new();
    for ry in 0..4 {
        for rx in 0..4 {
            let keep = |x: u32, y: u32| x / cell_w == rx && y / cell_h == ry;
            let zero = vec![[0.0f64; 3]; window_linear.len()];
            let w = region_stat(WIDTH, &window_linear, &zero, keep);
            let c = region_stat(WIDTH, &capture_linear, &zero, keep);
            let noise = region_stat(WIDTH, &capture_linear, &var_single, keep);
            for ch in 0..3 {
                let mut q = 0.0;
                let mut n = 0.0;
                for y in 0..HEIGHT {
                    for x in 0..WIDTH {
                        if keep(x, y) {
                            q += quantisation(window.get_pixel(x, y)[ch])
                                + quantisation(capture.get_pixel(x, y)[ch]);
                            n += 1.0;
                        }
                    }
                }
                let sigma = std::f64::consts::SQRT_2 * noise.std_error[ch];
                let tolerance = 4.5 * sigma + q / n;
                let difference = (w.mean[ch] - c.mean[ch]).abs();
                worst = worst.max(difference / tolerance);
                checks += 1;
                powerful += (c.mean[ch] > tolerance) as u32;
                if difference > tolerance {
                    failures.push(format!(
                        "region ({rx},{ry}) channel {ch}: window {:.5}, capture {:.5}, \
                         tolerance {tolerance:.5} (σ {sigma:.5}, q {:.5})",
                        w.mean[ch],
                        c.mean[ch],
                        q / n
                    ));
                }
            }
        }
    }
    assert!(
        failures.is_empty(),
        "the window's frame differs from the headless capture (images in {}):\n{}",
        scratch.display(),
        failures.join("\n")
    );
    assert!(
        powerful >= 16,
        "only {powerful} of {checks} checks could tell a black window from this frame"
    );
    eprintln!(
        "window vs capture: {checks} checks, worst |difference| / tolerance = {worst:.3}; \
         a black window would fail {powerful} of them"
    );

    // (c) The X server shows the same picture where the window is.
    let (x0, y0) = report
        .inner_position
        .expect("X11 reports the window's position");
    let (x0, y0) = (x0.max(0) as u32, y0.max(0) as u32);
    let matches = roots
        .iter()
        .map(|root| {
            let mut worst = 0u8;
            for y in 0..HEIGHT {
                for x in 0..WIDTH {
                    let a = window.get_pixel(x, y);
                    let b = root.get_pixel(x0 + x, y0 + y);
                    for c in 0..3 {
                        worst = worst.max(a[c].abs_diff(b[c]));
                    }
                }
            }
            worst
        })
        .collect::<Vec<u8>>();
    if !matches.contains(&0) {
        for (i, root) in roots.iter().enumerate() {
            let _ = root.save(scratch.join(format!("root-{i}.png")));
        }
        panic!(
            "the root window at ({x0}, {y0}) does not show the screenshot (largest channel \
             differences per grab: {matches:?}; images in {})",
            scratch.display()
        );
    }
    drop(xvfb);
    let _ = std::fs::remove_dir_all(&scratch);
    eprintln!("window test took {:.1} s", started.elapsed().as_secs_f64());
}
