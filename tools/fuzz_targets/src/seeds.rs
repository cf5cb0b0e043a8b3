//! The seed inputs of each target: `fuzz/corpus/<target>/` and `fuzz/crashes/<target>/` in the
//! repository, the repository's own assets, `../shared/external`'s samples (read in place, never
//! copied in), and a replay made by the engine's recorder. The corpus tests mutate them; the afl
//! campaigns start from them (`candela_fuzz --write-seeds DIR`).
//!
//! Reads files only; any thread.

use std::path::{Path, PathBuf};

use crate::Target;

/// At most this many seeds per target come from the assets and `../shared/external`.
const MAX_SEEDS: usize = 24;
/// Seeds larger than this are left to the campaigns (mutating them here is slow).
const MAX_SEED_BYTES: u64 = 256 * 1024;

pub fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

pub fn external() -> PathBuf {
    repo().join("../shared/external")
}

/// Files under `dir` (recursively) whose name ends with one of `endings`, sorted.
fn files(dir: &Path, endings: &[&str]) -> Vec<PathBuf> {
    let mut found = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&d) else {
            continue;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            if path.is_dir() {
                stack.push(path);
            } else {
                let name = path.to_string_lossy().to_lowercase();
                let small = entry.metadata().map(|m| m.len() <= MAX_SEED_BYTES);
                if endings.iter().any(|e| name.ends_with(e)) && small.unwrap_or(false) {
                    found.push(path);
                }
            }
        }
    }
    found.sort();
    found
}

/// `paths` thinned evenly to at most `n`.
fn spread(paths: Vec<PathBuf>, n: usize) -> Vec<PathBuf> {
    if paths.len() <= n {
        return paths;
    }
    let step = paths.len() as f64 / n as f64;
    (0..n)
        .map(|i| paths[(i as f64 * step) as usize].clone())
        .collect()
}

/// The seeds of `target` beyond its corpus folder.
fn extra_seeds(target: Target) -> Vec<PathBuf> {
    let assets = repo().join("assets");
    let ext = external();
    let found = match target {
        Target::Level | Target::Script => files(&assets, &[".ron"]),
        Target::Gltf => files(&ext.join("gltf"), &[".gltf"]),
        Target::Glb => files(&ext.join("gltf"), &[".glb"]),
        Target::Animation => [
            files(&ext.join("gltf"), &[".glb"]),
            files(&ext.join("animation-reference"), &[".gltf", ".glb"]),
        ]
        .concat(),
        Target::Obj => [
            files(&ext.join("obj"), &[".obj"]),
            files(&assets, &[".obj"]),
        ]
        .concat(),
        Target::Mtl => [
            files(&ext.join("obj"), &[".mtl"]),
            files(&assets, &[".mtl"]),
        ]
        .concat(),
        Target::Texture => files(&ext.join("gltf"), &[".png", ".jpg", ".jpeg"]),
        Target::Sound => files(&assets, &[".wav", ".ogg"]),
        _ => Vec::new(),
    };
    spread(found, MAX_SEEDS)
}

/// Every seed of `target`: its [`mutable_seeds`] and its [`campaign_corpus`].
pub fn seeds(target: Target) -> Vec<(String, Vec<u8>)> {
    let mut seeds = mutable_seeds(target);
    seeds.extend(campaign_corpus(target));
    seeds
}

/// The seeds the corpus test mutates: the hand-made `fuzz/corpus/<target>/*`, the crash inputs
/// `fuzz/crashes/<target>/`, the assets' and `../shared/external`'s samples, a recorded replay.
pub fn mutable_seeds(target: Target) -> Vec<(String, Vec<u8>)> {
    let fuzz = repo().join("fuzz");
    let corpus = fuzz.join("corpus").join(target.name());
    let mut paths: Vec<PathBuf> = files(&corpus, &[""])
        .into_iter()
        .filter(|p| !p.starts_with(corpus.join(CAMPAIGN_FOLDER)))
        .collect();
    paths.extend(files(&fuzz.join("crashes").join(target.name()), &[""]));
    paths.extend(extra_seeds(target));
    let mut seeds = read_all(paths);
    if target == Target::Replay {
        seeds.push(("a recorded replay".into(), sample_replay()));
    }
    seeds
}

/// Where a campaign's minimised corpus (afl-cmin) is committed, inside `fuzz/corpus/<target>/`.
pub const CAMPAIGN_FOLDER: &str = "afl";

/// The minimised corpus of the afl campaigns, `fuzz/corpus/<target>/afl/`: afl has mutated these
/// millions of times already, so the corpus test replays each once, unmutated.
pub fn campaign_corpus(target: Target) -> Vec<(String, Vec<u8>)> {
    let dir = repo()
        .join("fuzz/corpus")
        .join(target.name())
        .join(CAMPAIGN_FOLDER);
    read_all(files(&dir, &[""]))
}

fn read_all(paths: Vec<PathBuf>) -> Vec<(String, Vec<u8>)> {
    paths
        .into_iter()
        .filter_map(|p| std::fs::read(&p).ok().map(|b| (p.display().to_string(), b)))
        .collect()
}

/// A short recording made with the engine's recorder (held, pressed and motion values).
fn sample_replay() -> Vec<u8> {
    use candela::app::{ActionFrame, ActionSet, Recorder};
    let set = ActionSet::standard();
    let mut recorder = Recorder::new("fuzz", "seed", 0x1234, 60.0, &set);
    for step in 0..40_i32 {
        let mut frame = ActionFrame::empty(&set);
        frame.held = if step % 10 < 5 { 0b101 } else { 0 };
        frame.pressed = u64::from(step % 10 == 0);
        if let Some(v) = frame.values.last_mut() {
            *v = step * 97 - 900;
        }
        recorder
            .push(frame)
            .expect("a frame of the recorder's own set");
    }
    recorder.recording().encode()
}
