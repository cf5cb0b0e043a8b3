//! The character animation state machine on the Fox (glTF sample: Survey, Walk, Run): a speed
//! ramp up and down goes idle → walk → run → walk → idle with the switch points the ranges and
//! the hysteresis give; a jump goes through jump and fall; every change crossfades for exactly
//! the state's fade time with the two weights summing to 1 and the pose blended by them; the
//! playback rate follows the speed; two runs are identical; bad numbers are refused by name.

use std::path::{Path, PathBuf};

use candela::sim::animation::{
    AnimState, AnimatedModel, AnimationPlayer, Contact, Locomotion, PlayMode, StateCondition,
    StateMachine, StateMachineError, load_animation_file,
};

const DT: f64 = 1.0 / 60.0;
const HYSTERESIS: f32 = 0.2;

fn fox() -> anyhow::Result<AnimatedModel> {
    let path: PathBuf = Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../shared/external/gltf/Fox/glTF-Binary/Fox.glb"
    ))
    .to_path_buf();
    Ok(load_animation_file(&path)?)
}

fn state(
    name: &str,
    clip: usize,
    contact: Contact,
    speeds: (f32, f32),
    reference: Option<f32>,
    fade: f64,
) -> AnimState {
    AnimState {
        name: name.into(),
        clip,
        mode: PlayMode::Loop,
        when: StateCondition {
            contact,
            min_speed_mps: speeds.0,
            max_speed_mps: speeds.1,
        },
        reference_speed_mps: reference,
        min_rate: 0.5,
        max_rate: 2.0,
        fade_in_seconds: fade,
        blend: None,
    }
}

/// Fox clips: 0 Survey, 1 Walk, 2 Run.
fn machine() -> StateMachine {
    let inf = f32::INFINITY;
    StateMachine::new(
        vec![
            state("jump", 2, Contact::Rising, (0.0, inf), None, 0.1),
            state("fall", 2, Contact::Falling, (0.0, inf), None, 0.2),
            state("idle", 0, Contact::Grounded, (0.0, 0.3), None, 0.25),
            state("walk", 1, Contact::Grounded, (0.3, 3.5), Some(2.0), 0.25),
            state("run", 2, Contact::Grounded, (3.5, inf), Some(5.0), 0.3),
        ],
        HYSTERESIS,
    )
    .expect("valid states")
}

fn grounded(speed: f32) -> Locomotion {
    Locomotion {
        horizontal_speed_mps: speed,
        vertical_speed_mps: 0.0,
        grounded: true,
    }
}

/// Speeds 0 → 6 m/s over 3 s, then back to 0 over 3 s, then 0.5 s standing.
fn ramp() -> Vec<Locomotion> {
    let up = (0..180).map(|i| grounded(i as f32 / 180.0 * 6.0));
    let down = (0..180).map(|i| grounded(6.0 - i as f32 / 180.0 * 6.0));
    up.chain(down)
        .chain((0..30).map(|_| grounded(0.0)))
        .collect()
}

/// Per step: the state's name, the current clip, the current weight and the clip fading out.
type Trace = Vec<(String, usize, f32, Option<usize>, f64)>;

fn run(model: &AnimatedModel, moves: &[Locomotion]) -> (Trace, Vec<(usize, f32)>) {
    let mut machine = machine();
    let mut player = AnimationPlayer::new();
    let mut trace = Vec::new();
    let mut changes = Vec::new();
    for (i, m) in moves.iter().enumerate() {
        if let Some(change) = machine.update(&mut player, m, DT) {
            changes.push((i, m.horizontal_speed_mps));
            assert_eq!(Some(change.to), machine.current_index());
        }
        let _ = player.tick(&model.clips, DT);
        let current = player.current().expect("a clip plays");
        trace.push((
            machine.current().expect("a state").name.clone(),
            current.clip,
            player.current_weight(),
            player.fading_out().map(|p| p.clip),
            current.speed,
        ));
    }
    (trace, changes)
}

fn sequence(trace: &Trace) -> Vec<&str> {
    let mut names: Vec<&str> = trace.iter().map(|t| t.0.as_str()).collect();
    names.dedup();
    names
}

#[test]
fn a_speed_ramp_goes_idle_walk_run_walk_idle_at_the_widened_thresholds() -> anyhow::Result<()> {
    let model = fox();
    let model = model?;
    let moves = ramp();
    let (trace, changes) = run(&model, &moves);
    assert_eq!(
        sequence(&trace),
        ["idle", "walk", "run", "walk", "idle"],
        "{changes:?}"
    );
    // Going up, a state is left at its top + hysteresis; going down at its bottom − hysteresis
    // (one ramp step is 6/180 m/s).
    let step = 6.0 / 180.0 + 1e-4;
    let expected = [
        0.0,
        0.3 + HYSTERESIS,
        3.5 + HYSTERESIS,
        3.5 - HYSTERESIS,
        0.3 - HYSTERESIS,
    ];
    assert_eq!(changes.len(), expected.len());
    for (&(_, speed), want) in changes.iter().zip(expected) {
        assert!(
            (speed - want).abs() <= step,
            "switched at {speed} m/s, want {want}"
        );
    }
    Ok(())
}

#[test]
fn every_change_crossfades_for_the_fade_time_with_weights_summing_to_one() -> anyhow::Result<()> {
    let model = fox()?;
    let moves = ramp();
    let (trace, changes) = run(&model, &moves);
    let fades = [0.0, 0.25, 0.3, 0.25, 0.25];
    for (k, &(at, _)) in changes.iter().enumerate().skip(1) {
        // Steps with a clip fading out after the change: the fade lasts its time, to a step.
        let fading = trace[at..]
            .iter()
            .take_while(|t| t.3.is_some())
            .collect::<Vec<_>>();
        let want = (fades[k] / DT).round() as usize;
        assert!(
            fading.len() + 1 >= want && fading.len() <= want,
            "change {k}: {} fading steps, want {want}",
            fading.len()
        );
        // The incoming weight rises from 0 to 1; the outgoing is 1 − it (the player blends
        // exactly these two), so they sum to 1 and each stays in [0, 1]. (The last fading
        // step may round to 1: 14.999… steps of 1/60 s are still under 0.25 s.)
        let weights: Vec<f32> = fading.iter().map(|t| t.2).collect();
        assert!(weights.windows(2).all(|w| w[1] > w[0]), "{weights:?}");
        assert!(weights.iter().all(|w| *w > 0.0 && *w <= 1.0), "{weights:?}");
        assert!(
            (weights[0] - (DT / fades[k]) as f32).abs() < 1e-5,
            "{weights:?}"
        );
        let after = &trace[at + fading.len()];
        assert_eq!((after.2, after.3), (1.0, None), "the fade has ended");
    }
    Ok(())
}

#[test]
fn the_blended_pose_is_the_two_clips_mixed_by_the_weight() -> anyhow::Result<()> {
    let model = fox()?;
    let mut machine = machine();
    let mut player = AnimationPlayer::new();
    let rest = model.rest_pose();
    for _ in 0..20 {
        machine.update(&mut player, &grounded(0.0), DT);
        player.tick(&model.clips, DT);
    }
    machine.update(&mut player, &grounded(2.0), DT);
    player.tick(&model.clips, DT);
    for _ in 0..5 {
        machine.update(&mut player, &grounded(2.0), DT);
        player.tick(&model.clips, DT);
    }
    let (out, current) = (
        player.fading_out().expect("fading").clone(),
        player.current().expect("walking").clone(),
    );
    let weight = player.current_weight();
    assert!(weight > 0.1 && weight < 0.9, "{weight}");
    let mut expected = model.pose_at(out.clip, out.time_seconds);
    expected.blend(&model.pose_at(current.clip, current.time_seconds), weight);
    assert_eq!(player.pose(&model.clips, &rest), expected);
    assert_ne!(expected, model.pose_at(current.clip, current.time_seconds));
    Ok(())
}

#[test]
fn the_rate_follows_the_speed_within_its_limits() -> anyhow::Result<()> {
    let model = fox()?;
    let moves: Vec<Locomotion> = [0.0, 1.0, 1.5, 3.0, 3.6, 5.0, 12.0]
        .iter()
        .flat_map(|&s| std::iter::repeat_n(grounded(s), 30))
        .collect();
    let (trace, _) = run(&model, &moves);
    let at = |i: usize| (trace[i * 30 + 29].0.as_str(), trace[i * 30 + 29].4);
    assert_eq!(at(0), ("idle", 1.0));
    assert_eq!(at(1), ("walk", 0.5));
    assert_eq!(at(2), ("walk", 0.75));
    assert_eq!(at(3), ("walk", 1.5));
    assert_eq!(
        at(4),
        ("walk", f64::from(1.8f32)),
        "within the hysteresis walk stays"
    );
    assert_eq!(at(5), ("run", 1.0));
    assert_eq!(at(6), ("run", 2.0), "clamped to max_rate");
    Ok(())
}

#[test]
fn a_jump_rises_falls_and_lands() -> anyhow::Result<()> {
    let model = fox()?;
    let air = |v: f32| Locomotion {
        horizontal_speed_mps: 1.0,
        vertical_speed_mps: v,
        grounded: false,
    };
    let moves: Vec<Locomotion> = std::iter::repeat_n(grounded(0.0), 10)
        .chain((0..40).map(|i| air(4.0 - i as f32 * 0.2)))
        .chain(std::iter::repeat_n(grounded(0.0), 10))
        .collect();
    let (trace, _) = run(&model, &moves);
    assert_eq!(sequence(&trace), ["idle", "jump", "fall", "idle"]);
    Ok(())
}

#[test]
fn two_runs_are_identical() -> anyhow::Result<()> {
    let model = fox()?;
    let moves = ramp();
    let (a, ca) = run(&model, &moves);
    let (b, cb) = run(&model, &moves);
    assert_eq!(ca, cb);
    let bits = |t: &Trace| -> Vec<(String, usize, u32, Option<usize>, u64)> {
        t.iter()
            .map(|x| (x.0.clone(), x.1, x.2.to_bits(), x.3, x.4.to_bits()))
            .collect()
    };
    assert_eq!(bits(&a), bits(&b));
    Ok(())
}

#[test]
fn bad_numbers_are_refused_naming_the_state() {
    let bad = state("walk", 1, Contact::Grounded, (2.0, 1.0), None, 0.2);
    match StateMachine::new(vec![bad], 0.2) {
        Err(StateMachineError::BadState { state, message }) => {
            assert_eq!(state, "walk");
            assert!(message.contains("max_speed_mps"), "{message}");
        }
        other => panic!("expected a bad state, got {other:?}"),
    }
    let nan_fade = state("idle", 0, Contact::Grounded, (0.0, 1.0), None, f64::NAN);
    assert!(matches!(
        StateMachine::new(vec![nan_fade], 0.2),
        Err(StateMachineError::BadState { .. })
    ));
    assert_eq!(
        StateMachine::new(Vec::new(), 0.2),
        Err(StateMachineError::NoStates)
    );
    let ok = state("idle", 0, Contact::Grounded, (0.0, 1.0), None, 0.2);
    assert_eq!(
        StateMachine::new(vec![ok], -1.0),
        Err(StateMachineError::BadHysteresis(-1.0))
    );
}
