//! Time a game can turn (issue 34, items 5 and 6): a time of day set in a fixed step shows in
//! the next step's sun and moon and in the state hash, runs repeat bit for bit, the day flows at
//! the sky's `time_rate`, converging restarts on a jumping sun and floors on a slow one (and
//! keeps averaging when nothing changes), the sky-view table is kept while the sun stays in one
//! elevation step (and built ahead, bit for bit, for the next), and the sky's exposure falls as
//! the sun climbs. CPU tracer, tiny films.

use candela::app::{Engine, Step, TimeChange, lighting_change};
use candela::assets::SkyDesc;
use candela::ecs::{Renderable, Static, Transform};
use candela::sky::{Baked, PhysicalSky, SkyBaker, SkyTime, exposure_ev};

use crate::pipeline_common::{config, environment, quad_model};

/// Munich, 21 June 2026, 05:00 UTC (the sun low in the north-east).
fn dawn() -> SkyTime {
    SkyTime {
        latitude_deg: 48.1,
        longitude_deg: 11.6,
        year: 2026,
        month: 6,
        day: 21,
        utc_hours: 5.0,
        time_rate: 0.0,
    }
}

fn sky_at(time: SkyTime) -> PhysicalSky {
    PhysicalSky {
        time: Some(time),
        ..PhysicalSky::default()
    }
}

fn engine_at(time: SkyTime) -> Engine {
    let mut env = environment();
    env.sky = SkyDesc::Physical(sky_at(time));
    let mut engine = Engine::new(config(1, 4), env).expect("engine");
    let floor = engine.add_model(&quad_model(20.0, 0.0));
    engine.world_mut().spawn((
        Transform::IDENTITY,
        Renderable {
            model: floor,
            material_override: None,
        },
        Static,
    ));
    engine
}

/// Runs `frames` one-step frames; the game sets the time to `noon_hours` in step 3. Returns
/// each step's sun elevation as the step saw it, and the state hash after every frame.
fn run(noon_hours: f64, frames: u64) -> (Vec<f64>, Vec<u64>) {
    let mut engine = engine_at(dawn());
    let mut seen = Vec::new();
    let mut hashes = Vec::new();
    let mut game = |step: &mut Step<'_>| {
        seen.push(
            step.sky
                .expect("a physical sky has a sun")
                .sun
                .elevation_deg,
        );
        if step.index == 3 {
            step.commands.set_time_of_day(noon_hours);
        }
    };
    for _ in 0..frames {
        engine.frame(1.0 / 60.0, &mut game).expect("frame");
        hashes.push(engine.state_hash());
    }
    engine.shutdown();
    (seen, hashes)
}

#[test]
fn a_time_set_in_a_step_moves_the_sun_from_the_next_step_and_runs_repeat() {
    let (seen, hashes) = run(11.0, 8);
    let dawn_elevation = sky_at(dawn()).now().unwrap().sun.elevation_deg;
    let noon = sky_at(dawn().at_hours(11.0).unwrap()).now().unwrap();
    assert_eq!(seen.len(), 8);
    for (i, e) in seen.iter().enumerate() {
        let want = if i <= 3 {
            dawn_elevation
        } else {
            noon.sun.elevation_deg
        };
        assert_eq!(*e, want, "step {i}: {seen:?}");
    }
    assert!(noon.sun.elevation_deg > dawn_elevation + 30.0, "{seen:?}");
    // The moon and its phase are there too (a date places the sky).
    let moon = noon.moon.expect("a dated sky has a moon");
    assert!((0.0..=1.0).contains(&moon.illuminated_fraction));
    // A replay goes through the same states; another time is another state.
    let (_, again) = run(11.0, 8);
    assert_eq!(hashes, again);
    let (_, other) = run(11.5, 8);
    // Frame 3's step set the time: the hashes differ from its end on.
    assert_eq!(hashes[..3], other[..3], "the same until the time is set");
    for k in 3..8 {
        assert_ne!(
            hashes[k], other[k],
            "the time is in the state hash (frame {k})"
        );
    }
}

#[test]
fn the_day_flows_at_the_sky_rate_and_the_game_turns_it_back() {
    let mut engine = engine_at(SkyTime {
        time_rate: 3600.0,
        ..dawn()
    });
    // 60 steps of 1/60 s at 3600 s of day per second: one hour.
    for _ in 0..60 {
        engine
            .frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})
            .expect("frame");
    }
    let time = engine.sky_now().and_then(|n| n.time).expect("a time");
    assert!((time.utc_hours - 6.0).abs() < 1e-9, "{time:?}");
    // An altar turns time backwards: two hours back, then the day stops.
    let mut once = true;
    engine
        .frame(1.0 / 60.0, &mut |step: &mut Step<'_>| {
            if std::mem::take(&mut once) {
                step.commands.advance_time(-7200.0 - 1.0);
                step.commands.set_time_rate(0.0);
            }
        })
        .expect("frame");
    let time = engine.sky_now().and_then(|n| n.time).expect("a time");
    assert!(
        (time.utc_hours - (4.0 - 1.0 / 3600.0)).abs() < 1e-9,
        "{time:?}"
    );
    // Bad changes leave the time alone and say why.
    assert!(engine.change_time(TimeChange::Hours(24.0)).is_err());
    assert!(engine.change_time(TimeChange::Rate(-1.0)).is_err());
    assert!(engine.change_time(TimeChange::Rate(f64::NAN)).is_err());
    assert_eq!(engine.sky_now().and_then(|n| n.time), Some(time));
    engine.shutdown();
}

#[test]
fn converging_restarts_on_a_jumping_sun_floors_on_a_slow_one_and_averages_otherwise() {
    let mut engine = engine_at(dawn());
    let step_frame = |engine: &mut Engine, change: Option<TimeChange>| {
        let mut change = change;
        engine
            .frame(1.0 / 60.0, &mut |step: &mut Step<'_>| match change.take() {
                Some(TimeChange::Hours(h)) => step.commands.set_time_of_day(h),
                Some(TimeChange::Advance(s)) => step.commands.advance_time(s),
                _ => {}
            })
            .expect("frame");
    };
    // Frames 0..4 still; 4 jumps to noon; 5..17 still; 17 advances one second of day; 18 still.
    for k in 0..19u64 {
        let change = match k {
            4 => Some(TimeChange::Hours(11.0)),
            17 => Some(TimeChange::Advance(1.0)),
            _ => None,
        };
        step_frame(&mut engine, change);
    }
    let blends: Vec<f32> = engine
        .shutdown()
        .into_iter()
        .map(|r| r.expect("render").blend)
        .collect();
    let floor = candela::render::film::ConvergePolicy::default().lighting_floor;
    assert_eq!(blends.len(), 19);
    assert_eq!(blends[..4], [1.0, 0.5, 1.0 / 3.0, 0.25], "{blends:?}");
    assert_eq!(
        blends[4], 1.0,
        "a time set hours away restarts the film: {blends:?}"
    );
    assert_eq!(blends[5..7], [0.5, 1.0 / 3.0], "{blends:?}");
    assert_eq!(
        blends[16],
        1.0 / 13.0,
        "nothing changed: the mean goes on: {blends:?}"
    );
    assert_eq!(
        blends[17], floor,
        "a slow sun keeps the lighting floor: {blends:?}"
    );
    assert!(blends[18] < floor, "still again: {blends:?}");
}

#[test]
fn lighting_change_measures_the_sun_and_flags_other_changes() {
    let a = SkyDesc::Physical(sky_at(dawn()));
    let b = SkyDesc::Physical(sky_at(dawn().advanced(60.0).unwrap()));
    let c = SkyDesc::Physical(PhysicalSky {
        haze: 3.0,
        ..sky_at(dawn())
    });
    assert_eq!(lighting_change((None, &a), (None, &a)), 0.0);
    let minute = lighting_change((None, &a), (None, &b));
    // The sun crosses the sky at about 0.25° a minute (less at dawn in June).
    assert!(minute > 0.1 && minute < 0.3, "{minute}");
    assert_eq!(lighting_change((None, &a), (None, &c)), f32::INFINITY);
    assert_eq!(
        lighting_change((None, &a), (None, &SkyDesc::Constant([1.0; 3]))),
        f32::INFINITY
    );
}

#[test]
fn the_sky_table_is_kept_within_an_elevation_step_and_rebuilt_past_it() {
    let mut baker = SkyBaker::default();
    let sky = |elevation: f32| PhysicalSky {
        sun_elevation_deg: elevation,
        ..PhysicalSky::default()
    };
    assert_eq!(baker.update(&sky(20.0)).unwrap(), Baked::All);
    let built = baker.texels().clone();
    assert_eq!(baker.update(&sky(20.04)).unwrap(), Baked::Kept);
    assert!(std::sync::Arc::ptr_eq(&built, baker.texels()));
    assert_eq!(baker.update(&sky(20.2)).unwrap(), Baked::View);
    assert_ne!(*built, **baker.texels());
    // The kept tables give the same sky as a full build at the same elevation step.
    let full = candela::sky::SkyTables::build(&sky(20.2)).unwrap();
    assert_eq!(full.texels, **baker.texels());
    // The sun moving on steadily: the next step's table was built ahead, with the same bits.
    assert_eq!(baker.update(&sky(20.3)).unwrap(), Baked::Ahead);
    let full = candela::sky::SkyTables::build(&sky(20.3)).unwrap();
    assert_eq!(full.texels, **baker.texels());
    // Turning back: the table built ahead (20.4) is not the one needed; built on the spot.
    assert_eq!(baker.update(&sky(20.2)).unwrap(), Baked::View);
    assert_eq!(
        candela::sky::SkyTables::build(&sky(20.2)).unwrap().texels,
        **baker.texels()
    );
    assert_eq!(
        baker
            .update(&PhysicalSky {
                haze: 2.0,
                ..sky(20.2)
            })
            .unwrap(),
        Baked::All
    );
}

#[test]
fn the_sky_exposure_falls_as_the_sun_climbs_and_noon_and_night_both_read() {
    let mut baker = SkyBaker::default();
    let mut last = f32::INFINITY;
    let mut evs = Vec::new();
    for elevation in [-10.0f32, -6.0, -3.0, 0.0, 3.0, 10.0, 30.0, 60.0, 90.0] {
        let sky = PhysicalSky {
            sun_elevation_deg: elevation,
            ..PhysicalSky::default()
        };
        baker.update(&sky).unwrap();
        let ev = exposure_ev(baker.horizontal_illuminance(&sky).unwrap());
        evs.push((elevation, ev));
        assert!(ev.is_finite() && ev <= last, "{evs:?}");
        last = ev;
    }
    // Printed for docs/ACCURACY.md ("Exposure from the sky"): `--no-capture`.
    for (e, ev) in &evs {
        println!("sun {e:5.1} deg: exposure {ev:6.2} EV");
    }
    let at = |e: f32| evs.iter().find(|(x, _)| *x == e).unwrap().1;
    assert!(
        at(-6.0) > at(0.0) && at(0.0) > at(10.0) && at(10.0) > at(60.0),
        "{evs:?}"
    );
    // Noon: a diffuse mid grey under ~1.4 units (~100 000 lx) is shown near mid grey.
    assert!((-2.0..=3.0).contains(&at(60.0)), "{evs:?}");
    // Nautical twilight: many stops brighter, but not the 19 stops a full meter would give.
    assert!((6.0..=20.0).contains(&at(-10.0)), "{evs:?}");
}

/// A level with a floor under a physical sky placed by `time` (RON), in a fresh folder.
fn level_dir(tag: &str, time: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("candela_sky_time_{tag}_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    let level = format!(
        "Level(materials: [(name: \"floor\", kind: Diffuse, base_color: (0.5, 0.5, 0.5))], \
         grids: [(name: \"floor\", size: (12, 12), divisions: (1, 1), material: \"floor\")], \
         instances: [(model: \"floor\")], \
         camera: (position: (0, 4, 9), look_at: (0, 0.5, 0), vertical_fov_deg: 45), \
         sky: Physical((time: Some({time}))), \
         needs: (sun: true, sky: true))"
    );
    std::fs::write(dir.join("level.ron"), level).expect("write level");
    dir
}

#[test]
fn a_level_day_rate_that_is_negative_is_refused_naming_the_file_and_field() {
    let dir = level_dir(
        "bad_rate",
        "(latitude_deg: 48.1, longitude_deg: 11.6, year: 2026, month: 6, day: 21, \
         utc_hours: 5, time_rate: -60)",
    );
    let root = candela::assets::AssetRoot::new(&dir).expect("root");
    let message = match candela::assets::load_scene(&dir.join("level.ron"), &root) {
        Ok(_) => panic!("a negative time_rate must be refused"),
        Err(e) => e.to_string(),
    };
    assert!(message.contains("level.ron"), "{message}");
    assert!(message.contains("time.time_rate"), "{message}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_script_time_key_sets_the_time_of_day_at_its_frame() {
    let dir = level_dir(
        "script",
        "(latitude_deg: 48.1, longitude_deg: 11.6, year: 2026, month: 6, day: 21, utc_hours: 1)",
    );
    let text = "Script(level: (path: \"level.ron\"), frames: 3, seconds_per_frame: 0.016666668, \
                render: (width: 8, height: 8, spp: 1, auto_exposure: true), \
                times: [(frame: 1, utc_hours: 11)], \
                screenshots: [(frame: 0, name: \"night\"), (frame: 2, name: \"noon\")])";
    let script = candela::app::Script::parse(&dir.join("time.ron"), text).expect("script");
    let level = script.load_level().expect("level");
    let options = candela::app::RunOptions {
        out_dir: Some(dir.clone()),
        ..Default::default()
    };
    let report = candela::app::run_script(&script, &level, &options, &mut |_| {}).expect("runs");
    let mean = |name: &str| {
        let shot = report
            .screenshots
            .iter()
            .find(|s| s.stem == name)
            .expect(name);
        shot.film.image_mean().iter().sum::<f64>()
    };
    let (night, noon) = (mean("night"), mean("noon"));
    assert!(
        noon > 1000.0 * night.max(1e-12),
        "night {night}, noon {noon}"
    );
    assert!(dir.join("noon.png").is_file());
    // Time keys need a physical sky with a time; bad hours are refused with the item named.
    let bad = text.replace("utc_hours: 11", "utc_hours: 24");
    let e = candela::app::Script::parse(&dir.join("time.ron"), &bad).unwrap_err();
    assert!(e.to_string().contains("times[0]"), "{e}");
    let _ = std::fs::remove_dir_all(&dir);
}
