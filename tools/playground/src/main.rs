//! `playground LEVEL [--replay FILE] [--headless] [--steps N] [--bench]`: plays a level in first
//! person (see `playground::Args`). Headless, prints one summary line and exits non-zero when
//! a replay does not finish or fails.

use clap::Parser;

fn main() -> std::process::ExitCode {
    env_logger::Builder::from_env(env_logger::Env::default().default_filter_or("warn")).init();
    match playground::run(&playground::Args::parse()) {
        Ok(line) => {
            println!("{line}");
            std::process::ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("playground: {e:#}");
            std::process::ExitCode::FAILURE
        }
    }
}
