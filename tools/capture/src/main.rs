//! `capture <level> --tracer gpu|cpu --spp N --width W --height H --out frame.png
//! [--exr frame.exr] [--seed S] [--denoise] [--seconds S]` (with `--seconds`, stop at a render-time
//! budget instead of a sample count): renders a level headless and prints time,
//! samples per second and rays per second. `capture --script file.ron [--out-dir DIR]` runs a capture script
//! (frames, camera, motions, light switches, screenshots) and prints the time per frame split
//! into update, upkeep and render, and the commit bytes. See `capture::CaptureArgs`.

use clap::Parser;

fn main() -> std::process::ExitCode {
    env_logger::Builder::from_env(env_logger::Env::default().default_filter_or("warn")).init();
    let args = capture::CaptureArgs::parse();
    let outcome = if args.script.is_some() {
        capture::run_script_mode(&args).map(|s| s.to_string())
    } else {
        capture::run(&args).map(|r| r.to_string())
    };
    match outcome {
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
