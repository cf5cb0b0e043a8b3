//! The README's render command works with no display and no GPU: `cargo xtask render` runs the
//! capture tool with `xtask::RENDER_ARGS`; this test runs the same arguments through the same
//! library entry point (with the output moved to a temporary folder), with `DISPLAY` and
//! `WAYLAND_DISPLAY` removed, and checks the PNG is a Cornell box: the right size, a red wall on
//! the left, a green wall on the right, the light at the top brighter than everything else.

use clap::Parser;

fn mean_rgb(img: &image::RgbImage, x0: u32, y0: u32, x1: u32, y1: u32) -> [f64; 3] {
    let mut sum = [0.0f64; 3];
    let mut n = 0.0;
    for y in y0..y1 {
        for x in x0..x1 {
            let p = img.get_pixel(x, y);
            for c in 0..3 {
                sum[c] += p[c] as f64;
            }
            n += 1.0;
        }
    }
    sum.map(|s| s / n)
}

#[test]
fn readme_render_command_writes_a_cornell_box_png_headless() {
    // Changes process-wide state: alone in its process under any test runner.
    if !candela_tests::alone::alone_in_process(
        "headless::readme_render_command_writes_a_cornell_box_png_headless",
    ) {
        return;
    }
    // SAFETY: alone in its process (above), so no other thread reads the environment.
    unsafe {
        std::env::remove_var("DISPLAY");
        std::env::remove_var("WAYLAND_DISPLAY");
    }
    let readme =
        std::fs::read_to_string(candela_tests::repo().join("README.md")).expect("README.md");
    assert!(
        readme.contains("cargo xtask render"),
        "the README's render command is `cargo xtask render`"
    );
    let out = std::env::temp_dir().join(format!("candela_headless_{}", std::process::id()));
    let png = out.join("cornell_box.png");
    let mut args: Vec<String> = vec!["capture".into()];
    let mut given = xtask::RENDER_ARGS.iter().map(|s| s.to_string()).peekable();
    while let Some(a) = given.next() {
        if a == "--out" {
            given.next();
            args.push(a);
            args.push(png.display().to_string());
        } else if a.ends_with(".ron") {
            args.push(candela_tests::repo().join(&a).display().to_string());
        } else {
            args.push(a);
        }
    }
    args.push("--quiet".into());
    let report =
        capture::run(&capture::CaptureArgs::parse_from(&args)).expect("capture runs headless");
    eprintln!("{report}");
    // `auto`: the GPU tracer on a real GPU, the CPU tracer when the only adapter is software.
    let expected = match candela::render::gpu::GpuContext::probe() {
        Some(info) if !candela::render::auto::is_software(info.device_type) => "gpu",
        _ => "cpu",
    };
    assert_eq!(
        report.tracer, expected,
        "the README renders with the tracer `auto` picks for this machine"
    );
    let img = image::open(&png).expect("PNG written").to_rgb8();
    assert_eq!(img.dimensions(), (256, 256));
    let left = mean_rgb(&img, 10, 100, 30, 160);
    let right = mean_rgb(&img, 226, 100, 246, 160);
    let light = mean_rgb(&img, 110, 32, 146, 40);
    let floor = mean_rgb(&img, 100, 220, 156, 250);
    assert!(left[0] > 2.0 * left[1], "left wall is red: {left:?}");
    assert!(
        right[1] > 1.3 * right[0] && right[1] > 2.0 * right[2],
        "right wall is green: {right:?}"
    );
    assert!(
        light.iter().all(|&c| c > 250.0),
        "the light is saturated: {light:?}"
    );
    let floor_luma = 0.2126 * floor[0] + 0.7152 * floor[1] + 0.0722 * floor[2];
    assert!(
        floor_luma > 20.0 && floor_luma < 250.0,
        "the floor is lit, not saturated: {floor:?}"
    );
    assert!(
        floor[0] > floor[2],
        "the light is warm (17, 12, 4): {floor:?}"
    );
    let _ = std::fs::remove_dir_all(&out);
}
