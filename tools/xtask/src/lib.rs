//! The pieces of `cargo xtask` that tests share: the README's render command and the system
//! packages the engine needs. See `main.rs` for the commands themselves.

pub mod packages;

/// Arguments `cargo xtask render` passes to the capture tool (the README's render command).
pub const RENDER_ARGS: &[&str] = &[
    "assets/test_scenes/cornell_box.ron",
    "--tracer",
    "auto",
    "--spp",
    "64",
    "--width",
    "256",
    "--height",
    "256",
    "--out",
    "out/cornell_box.png",
];
