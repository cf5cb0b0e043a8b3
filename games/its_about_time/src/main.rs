//! `its_about_time`: play It's About Time in a window, or `its_about_time --replay FILE
//! --headless` to replay a recording and print one summary line (see `its_about_time::cli`).

use clap::Parser;

fn main() -> std::process::ExitCode {
    env_logger::Builder::from_env(env_logger::Env::default().default_filter_or("warn")).init();
    match its_about_time::cli::run(&its_about_time::cli::Args::parse()) {
        Ok(line) => {
            println!("{line}");
            std::process::ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("its_about_time: {e:#}");
            std::process::ExitCode::FAILURE
        }
    }
}
