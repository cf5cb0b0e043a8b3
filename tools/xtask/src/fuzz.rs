//! `cargo xtask fuzz [--target NAME] [--seconds N]`: the coverage-guided campaigns. Installs
//! cargo-afl (AFL++ for Rust, works on the stable toolchain) when missing, builds `fuzz/` with
//! afl's instrumentation, starts each target from its seeds (`candela_fuzz --write-seeds`) for
//! N seconds (default 60), then prints what afl's `fuzzer_stats` say (executions, edge coverage,
//! crashes), appends the same to `fuzz/campaigns.csv` and copies each crash input into
//! `fuzz/crashes/<target>/`, where the corpus test replays it. Campaign output stays in
//! `fuzz/out/` (ignored by git). Uses only `std`.

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
    let mut it = args.iter();
    while let Some(arg) = it.next() {
        match arg.as_str() {
            "--target" => targets.push(it.next().ok_or("--target needs a name")?.clone()),
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
    build(&fuzz_dir)?;
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

fn build(fuzz_dir: &Path) -> Result<(), String> {
    let attempt = || {
        let mut build = cargo();
        build
            .args(["afl", "build", "--release", "--manifest-path"])
            .arg(fuzz_dir.join("Cargo.toml"));
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

fn campaign(fuzz_dir: &Path, binary: &Path, target: &str, seconds: u64) -> Result<(), String> {
    let seeds = fuzz_dir.join("out").join(target).join("seeds");
    let out = fuzz_dir.join("out").join(target).join("afl");
    let _ = std::fs::remove_dir_all(&seeds);
    let mut write = Command::new(binary);
    write.arg("--write-seeds").arg(target).arg(&seeds);
    run(write)?;
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
    let (execs, coverage, crashes) = (
        field("execs_done"),
        field("bitmap_cvg"),
        field("saved_crashes"),
    );
    println!(
        "fuzz {target}: {execs} executions in {seconds} s, edge coverage {coverage}, {crashes} crashes"
    );
    append_record(fuzz_dir, target, seconds, &execs, &coverage, &crashes)?;
    keep_crashes(fuzz_dir, &out.join("default/crashes"), target)
}

fn append_record(
    fuzz_dir: &Path,
    target: &str,
    seconds: u64,
    execs: &str,
    coverage: &str,
    crashes: &str,
) -> Result<(), String> {
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
        text.push_str("unix_time,target,seconds,executions,edge_coverage,crashes\n");
    }
    text.push_str(&format!(
        "{when},{target},{seconds},{execs},{coverage},{crashes}\n"
    ));
    file.write_all(text.as_bytes())
        .map_err(|e| format!("cannot write {}: {e}", path.display()))
}

fn keep_crashes(fuzz_dir: &Path, crashes: &Path, target: &str) -> Result<(), String> {
    let Ok(entries) = std::fs::read_dir(crashes) else {
        return Ok(());
    };
    let keep = fuzz_dir.join("crashes").join(target);
    for entry in entries.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        if name.starts_with("id:") {
            std::fs::create_dir_all(&keep)
                .map_err(|e| format!("cannot create {}: {e}", keep.display()))?;
            let short: String = name
                .chars()
                .take(9)
                .filter(|c| c.is_ascii_alphanumeric())
                .collect();
            let to = keep.join(format!("{short}_{}", std::process::id()));
            std::fs::copy(entry.path(), &to)
                .map_err(|e| format!("cannot copy a crash to {}: {e}", to.display()))?;
            eprintln!("xtask: kept crash {}", to.display());
        }
    }
    Ok(())
}
