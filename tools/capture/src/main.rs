//! `capture <level> --tracer gpu|cpu --spp N --width W --height H --out frame.png
//! [--exr frame.exr] [--seed S]`: renders a level headless and prints time, samples per second
//! and rays per second. See `capture::CaptureArgs` for every option.

use clap::Parser;

fn main() -> std::process::ExitCode {
    env_logger::Builder::from_env(env_logger::Env::default().default_filter_or("warn")).init();
    let args = capture::CaptureArgs::parse();
    match capture::run(&args) {
        Ok(report) => {
            println!("{report}");
            std::process::ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("capture: {e:#}");
            std::process::ExitCode::FAILURE
        }
    }
}
