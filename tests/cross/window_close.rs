//! The demo level in a real window under Xvfb, closed the way a player closes it: the window
//! manager's close request (`WM_DELETE_WINDOW`). One window run per process (winit allows one
//! event loop per process), so the test runs alone in its process
//! under any runner (`candela_tests::alone`).
//!
//! It runs the view tool's library entry on the demo city (≥ 200k static triangles, 100+ movers,
//! the waving pool; CPU tracer, 96 × 54, 1 spp) for 3 frames with `--hold 60`, waits for the
//! screenshot, asks the window to close and checks: the run ended because the window was
//! closed (not by the frame count, not by Ctrl-C, not by the 60 s hold), it ended within
//! [`CLOSE_LIMIT`] (20 s) of the first request (asked again every 0.5 s; the render thread
//! joined: no deadlock), 3 frames ran, and the screenshot shows the city (not a blank window:
//! many distinct colours and pixels off black). The limit is a deadlock bound, not a speed
//! check: a clean close takes well under a second; 20 s leaves room for a loaded machine.

use std::collections::HashSet;
use std::sync::Arc;
use std::sync::atomic::AtomicBool;
use std::time::{Duration, Instant};

use candela::app::WindowEnd;
use candela_tests::repo;
use candela_tests::xvfb::{close_windows, set_environment, start_xvfb};
use clap::Parser;

/// How long after the first close request the run must have ended (documented above).
const CLOSE_LIMIT: Duration = Duration::from_secs(20);

#[test]
fn the_demo_runs_in_a_window_and_closing_the_window_ends_it_cleanly() {
    // Changes process-wide state: alone in its process under any test runner.
    if !candela_tests::alone::alone_in_process(
        "window_close::the_demo_runs_in_a_window_and_closing_the_window_ends_it_cleanly",
    ) {
        return;
    }
    let scratch = std::env::temp_dir().join(format!("candela_close_{}", std::process::id()));
    std::fs::create_dir_all(&scratch).expect("scratch folder");
    let xvfb = start_xvfb();
    set_environment(&xvfb.display, &scratch);
    let level = repo().join("assets/test_scenes/demo/demo.ron");
    let shot_path = scratch.join("demo.png");
    let args = view::ViewArgs::parse_from([
        "view",
        &level.display().to_string(),
        "--tracer",
        "cpu",
        "--spp",
        "1",
        "--frames",
        "3",
        "--width",
        "96",
        "--height",
        "54",
        "--hold",
        "60",
        "--screenshot",
        &shot_path.display().to_string(),
    ]);
    let stop = Arc::new(AtomicBool::new(false));
    let started = Instant::now();
    let run = std::thread::spawn(move || view::run(&args, stop));
    while !shot_path.exists() {
        if run.is_finished() {
            let outcome = run.join().expect("the view thread did not panic");
            panic!("view ended before its screenshot: {outcome:?}");
        }
        assert!(
            started.elapsed() < Duration::from_secs(240),
            "no screenshot after 240 s"
        );
        std::thread::sleep(Duration::from_millis(50));
    }
    std::thread::sleep(Duration::from_millis(300));
    // Ask as a player would, again every half second until the run ends (a request that lands
    // while the window is still being set up can be dropped by the X server's client).
    let asked = Instant::now();
    let mut requests = 0;
    while !run.is_finished() && asked.elapsed() < CLOSE_LIMIT {
        let windows = close_windows(&xvfb.display).expect("X connection");
        assert!(windows >= 1, "no top-level window on {}", xvfb.display);
        requests += 1;
        std::thread::sleep(Duration::from_millis(500));
    }
    eprintln!("{requests} close request(s)");
    // Judge before joining: a run that ignores the request must fail here, not hang the test
    // in `join` (or end later by its hold and be judged by that).
    let closing = asked.elapsed();
    assert!(
        run.is_finished(),
        "still running {closing:?} after the first close request (limit {CLOSE_LIMIT:?})"
    );
    let report = run
        .join()
        .expect("the view thread did not panic")
        .expect("view runs the demo in the Xvfb window");
    eprintln!(
        "{}\nclosed within {closing:?} of the request",
        view::describe(&report)
    );
    assert_eq!(
        report.ended_by,
        WindowEnd::Closed,
        "the close request ends the run"
    );
    assert_eq!(report.frames, 3);
    let shot = image::open(&shot_path).expect("screenshot PNG").to_rgb8();
    assert_eq!(shot.dimensions(), (96, 54));
    let colours: HashSet<[u8; 3]> = shot.pixels().map(|p| p.0).collect();
    let lit = shot.pixels().filter(|p| p.0.iter().any(|&c| c > 8)).count();
    assert!(
        colours.len() > 50 && lit > 96 * 54 / 2,
        "the window shows no city: {} colours, {lit} lit pixels",
        colours.len()
    );
}
