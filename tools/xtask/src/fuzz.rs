//! `cargo xtask fuzz [--target NAME] [--seconds N] [--build]`: the coverage-guided campaigns.
//! Installs cargo-afl (AFL++ for Rust, works on the stable toolchain) when missing, builds `fuzz/`
//! with afl's instrumentation kept only for the crates under test (`fuzz/rustc_wrapper.sh` as
//! `RUSTC_WRAPPER`; `--build` stops there and prints the build time), starts each target from its
//! seeds (`candela_fuzz --write-seeds`) and its committed corpus (`fuzz/corpus/<target>/`), or
//! resumes it where `fuzz/out/<target>/` holds an earlier campaign, for N seconds (default 60), then
//! prints what afl's `fuzzer_stats` say, appends them to `fuzz/campaigns.csv` and
//! copies each crash input into `fuzz/crashes/<target>/`, where the corpus test replays it.
//! Campaign output stays in `fuzz/out/` (ignored by git). Uses only `std`.

use std::path::Path;
use std::process::Command;

use crate::{cargo, run, workspace_root};

/// Every fuzz target's name (the `fuzz_targets::Target` names; xtask does not link the engine).
const TARGETS: &[&str] = &[
    "level",
    "script",
    "replay",
    "settings",
    "save",
    "bindings",
    "gltf",
    "glb",
    "animation",
    "obj",
    "mtl",
    "texture",
    "sound",
    "asset_path",
];

pub fn fuzz(args: &[String]) -> Result<(), String> {
    let mut targets: Vec<String> = Vec::new();
    let mut seconds = 60_u64;
    let mut build_only = false;
    let mut it = args.iter();
    while let Some(arg) = it.next() {
        match arg.as_str() {
            "--target" => targets.push(it.next().ok_or("--target needs a name")?.clone()),
            "--build" => build_only = true,
            "--seconds" => {
                let value = it.next().ok_or("--seconds needs a number")?;
                seconds = value
                    .parse()
                    .map_err(|_| format!("--seconds {value:?} is not a whole number"))?;
            }
            other => return Err(format!("unknown fuzz argument {other:?}")),
        }
    }
    if targets.is_empty() {
        targets = TARGETS.iter().map(|t| t.to_string()).collect();
    }
    if let Some(bad) = targets.iter().find(|t| !TARGETS.contains(&t.as_str())) {
        return Err(format!("unknown target {bad:?}; targets: {TARGETS:?}"));
    }
    ensure_cargo_afl()?;
    let root = workspace_root();
    let fuzz_dir = root.join("fuzz");
    let started = std::time::Instant::now();
    build(&fuzz_dir)?;
    eprintln!(
        "xtask: afl build took {:.0} s",
        started.elapsed().as_secs_f64()
    );
    if build_only {
        return Ok(());
    }
    let binary = fuzz_dir.join("target/release/candela_fuzz");
    for target in &targets {
        campaign(&fuzz_dir, &binary, target, seconds)?;
    }
    Ok(())
}

fn ensure_cargo_afl() -> Result<(), String> {
    let present = cargo()
        .args(["afl", "--version"])
        .output()
        .map(|o| o.status.success())
        .unwrap_or(false);
    if !present {
        eprintln!("xtask: installing cargo-afl (cargo install cargo-afl --locked)");
        let mut install = cargo();
        install.args(["install", "cargo-afl", "--locked"]);
        run(install)?;
    }
    Ok(())
}

/// `cargo afl build --release` of `fuzz/`, through `fuzz/rustc_wrapper.sh`, which keeps afl's
/// coverage instrumentation only for the crates under test.
fn build(fuzz_dir: &Path) -> Result<(), String> {
    let wrapper = fuzz_dir.join("rustc_wrapper.sh");
    let script =
        std::fs::read(&wrapper).map_err(|e| format!("cannot read {}: {e}", wrapper.display()))?;
    // Cargo does not fingerprint RUSTC_WRAPPER: a cfg carrying the script's hash makes a changed
    // list of instrumented crates rebuild (cargo-afl appends the caller's RUSTFLAGS to its own).
    let mut rustflags = format!("--cfg candela_afl_wrapper=\"{:016x}\"", fnv1a(&script));
    if let Ok(user) = std::env::var("RUSTFLAGS") {
        rustflags = format!("{rustflags} {user}");
    }
    let attempt = || {
        let mut build = cargo();
        build
            .args(["afl", "build", "--release", "--manifest-path"])
            .arg(fuzz_dir.join("Cargo.toml"))
            .env("RUSTC_WRAPPER", &wrapper)
            .env("RUSTFLAGS", &rustflags);
        run(build)
    };
    if attempt().is_ok() {
        return Ok(());
    }
    // A fresh cargo-afl has not built AFL++ and its LLVM runtime yet.
    eprintln!("xtask: building AFL++ for cargo-afl (cargo afl config --build)");
    let mut config = cargo();
    config.args(["afl", "config", "--build"]);
    run(config)?;
    attempt()
}

/// 64-bit FNV-1a: a stable hash of the wrapper script (std's hasher may change between releases).
fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |hash, &b| {
        (hash ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}

/// One campaign slice: a fresh start from the seeds and the committed corpus, or a resumption of
/// `fuzz/out/<target>/` (afl's `AFL_AUTORESUME`: the queue, the crashes and the counters carry
/// over, so `execs_done` and `run_time` in its stats are totals over every slice).
fn campaign(fuzz_dir: &Path, binary: &Path, target: &str, seconds: u64) -> Result<(), String> {
    let seeds = fuzz_dir.join("out").join(target).join("seeds");
    let out = fuzz_dir.join("out").join(target).join("afl");
    let _ = std::fs::remove_dir_all(&seeds);
    let mut write = Command::new(binary);
    write.arg("--write-seeds").arg(target).arg(&seeds);
    run(write)?;
    copy_corpus(&fuzz_dir.join("corpus").join(target), &seeds)?;
    let mut afl = cargo();
    afl.args(["afl", "fuzz", "-i"])
        .arg(&seeds)
        .arg("-o")
        .arg(&out)
        .args(["-V", &seconds.to_string(), "--"])
        .arg(binary)
        .env("CANDELA_FUZZ_TARGET", target)
        .env("AFL_NO_UI", "1")
        .env("AFL_SKIP_CPUFREQ", "1")
        // The machine is shared: let the scheduler move afl to whichever core is idle.
        .env("AFL_NO_AFFINITY", "1")
        .env("AFL_I_DONT_CARE_ABOUT_MISSING_CRASHES", "1")
        .env("AFL_AUTORESUME", "1");
    run(afl)?;
    let stats = std::fs::read_to_string(out.join("default/fuzzer_stats"))
        .map_err(|e| format!("afl wrote no fuzzer_stats for {target}: {e}"))?;
    let field = |name: &str| {
        stats
            .lines()
            .find_map(|l| {
                let (k, v) = l.split_once(':')?;
                (k.trim() == name).then(|| v.trim().to_string())
            })
            .unwrap_or_else(|| "?".into())
    };
    let record = [
        target.to_string(),
        seconds.to_string(),
        field("run_time"),
        field("execs_done"),
        field("execs_per_sec"),
        field("edges_found"),
        field("total_edges"),
        field("bitmap_cvg"),
        field("corpus_count"),
        field("saved_crashes"),
    ];
    println!(
        "fuzz {target}: {} executions in {} s over every slice ({} exec/s), {} of {} edges ({}), \
         corpus {}, {} crashes",
        record[3], record[2], record[4], record[5], record[6], record[7], record[8], record[9]
    );
    append_record(fuzz_dir, &record)?;
    keep_crashes(fuzz_dir, &out.join("default/crashes"), target)
}

/// Copies the committed corpus `fuzz/corpus/<target>/` (the hand-made inputs and, in `afl/`, the
/// campaigns' minimised corpus) beside the seeds (afl's `-i`).
fn copy_corpus(corpus: &Path, seeds: &Path) -> Result<(), String> {
    let mut folders = vec![corpus.to_path_buf()];
    let mut n = 0_usize;
    while let Some(folder) = folders.pop() {
        let Ok(entries) = std::fs::read_dir(&folder) else {
            continue;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            if path.is_dir() {
                folders.push(path);
                continue;
            }
            n += 1;
            let to = seeds.join(format!("corpus_{n:05}"));
            std::fs::copy(&path, &to)
                .map_err(|e| format!("cannot copy {} to {}: {e}", path.display(), to.display()))?;
        }
    }
    Ok(())
}

/// Appends one line to `fuzz/campaigns.csv` (the header names the columns).
fn append_record(fuzz_dir: &Path, record: &[String]) -> Result<(), String> {
    use std::io::Write;
    let path = fuzz_dir.join("campaigns.csv");
    let new = !path.exists();
    let mut file = std::fs::OpenOptions::new()
        .create(true)
        .append(true)
        .open(&path)
        .map_err(|e| format!("cannot open {}: {e}", path.display()))?;
    let when = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map(|d| d.as_secs())
        .unwrap_or(0);
    let mut text = String::new();
    if new {
        text.push_str(CSV_HEADER);
        text.push('\n');
    }
    text.push_str(&format!("{when},{}\n", record.join(",")));
    file.write_all(text.as_bytes())
        .map_err(|e| format!("cannot write {}: {e}", path.display()))
}

/// `seconds` is this slice; `run_time` and `executions` are totals over every slice of the
/// campaign; `edge_coverage` is `edges_found` over the edges afl's map holds (only the
/// instrumented crates' edges).
const CSV_HEADER: &str = "unix_time,target,seconds,run_time,executions,execs_per_sec,\
edges_found,total_edges,edge_coverage,corpus,crashes";

/// Copies each crash input into `fuzz/crashes/<target>/crash_<hash of its bytes>` (the same input
/// found again, or copied again by a later slice, keeps one file).
fn keep_crashes(fuzz_dir: &Path, crashes: &Path, target: &str) -> Result<(), String> {
    let Ok(entries) = std::fs::read_dir(crashes) else {
        return Ok(());
    };
    let keep = fuzz_dir.join("crashes").join(target);
    for entry in entries.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        if !name.starts_with("id:") {
            continue;
        }
        let bytes = std::fs::read(entry.path())
            .map_err(|e| format!("cannot read {}: {e}", entry.path().display()))?;
        std::fs::create_dir_all(&keep)
            .map_err(|e| format!("cannot create {}: {e}", keep.display()))?;
        let to = keep.join(format!("crash_{:016x}", fnv1a(&bytes)));
        if !to.exists() {
            std::fs::write(&to, &bytes)
                .map_err(|e| format!("cannot write a crash to {}: {e}", to.display()))?;
            eprintln!("xtask: kept crash {}", to.display());
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// What `fuzz/rustc_wrapper.sh` hands on to "rustc" (`echo` here) for `crate`.
    fn wrapped(crate_name: &str) -> String {
        let script = workspace_root().join("fuzz/rustc_wrapper.sh");
        let out = Command::new("bash")
            .arg(script)
            .args(["echo", "--crate-name", crate_name, "--edition=2024"])
            .args(["-C", "opt-level=3", "-C", "codegen-units=1"])
            .args(["-C", "passes=sancov-module"])
            .args(["-C", "llvm-args=-sanitizer-coverage-level=3"])
            .args(["-Cllvm-args=-sanitizer-coverage-trace-compares"])
            .args(["--cfg", "fuzzing", "-Clink-arg=afl-compiler-rt.o"])
            .output()
            .expect("bash runs the wrapper");
        assert!(out.status.success(), "the wrapper failed: {out:?}");
        String::from_utf8_lossy(&out.stdout).trim().to_string()
    }

    #[test]
    fn the_wrapper_instruments_the_crates_under_test_only() {
        let all = "--crate-name NAME --edition=2024 -C opt-level=3 -C codegen-units=1 \
                   -C passes=sancov-module -C llvm-args=-sanitizer-coverage-level=3 \
                   -Cllvm-args=-sanitizer-coverage-trace-compares --cfg fuzzing \
                   -Clink-arg=afl-compiler-rt.o";
        for tested in ["candela", "gltf_json", "symphonia_format_ogg", "zune_jpeg"] {
            assert_eq!(wrapped(tested), all.replace("NAME", tested), "{tested}");
        }
        for other in [
            "wgpu_core",
            "naga",
            "egui",
            "rapier3d",
            "build_script_build",
        ] {
            let expected = format!(
                "--crate-name {other} --edition=2024 -C opt-level=3 --cfg fuzzing \
                 -Clink-arg=afl-compiler-rt.o"
            );
            assert_eq!(wrapped(other), expected, "{other}");
        }
    }

    #[test]
    fn the_wrapper_hash_is_stable() {
        // FNV-1a's published test vectors: a changed hash would rebuild every afl artefact.
        assert_eq!(fnv1a(b""), 0xcbf2_9ce4_8422_2325);
        assert_eq!(fnv1a(b"a"), 0xaf63_dc4c_8601_ec8c);
    }
}
