//! With the CPU tracer the same capture script gives the same images bit for bit (the reasons
//! are in `engine/src/app/script/run.rs`): two runs of a script that uses every feature (camera
//! keys with a cut, every motion kind, light switches, waves) write byte-identical EXR and PNG
//! files and bit-identical films. A third run with another seed must differ, so that the
//! comparison can fail.

use std::path::{Path, PathBuf};

use candela::app::{RunOptions, Script, ScriptReport, run_script};

fn script() -> Script {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/test_scenes/script/determinism.ron");
    Script::read(&path).expect("determinism.ron")
}

fn run(script: &Script, out: &Path) -> ScriptReport {
    let desc = script.load_level().expect("small level");
    let options = RunOptions {
        out_dir: Some(out.to_path_buf()),
        ..Default::default()
    };
    run_script(script, &desc, &options, &mut |_| {}).expect("script runs")
}

fn out_dir(tag: &str) -> PathBuf {
    std::env::temp_dir().join(format!("candela_determinism_{}_{tag}", std::process::id()))
}

#[test]
fn same_script_same_bits() {
    let script = script();
    let (a_dir, b_dir) = (out_dir("a"), out_dir("b"));
    let a = run(&script, &a_dir);
    let b = run(&script, &b_dir);
    assert_eq!(a.frames.len(), 12);
    assert_eq!(a.screenshots.len(), 2);
    for (sa, sb) in a.screenshots.iter().zip(&b.screenshots) {
        assert_eq!(sa.frame, sb.frame);
        let bits = |s: &candela::app::ShotResult| -> Vec<u32> {
            s.film
                .mean
                .iter()
                .flat_map(|p| p.to_array().map(f32::to_bits))
                .collect()
        };
        assert_eq!(bits(sa), bits(sb), "film of frame {}", sa.frame);
        let mean = sa.film.image_mean();
        assert!(mean.iter().all(|m| *m > 0.0 && m.is_finite()), "{mean:?}");
        for (fa, fb) in [(&sa.exr, &sb.exr), (&sa.png, &sb.png)] {
            let (fa, fb) = (fa.as_ref().expect("written"), fb.as_ref().expect("written"));
            let (ba, bb) = (std::fs::read(fa).expect("a"), std::fs::read(fb).expect("b"));
            assert!(ba == bb, "{} and {} differ", fa.display(), fb.display());
        }
    }
    // The commits are the same too.
    let bytes = |r: &ScriptReport| r.frames.iter().map(|f| f.commit_bytes).collect::<Vec<_>>();
    assert_eq!(bytes(&a), bytes(&b));

    let mut other = script.clone();
    other.render.seed += 1;
    let c = run(&other, &out_dir("c"));
    assert_ne!(
        c.screenshots[1].film.mean, a.screenshots[1].film.mean,
        "another seed gives other samples"
    );
    for dir in [a_dir, b_dir, out_dir("c")] {
        let _ = std::fs::remove_dir_all(dir);
    }
}
