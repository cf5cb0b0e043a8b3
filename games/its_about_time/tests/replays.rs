//! The committed replays play headless (CPU tracer) and must still solve what they were
//! recorded for: the whole game (every artifact, each puzzle solved as its design says, the
//! ending) and each puzzle's own replay from the start. A recording cut short does not reach
//! the ending, and the binary says so with a non-zero exit.

use std::path::{Path, PathBuf};

use its_about_time::camera_areas::share_inside;
use its_about_time::game::TimeEvent;
use its_about_time::game::soundscape::Surface;
use its_about_time::headless::{RunSummary, play_replay};
use its_about_time::replays::{full_game, named};
use its_about_time::world::RuinsWorld;

fn world() -> anyhow::Result<RuinsWorld> {
    RuinsWorld::open(Some(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/its_about_time/ruins.ron"),
    ))
}

fn replay(world: &RuinsWorld) -> PathBuf {
    full_game(world.root.path())
}

/// The first rising (or falling) of the rule `name`: its step and local hours.
fn rule(run: &RunSummary, name: &str, rising: bool) -> Option<(u64, Option<f64>)> {
    run.log.iter().find_map(|(step, e)| match e {
        TimeEvent::Rule {
            name: n,
            rising: r,
            hours,
        } if n == name && *r == rising => Some((*step, *hours)),
        _ => None,
    })
}

/// The step an artifact was taken.
fn taken(run: &RunSummary, artifact: &str) -> Option<u64> {
    run.log.iter().find_map(|(step, e)| match e {
        TimeEvent::Artifact(a) if a == artifact => Some(*step),
        _ => None,
    })
}

/// The sun gate rose only after time was turned forward, at the hour the slot lets the sun in
/// (about 15:15 local solar time), and before the disc behind it was taken.
fn sun_gate_solved(run: &RunSummary) {
    let line = run.line();
    let turn = (run.log.iter()).find(|(_, e)| matches!(e, TimeEvent::Turned(s) if *s > 0.0));
    let gate = rule(run, "sun_gate", true);
    let disc = taken(run, "artifact_sun");
    let (Some(turn), Some((gate, hours)), Some(disc)) = (turn, gate, disc) else {
        panic!("turn {turn:?}, gate {gate:?}, disc {disc:?}: {line}");
    };
    assert!(turn.0 < gate && gate < disc, "{turn:?} {gate} {disc}");
    let hours = hours.expect("the ruins' sky has a time");
    assert!(
        (14.0..16.5).contains(&hours),
        "the gate rose at {hours} h: {line}"
    );
}

/// The pool was drained at the sluice, filled again from its floor, and the Rain Jar on the
/// terrace (out of reach from the floor and from outside) was taken only after the water had
/// carried the float up (2 s still, then 4 s rising: 6 s = 360 fixed steps after the fill);
/// then drained again from the terrace to come down.
fn water_stair_solved(run: &RunSummary) {
    let line = run.line();
    let drained = rule(run, "pool_drains_sluice", true).map(|r| r.0);
    let filled = rule(run, "pool_fills", true).map(|r| r.0);
    let jar = taken(run, "artifact_water");
    let (Some(drained), Some(filled), Some(jar)) = (drained, filled, jar) else {
        panic!("drained {drained:?}, filled {filled:?}, jar {jar:?}: {line}");
    };
    assert!(drained < filled, "{line}");
    assert!(
        jar >= filled + 360,
        "the jar was taken {} steps after the fill: {line}",
        jar - filled
    );
    let down = rule(run, "pool_drains_terrace", true).map(|r| r.0);
    assert!(
        down.is_some_and(|d| d > jar),
        "never drained from the terrace: {line}"
    );
}

/// The vault of weights opened, then its Balance Stone was taken; the explorer leaned into
/// the blocks with its push pose before the vault opened.
fn weights_solved(run: &RunSummary) {
    let open = rule(run, "weights_open", true).map(|r| r.0);
    let pushed = (run.log.iter()).find(|(_, e)| matches!(e, TimeEvent::Push(true)));
    assert!(
        matches!((pushed, open), (Some(p), Some(o)) if p.0 < o),
        "pushed {pushed:?}, open {open:?}: {}",
        run.line()
    );
    let stone = taken(run, "artifact_weights");
    assert!(
        matches!((open, stone), (Some(o), Some(s)) if o < s),
        "open {open:?}, taken {stone:?}: {}",
        run.line()
    );
}

/// The boulder was released, the brittle wall broke, and the Thunder Stone behind it was taken.
fn rolling_stone_solved(run: &RunSummary) {
    let released = rule(run, "boulder_released", true).map(|r| r.0);
    let stone = taken(run, "artifact_stone");
    assert_eq!(run.broken, 1, "the wall stands: {}", run.line());
    assert!(
        matches!((released, stone), (Some(r), Some(s)) if r < s),
        "released {released:?}, taken {stone:?}: {}",
        run.line()
    );
}

/// Night fell before any torch took; a wrong torch put the lit one out; then the four burned
/// in the wall's order (eye, sun, serpent, fret), the shrine opened and the Moon Mirror was taken.
fn night_shrine_solved(run: &RunSummary) {
    let line = run.line();
    let night = rule(run, "night_falls", true).expect("night fell").0;
    let torches: Vec<(u64, &str)> = (run.log.iter())
        .filter_map(|(step, e)| match e {
            TimeEvent::Rule {
                name, rising: true, ..
            } if name.starts_with("torch_") => Some((*step, name.as_str())),
            _ => None,
        })
        .collect();
    let names: Vec<&str> = torches.iter().map(|t| t.1).collect();
    assert_eq!(
        names,
        [
            "torch_eye_lit",
            "torch_fret_wrong",
            "torch_eye_lit",
            "torch_sun_lit",
            "torch_serpent_lit",
            "torch_fret_lit"
        ],
        "{line}"
    );
    assert!(torches[0].0 > night, "a torch before nightfall: {line}");
    assert!(
        rule(run, "night_falls", false).is_none_or(|d| d.0 > torches[5].0),
        "day came back while the torches were lit: {line}"
    );
    let open = rule(run, "shrine_open", true).expect("the shrine opened").0;
    let mirror = taken(run, "artifact_night").expect("the mirror was taken");
    assert!(torches[5].0 <= open && open < mirror, "{line}");
    let hours = run.local_hours.expect("the ruins' sky has a time");
    assert!(
        !(6.5..18.0).contains(&hours),
        "it is day at the end ({hours} h): {line}"
    );
}

#[test]
fn the_full_game_replay_solves_every_puzzle_and_reaches_the_ending() -> anyhow::Result<()> {
    let world = world()?;
    let run = play_replay(&world, &replay(&world))?;
    let line = run.line();
    assert!(run.solved(), "{line}");
    assert_eq!(
        run.artifacts,
        [
            "artifact_sun",
            "artifact_water",
            "artifact_stone",
            "artifact_weights",
            "artifact_night"
        ],
        "{line}"
    );
    sun_gate_solved(&run);
    water_stair_solved(&run);
    rolling_stone_solved(&run);
    weights_solved(&run);
    night_shrine_solved(&run);
    footsteps_follow_the_ground(&run);
    events_sound_their_own(&run);
    Ok(())
}

/// Each puzzle's moments sound the game's own one-shots (`assetgen ruins-sounds`), not
/// Reflect's chime and door: five artifact chimes; a torch catching at each torch lit in order
/// (the route lights one, puts it out with a wrong torch on purpose, then lights all four:
/// five) and the douse at the wrong one; the sluice at every drain and fill of the water
/// stair; and the temple waking once at the end.
fn events_sound_their_own(run: &RunSummary) {
    let count = |name: &str| run.sounds.iter().filter(|s| *s == name).count();
    let counts: Vec<(&str, usize)> = [
        "artifact_chime",
        "torch_ignite",
        "torch_douse",
        "sluice",
        "altar_gong",
        "temple_awake",
        "chime",
        "door",
    ]
    .iter()
    .map(|n| (*n, count(n)))
    .collect();
    eprintln!("sounds started: {counts:?}");
    assert_eq!(count("artifact_chime"), 5, "{counts:?}");
    assert_eq!(count("torch_ignite"), 5, "{counts:?}");
    assert_eq!(count("torch_douse"), 1, "{counts:?}");
    assert!(count("sluice") >= 2, "{counts:?}");
    assert_eq!(count("temple_awake"), 1, "{counts:?}");
    assert_eq!(count("chime") + count("door"), 0, "{counts:?}");
}

/// The explorer's footsteps sound what lies under its feet: the whole game walks mostly on the
/// plaza's sand and sometimes on stone (plates, glyph tiles, the broken wall's pieces), about a
/// stride (0.8 m) apart, so a few hundred in three minutes of play.
fn footsteps_follow_the_ground(run: &RunSummary) {
    let count = |s: Surface| run.footsteps.iter().filter(|(_, f)| *f == s).count();
    let (sand, stone) = (count(Surface::Sand), count(Surface::Stone));
    assert!(
        sand > 100 && stone > 0 && stone < sand,
        "footsteps: {sand} on sand, {stone} on stone"
    );
}

/// While the explorer solves a puzzle — from the replay's first event (time turned, a rule
/// rising, a push) to its artifact — the follow camera stays inside the puzzle's render area
/// (`render_areas` in the level), so the light table is the area's, not every group's: at
/// least 95 % of those frames. Before issue 36 widened the boxes, the sun gate's camera spent
/// the time turning at the plaza's sun altar outside every box (44 % of the whole replay in
/// its area), the water stair's stood at the levers east of its box, the night shrine's at
/// its altar north of its box.
fn camera_stays_in_its_area(world: &RuinsWorld, run: &RunSummary, area: &str, artifact: &str) {
    let first = run.log.first().map_or(0, |(step, _)| *step) as usize;
    let Some(last) = taken(run, artifact) else {
        panic!("{artifact} not taken: {}", run.line());
    };
    let path = &run.camera_path;
    let solving = &path[first.min(path.len())..(last as usize).min(path.len())];
    let share = share_inside(&world.level.render_areas, solving, area);
    eprintln!(
        "{area}: camera in its area {:.1} % of {} frames solving (steps {first}..{last}), {:.1} % of the replay",
        100.0 * share,
        solving.len(),
        100.0 * share_inside(&world.level.render_areas, path, area)
    );
    assert!(
        solving.len() > 60 && share >= 0.95,
        "{area}: the camera was in its area {:.1} % of the {} frames solving: {}",
        100.0 * share,
        solving.len(),
        run.line()
    );
}

#[test]
fn each_puzzle_replay_takes_its_artifact() -> anyhow::Result<()> {
    let world = world()?;
    let play = |name: &str| {
        let run = play_replay(&world, &named(world.root.path(), name))?;
        let artifact = run.artifacts.first().cloned().unwrap_or_default();
        camera_stays_in_its_area(&world, &run, name, &artifact);
        anyhow::Ok(run)
    };
    let run = play("sun_gate")?;
    assert_eq!(run.artifacts, ["artifact_sun"], "{}", run.line());
    sun_gate_solved(&run);
    let run = play("water_stair")?;
    assert_eq!(run.artifacts, ["artifact_water"], "{}", run.line());
    water_stair_solved(&run);
    let run = play("rolling_stone")?;
    assert_eq!(run.artifacts, ["artifact_stone"], "{}", run.line());
    rolling_stone_solved(&run);
    let run = play("weights")?;
    assert_eq!(run.artifacts, ["artifact_weights"], "{}", run.line());
    weights_solved(&run);
    let run = play("night_shrine")?;
    assert_eq!(run.artifacts, ["artifact_night"], "{}", run.line());
    night_shrine_solved(&run);
    assert!(
        !run.ending,
        "one artifact does not end the game: {}",
        run.line()
    );
    Ok(())
}

#[test]
fn a_replay_cut_short_does_not_reach_the_ending() -> anyhow::Result<()> {
    let world = world()?;
    let mut cut = candela::app::Recording::read(&replay(&world))?;
    let total: u32 = cut.runs.iter().map(|r| r.steps).sum();
    let mut keep = total / 3;
    cut.runs.retain_mut(|run| {
        let take = run.steps.min(keep);
        keep -= take;
        run.steps = take;
        take > 0
    });
    let path = std::env::temp_dir().join(format!("iat_cut_{}.replay", std::process::id()));
    cut.write(&path)?;
    let run = play_replay(&world, &path)?;
    let _ = std::fs::remove_file(&path);
    assert!(!run.solved() && !run.ending, "{}", run.line());
    assert!(run.artifacts.len() < 5, "{}", run.line());
    // And the binary exits non-zero naming the file.
    cut.write(&path)?;
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_its_about_time"))
        .args(["--headless", "--replay"])
        .arg(&path)
        .output()?;
    let _ = std::fs::remove_file(&path);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{err}");
    assert!(err.contains("did not reach the ending"), "{err}");
    Ok(())
}
