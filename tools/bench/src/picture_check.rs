//! The test of `bench picture`: `--quick` (tiny sizes, one chamber) gives finite, positive
//! figures for every configuration, and the measurement can tell converged from noisy: a
//! 32-spp render of a frame's view is far closer to an independent 32-spp render of it than a
//! 1-spp render is, and two runs of the same drive reach the same view at the same frame (the
//! determinism the shared references rely on).
//!
//! Owns: the test. Must not: write files.

use std::collections::BTreeSet;
use std::sync::{Arc, Mutex};

use clap::Parser;
use indicatif::ProgressBar;
use reflect::world::ReflectWorld;

use super::picture::{PictureArgs, measure};
use super::picture_metrics::{reference_noise, rel_mse};
use super::picture_run::{Config, Drive, play};
use super::picture_tracer::{Reference, References};

#[derive(Parser)]
struct Cli {
    #[command(flatten)]
    args: PictureArgs,
}

fn world() -> (ReflectWorld, std::path::PathBuf) {
    let (path, root) = reflect::cli::locate(None).expect("the game file");
    let world = ReflectWorld::load(&path, &root).expect("the world");
    (world, root.path().join("reflect/replays"))
}

/// A reference of `frame` of chamber 1's still view at 32×18 with `spp` samples.
fn reference(world: &ReflectWorld, frame: u64, spp: u32) -> Reference {
    let refs = Arc::new(Mutex::new(References {
        wanted: BTreeSet::from([frame]),
        spp,
        ..Default::default()
    }));
    let config = Config {
        width: 32,
        height: 18,
        denoise: false,
        upscale: 1,
        indirect_every: 1,
        first_hit_guides: false,
    };
    let keep = BTreeSet::from([frame]);
    play(
        world,
        0,
        Drive::Still,
        config,
        frame + 1,
        &keep,
        refs.clone(),
        ProgressBar::hidden(),
    )
    .expect("the run");
    let refs = refs.lock().expect("references lock");
    refs.done.get(&frame).expect("the reference").clone()
}

#[test]
fn quick_figures_are_finite_and_converged_beats_one_spp() {
    let (world, replays) = world();
    let args = Cli::parse_from(["picture", "--quick"]).args;
    let outcome = measure(&args, &world, &replays).expect("bench picture --quick");
    assert_eq!(outcome.compared.len(), outcome.configs.len());
    for c in &outcome.compared {
        let figures = [
            c.rel_mse,
            c.srgb_rmse,
            c.reference_rel_mse,
            c.reference_srgb_rmse,
        ];
        assert!(figures.iter().all(|f| f.is_finite() && *f > 0.0), "{c:?}");
    }
    assert!(outcome.frame_ms.iter().all(|t| t.is_finite() && *t > 0.0));
    assert_eq!(outcome.stability.len(), 2 * outcome.configs.len());
    for s in &outcome.stability {
        assert!(s.displayed.is_finite() && s.reference.is_finite(), "{s:?}");
    }
    let turn = outcome
        .stability
        .iter()
        .find(|s| s.drive == "turn")
        .expect("a turn row");
    assert!(
        turn.degrees_per_frame > 0.05,
        "the turn did not turn: {turn:?}"
    );

    let converged = reference(&world, 5, 64);
    let noisy = reference(&world, 5, 2);
    assert_eq!(
        converged.camera, noisy.camera,
        "two runs reached different views"
    );
    assert!(
        reference_noise(&converged).0 > 0.0,
        "the halves are not independent"
    );
    // Against the converged reference's second half (32 spp, its own seeds): its first half
    // (32 spp) should be about (1/32 + 1/32) / (1 + 1/32) ≈ 1/16 of a 1-spp render's error.
    let truth = &converged.halves[1];
    let e32 = rel_mse(&converged.halves[0], truth);
    let e1 = rel_mse(&noisy.halves[0], truth);
    assert!(e32 * 4.0 < e1, "32 spp: {e32}, 1 spp: {e1}");
}
