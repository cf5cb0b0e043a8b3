//! `cargo xtask`: the two commands of the README, and the machine set-up they need.
//!
//! `cargo xtask play [reflect args…]` plays Reflect in a window, `cargo xtask play its_about_time
//! [args…]` plays It's About Time; `cargo xtask playground [args…]`
//! plays the game platform's test level;
//! `cargo xtask render [capture args…]` renders the Cornell box test scene to `out/cornell_box.png`;
//! `cargo xtask test [nextest args…]` runs every test of the workspace; `cargo xtask fuzz` runs the
//! afl campaigns (`fuzz.rs`). Both first install the
//! system packages the engine needs (Vulkan loader, Mesa's software Vulkan driver lavapipe, X
//! virtual framebuffer for window tests): with apt when running as root, otherwise they print the
//! exact command to run. Uses only `std` so that it builds in seconds on a fresh machine.
//! Must not: contain engine logic; it only prepares the machine and runs cargo.

mod fuzz;

use xtask::{RENDER_ARGS, packages};

use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let Some(command) = args.first() else {
        eprintln!(
            "usage: cargo xtask play [its_about_time] | playground | render [capture args…] | test [nextest args…] | fuzz"
        );
        return ExitCode::from(2);
    };
    let rest = &args[1..];
    let result = match command.as_str() {
        "render" => render(rest),
        "play" => play(rest),
        "playground" => playground(rest),
        "test" => test(rest),
        "packages" => packages::ensure(packages::ALL).map(|_| ()),
        "fuzz" => fuzz::fuzz(rest),
        other => Err(format!(
            "unknown command {other:?}: use `play`, `playground`, `render`, `test` or `fuzz`"
        )),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("xtask: {message}");
            ExitCode::FAILURE
        }
    }
}

/// The workspace root (the folder holding the top-level Cargo.toml).
fn workspace_root() -> PathBuf {
    let manifest_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    manifest_dir
        .ancestors()
        .nth(2)
        .map(Path::to_path_buf)
        .unwrap_or_else(|| manifest_dir.to_path_buf())
}

/// Environment every engine process gets: Vulkan only (no GL probing), a private runtime dir.
fn engine_env(command: &mut Command) {
    if std::env::var_os("WGPU_BACKEND").is_none() {
        command.env("WGPU_BACKEND", "vulkan");
    }
    if std::env::var_os("XDG_RUNTIME_DIR").is_none() {
        let dir = std::env::temp_dir().join(format!("candela-xdg-{}", std::process::id()));
        if std::fs::create_dir_all(&dir).is_ok() {
            #[cfg(unix)]
            {
                use std::os::unix::fs::PermissionsExt;
                let _ = std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(0o700));
            }
            command.env("XDG_RUNTIME_DIR", dir);
        }
    }
}

fn run(mut command: Command) -> Result<(), String> {
    engine_env(&mut command);
    command.current_dir(workspace_root());
    let shown = format!("{command:?}");
    let status = command
        .status()
        .map_err(|e| format!("cannot start {shown}: {e}"))?;
    if status.success() {
        Ok(())
    } else {
        Err(format!("{shown} failed with {status}"))
    }
}

fn cargo() -> Command {
    Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()))
}

/// The games `cargo xtask play` knows; the first is the default.
const GAMES: [&str; 2] = ["reflect", "its_about_time"];

/// Plays a game in a window (title menu, levels, ending): Reflect, or the game named first
/// (`cargo xtask play its_about_time`); the other arguments go to the game's binary.
fn play(extra: &[String]) -> Result<(), String> {
    packages::ensure(packages::RENDER)?;
    let (game, extra) = match extra.first() {
        Some(first) if GAMES.contains(&first.as_str()) => (first.as_str(), &extra[1..]),
        _ => (GAMES[0], extra),
    };
    let mut command = cargo();
    command.args(["run", "--release", "--package", game, "--bin", game, "--"]);
    command.args(extra);
    run(command)
}

/// Plays the game platform's first-person test level in a window; extra arguments go to the
/// playground tool.
fn playground(extra: &[String]) -> Result<(), String> {
    packages::ensure(packages::RENDER)?;
    let mut command = cargo();
    command.args(["run", "--release", "--package", "playground", "--"]);
    command.arg("assets/test_scenes/platform/first_person.ron");
    command.args(extra);
    run(command)
}

fn render(extra: &[String]) -> Result<(), String> {
    packages::ensure(packages::RENDER)?;
    let mut command = cargo();
    command.args(["run", "--release", "--package", "capture", "--"]);
    if extra.is_empty() {
        command.args(RENDER_ARGS);
    } else {
        command.args(extra);
    }
    run(command)
}

fn test(extra: &[String]) -> Result<(), String> {
    packages::ensure(packages::ALL)?;
    let nextest = cargo()
        .args(["nextest", "--version"])
        .output()
        .map(|o| o.status.success())
        .unwrap_or(false);
    let mut command = cargo();
    if nextest {
        command.args([
            "nextest",
            "run",
            "--release",
            "--workspace",
            "--no-fail-fast",
        ]);
    } else {
        eprintln!(
            "xtask: cargo-nextest not found (install: cargo install cargo-nextest --locked); using cargo test"
        );
        command.args(["test", "--release", "--workspace", "--no-fail-fast"]);
    }
    command.args(extra);
    run(command)
}
