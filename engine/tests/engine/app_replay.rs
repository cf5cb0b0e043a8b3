//! Per-step input recording and replay: record → write → read → replay gives back exactly the
//! frames recorded, whatever the frame pacing on either side; and every bad replay (truncated, another level, another game, another
//! step rate, an unknown action, a wrong version, a corrupt byte) is a clear error naming the
//! file. The byte layout and the fixed point are checked in `app_replay_format.rs`.

use crate::app_common;

use std::path::Path;

use anyhow::Result;
use app_common::Scratch;
use candela::app::{
    ActionDef, ActionFrame, ActionKind, ActionSet, Binding, FixedClock, InputState, KeyCode,
    MouseButton, PadAxis, PadButton, Recorder, Recording, Replay, ReplayError, ReplayTarget,
    StepInput, game_actions as ga, level_hash, quantise_axis, quantise_motion,
};

const GAME: &str = "reflect";
const LEVEL: &str = "test_walk";
const HZ: f64 = 60.0;

/// One thing the player does, at the start of step `.0` (steps count from 0).
#[derive(Clone, Copy)]
enum Ev {
    Key(KeyCode, bool),
    Mouse(MouseButton, bool),
    Motion(f32, f32),
    Pad(PadButton, bool),
    Stick(PadAxis, f32),
}

/// A scripted player: walk, look around with fractional mouse counts, tap jump inside one
/// step, push the stick, click.
fn script() -> Vec<(u64, Ev)> {
    use Ev::*;
    let mut s = vec![
        (0, Key(KeyCode::KeyW, true)),
        (3, Motion(1.5, -0.25)),
        (3, Motion(0.125, 0.0)),
        (10, Key(KeyCode::Space, true)),
        (10, Key(KeyCode::Space, false)), // a tap shorter than a step
        (20, Stick(PadAxis::LeftStickX, 0.333)),
        (25, Pad(PadButton::West, true)),
        (26, Pad(PadButton::West, false)),
        (40, Key(KeyCode::KeyW, false)),
        (41, Mouse(MouseButton::Left, true)),
        (44, Mouse(MouseButton::Left, false)),
        (50, Stick(PadAxis::LeftStickX, 0.0)),
    ];
    s.extend((60..70).map(|i| (i, Motion(i as f32 * 0.37, 1.0))));
    s
}

fn apply(input: &mut InputState, ev: Ev) {
    match ev {
        Ev::Key(k, d) => input.key(k, d),
        Ev::Mouse(b, d) => input.mouse_button(b, d),
        Ev::Motion(x, y) => input.mouse_motion(x, y),
        Ev::Pad(b, d) => input.pad_button(b, d),
        Ev::Stick(a, v) => input.pad_axis(a, v),
    }
}

/// Plays the script for `steps` steps, each step's events spread over `frames_per_step`
/// frames (so frame boundaries fall differently), through `source`; returns the frames.
fn play(
    set: &ActionSet,
    source: &mut StepInput,
    steps: u64,
    frames_per_step: usize,
) -> Result<Vec<ActionFrame>> {
    let mut input = InputState::new(&set.default_map());
    let events = script();
    let mut out = Vec::new();
    for step in 0..steps {
        let now: Vec<Ev> = events
            .iter()
            .filter(|(s, _)| *s == step)
            .map(|e| e.1)
            .collect();
        for f in 0..frames_per_step {
            for (i, ev) in now.iter().enumerate() {
                if i % frames_per_step == f {
                    apply(&mut input, *ev);
                }
            }
            if f + 1 < frames_per_step {
                input.end_frame(); // a rendered frame without a fixed step
            }
        }
        out.extend(source.next_step(&mut input, set)?);
        input.end_frame();
    }
    Ok(out)
}

fn target<'a>(set: &'a ActionSet, hash: u64) -> ReplayTarget<'a> {
    ReplayTarget {
        game: GAME,
        level_id: LEVEL,
        level_hash: hash,
        step_hz: HZ,
        actions: set,
    }
}

/// A level file and its hash, and a recording of the script on it.
fn recorded(dir: &Scratch, set: &ActionSet) -> Result<(u64, std::path::PathBuf, Vec<ActionFrame>)> {
    let level = dir.join("level.ron");
    std::fs::write(&level, "Level(models: [], instances: [])")?;
    let hash = level_hash(&level)?;
    let path = dir.join("walk.replay");
    let mut rec = StepInput::record(Recorder::new(GAME, LEVEL, hash, HZ, set), &path);
    let frames = play(set, &mut rec, 120, 1)?;
    rec.finish()?;
    Ok((hash, path, frames))
}

#[test]
fn record_then_replay_gives_back_exactly_the_frames() -> Result<()> {
    let dir = Scratch::new("replay_round_trip");
    let set = ActionSet::standard();
    let (hash, path, frames) = recorded(&dir, &set)?;
    assert_eq!(frames.len(), 120);
    let id = |n| set.id(n).expect("id");
    assert!(frames[0].held(id(ga::MOVE_FORWARD)) && frames[0].pressed(id(ga::MOVE_FORWARD)));
    assert!(!frames[1].pressed(id(ga::MOVE_FORWARD)) && frames[1].held(id(ga::MOVE_FORWARD)));
    assert!(
        frames[10].pressed(id(ga::JUMP)) && !frames[10].held(id(ga::JUMP)),
        "the tap"
    );
    assert_eq!(frames[3].raw(id(ga::LOOK_X)), quantise_motion(1.625));
    assert_eq!(frames[3].raw(id(ga::LOOK_Y)), quantise_motion(-0.25));
    assert_eq!(frames[4].raw(id(ga::LOOK_X)), 0);
    assert_eq!(frames[30].raw(id(ga::MOVE_X)), quantise_axis(0.333));

    let mut replay = Replay::open(&path, &target(&set, hash))?;
    assert_eq!(replay.steps(), 120);
    assert!(
        replay.header().game == GAME && replay.header().level_id == LEVEL,
        "{:?}",
        replay.header()
    );
    // Replayed under an irregular frame pacing: steps, not frames, pull the frames.
    let mut clock = FixedClock::new(HZ);
    let pacing = [0.007, 0.05, 0.0, 0.016, 0.1, 0.033];
    let mut back = Vec::new();
    let mut frame = 0;
    while !replay.finished() {
        for _ in 0..clock.advance(pacing[frame % pacing.len()]) {
            back.extend(replay.next_frame());
        }
        frame += 1;
    }
    assert_eq!(back, frames);
    assert_eq!(replay.next_frame(), None);

    // The same through StepInput, and the file is compact (runs, not one record per step).
    let mut source = StepInput::Replay(Replay::open(&path, &target(&set, hash))?);
    let again = play(&set, &mut source, 130, 1)?;
    assert_eq!(again, frames, "after the last step a replay yields nothing");
    let recording = Recording::read(&path)?;
    assert!(recording.runs.len() < 40, "{} runs", recording.runs.len());
    assert!(std::fs::metadata(&path)?.len() < 4096);
    Ok(())
}

#[test]
fn frame_boundaries_between_steps_do_not_change_the_frames() -> Result<()> {
    let set = ActionSet::standard();
    let record = |frames_per_step| -> Result<Vec<ActionFrame>> {
        let mut rec = StepInput::record(
            Recorder::new(GAME, LEVEL, 1, HZ, &set),
            Path::new("unused.replay"),
        );
        play(&set, &mut rec, 80, frames_per_step)
    };
    let one = record(1)?;
    assert_eq!(record(2)?, one);
    assert_eq!(record(5)?, one);
    Ok(())
}

#[test]
fn a_truncated_replay_names_the_file_and_where_it_ends() -> Result<()> {
    let dir = Scratch::new("replay_truncated");
    let set = ActionSet::standard();
    let (hash, path, _) = recorded(&dir, &set)?;
    let bytes = std::fs::read(&path)?;
    let cut = dir.join("cut.replay");
    for (len, at) in [
        (14, "inside the header"),
        (bytes.len() / 2, "in step"),
        (bytes.len() - 12, "in step"),
        (bytes.len() - 3, "before its checksum"),
    ] {
        std::fs::write(&cut, &bytes[..len])?;
        match Replay::open(&cut, &target(&set, hash)) {
            Err(e @ ReplayError::Truncated { .. }) => {
                let m = e.to_string();
                assert!(m.starts_with(&cut.display().to_string()), "{m}");
                assert!(m.contains(at), "cut at {len}: {m}");
            }
            other => panic!("cut at {len}: expected truncated, got {other:?}"),
        }
    }
    std::fs::write(&cut, &bytes[..5])?;
    assert!(matches!(
        Replay::open(&cut, &target(&set, hash)),
        Err(ReplayError::NotARecording { .. })
    ));
    Ok(())
}

#[test]
fn a_replay_from_another_level_game_or_step_rate_is_refused() -> Result<()> {
    let dir = Scratch::new("replay_other_level");
    let set = ActionSet::standard();
    let (hash, path, _) = recorded(&dir, &set)?;
    // The same level id, its file edited since: another content hash.
    let level = dir.join("level.ron");
    std::fs::write(
        &level,
        "Level(models: [], instances: [], sky: Constant((1, 1, 1)))",
    )?;
    let edited = level_hash(&level)?;
    assert_ne!(edited, hash);
    let e = Replay::open(&path, &target(&set, edited)).expect_err("other level");
    let m = e.to_string();
    assert!(matches!(e, ReplayError::OtherLevel { .. }), "{e:?}");
    assert!(m.starts_with(&path.display().to_string()), "{m}");
    assert!(
        m.contains(&format!("{hash:016x}")) && m.contains(&format!("{edited:016x}")),
        "{m}"
    );
    // Another level id with the same bytes.
    let other = ReplayTarget {
        level_id: "tower",
        ..target(&set, hash)
    };
    assert!(matches!(
        Replay::open(&path, &other),
        Err(ReplayError::OtherLevel { .. })
    ));
    let other_game = ReplayTarget {
        game: "its_about_time",
        ..target(&set, hash)
    };
    assert!(matches!(
        Replay::open(&path, &other_game),
        Err(ReplayError::OtherGame { .. })
    ));
    let other_rate = ReplayTarget {
        step_hz: 120.0,
        ..target(&set, hash)
    };
    assert!(matches!(
        Replay::open(&path, &other_rate),
        Err(ReplayError::StepRate { .. })
    ));
    Ok(())
}

#[test]
fn unknown_actions_and_kinds_are_named_and_known_ones_are_remapped() -> Result<()> {
    let dir = Scratch::new("replay_actions");
    let grapple = ActionDef {
        name: "grapple".into(),
        kind: ActionKind::Button,
        defaults: vec![Binding::Key(KeyCode::KeyG)],
    };
    let with_grapple = ActionSet::standard().with(grapple.clone())?;
    let path = dir.join("grapple.replay");
    let mut rec = Recorder::new(GAME, LEVEL, 7, HZ, &with_grapple);
    let mut f = ActionFrame::empty(&with_grapple);
    let g = with_grapple.id("grapple").expect("id");
    f.held |= 1 << g.0;
    f.values[with_grapple.id(ga::LOOK_X).expect("id").0 as usize] = 99;
    rec.push(f)?;
    rec.write(&path)?;

    let standard = ActionSet::standard();
    match Replay::open(&path, &target(&standard, 7)) {
        Err(e @ ReplayError::UnknownAction { .. }) => {
            let m = e.to_string();
            assert!(m.starts_with(&path.display().to_string()), "{m}");
            assert!(m.contains("unknown action `grapple`"), "{m}");
        }
        other => panic!("expected an unknown action, got {other:?}"),
    }

    // A game whose set lists grapple first and adds an action: frames follow the names.
    let reordered = ActionSet::new(
        std::iter::once(grapple)
            .chain(ActionSet::standard().defs().iter().cloned())
            .chain(std::iter::once(ActionDef {
                name: "crouch".into(),
                kind: ActionKind::Button,
                defaults: vec![],
            }))
            .collect(),
    )?;
    let frame = Replay::open(&path, &target(&reordered, 7))?
        .next_frame()
        .expect("one step");
    assert!(frame.held(reordered.id("grapple").expect("id")));
    assert_eq!(frame.held.count_ones(), 1);
    assert_eq!(frame.raw(reordered.id(ga::LOOK_X).expect("id")), 99);
    assert_eq!(frame.values.len(), reordered.len());

    // The same name with another kind.
    let kind_changed = ActionSet::standard().with(ActionDef {
        name: "grapple".into(),
        kind: ActionKind::Axis,
        defaults: vec![],
    })?;
    assert!(matches!(
        Replay::open(&path, &target(&kind_changed, 7)),
        Err(ReplayError::ActionKind { .. })
    ));
    Ok(())
}

#[test]
fn a_wrong_version_or_a_corrupt_byte_is_refused() -> Result<()> {
    let dir = Scratch::new("replay_version");
    let set = ActionSet::standard();
    let (hash, path, _) = recorded(&dir, &set)?;
    let bytes = std::fs::read(&path)?;
    let bad = dir.join("bad.replay");

    let mut v3 = bytes.clone();
    v3[8..12].copy_from_slice(&3u32.to_le_bytes());
    std::fs::write(&bad, &v3)?;
    match Replay::open(&bad, &target(&set, hash)) {
        Err(e @ ReplayError::Version { found: 3, .. }) => {
            assert!(e.to_string().contains("bad.replay"), "{e}");
            assert!(e.to_string().contains("version 3"), "{e}");
        }
        other => panic!("expected a version error, got {other:?}"),
    }

    let mut flipped = bytes.clone();
    let last_frame_byte = bytes.len() - 9;
    flipped[last_frame_byte] ^= 0x10;
    std::fs::write(&bad, &flipped)?;
    assert!(matches!(
        Replay::open(&bad, &target(&set, hash)),
        Err(ReplayError::Corrupt { .. })
    ));

    let mut longer = bytes.clone();
    longer.push(0);
    std::fs::write(&bad, &longer)?;
    assert!(matches!(
        Replay::open(&bad, &target(&set, hash)),
        Err(ReplayError::Corrupt { .. })
    ));
    let missing = Replay::open(&dir.join("none.replay"), &target(&set, hash)).expect_err("missing");
    assert!(missing.to_string().contains("none.replay"), "{missing}");
    Ok(())
}
