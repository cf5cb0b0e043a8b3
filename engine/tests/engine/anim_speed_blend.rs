//! The walk/run blend by speed on the generated hero: one locomotion state plays `walk` with
//! `run` mixed in at the same fraction of its cycle, weighted by ground speed. The weight is
//! monotone in speed (0 at and below `from`, 1 at and above `to`); at walk speed the pose is
//! the walk clip's, at run speed the run clip's at the same phase; the playback rate follows
//! the blended stride; a level's `blend:` entry loads into the same thing and bad numbers are
//! refused by name.

use std::path::{Path, PathBuf};

use candela::sim::animation::{
    AnimState, AnimatedModel, AnimationPlayer, Contact, Locomotion, PlayMode, Pose, SpeedBlend,
    StateCondition, StateMachine, StateMachineError, load_animation_file,
};

const DT: f64 = 1.0 / 60.0;
/// The walk's and run's reference speeds (the courtyard level's), m/s.
const WALK_MPS: f32 = 1.45;
const RUN_MPS: f32 = 3.35;
const FROM_MPS: f32 = 2.0;
const TO_MPS: f32 = 4.5;

fn hero() -> anyhow::Result<AnimatedModel> {
    let path: PathBuf =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/common/hero/hero.glb");
    Ok(load_animation_file(&path)?)
}

fn blend(model: &AnimatedModel) -> anyhow::Result<SpeedBlend> {
    let (walk, run) = (model.find_clip("walk")?, model.find_clip("run")?);
    Ok(SpeedBlend {
        clip: run,
        reference_speed_mps: RUN_MPS,
        from_speed_mps: FROM_MPS,
        to_speed_mps: TO_MPS,
        cycle_ratio: (model.clips[run].duration_seconds / model.clips[walk].duration_seconds)
            as f32,
    })
}

fn machine(model: &AnimatedModel, blend: Option<SpeedBlend>) -> anyhow::Result<StateMachine> {
    Ok(StateMachine::new(
        vec![AnimState {
            name: "move".into(),
            clip: model.find_clip("walk")?,
            mode: PlayMode::Loop,
            when: StateCondition {
                contact: Contact::Any,
                min_speed_mps: 0.0,
                max_speed_mps: f32::INFINITY,
            },
            reference_speed_mps: Some(WALK_MPS),
            min_rate: 0.1,
            max_rate: 4.0,
            fade_in_seconds: 0.0,
            blend,
        }],
        0.0,
    )?)
}

/// The largest difference between two poses' translations and rotations.
fn distance(a: &Pose, b: &Pose) -> f32 {
    let mut d: f32 = 0.0;
    for i in 0..a.len().min(b.len()) {
        d = d.max((a.translation[i] - b.translation[i]).length());
        d = d.max(1.0 - a.rotation[i].dot(b.rotation[i]).abs());
    }
    d
}

/// Steps the machine at `speed` for `steps` and returns the player.
fn run_at(model: &AnimatedModel, speed: f32, steps: usize) -> anyhow::Result<AnimationPlayer> {
    let mut machine = machine(model, Some(blend(model)?))?;
    let mut player = AnimationPlayer::new();
    let m = Locomotion {
        horizontal_speed_mps: speed,
        vertical_speed_mps: 0.0,
        grounded: true,
    };
    for _ in 0..steps {
        machine.update(&mut player, &m, DT);
        player.tick(&model.clips, DT);
    }
    Ok(player)
}

#[test]
fn the_blend_weight_rises_monotonically_with_speed() -> anyhow::Result<()> {
    let b = blend(&hero()?)?;
    let mut last = -1.0;
    for i in 0..=120 {
        let speed = 0.05 * i as f32;
        let w = b.weight(speed);
        assert!(
            (0.0..=1.0).contains(&w) && w >= last,
            "{speed} m/s: {w} after {last}"
        );
        last = w;
    }
    assert_eq!(b.weight(FROM_MPS), 0.0);
    assert_eq!(b.weight(TO_MPS), 1.0);
    assert!((b.weight(0.5 * (FROM_MPS + TO_MPS)) - 0.5).abs() < 1e-6);
    assert_eq!(b.weight(f32::NAN), 0.0);
    Ok(())
}

#[test]
fn at_walk_speed_the_pose_is_the_walk_and_at_run_speed_the_run() -> anyhow::Result<()> {
    let model = hero()?;
    let (walk, run) = (model.find_clip("walk")?, model.find_clip("run")?);
    let rest = model.rest_pose();
    let walk_s = model.clips[walk].duration_seconds;
    let run_s = model.clips[run].duration_seconds;
    for steps in [7, 23, 50] {
        let player = run_at(&model, WALK_MPS, steps)?;
        let p = player.current().ok_or_else(|| anyhow::anyhow!("playing"))?;
        assert_eq!(p.blend.map(|b| b.weight), Some(0.0));
        let pose = player.pose(&model.clips, &rest);
        let d = distance(&pose, &model.pose_at(walk, p.time_seconds));
        assert!(d < 1e-5, "walk speed, {steps} steps: {d}");

        let player = run_at(&model, 5.0, steps)?;
        let p = player.current().ok_or_else(|| anyhow::anyhow!("playing"))?;
        assert_eq!(p.blend.map(|b| b.weight), Some(1.0));
        let pose = player.pose(&model.clips, &rest);
        let phase = p.time_seconds / walk_s;
        let d = distance(&pose, &model.pose_at(run, phase * run_s));
        assert!(d < 1e-5, "run speed, {steps} steps: {d}");
        assert!(
            distance(&pose, &model.pose_at(walk, p.time_seconds)) > 0.01,
            "the run is not the walk"
        );
        // Halfway: neither clip alone.
        let player = run_at(&model, 0.5 * (FROM_MPS + TO_MPS), steps)?;
        let p = player.current().ok_or_else(|| anyhow::anyhow!("playing"))?;
        let pose = player.pose(&model.clips, &rest);
        let phase = p.time_seconds / walk_s;
        assert!(distance(&pose, &model.pose_at(walk, p.time_seconds)) > 1e-3);
        assert!(distance(&pose, &model.pose_at(run, phase * run_s)) > 1e-3);
    }
    Ok(())
}

#[test]
fn the_rate_follows_the_blended_stride() -> anyhow::Result<()> {
    let model = hero()?;
    let b = blend(&model)?;
    // Walk speed: the walk's own rate; 5 m/s: the run's cycles per second, in walk time.
    let rate_at = |speed: f32| -> anyhow::Result<f64> {
        let player = run_at(&model, speed, 3)?;
        Ok(player.current().map_or(0.0, |p| p.speed))
    };
    assert!((rate_at(WALK_MPS)? - 1.0).abs() < 1e-6);
    let run_rate = 5.0 / (RUN_MPS * b.cycle_ratio);
    assert!((rate_at(5.0)? - f64::from(run_rate)).abs() < 1e-5);
    // Metres per cycle grow with speed between the two strides.
    let mut last = 0.0;
    for i in 1..=12 {
        let speed = 0.5 * i as f32;
        let stride = speed / b.rate(WALK_MPS, speed);
        assert!(
            stride >= last - 1e-5,
            "{speed} m/s: {stride} m after {last} m"
        );
        last = stride;
    }
    Ok(())
}

#[test]
fn a_blend_with_bad_numbers_is_refused_by_name() -> anyhow::Result<()> {
    let model = hero()?;
    let good = blend(&model)?;
    for (bad, what) in [
        (
            SpeedBlend {
                to_speed_mps: 1.0,
                ..good
            },
            "to_speed_mps",
        ),
        (
            SpeedBlend {
                reference_speed_mps: 0.0,
                ..good
            },
            "reference_speed_mps",
        ),
        (
            SpeedBlend {
                from_speed_mps: f32::NAN,
                ..good
            },
            "from_speed_mps",
        ),
    ] {
        match machine(&model, Some(bad)) {
            Err(e) => {
                let text = e.to_string();
                assert!(text.contains("\"move\"") && text.contains(what), "{text}");
                assert!(matches!(
                    e.downcast_ref::<StateMachineError>(),
                    Some(StateMachineError::BadState { .. })
                ));
            }
            Ok(_) => anyhow::bail!("{what} accepted"),
        }
    }
    Ok(())
}

/// The courtyard level with its walk and run states replaced by one blended `move` state
/// whose blend names `blend_clip`.
fn blended_courtyard(dir: &Path, blend_clip: &str) -> anyhow::Result<PathBuf> {
    let repo = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let source =
        std::fs::read_to_string(repo.join("assets/test_scenes/platform/third_person.ron"))?;
    let walk_and_run = "(name: \"walk\", clip: \"walk\", contact: Grounded, min_speed_mps: 0.3, \
                        max_speed_mps: 3.5,\n                reference_speed_mps: 1.45),\n            \
                        (name: \"run\", clip: \"run\", contact: Grounded, min_speed_mps: 3.5,\n                \
                        reference_speed_mps: 3.35),";
    anyhow::ensure!(
        source.contains(walk_and_run),
        "the courtyard's states changed"
    );
    let blended = format!(
        "(name: \"move\", clip: \"walk\", contact: Grounded, min_speed_mps: 0.3, \
         reference_speed_mps: 1.45, max_rate: 3, blend: (clip: \"{blend_clip}\", \
         reference_speed_mps: 3.35, from_speed_mps: 2, to_speed_mps: 4.5)),"
    );
    let path = dir.join(format!("blended_{blend_clip}.ron"));
    std::fs::write(&path, source.replace(walk_and_run, &blended))?;
    Ok(path)
}

#[test]
fn a_level_blend_entry_loads_and_an_unknown_clip_is_refused() -> anyhow::Result<()> {
    let repo = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let root = candela::assets::AssetRoot::new(repo.join("assets"))?;
    let dir = std::env::temp_dir().join(format!("candela_speed_blend_{}", std::process::id()));
    std::fs::create_dir_all(&dir)?;
    let good = candela::level::load_level(&blended_courtyard(&dir, "run")?, &root);
    let bad = candela::level::load_level(&blended_courtyard(&dir, "sprint")?, &root);
    let _ = std::fs::remove_dir_all(&dir);
    let level = good?;
    let model = hero()?;
    let character = level
        .characters
        .first()
        .ok_or_else(|| anyhow::anyhow!("a character"))?;
    let state = character
        .machine
        .states()
        .iter()
        .find(|s| s.name == "move")
        .ok_or_else(|| anyhow::anyhow!("the move state"))?;
    let b = state.blend.ok_or_else(|| anyhow::anyhow!("a blend"))?;
    assert_eq!(b.clip, model.find_clip("run")?);
    assert!((b.cycle_ratio - 0.7).abs() < 1e-4, "{}", b.cycle_ratio);
    assert_eq!((b.from_speed_mps, b.to_speed_mps), (2.0, 4.5));
    let error = match bad {
        Ok(_) => anyhow::bail!("a blend of a clip the hero lacks loaded"),
        Err(e) => format!("{e:#}"),
    };
    assert!(
        error.contains("\"move\"")
            && error.contains("\"sprint\"")
            && error.contains("blended_sprint.ron"),
        "{error}"
    );
    Ok(())
}
