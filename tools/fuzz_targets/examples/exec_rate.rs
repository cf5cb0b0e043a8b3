//! Executions per second of each fuzz target, in process: every seed of the target (the
//! corpus test's seeds) and `--mutations N` deterministic mutations of each (default 40), run
//! through `fuzz_targets::run` again and again for at least `--seconds S` (default 1.0) per
//! target. Beside it, for the targets that used to write their input to a file, the same
//! inputs through the old file path: the harness as it was before the loaders took bytes
//! (input written under the scratch folder, then `load_model_file`, `load_animation_file` or
//! `load_level`), so one run on one machine gives the A/B.
//!
//! The table also counts the seeds each path accepts: the two harnesses must agree on them.
//!
//! `cargo run --release -p fuzz_targets --example exec_rate [-- --seconds S --mutations N]`
//! prints a Markdown table. Runs on the main thread. Writes only in the scratch folder.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::PathBuf;
use std::time::{Duration, Instant};

use candela::assets::load_model_file;
use candela::level::load_level;
use candela::sim::animation::load_animation_file;
use fuzz_targets::fixed::{FIXED_OBJ, PLAIN_MTL, TEXTURE_MTL};
use fuzz_targets::{Outcome, Target, mutate::mutate, run, scratch, seeds::seeds};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let value = |flag: &str, default: f64| -> f64 {
        args.iter()
            .position(|a| a == flag)
            .and_then(|i| args.get(i + 1))
            .and_then(|v| v.parse().ok())
            .unwrap_or(default)
    };
    let seconds = Duration::from_secs_f64(value("--seconds", 1.0));
    let mutations = value("--mutations", 40.0) as u64;
    // Panics are counted, not printed (the corpus test reports them).
    std::panic::set_hook(Box::new(|_| {}));
    println!(
        "| target | inputs | from memory (exec/s) | old file path (exec/s) | speed-up | seeds accepted (memory / file) |"
    );
    println!("|---|---:|---:|---:|---:|---:|");
    for target in Target::ALL {
        let inputs = inputs(target, mutations);
        let seeds = seeds(target);
        let accepted_memory = seeds
            .iter()
            .filter(|(_, seed)| matches!(run(target, seed), Outcome::Accepted))
            .count();
        let memory = rate(&inputs, seconds, |input| {
            let _ = run(target, input);
        });
        let old = has_old_file_path(target).then(|| {
            rate(&inputs, seconds, |input| {
                old_file_path(target, input);
            })
        });
        let (old_text, ratio, accepted_file) = match old {
            Some(old) => {
                let accepted = seeds
                    .iter()
                    .filter(|(_, seed)| old_file_path(target, seed))
                    .count();
                (
                    format!("{old:.0}"),
                    format!("{:.1}×", memory / old),
                    accepted.to_string(),
                )
            }
            None => (
                "(in memory already)".to_string(),
                "—".to_string(),
                "—".to_string(),
            ),
        };
        println!(
            "| {} | {} | {memory:.0} | {old_text} | {ratio} | {accepted_memory} / {accepted_file} |",
            target.name(),
            inputs.len()
        );
    }
    let _ = std::panic::take_hook();
}

/// The target's seeds, each followed by `mutations` mutations of it.
fn inputs(target: Target, mutations: u64) -> Vec<Vec<u8>> {
    let mut all = Vec::new();
    for (_, seed) in seeds(target) {
        for n in 1..=mutations {
            all.push(mutate(&seed, n, target.is_text()));
        }
        all.push(seed);
    }
    all
}

/// Executions per second of `body` over `inputs`, in whole passes for at least `at_least`.
fn rate(inputs: &[Vec<u8>], at_least: Duration, mut body: impl FnMut(&[u8])) -> f64 {
    let start = Instant::now();
    let mut runs = 0_u64;
    while start.elapsed() < at_least || runs == 0 {
        for input in inputs {
            let _ = catch_unwind(AssertUnwindSafe(|| body(input)));
            runs += 1;
        }
    }
    runs as f64 / start.elapsed().as_secs_f64()
}

fn has_old_file_path(target: Target) -> bool {
    matches!(
        target,
        Target::Level
            | Target::Gltf
            | Target::Glb
            | Target::Animation
            | Target::Obj
            | Target::Mtl
            | Target::Texture
    )
}

/// Writes `bytes` to `name` in the scratch asset root (what every execution did before).
fn write(name: &str, bytes: &[u8]) -> PathBuf {
    let path = scratch::root().join(name);
    if let Err(e) = std::fs::write(&path, bytes) {
        panic!("cannot write {}: {e}", path.display());
    }
    path
}

/// The old harness of `target`: the input and its fixed companions written to files, then the
/// file-based loader (the model check after a load is left out: it is the same either way).
/// Whether the loader accepted the input.
fn old_file_path(target: Target, bytes: &[u8]) -> bool {
    let model = |path: PathBuf| load_model_file(&path).is_ok();
    match target {
        Target::Level => {
            load_level(&write("fuzz_level.ron", bytes), &scratch::asset_root()).is_ok()
        }
        Target::Gltf => model(write("fuzz.gltf", bytes)),
        Target::Glb => model(write("fuzz.glb", bytes)),
        Target::Animation => {
            let name = if bytes.starts_with(b"glTF") {
                "fuzz_anim.glb"
            } else {
                "fuzz_anim.gltf"
            };
            load_animation_file(&write(name, bytes)).is_ok()
        }
        Target::Obj => {
            write("fuzz.mtl", PLAIN_MTL);
            model(write("fuzz.obj", bytes))
        }
        Target::Mtl => {
            write("fuzz.mtl", bytes);
            model(write("fuzz.obj", FIXED_OBJ))
        }
        Target::Texture => {
            write("fuzz_texture", bytes);
            write("fuzz.mtl", TEXTURE_MTL);
            model(write("fuzz.obj", FIXED_OBJ))
        }
        _ => false,
    }
}
