//! A capture script's `hold_from_frame` (`engine/src/app/script/desc.rs`) on the wading level
//! (`assets/test_scenes/wading/`: the hero knee-deep in a simulated water that ripples round
//! its legs): before the hold every frame refits the moving water and the skinned hero; from
//! the hold on, nothing moves (no refit, no rebuild), so the film converges on that moment.
//! A hold at or past the last frame is refused, naming the field and the script.

use std::path::{Path, PathBuf};

use candela::app::{RunOptions, Script, run_script};

fn script() -> anyhow::Result<Script> {
    let path: PathBuf = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../assets/test_scenes/wading/wading_script.ron");
    Ok(Script::read(&path)?)
}

#[test]
fn after_the_hold_nothing_is_refitted() -> anyhow::Result<()> {
    let mut script = script()?;
    script.frames = 24;
    script.hold_from_frame = Some(12);
    script.screenshots.clear();
    let level = script.load_level()?;
    let options = RunOptions {
        size: Some((48, 27)),
        spp: Some(1),
        ..Default::default()
    };
    let report = run_script(&script, &level, &options, &mut |_| {})?;
    assert_eq!(report.frames.len(), 24);
    let refits: Vec<u32> = report.frames.iter().map(|f| f.upkeep.blas_refits).collect();
    // Frame 0 builds; frames 1..12 move the water (rippling) and the hero (idle).
    assert!(
        refits[1..12].iter().all(|&r| r > 0),
        "the water and the hero move before the hold: {refits:?}"
    );
    // The frame of the hold still poses what the last step left; after it, nothing.
    for f in &report.frames[13..] {
        assert_eq!(
            (f.upkeep.blas_refits, f.upkeep.blas_rebuilds),
            (0, 0),
            "frame {} after the hold: {refits:?}",
            f.frame
        );
    }
    Ok(())
}

#[test]
fn a_hold_past_the_last_frame_is_refused() -> anyhow::Result<()> {
    let mut script = script()?;
    script.hold_from_frame = Some(script.frames);
    let error = script
        .validate()
        .err()
        .map(|e| e.to_string())
        .unwrap_or_default();
    assert!(
        error.contains("hold_from_frame") && error.contains("wading_script.ron"),
        "{error}"
    );
    Ok(())
}
