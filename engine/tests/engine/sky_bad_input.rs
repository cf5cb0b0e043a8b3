//! Issue 34's bad input, each case through the level loader from a level text: a sun below
//! −90° (or above 90°), a negative or non-finite haze (and `turbidity`, which this sky does not
//! have: Hosek–Wilkie's turbidity 3 is `haze: 5.949` with the aerosols of
//! `Aerosol::TURBIDITY_3`), aerosols out of range, a cloud texture of 0 size (0 texels, a 0 m
//! tile, more texels than the cap, a cloud of 0 radius), a latitude out of range (north,
//! south, not finite), and beside them a longitude and an hour out of range. Each is an
//! `AssetError` whose message names the level file and the field.
//!
//! (`sky_level.rs` and `sky_clouds.rs` check a few of these beside the good levels; this file
//! is the list, one test per case.)

use std::path::PathBuf;

use candela::assets::{AssetRoot, load_scene};

/// A fresh folder, removed on drop.
struct Dir(PathBuf);

impl Drop for Dir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Loads a level whose sky is `Physical((sky))` from `<name>.ron` and returns the loader's
/// message; panics if it loads.
fn refusal(name: &str, sky: &str) -> String {
    let dir = std::env::temp_dir().join(format!("candela_sky_bad_{name}_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    let d = Dir(dir);
    let text = format!(
        "Level(models: [], instances: [], camera: (position: (0, 1, 3), look_at: (0, 0, 0), \
         vertical_fov_deg: 40), sky: Physical(({sky})))"
    );
    let path = d.0.join(format!("{name}.ron"));
    std::fs::write(&path, text).expect("write level");
    match load_scene(&path, &AssetRoot::new(&d.0).expect("root")) {
        Ok(_) => panic!("{name}: the level loaded; it should be refused"),
        Err(e) => e.to_string(),
    }
}

/// The level `name` with sky `sky` is refused with a message naming `<name>.ron` and `field`.
fn refused(name: &str, sky: &str, field: &str) {
    let message = refusal(name, sky);
    println!("{name}: {message}");
    assert!(
        message.contains(&format!("{name}.ron")),
        "{name}: does not name the file: {message}"
    );
    assert!(
        message.contains(field),
        "{name}: does not name {field}: {message}"
    );
}

/// A `time: Some(...)` at Munich with `latitude`, `longitude` and `hours` (RON numbers).
fn time(latitude: &str, longitude: &str, hours: &str) -> String {
    format!(
        "time: Some((latitude_deg: {latitude}, longitude_deg: {longitude}, year: 2026, \
         month: 9, day: 26, utc_hours: {hours}))"
    )
}

const BLOB: &str = "shape: Gaussian(centre_m: (0.0, 0.0), radius_m: 50.0, optical_depth: 1.0)";

#[test]
fn a_sun_below_minus_90_or_above_90_is_refused() {
    refused("sun_below", "sun_elevation_deg: -90.5", "sun_elevation_deg");
    refused("sun_above", "sun_elevation_deg: 90.5", "sun_elevation_deg");
    refused("sun_nan", "sun_elevation_deg: NaN", "sun_elevation_deg");
}

#[test]
fn a_negative_or_non_finite_haze_and_a_turbidity_are_refused() {
    refused("haze_negative", "haze: -0.5", "haze");
    refused("haze_nan", "haze: NaN", "haze");
    refused("haze_inf", "haze: inf", "haze");
    refused("ozone_negative", "ozone: -1.0", "ozone");
    // There is no turbidity knob: the parser refuses the unknown field by name, and its list
    // of expected fields shows `haze`.
    let message = refusal("turbidity", "turbidity: -3.0");
    assert!(message.contains("turbidity.ron"), "{message}");
    assert!(message.contains("`turbidity`"), "{message}");
    assert!(message.contains("haze"), "{message}");
}

#[test]
fn a_cloud_texture_of_zero_size_is_refused() {
    let clouds = |texels: &str, size: &str| {
        format!("clouds: Some((height_m: 1000.0, texels: {texels}, size_m: {size}, {BLOB}))")
    };
    refused("texels_zero", &clouds("0", "800.0"), "clouds.texels");
    refused("tile_zero", &clouds("64", "0.0"), "clouds.size_m");
    refused("tile_negative", &clouds("64", "-800.0"), "clouds.size_m");
    refused("texels_huge", &clouds("4096", "800.0"), "clouds.texels");
    refused(
        "cloud_radius_zero",
        "clouds: Some((height_m: 1000.0, texels: 64, size_m: 800.0, \
         shape: Gaussian(centre_m: (0.0, 0.0), radius_m: 0.0, optical_depth: 1.0)))",
        "clouds.shape.radius_m",
    );
}

#[test]
fn a_latitude_out_of_range_is_refused() {
    refused(
        "latitude_north",
        &time("90.5", "11.6", "12.0"),
        "time.latitude_deg",
    );
    refused(
        "latitude_south",
        &time("-91.0", "11.6", "12.0"),
        "time.latitude_deg",
    );
    refused(
        "latitude_nan",
        &time("NaN", "11.6", "12.0"),
        "time.latitude_deg",
    );
}

#[test]
fn a_longitude_or_an_hour_out_of_range_is_refused() {
    refused(
        "longitude",
        &time("48.1", "181.0", "12.0"),
        "time.longitude_deg",
    );
    refused("hour_24", &time("48.1", "11.6", "24.0"), "time.utc_hours");
    refused(
        "hour_negative",
        &time("48.1", "11.6", "-0.5"),
        "time.utc_hours",
    );
}

#[test]
fn aerosols_out_of_range_are_refused() {
    refused("aerosol_g", "aerosol: (g: 1.2)", "aerosol.g");
    refused(
        "aerosol_forward",
        "aerosol: (forward_share: -0.1)",
        "aerosol.forward_share",
    );
    refused(
        "aerosol_angstrom",
        "aerosol: (angstrom: NaN)",
        "aerosol.angstrom",
    );
    refused(
        "aerosol_height",
        "aerosol: (scale_height_km: 0)",
        "aerosol.scale_height_km",
    );
    refused(
        "aerosol_absorbs",
        "aerosol: (absorption_per_km: -1e-3)",
        "aerosol.absorption_per_km",
    );
    // A partial aerosol takes the Earth preset's other fields and loads.
    let dir = std::env::temp_dir().join(format!("candela_sky_aerosol_ok_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    let d = Dir(dir);
    let path = d.0.join("aerosol_ok.ron");
    let text = "Level(models: [], instances: [], camera: (position: (0, 1, 3), look_at: (0, 0, 0), \
                vertical_fov_deg: 40), sky: Physical((aerosol: (g: 0.5, angstrom: 1.3))))";
    std::fs::write(&path, text).expect("write level");
    let loaded = load_scene(&path, &AssetRoot::new(&d.0).expect("root"));
    assert!(
        loaded.is_ok(),
        "a partial aerosol is refused: {:?}",
        loaded.err()
    );
}
