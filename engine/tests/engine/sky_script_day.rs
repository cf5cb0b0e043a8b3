//! A capture script's time keys move the sun, `render.max_exposure_ev` caps the sky's meter
//! and a screenshot's `exposure_compensation_ev` shifts it — cheap, at 24 × 24 pixels: a floor
//! with a wide block at its centre seen from straight above (image left = west, −X; right =
//! east, +X), near Petra on 2026-09-26.
//!
//! * Morning (06:00 UTC, sun 31° high in the east-south-east) throws the block's shadow west,
//!   into the image's left half; afternoon (13:00 UTC, 31° in the west-south-west) throws it
//!   east. The dimmer half flips with the key.
//! * The floor at noon (09:30, 58°) is brighter than at dawn (03:51, 4°) in radiance, i.e.
//!   with the exposure fixed.
//! * At midnight the meter exposes for the moon (about +16 stops); a cap of +6 stops gives a
//!   darker PNG than no cap, and so does a shot's exposure compensation of −2 stops.

use std::path::{Path, PathBuf};

use candela::app::{RunOptions, Script, ScriptReport, run_script};

/// A fresh folder, removed on drop.
struct Dir(PathBuf);

impl Drop for Dir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

fn folder(tag: &str) -> Dir {
    let dir = std::env::temp_dir().join(format!("candela_sky_day_{tag}_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    std::fs::write(
        dir.join("level.ron"),
        "Level(materials: [(name: \"floor\", kind: Diffuse, base_color: (0.5, 0.5, 0.5))], \
         grids: [(name: \"floor\", size: (24, 24), divisions: (1, 1), material: \"floor\")], \
         boxes: [(name: \"block\", size: (1, 5, 10), material: \"floor\")], \
         instances: [(model: \"floor\"), (model: \"block\", transform: (translation: (0, 2.5, 0)))], \
         camera: (position: (0, 30, 0.5), look_at: (0, 0, 0), vertical_fov_deg: 40), \
         sky: Physical((time: Some((latitude_deg: 30.33, longitude_deg: 35.44, year: 2026, \
         month: 9, day: 26, utc_hours: 0)))), \
         render: (max_bounces: 1, roulette_start: 1))",
    )
    .expect("write level");
    Dir(dir)
}

/// Runs a script of one shot per `(utc_hours, name)`, two frames of 4 samples each; `shot`
/// is added to every screenshot entry.
fn run(dir: &Path, render: &str, shot: &str, shots: &[(f64, &str)]) -> ScriptReport {
    let times: Vec<String> = (shots.iter().enumerate())
        .map(|(i, (h, _))| format!("(frame: {}, utc_hours: {h})", 2 * i))
        .collect();
    let names: Vec<String> = (shots.iter().enumerate())
        .map(|(i, (_, n))| format!("(frame: {}, name: \"{n}\"{shot})", 2 * i + 1))
        .collect();
    let text = format!(
        "Script(level: (path: \"level.ron\"), frames: {}, seconds_per_frame: 0.05, \
         render: (width: 24, height: 24, spp: 4, seed: 1, {render}), \
         times: [{}], screenshots: [{}])",
        2 * shots.len(),
        times.join(", "),
        names.join(", ")
    );
    let script = Script::parse(&dir.join("day.ron"), &text).expect("script");
    let level = script.load_level().expect("level");
    let options = RunOptions {
        out_dir: Some(dir.to_path_buf()),
        ..Default::default()
    };
    run_script(&script, &level, &options, &mut |_| {}).expect("runs")
}

/// Mean luminance-ish (sum of channels) of the film `name` over columns `columns`, rows
/// clear of the block's footprint.
fn mean(report: &ScriptReport, name: &str, columns: std::ops::Range<u32>) -> f64 {
    let film = &(report.screenshots.iter().find(|s| s.stem == name))
        .expect(name)
        .film;
    let (mut sum, mut n) = (0.0, 0.0);
    for y in 0..film.height {
        for x in columns.clone() {
            let p = film.mean[(y * film.width + x) as usize];
            sum += f64::from(p.x + p.y + p.z);
            n += 1.0;
        }
    }
    sum / n
}

#[test]
fn time_keys_move_the_sun_across_the_sky() {
    let dir = folder("keys");
    let report = run(
        &dir.0,
        "auto_exposure: false",
        "",
        &[
            (3.85, "dawn"),
            (6.0, "morning"),
            (9.5, "noon"),
            (13.0, "afternoon"),
        ],
    );
    // Half-images clear of the block (it spans about columns 11..13).
    let (west, east) = (0..10, 14..24);
    let morning = (
        mean(&report, "morning", west.clone()),
        mean(&report, "morning", east.clone()),
    );
    let afternoon = (
        mean(&report, "afternoon", west.clone()),
        mean(&report, "afternoon", east),
    );
    println!("morning west/east {morning:?}, afternoon west/east {afternoon:?}");
    assert!(
        morning.0 < 0.9 * morning.1,
        "morning: the shadow should lie west: {morning:?}"
    );
    assert!(
        afternoon.1 < 0.9 * afternoon.0,
        "afternoon: the shadow should lie east: {afternoon:?}"
    );
    let (dawn, noon) = (mean(&report, "dawn", 0..24), mean(&report, "noon", 0..24));
    println!("floor at dawn {dawn}, at noon {noon}");
    assert!(
        noon > 3.0 * dawn,
        "noon {noon} should be far brighter than dawn {dawn}"
    );
}

/// Mean of a PNG's bytes (a brighter picture has a larger mean).
fn png_mean(path: &Path) -> f64 {
    let image = image::open(path).expect("png").to_rgb8();
    let bytes = image.as_raw();
    bytes.iter().map(|&b| f64::from(b)).sum::<f64>() / bytes.len() as f64
}

#[test]
fn a_cap_on_the_sky_meter_and_a_compensation_darken_the_night_shot() {
    let dir = folder("cap");
    run(&dir.0, "auto_exposure: true", "", &[(21.0, "metered")]);
    run(
        &dir.0,
        "auto_exposure: true, max_exposure_ev: 6",
        "",
        &[(21.0, "capped")],
    );
    run(
        &dir.0,
        "auto_exposure: true",
        ", exposure_compensation_ev: -2",
        &[(21.0, "compensated")],
    );
    let (metered, capped, compensated) = (
        png_mean(&dir.0.join("metered.png")),
        png_mean(&dir.0.join("capped.png")),
        png_mean(&dir.0.join("compensated.png")),
    );
    println!(
        "midnight PNG mean: metered {metered:.2}, capped at +6 EV {capped:.2}, \
         compensated by -2 EV {compensated:.2}"
    );
    assert!(metered > 20.0, "the metered night should read: {metered}");
    assert!(
        capped < 0.25 * metered,
        "capped {capped} vs metered {metered}"
    );
    assert!(
        compensated < 0.8 * metered && compensated > 0.1 * metered,
        "compensated {compensated} vs metered {metered}"
    );
    // A cap that is not a number is refused, naming the field.
    let bad = "Script(frames: 1, seconds_per_frame: 0.05, render: (max_exposure_ev: NaN))";
    let e = Script::parse(&dir.0.join("bad.ron"), bad)
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("bad.ron") && e.contains("render.max_exposure_ev"),
        "{e}"
    );
}
