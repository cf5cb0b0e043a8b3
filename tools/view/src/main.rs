//! `view <level> [--tracer gpu|cpu] [--spp N] [--width W --height H] [--frames N --screenshot
//! out.png]`: opens a level in a window with a fly camera and the stats overlay. Ctrl-C, closing
//! the window or the end of `--frames` leave cleanly. See `view::ViewArgs` for every option.

use std::sync::Arc;
use std::sync::atomic::AtomicBool;

use clap::Parser;

fn main() -> std::process::ExitCode {
    env_logger::Builder::from_env(env_logger::Env::default().default_filter_or("warn")).init();
    let args = view::ViewArgs::parse();
    let stop = view::stop_on_ctrl_c().unwrap_or_else(|e| {
        eprintln!("view: {e:#}; Ctrl-C will not stop cleanly");
        Arc::new(AtomicBool::new(false))
    });
    match view::run(&args, stop) {
        Ok(report) => {
            println!("{}", view::describe(&report));
            std::process::ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("view: {e:#}");
            std::process::ExitCode::FAILURE
        }
    }
}
