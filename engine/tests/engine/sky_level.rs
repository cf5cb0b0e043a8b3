//! `sky: Physical(...)` in a level file: a good one loads and gives a sky table and a sun; bad
//! values (negative haze, a sun below −90°, a bad date, a level `sun` beside it) are
//! `AssetError`s naming the level file and the field.

use std::path::PathBuf;

use candela::assets::{AssetError, AssetRoot, SkyDesc, load_scene};

struct Dir(PathBuf);

impl Dir {
    fn new(name: &str) -> Self {
        let path = std::env::temp_dir().join(format!("candela_sky_{name}_{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&path);
        std::fs::create_dir_all(&path).expect("temp dir");
        Dir(path)
    }
}

impl Drop for Dir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

fn load(name: &str, extra: &str) -> Result<candela::assets::SceneDesc, AssetError> {
    let d = Dir::new(name);
    let text = format!(
        "Level(models: [], instances: [], camera: (position: (0, 1, 3), look_at: (0, 0, 0), \
         vertical_fov_deg: 40), {extra})"
    );
    let path = d.0.join(format!("{name}.ron"));
    std::fs::write(&path, text).expect("write");
    load_scene(&path, &AssetRoot::new(&d.0).expect("root"))
}

fn refused(name: &str, extra: &str, field: &str) {
    let message = match load(name, extra) {
        Ok(_) => panic!("{name} should be refused"),
        Err(e) => e.to_string(),
    };
    assert!(
        message.contains(&format!("{name}.ron")),
        "does not name the file: {message}"
    );
    assert!(message.contains(field), "does not name {field}: {message}");
}

#[test]
fn physical_sky_loads_with_defaults_and_a_time() {
    let desc = load(
        "good",
        "sky: Physical((time: Some((latitude_deg: 48.1, longitude_deg: 11.6, year: 2026, \
         month: 6, day: 21, utc_hours: 10.5)), haze: 22.05))",
    )
    .expect("loads");
    let SkyDesc::Physical(sky) = desc.sky else {
        panic!("not physical: {:?}", desc.sky)
    };
    let sun = sky.sun_horizontal().expect("sun");
    // Munich at 12:30 CEST on the solstice: the sun stands about 64° high, south-east of south.
    assert!((55.0..70.0).contains(&sun.elevation_deg), "{sun:?}");
    assert!((120.0..200.0).contains(&sun.azimuth_deg), "{sun:?}");
    assert!(load("defaults", "sky: Physical(())").is_ok());
}

#[test]
fn bad_physical_skies_name_the_file_and_the_field() {
    refused("negative_haze", "sky: Physical((haze: -1.0))", "haze");
    refused(
        "negative_night",
        "sky: Physical((night_sky: -1.0))",
        "night_sky",
    );
    refused(
        "deep_sun",
        "sky: Physical((sun_elevation_deg: -91.0))",
        "sun_elevation_deg",
    );
    refused(
        "bad_albedo",
        "sky: Physical((ground_albedo: (0.3, 1.5, 0.3)))",
        "ground_albedo",
    );
    refused(
        "bad_date",
        "sky: Physical((time: Some((latitude_deg: 0.0, longitude_deg: 0.0, year: 2026, month: 2, \
         day: 30, utc_hours: 1.0))))",
        "2026-02-30",
    );
    refused(
        "bad_latitude",
        "sky: Physical((time: Some((latitude_deg: 95.0, longitude_deg: 0.0, year: 2026, month: 2, \
         day: 3, utc_hours: 1.0))))",
        "latitude",
    );
    refused(
        "with_sun",
        "sun: Some((direction: (0, 1, 0), irradiance: (1, 1, 1))), sky: Physical(())",
        "sun must be None",
    );
}
