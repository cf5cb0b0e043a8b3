//! The test of `bench picture-ruins`: `--quick` (the sun gate's replay, one compared frame
//! with the camera in its area, 32×18 and 64×36, 16-spp references) gives finite, positive
//! figures (and the still view finite ones), and the measure can fail: the reference is finite and not black, its error against
//! itself is 0 and a black frame's against it is the definition's, well above 0.
//!
//! Owns: the test. Must not: write files.

use std::collections::BTreeSet;
use std::sync::{Arc, Mutex};

use candela::render::RenderConfig;
use clap::Parser;
use glam::Vec3;
use indicatif::ProgressBar;
use its_about_time::replays::named;
use its_about_time::world::RuinsWorld;

use super::picture_metrics::{rel_mse, rmse, srgb_at};
use super::picture_ruins::{RuinsPictureArgs, chosen_frames, measure};
use super::picture_ruins_run::{RuinsRun, play_ruins};
use super::picture_tracer::References;

#[derive(Parser)]
struct Cli {
    #[command(flatten)]
    args: RuinsPictureArgs,
}

#[test]
fn quick_ruins_figures_are_finite_and_the_reference_is_not_black() {
    let world = RuinsWorld::open(None).expect("the ruins");
    let args = Cli::parse_from(["picture-ruins", "--quick", "--still"]).args;
    let outcome = measure(&args, &world).expect("bench picture-ruins --quick");
    assert_eq!(outcome.compared.len(), outcome.configs.len());
    for c in &outcome.compared {
        let figures = [
            c.rel_mse,
            c.srgb_rmse,
            c.reference_rel_mse,
            c.reference_srgb_rmse,
        ];
        assert!(figures.iter().all(|f| f.is_finite() && *f > 0.0), "{c:?}");
        assert!(c.local_hours.is_finite(), "{c:?}");
    }
    assert_eq!(outcome.still.len(), outcome.configs.len());
    for s in &outcome.still {
        assert!(s.displayed.is_finite() && s.reference.is_finite(), "{s:?}");
    }
    let frame = outcome.compared[0].frame;

    // The reference of that frame, rendered again on its own (render areas off).
    let mut full = world.clone();
    full.level.render_areas.clear();
    let replay = named(world.root.path(), "sun_gate");
    let refs = Arc::new(Mutex::new(References {
        wanted: BTreeSet::from([frame]),
        spp: 8,
        ..Default::default()
    }));
    let run = RuinsRun {
        world: &full,
        replay: Some(&replay),
        render: RenderConfig::cpu(32, 18),
        frames: frame + 1,
        live: BTreeSet::from([frame]),
        cuts: BTreeSet::new(),
        keep: BTreeSet::from([frame]),
    };
    let played = play_ruins(&run, refs.clone(), ProgressBar::hidden()).expect("the run");
    let refs = refs.lock().expect("references lock");
    let reference = refs.done.get(&frame).expect("the reference").mean();
    assert!(reference.iter().all(|p| p.is_finite()));
    let luminance: f32 = reference.iter().map(|p| p.dot(Vec3::ONE)).sum();
    assert!(luminance > 0.0, "the reference is black");
    assert_eq!(rel_mse(&reference, &reference), 0.0);
    let black = vec![Vec3::ZERO; reference.len()];
    // A black frame's error is the mean of r² / (r² + 0.01): 1 where the radiance is far above
    // 0.1, less in the dark (the ruins' radiance is of that order: the game exposes it up).
    let e = rel_mse(&black, &reference);
    let expected = (reference.iter())
        .flat_map(|p| p.to_array())
        .map(|r| f64::from(r).powi(2) / (f64::from(r).powi(2) + 0.01))
        .sum::<f64>()
        / (3 * reference.len()) as f64;
    assert!((e - expected).abs() < 1e-9, "{e} against {expected}");
    assert!(e > 0.1 && e <= 1.0, "a black frame's relative MSE {e}");
    // Exposed as the game exposes it, the sRGB picture is neither all black nor all white.
    let ev = played
        .exposure_ev
        .get(&frame)
        .copied()
        .expect("the exposure");
    let picture = srgb_at(&reference, ev);
    let mean = picture.iter().map(|p| p[0] + p[1] + p[2]).sum::<f32>() / (3 * picture.len()) as f32;
    assert!(mean > 0.05 && mean < 0.95, "mean sRGB {mean} at {ev} EV");
    assert!(rmse(&srgb_at(&black, ev), &picture) > 0.05);
}

#[test]
fn chosen_frames_are_in_the_area_spread_and_apart() {
    let area = candela::assets::RenderArea {
        name: "a".into(),
        min: [0.0; 3],
        max: [1.0; 3],
        light_groups: Vec::new(),
    };
    // Inside from frame 20 to 79, outside before and after.
    let cameras: Vec<[f32; 3]> = (0..100)
        .map(|f| {
            if (20..80).contains(&f) {
                [0.5; 3]
            } else {
                [2.0; 3]
            }
        })
        .collect();
    // Candidates 20, 25, …, 75: three spread evenly.
    let picked = chosen_frames(&cameras, &area, 5, 10, 3);
    assert_eq!(picked, BTreeSet::from([30, 50, 70]));
    // A 25-frame warm-up: a frame within 25 of the one before is dropped.
    let picked = chosen_frames(&cameras, &area, 5, 25, 3);
    assert_eq!(picked, BTreeSet::from([30, 70]));
    let outside = vec![[2.0; 3]; 100];
    assert!(chosen_frames(&outside, &area, 5, 10, 3).is_empty());
}
