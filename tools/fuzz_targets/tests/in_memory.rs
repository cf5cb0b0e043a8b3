//! No target writes a file per execution: after every target has run on each of its seeds,
//! the scratch folder (the only folder on disk a target reads: `level` and `asset_path`) holds
//! exactly the files it held before, with the same sizes and modification times.

use std::collections::BTreeMap;
use std::path::Path;
use std::time::SystemTime;

use fuzz_targets::{Target, run, scratch, seeds::seeds};

/// Every entry below `dir` (symbolic links listed, not followed): path → (size, modified).
fn snapshot(dir: &Path, into: &mut BTreeMap<String, (u64, Option<SystemTime>)>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let path = entry.path();
        let Ok(meta) = std::fs::symlink_metadata(&path) else {
            continue;
        };
        into.insert(
            path.display().to_string(),
            (meta.len(), meta.modified().ok()),
        );
        if meta.is_dir() {
            snapshot(&path, into);
        }
    }
}

#[test]
fn no_target_writes_a_file_per_execution() {
    let folder = scratch::folder();
    let mut before = BTreeMap::new();
    snapshot(&folder, &mut before);
    assert!(!before.is_empty(), "the scratch folder was not made");
    let mut runs = 0;
    for target in Target::ALL {
        for (_, seed) in seeds(target) {
            let _ = run(target, &seed);
            runs += 1;
        }
    }
    let mut after = BTreeMap::new();
    snapshot(&folder, &mut after);
    let changed: Vec<&String> = after
        .iter()
        .filter(|(path, entry)| before.get(*path) != Some(entry))
        .map(|(path, _)| path)
        .collect();
    assert!(
        changed.is_empty() && before.len() == after.len(),
        "{runs} runs wrote to the scratch folder {}: {changed:?}",
        folder.display()
    );
}
