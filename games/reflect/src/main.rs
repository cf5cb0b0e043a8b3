//! `reflect`: play Reflect in a window, or `reflect --replay FILE --headless` to replay a
//! recording and print one summary line (see `reflect::cli::Args`).

use clap::Parser;

fn main() -> std::process::ExitCode {
    env_logger::Builder::from_env(env_logger::Env::default().default_filter_or("warn")).init();
    match reflect::cli::run(&reflect::cli::Args::parse()) {
        Ok(line) => {
            println!("{line}");
            std::process::ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("reflect: {e:#}");
            std::process::ExitCode::FAILURE
        }
    }
}
