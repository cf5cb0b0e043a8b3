//! The animation player and authored clips: once / loop / ping-pong, pause, reverse, speed,
//! events in order, crossfade weights, and level-file (RON) clips with their errors.
//! Expected values follow from the clip definitions here (linear keys, so the value at a
//! time is a hand-checkable lerp); comparisons allow float32 rounding (1e-6 on unit values).

use std::path::Path;

use candela::sim::animation::{
    AnimError, AnimationPlayer, AuthoredClipSet, Channel, Clip, ClipEvent, Interpolation, PlayMode,
    Playback, Pose, Property, sample_channel,
};
use glam::Quat;

type TestResult = Result<(), Box<dyn std::error::Error>>;

const EPS: f32 = 1e-6;

/// Clip 0: target 0 rises linearly from y = 0 to y = 2 over 2 s, with events at 0, 0.5, 2.
/// Clip 1: target 0 held at y = 10 and turned 90° about Y.
fn clips() -> Vec<Clip> {
    let mut rise = Clip::new(
        "rise",
        vec![Channel {
            target: 0,
            property: Property::Translation,
            interpolation: Interpolation::Linear,
            times_seconds: vec![0.0, 2.0],
            values: vec![0.0, 0.0, 0.0, 0.0, 2.0, 0.0],
            width: 3,
        }],
    );
    rise.events = ["start:0", "early:0.5", "top:2"]
        .iter()
        .filter_map(|s| s.split_once(':'))
        .map(|(name, t)| ClipEvent {
            name: name.to_string(),
            time_seconds: t.parse().unwrap_or(f64::NAN),
        })
        .collect();
    let turn = Quat::from_rotation_y(std::f32::consts::FRAC_PI_2);
    let hold = Clip::new(
        "hold",
        vec![
            Channel {
                target: 0,
                property: Property::Translation,
                interpolation: Interpolation::Step,
                times_seconds: vec![0.0],
                values: vec![0.0, 10.0, 0.0],
                width: 3,
            },
            Channel {
                target: 0,
                property: Property::Rotation,
                interpolation: Interpolation::Step,
                times_seconds: vec![0.0],
                values: turn.to_array().to_vec(),
                width: 4,
            },
        ],
    );
    vec![rise, hold]
}

fn names(events: &[candela::sim::animation::FiredEvent]) -> Vec<&str> {
    events.iter().map(|e| e.name.as_str()).collect()
}

fn height(player: &AnimationPlayer, clips: &[Clip]) -> f32 {
    player.pose(clips, &Pose::identity(1)).translation[0].y
}

#[test]
fn once_plays_to_the_end_and_holds() {
    let clips = clips();
    let mut player = AnimationPlayer::new();
    player.play(Playback::new(0, PlayMode::Once));
    assert_eq!(names(&player.tick(&clips, 0.5)), ["start", "early"]);
    assert!((height(&player, &clips) - 0.5).abs() < EPS);
    assert_eq!(names(&player.tick(&clips, 5.0)), ["top"]);
    assert!(player.current().is_some_and(|p| p.finished));
    assert!((height(&player, &clips) - 2.0).abs() < EPS);
    assert!(
        player.tick(&clips, 1.0).is_empty(),
        "a finished clip fires nothing"
    );
}

#[test]
fn pause_stops_the_playhead() {
    let clips = clips();
    let mut player = AnimationPlayer::new();
    player.play(Playback::new(0, PlayMode::Loop));
    player.tick(&clips, 0.25);
    player.set_paused(true);
    assert!(player.tick(&clips, 10.0).is_empty());
    assert!((height(&player, &clips) - 0.25).abs() < EPS);
    player.set_paused(false);
    player.tick(&clips, 0.25);
    assert!((height(&player, &clips) - 0.5).abs() < EPS);
}

#[test]
fn loop_wraps_and_fires_each_lap() {
    let clips = clips();
    let mut player = AnimationPlayer::new();
    player.play(Playback::new(0, PlayMode::Loop));
    // 2.5 s: the whole 2 s lap, then 0.5 s into the next.
    let fired = player.tick(&clips, 2.5);
    assert_eq!(names(&fired), ["start", "early", "top", "start", "early"]);
    assert!((height(&player, &clips) - 0.5).abs() < EPS);
    // A huge step must neither hang nor leave the clip's range.
    player.tick(&clips, 1.0e9 + 0.3);
    let time = player.current().map_or(-1.0, |p| p.time_seconds);
    assert!((0.0..=2.0).contains(&time), "time {time}");
}

#[test]
fn ping_pong_turns_at_the_ends() {
    let clips = clips();
    let mut player = AnimationPlayer::new();
    player.play(Playback::new(0, PlayMode::PingPong));
    // Up for 2 s, then back down for 0.5 s: at y = 1.5, moving backward.
    assert_eq!(names(&player.tick(&clips, 2.5)), ["start", "early", "top"]);
    assert!((height(&player, &clips) - 1.5).abs() < EPS);
    assert!(player.current().is_some_and(|p| p.reversed));
    // Down to the start (events met in reverse order), turning there.
    assert_eq!(names(&player.tick(&clips, 1.5)), ["early", "start"]);
    assert!(player.current().is_some_and(|p| !p.reversed));
    player.tick(&clips, 0.25);
    assert!((height(&player, &clips) - 0.25).abs() < EPS);
}

#[test]
fn reverse_and_speed() {
    let clips = clips();
    let mut player = AnimationPlayer::new();
    player.play(Playback::new(0, PlayMode::Once));
    player.tick(&clips, 1.0);
    player.reverse();
    player.tick(&clips, 0.25);
    assert!((height(&player, &clips) - 0.75).abs() < EPS);
    // Played backward to its start, a Once clip finishes there.
    assert_eq!(names(&player.tick(&clips, 5.0)), ["early", "start"]);
    assert!(player.current().is_some_and(|p| p.finished));
    assert!(height(&player, &clips).abs() < EPS);

    // A door closing: from the end, backward, at double speed.
    let mut closing = Playback::reversed_from_end(0, PlayMode::Once, &clips);
    closing.speed = 2.0;
    player.play(closing);
    assert_eq!(names(&player.tick(&clips, 0.25)), ["top"]);
    assert!((height(&player, &clips) - 1.5).abs() < EPS);
}

#[test]
fn crossfade_blends_by_elapsed_fraction() {
    let clips = clips();
    let mut player = AnimationPlayer::new();
    player.play(Playback::new(0, PlayMode::Once));
    player.tick(&clips, 1.0); // y = 1 in clip 0
    player.crossfade(Playback::new(1, PlayMode::Loop), 1.0);
    player.tick(&clips, 0.25); // clip 0 at y = 1.25, weight of clip 1 = 0.25
    assert!((player.current_weight() - 0.25).abs() < EPS);
    let pose = player.pose(&clips, &Pose::identity(1));
    let expected = 1.25 * 0.75 + 10.0 * 0.25;
    assert!((pose.translation[0].y - expected).abs() < 1e-5);
    // The rotation is a unit quaternion between identity and the 90° turn.
    let rotation = pose.rotation[0];
    assert!((rotation.length() - 1.0).abs() < EPS);
    let angle = rotation.angle_between(Quat::IDENTITY);
    assert!(
        angle > 0.0 && angle < std::f32::consts::FRAC_PI_2,
        "{angle}"
    );
    // After the fade, only clip 1 remains.
    player.tick(&clips, 1.0);
    assert_eq!(player.current_weight(), 1.0);
    assert!((height(&player, &clips) - 10.0).abs() < EPS);
}

#[test]
fn cubic_spline_follows_the_hermite_basis() {
    // Keys at 0 s (value 0, out-tangent 1/s) and 2 s (value 1, in-tangent 0). At u = 0.5 the
    // Hermite basis is h00 = h01 = 0.5, h10 = 0.125, and the tangent is scaled by the 2 s
    // interval: 0.5·0 + 0.125·2·1 + 0.5·1 = 0.75.
    let channel = Channel {
        target: 0,
        property: Property::Scale,
        interpolation: Interpolation::CubicSpline,
        times_seconds: vec![0.0, 2.0],
        values: vec![
            0.0, 0.0, 0.0, /* value */ 0.0, 0.0, 0.0, /* out */ 1.0, 1.0, 1.0, //
            0.0, 0.0, 0.0, /* value */ 1.0, 1.0, 1.0, /* out */ 0.0, 0.0, 0.0,
        ],
        width: 3,
    };
    let mut out = [0.0f32; 3];
    sample_channel(&channel, 1.0, &mut out);
    let (h00, h10, h01) = (0.5f32, 0.125f32, 0.5f32);
    let expected = h00 * 0.0 + h10 * 2.0 * 1.0 + h01 * 1.0;
    assert!((out[0] - expected).abs() < EPS, "{out:?}");
    // Outside the keys the end values hold, never a tangent.
    sample_channel(&channel, -1.0, &mut out);
    assert_eq!(out, [0.0; 3]);
    sample_channel(&channel, 9.0, &mut out);
    assert_eq!(out, [1.0; 3]);
}

const DOOR: &str = r#"AuthoredClipSet(
    targets: ["door", "lift"],
    clips: [
        AuthoredClip(
            name: "open",
            tracks: [
                AuthoredTrack(target: "door", property: Translation, interpolation: Linear,
                    keys: [AuthoredKey(time_seconds: 0.0, value: [0.0, 0.0, 0.0]),
                           AuthoredKey(time_seconds: 1.5, value: [0.0, 2.5, 0.0])]),
                AuthoredTrack(target: "lift", property: Rotation, interpolation: Step,
                    keys: [AuthoredKey(time_seconds: 0.0, value: [0.0, 0.0, 0.0, 2.0]),
                           AuthoredKey(time_seconds: 1.0, value: [0.0, 2.0, 0.0, 0.0])]),
            ],
            events: [ClipEvent(time_seconds: 1.5, name: "opened")],
        ),
    ],
)"#;

#[test]
fn authored_clips_from_ron() -> TestResult {
    let file = Path::new("levels/door.ron");
    let clips = AuthoredClipSet::from_ron(file, DOOR)?.to_clips(file)?;
    assert_eq!(clips.len(), 1);
    assert_eq!(clips[0].duration_seconds, 1.5);
    let mut player = AnimationPlayer::new();
    player.play(Playback::new(0, PlayMode::Once));
    player.tick(&clips, 0.75);
    let pose = player.pose(&clips, &Pose::identity(2));
    assert!((pose.translation[0].y - 1.25).abs() < EPS);
    // Authored rotations are normalised: (0, 0, 0, 2) is the identity.
    assert!(pose.rotation[1].abs_diff_eq(Quat::IDENTITY, EPS));
    assert_eq!(names(&player.tick(&clips, 1.0)), ["opened"]);
    let pose = player.pose(&clips, &Pose::identity(2));
    assert!(pose.rotation[1].abs_diff_eq(Quat::from_xyzw(0.0, 1.0, 0.0, 0.0), EPS));
    Ok(())
}

#[test]
fn authored_clip_errors_name_the_file_and_item() {
    let file = Path::new("levels/door.ron");
    let unknown = DOOR.replace(r#"target: "lift""#, r#"target: "lfit""#);
    match AuthoredClipSet::from_ron(file, &unknown).and_then(|s| s.to_clips(file)) {
        Err(error @ AnimError::UnknownTarget { .. }) => {
            let message = error.to_string();
            assert!(
                message.contains("door.ron") && message.contains("lfit"),
                "{message}"
            );
        }
        other => panic!("expected UnknownTarget, got {other:?}"),
    }
    let short = DOOR.replace("value: [0.0, 2.5, 0.0]", "value: [0.0, 2.5]");
    match AuthoredClipSet::from_ron(file, &short).and_then(|s| s.to_clips(file)) {
        Err(error @ AnimError::BadChannel { .. }) => {
            assert!(error.to_string().contains("key 1"), "{error}");
        }
        other => panic!("expected BadChannel, got {other:?}"),
    }
    let nan = DOOR.replace("time_seconds: 1.5, value", "time_seconds: NaN, value");
    assert!(matches!(
        AuthoredClipSet::from_ron(file, &nan).and_then(|s| s.to_clips(file)),
        Err(AnimError::NonFiniteKey { key: 1, .. })
    ));
    assert!(matches!(
        AuthoredClipSet::from_ron(file, "AuthoredClipSet(targets: [], clips: [], extra: 1)"),
        Err(AnimError::BadRon { .. })
    ));
}

#[test]
fn example_level_clips_load_and_play() -> TestResult {
    let file = Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../assets/test_scenes/anim/door_and_lift.ron"
    ));
    let set = AuthoredClipSet::load(file)?;
    let clips = set.to_clips(file)?;
    let lift = clips
        .iter()
        .position(|c| c.name == "lift_cycle")
        .ok_or("no lift_cycle clip")?;
    let target = set
        .targets
        .iter()
        .position(|t| t == "lift")
        .ok_or("no lift target")?;
    let mut player = AnimationPlayer::new();
    player.play(Playback::new(lift, PlayMode::PingPong));
    // Up the shaft and back: the platform never leaves [0, 6] m and ends where it started.
    let mut arrivals = 0;
    for _ in 0..(12 * 60) {
        let fired = player.tick(&clips, 1.0 / 60.0);
        arrivals += fired.iter().filter(|e| e.name == "lift_arrived").count();
        let y = player
            .pose(&clips, &Pose::identity(set.targets.len()))
            .translation[target]
            .y;
        assert!((-EPS..=6.0 + EPS).contains(&y), "{y}");
    }
    // 12 s of ping-pong over a 6 s clip passes the 5 s mark once up and once down.
    assert_eq!(arrivals, 2);
    let y = player
        .pose(&clips, &Pose::identity(set.targets.len()))
        .translation[target]
        .y;
    assert!(y.abs() < 1e-3, "{y}");
    assert!(matches!(
        AuthoredClipSet::load(Path::new("no/such/clips.ron")),
        Err(AnimError::Asset(_))
    ));
    Ok(())
}
