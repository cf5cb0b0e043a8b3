//! Without a display the view tool fails at once with a message that says so and points to
//! headless rendering (the capture tool) and to Xvfb, before any window or device is touched.

use std::sync::Arc;
use std::sync::atomic::AtomicBool;

use clap::Parser;

#[test]
fn no_display_is_a_clear_error() {
    // SAFETY: this test binary holds only this test; no other thread reads the environment.
    unsafe {
        std::env::remove_var("DISPLAY");
        std::env::remove_var("WAYLAND_DISPLAY");
    }
    let level = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../assets/test_scenes/cornell_box.ron"
    );
    let args = view::ViewArgs::parse_from(["view", level, "--frames", "1"]);
    let started = std::time::Instant::now();
    let error = view::run(&args, Arc::new(AtomicBool::new(false)))
        .expect_err("no window without a display");
    let message = format!("{error:#}");
    assert!(message.contains("no display"), "{message}");
    assert!(message.contains("DISPLAY is not set"), "{message}");
    assert!(
        message.contains("capture") && message.contains("Xvfb"),
        "{message}"
    );
    assert!(started.elapsed().as_secs() < 30, "it failed fast");
}
