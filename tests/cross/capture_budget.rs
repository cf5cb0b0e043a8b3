//! `capture --seconds S`: a capture that stops at a render-time budget instead of a sample
//! count (issue 13: equal-time comparisons), on the CPU tracer.

use clap::Parser;

fn args(extra: &[&str], png: &std::path::Path) -> capture::CaptureArgs {
    let level = candela_tests::repo().join("assets/test_scenes/cornell_box.ron");
    let mut a: Vec<String> = vec!["capture".into(), level.display().to_string()];
    a.extend(
        [
            "--tracer", "cpu", "--width", "64", "--height", "64", "--batch", "2", "--quiet",
        ]
        .map(String::from),
    );
    a.extend(extra.iter().map(|s| s.to_string()));
    a.push("--out".into());
    a.push(png.display().to_string());
    capture::CaptureArgs::parse_from(&a)
}

#[test]
fn capture_stops_at_the_time_budget_and_spp_still_caps_it() {
    let dir = std::env::temp_dir().join(format!("candela_budget_{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let png = dir.join("budget.png");

    let budget = 0.3;
    let report = capture::run(&args(&["--seconds", "0.3"], &png)).expect("budget capture");
    eprintln!("{report}");
    assert!(
        report.render_seconds >= budget,
        "stopped before the budget: {} s",
        report.render_seconds
    );
    // The upper bound, from the run's own figures (no wall-clock limit): the budget is checked
    // before each batch, so the run ends with the first batch that finishes past it, and
    // without its last batch it was under the budget. A run that overshoots by even one more
    // batch (a budget read in the wrong unit, a check after the loop) fails.
    assert!(
        report.render_seconds - report.slowest_batch_seconds < budget,
        "ran past the budget by more than one batch: {} s in all, slowest batch {} s",
        report.render_seconds,
        report.slowest_batch_seconds
    );
    assert!(
        report.spp >= 2 && report.spp % 2 == 0,
        "whole batches: {}",
        report.spp
    );
    assert_eq!(
        report.samples,
        report.spp as u64 * 64 * 64,
        "the report counts what was rendered"
    );
    let img = image::open(&png).expect("PNG written").to_rgb8();
    assert_eq!(img.dimensions(), (64, 64));

    // A sample cap still holds under a budget that would allow far more.
    let capped = capture::run(&args(&["--seconds", "1000", "--spp", "4"], &png)).expect("capped");
    assert_eq!(capped.spp, 4, "--spp caps a --seconds capture");

    for bad in ["0", "-1", "NaN", "inf"] {
        let flag = format!("--seconds={bad}");
        let err = capture::run(&args(&[flag.as_str()], &png)).expect_err(bad);
        assert!(
            format!("{err:#}").contains("--seconds"),
            "{bad}: the error names the flag: {err:#}"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}
