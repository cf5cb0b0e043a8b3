//! Triggers end to end, headless (issue 4): in `assets/test_scenes/gameplay/plate_door.ron` a
//! crate falls on a pressure plate, and through the engine's own frame loop (CPU tracer,
//! 24×16, 1 spp) that
//! * opens the door: the `door_open` clip runs, the door's `Transform` and its kinematic body
//!   end 1.6 m to the side, and the clip's `door_opened` event wins the level;
//! * switches light group 2 on: the render thread's own light distribution grows from the
//!   hall lamp's 12 emissive triangles to 24, in the frame after the crate landed;
//! * plays the chime at the plate, recorded by the silent audio backend.
//!
//! The same run twice gives the same state hash (deterministic triggers).

use std::path::PathBuf;

use candela::app::{Engine, Step};
use candela::assets::AssetRoot;
use candela::ecs::Transform;
use candela::level::load_level;
use candela::render::RenderConfig;
use candela::sim::triggers::{OccupantKind, Outcome, Phase};
use glam::Vec3;

fn assets() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../assets")
}

/// What one run saw.
#[derive(Debug, PartialEq)]
struct Run {
    /// Fixed step at which the crate entered the plate, and at which the level was won.
    entered_step: u64,
    won_step: u64,
    /// Light counts the render thread reported, frame by frame.
    lights: Vec<u32>,
    /// Bits of the final crate and door transforms.
    hash: u64,
    /// What the silent audio backend recorded: (name, seconds, position) of each sound.
    played: Vec<(String, f64, Option<Vec3>)>,
}

fn hash(values: &[f32]) -> u64 {
    // FNV-1a over the bits: any difference in any value changes it.
    values.iter().fold(0xcbf2_9ce4_8422_2325, |h, v| {
        (h ^ u64::from(v.to_bits())).wrapping_mul(0x100_0000_01b3)
    })
}

fn run() -> anyhow::Result<Run> {
    let root = AssetRoot::new(assets())?;
    let path = assets().join("test_scenes/gameplay/plate_door.ron");
    let scene = load_level(&path, &root)?;
    let config = RenderConfig {
        seed: 5,
        ..RenderConfig::cpu(24, 16)
    };
    let mut engine = Engine::new(config, candela::app::Environment::of(&scene.scene))?;
    let spawned = engine.spawn_level(&scene);
    let (crate_, door) = (spawned.by_name["crate"], spawned.by_name["door"]);
    let door_rest = engine.world().get::<&Transform>(door)?.translation;
    let plate = engine.logic().volume_index("plate").expect("volume");

    let mut lights = Vec::new();
    let mut entered_step = None;
    let mut won_step = None;
    // 1/60 s frames, one fixed step each; 4 s is enough to fall 1.2 m and open the door.
    for _ in 0..240 {
        engine.frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})?;
        let step = engine.logic().steps();
        let log = engine.logic().last_step();
        if log.volume_events.iter().any(|e| {
            e.volume == plate
                && e.occupant == crate_
                && e.kind == OccupantKind::Body
                && e.phase == Phase::Enter
        }) {
            assert!(entered_step.is_none(), "the crate entered twice");
            entered_step = Some(step);
        }
        if won_step.is_none() && engine.logic().outcome().is_some() {
            won_step = Some(step);
        }
        for rendered in engine.rendered() {
            lights.push(rendered?.lights);
        }
    }
    let entered_step = entered_step.expect("the crate never reached the plate");
    let won_step = won_step.expect("the level was never won");
    assert_eq!(
        engine.logic().outcome(),
        Some(&Outcome::Won("door_opened".into()))
    );

    // The door opened along its clip, and its kinematic body went with it.
    let door_now = engine.world().get::<&Transform>(door)?.translation;
    assert!(
        (door_now - (door_rest + Vec3::X * 1.6)).length() < 1e-5,
        "door at {door_now}, rest {door_rest}"
    );
    let (body, _) = engine.physics().pose(door).expect("door body");
    assert!(
        (body - door_now).length() < 1e-4,
        "body {body} vs {door_now}"
    );
    // The clip takes 1 s = 60 steps from the step after the plate was pressed; the event
    // fires on the step the playhead reaches the end.
    assert_eq!(
        won_step,
        entered_step + 60,
        "entered {entered_step}, won {won_step}"
    );

    // The chime: started by the rule in the crate's entry step, at the plate, and heard.
    assert!(
        engine.audio().is_silent(),
        "headless engines record silently"
    );
    let played: Vec<(String, f64, Option<Vec3>)> = engine
        .audio()
        .played()
        .iter()
        .map(|p| (p.name.to_string(), p.time_seconds, p.position))
        .collect();
    let rate = f64::from(engine.audio().recorded_sample_rate_hz().expect("silent"));
    let samples = engine.audio().recorded_samples().expect("silent");
    assert_eq!(
        engine.audio().recorded_start_frame(),
        0,
        "4 s fit in the recording"
    );
    let start = ((entered_step - 1) as f64 / 60.0 * rate) as usize;
    // Every recorded sample is finite (a NaN would vanish in the `f32::max` fold of `peak`),
    // and both windows hold samples (an empty window's peak is 0).
    if let Some(bad) = samples.iter().flatten().position(|s| !s.is_finite()) {
        anyhow::bail!("recorded sample {bad} is not finite");
    }
    assert!(
        start > 0 && samples.len() >= start + rate as usize / 2,
        "the recording ({} frames) does not cover the half second after the plate (frame {start})",
        samples.len()
    );
    let peak = |range: &[[f32; 2]]| range.iter().flatten().fold(0.0f32, |m, s| m.max(s.abs()));
    assert_eq!(
        peak(&samples[..start]),
        0.0,
        "silence before the plate was pressed"
    );
    let heard = peak(&samples[start..(start + rate as usize / 2).min(samples.len())]);
    assert!(
        heard > 0.01,
        "the chime is not in the recording (peak {heard})"
    );

    let crate_now = *engine.world().get::<&Transform>(crate_)?;
    let hash = hash(
        &[
            crate_now.translation.to_array(),
            crate_now.rotation.to_array()[..3].try_into()?,
            door_now.to_array(),
        ]
        .concat(),
    );
    for rendered in engine.shutdown() {
        lights.push(rendered?.lights);
    }
    Ok(Run {
        entered_step,
        won_step,
        lights,
        hash,
        played,
    })
}

#[test]
fn crate_on_plate_opens_door_switches_lights_plays_sound() -> anyhow::Result<()> {
    let first = run()?;
    println!(
        "crate entered the plate at step {}, won at {}",
        first.entered_step, first.won_step
    );
    // Light counts on the render side: the hall lamp alone, then both lamps.
    let lamp = 12;
    let switch = first
        .lights
        .iter()
        .position(|&l| l == 2 * lamp)
        .expect("group 2 never entered the render side's distribution");
    assert!(
        first.lights[..switch].iter().all(|&l| l == lamp),
        "{:?}",
        first.lights
    );
    assert!(
        first.lights[switch..].iter().all(|&l| l == 2 * lamp),
        "{:?}",
        first.lights
    );
    // Frame k runs fixed step k + 1; the rule fired in the crate's entry step, so the render
    // side sees the new table in that same frame's commit.
    assert_eq!(switch as u64 + 1, first.entered_step, "{:?}", first.lights);

    // One chime, at the plate, in the step the crate entered (audio time counts steps before
    // that one: the sound starts at the beginning of the step's audio).
    assert_eq!(first.played.len(), 1, "{:?}", first.played);
    let (name, time, at) = &first.played[0];
    assert_eq!(name, "chime");
    assert!(
        (time - (first.entered_step - 1) as f64 / 60.0).abs() < 1e-9,
        "{time}"
    );
    assert_eq!(*at, Some(Vec3::new(0.0, 0.02, 0.0)));

    let second = run()?;
    assert_eq!(
        first, second,
        "the same level and input must give the same run"
    );
    Ok(())
}
