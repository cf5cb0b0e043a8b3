//! The physical sky (`candela::sky`, Hillaire 2020 with the aerosols of
//! `sky::Aerosol::TURBIDITY_3`) against Mitsuba 3.9.1's `sunsky` (Hosek–Wilkie 2012 sky + 2013
//! sun, turbidity 3, ground albedo 0.3) in `../shared/external/reference/sky/` (read in place;
//! see its README and scene.md).
//!
//! Calibration, once, at 60° (`sky::HAZE_TURBIDITY_3` and `sky::atmosphere::SOLAR_IRRADIANCE`):
//! haze from the diffuse-to-global ratio, then the solar irradiance per channel from the direct
//! normal irradiance's colour and level. Checked here: that the calibration holds at 60° (DNI
//! within 1 % per channel, ratio within 0.003), then at every elevation the diffuse-to-global
//! horizontal ratio (luminance Y) within ±0.03 (at 30°, 60°, 90°; 10° is in the known gap), the zenith's CIE 1960 chromaticity within
//! Δuv 0.01 where the zenith is more than 5° from the sun (at 90° it is the sun's centre:
//! printed, not checked), and the sky's luminance more than 5° from the sun within a median
//! relative error of 15 % and a 95th percentile of 35 % (sky.exr's 512 × 128 grid) at 30°, 60°
//! and 90°. At 10° the luminance is a known gap (`#[ignore]`d test, docs/ACCURACY.md).
//! Horizontal irradiance comes from fine quadrature of the sky-view lookup both tracers use.
//! Figures are recorded in docs/ACCURACY.md ("Physical sky").

use std::path::{Path, PathBuf};

use candela::sky::{HAZE_TURBIDITY_3, Horizontal, PhysicalSky, SkyTables};
use glam::{DVec3, Vec3};

const ELEVATIONS: [u32; 4] = [10, 30, 60, 90];

fn reference_dir(elevation: u32) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../shared/external/reference/sky")
        .join(format!("turb3_alb0.3_elev{elevation}"))
}

fn luminance(c: DVec3) -> f64 {
    0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z
}

fn sky(elevation: u32, haze: f32) -> PhysicalSky {
    PhysicalSky {
        sun_elevation_deg: elevation as f32,
        sun_azimuth_deg: 0.0,
        time: None,
        haze,
        aerosol: candela::sky::Aerosol::TURBIDITY_3,
        ozone: 1.0,
        ground_albedo: [0.3; 3],
        sun_scale: 1.0,
        night_sky: 1.0,
        clouds: None,
    }
}

/// Diffuse horizontal irradiance of the sky-view lookup: midpoint quadrature over elevation
/// and azimuth (400 × 800 cells; halving both changes it by < 1e-4 relative).
pub(crate) fn horizontal_irradiance(tables: &SkyTables) -> DVec3 {
    let (n_e, n_a) = (400, 800);
    let (de, da) = (
        std::f64::consts::FRAC_PI_2 / n_e as f64,
        std::f64::consts::TAU / n_a as f64,
    );
    let mut sum = DVec3::ZERO;
    for i in 0..n_e {
        let e = (i as f64 + 0.5) * de;
        let mut ring = DVec3::ZERO;
        for j in 0..n_a {
            let a = (j as f64 + 0.5) * da;
            let d = Vec3::new(
                (e.cos() * a.sin()) as f32,
                e.sin() as f32,
                (-e.cos() * a.cos()) as f32,
            );
            ring += tables.radiance(d).as_dvec3();
        }
        sum += ring * (e.sin() * e.cos() * de * da);
    }
    sum
}

struct Figures {
    dni: DVec3,
    dhi: DVec3,
}

fn figures(elevation: u32, haze: f32) -> anyhow::Result<(SkyTables, Figures)> {
    let s = sky(elevation, haze);
    let tables = SkyTables::build(&s)?;
    let dhi = horizontal_irradiance(&tables);
    Ok((
        tables,
        Figures {
            dni: s.sun_irradiance()?.as_dvec3(),
            dhi,
        },
    ))
}

fn ratio(f: &Figures, elevation: u32) -> f64 {
    let ghi = f.dhi + f.dni * (elevation as f64).to_radians().sin();
    luminance(f.dhi) / luminance(ghi)
}

fn json(elevation: u32) -> anyhow::Result<serde_json::Value> {
    let text = std::fs::read_to_string(reference_dir(elevation).join("figures.json"))?;
    Ok(serde_json::from_str(&text)?)
}

fn number(v: &serde_json::Value, path: &[&str]) -> anyhow::Result<f64> {
    let mut v = v;
    for key in path {
        v = v
            .get(key)
            .ok_or_else(|| anyhow::anyhow!("figures.json lacks {path:?}"))?;
    }
    v.as_f64()
        .ok_or_else(|| anyhow::anyhow!("figures.json: {path:?} is not a number"))
}

fn rgb(v: &serde_json::Value, path: &[&str]) -> anyhow::Result<DVec3> {
    let mut out = [0.0; 3];
    for (i, o) in out.iter_mut().enumerate() {
        let mut w = v;
        for key in path {
            w = w
                .get(key)
                .ok_or_else(|| anyhow::anyhow!("figures.json lacks {path:?}"))?;
        }
        *o = w
            .get(i)
            .and_then(|x| x.as_f64())
            .ok_or_else(|| anyhow::anyhow!("{path:?}[{i}]"))?;
    }
    Ok(DVec3::from(out))
}

/// CIE 1960 (u, v) of a linear Rec.709 colour.
fn uv(c: DVec3) -> (f64, f64) {
    let x = 0.4124 * c.x + 0.3576 * c.y + 0.1805 * c.z;
    let y = 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
    let z = 0.0193 * c.x + 0.1192 * c.y + 0.9505 * c.z;
    let d = x + 15.0 * y + 3.0 * z;
    (4.0 * x / d, 6.0 * y / d)
}

fn read_sky_exr(path: &Path) -> anyhow::Result<(usize, Vec<DVec3>)> {
    use exr::prelude::*;
    let image = read_first_rgba_layer_from_file(
        path,
        |resolution, _| {
            (
                resolution.width(),
                vec![DVec3::ZERO; resolution.width() * resolution.height()],
            )
        },
        |(width, pixels): &mut (usize, Vec<DVec3>),
         position,
         (r, g, b, _a): (f32, f32, f32, f32)| {
            pixels[position.y() * *width + position.x()] = DVec3::new(r as f64, g as f64, b as f64);
        },
    )?;
    Ok(image.layer_data.channel_data.pixels)
}

fn percentile(sorted: &[f64], p: f64) -> f64 {
    sorted[((sorted.len() - 1) as f64 * p).round() as usize]
}

#[test]
fn calibration_holds_at_60_degrees() -> anyhow::Result<()> {
    let reference = json(60)?;
    let (_, ours) = figures(60, HAZE_TURBIDITY_3)?;
    let sin60 = 60f64.to_radians().sin();
    let dni_ref = rgb(&reference, &["sun_horizontal_irradiance", "rgb"])? / sin60;
    let ratio_ref = number(&reference, &["diffuse_to_global_ratio", "Y"])?;
    let r = ratio(&ours, 60);
    println!(
        "60°: DNI {:.4?} (Mitsuba {dni_ref:.4?}), DHI/GHI {r:.4} (Mitsuba {ratio_ref:.4})",
        ours.dni
    );
    for c in 0..3 {
        assert!(
            (ours.dni[c] / dni_ref[c] - 1.0).abs() < 0.01,
            "DNI channel {c}: {} vs {}",
            ours.dni,
            dni_ref
        );
    }
    assert!((r - ratio_ref).abs() < 0.003, "ratio {r} vs {ratio_ref}");
    Ok(())
}

/// One elevation's measured figures against Mitsuba's.
struct Comparison {
    ratio: f64,
    ratio_ref: f64,
    luminance_median: f64,
    luminance_p95: f64,
    zenith_duv: f64,
}

fn compare(elevation: u32) -> anyhow::Result<Comparison> {
    let reference = json(elevation)?;
    let (tables, ours) = figures(elevation, HAZE_TURBIDITY_3)?;
    let (r, r_ref) = (
        ratio(&ours, elevation),
        number(&reference, &["diffuse_to_global_ratio", "Y"])?,
    );
    let dni_ref = number(&reference, &["sun", "direct_normal_irradiance_Y"])?;
    let dhi_ref = number(&reference, &["diffuse_horizontal_irradiance", "Y"])?;
    // Sky luminance > 5° from the sun over sky.exr's grid.
    let (width, pixels) = read_sky_exr(&reference_dir(elevation).join("sky.exr"))?;
    anyhow::ensure!(
        width == 512 && pixels.len() == 512 * 128,
        "sky.exr is not 512 × 128"
    );
    let sun = Horizontal {
        elevation_deg: elevation as f64,
        azimuth_deg: 0.0,
    }
    .direction();
    let mut errors = Vec::new();
    for row in 0..128 {
        for col in 0..512 {
            let h = Horizontal {
                elevation_deg: 90.0 * row as f64 / 127.0,
                azimuth_deg: 360.0 * col as f64 / 512.0,
            };
            let d = h.direction();
            if d.dot(sun).clamp(-1.0, 1.0).acos().to_degrees() <= 5.0 {
                continue;
            }
            let y_ref = luminance(pixels[row * 512 + col]);
            let y = luminance(tables.radiance(d).as_dvec3());
            errors.push((y / y_ref - 1.0).abs());
        }
    }
    errors.sort_by(f64::total_cmp);
    let (median, p95) = (percentile(&errors, 0.5), percentile(&errors, 0.95));
    let zenith = tables.radiance(Vec3::Y).as_dvec3();
    let zenith_ref = rgb(&reference, &["zenith_sky_radiance", "rgb"])?;
    let ((u, v), (u_ref, v_ref)) = (uv(zenith), uv(zenith_ref));
    let duv = ((u - u_ref).powi(2) + (v - v_ref).powi(2)).sqrt();
    println!(
        "{elevation:>2}°: DNI Y {:.4} ({dni_ref:.4}), DHI Y {:.4} ({dhi_ref:.4}), DHI/GHI {r:.4} \
         ({r_ref:.4}), sky Y rel. error median {median:.3} p95 {p95:.3} ({} directions), \
         zenith Y {:.4} ({:.4}) Δuv {duv:.4}",
        luminance(ours.dni),
        luminance(ours.dhi),
        errors.len(),
        luminance(zenith),
        luminance(zenith_ref),
    );
    Ok(Comparison {
        ratio: r,
        ratio_ref: r_ref,
        luminance_median: median,
        luminance_p95: p95,
        zenith_duv: duv,
    })
}

/// At 30°, 60° and 90°; 10° is in the known gap of the low sun
/// (`sky_luminance_at_a_low_sun_matches_mitsuba`): with the scattering orders the sky there is
/// brighter (right against brute force, `sky_brute_force`) while this atmosphere's sun at 10° is
/// still 32 % dimmer than Hosek–Wilkie's, so the ratio is 0.042 above theirs.
#[test]
fn diffuse_to_global_ratio_matches_mitsuba() -> anyhow::Result<()> {
    for elevation in ELEVATIONS.into_iter().filter(|&e| e > 10) {
        let c = compare(elevation)?;
        assert!(
            (c.ratio - c.ratio_ref).abs() <= 0.03,
            "{elevation}°: DHI/GHI {:.4} vs Mitsuba {:.4}",
            c.ratio,
            c.ratio_ref
        );
    }
    Ok(())
}

/// The sky's luminance distribution at 30°, 60° and 90°, and the zenith's colour wherever the
/// zenith is away from the sun (10°, 30°, 60°).
#[test]
fn sky_luminance_and_zenith_colour_match_mitsuba() -> anyhow::Result<()> {
    let mut failures = Vec::new();
    for elevation in ELEVATIONS {
        let c = compare(elevation)?;
        if elevation > 10 && (c.luminance_median > 0.15 || c.luminance_p95 > 0.35) {
            failures.push(format!(
                "{elevation}°: sky luminance median {:.3} p95 {:.3}",
                c.luminance_median, c.luminance_p95
            ));
        }
        if elevation < 85 && c.zenith_duv > 0.01 {
            failures.push(format!("{elevation}°: zenith Δuv {:.4}", c.zenith_duv));
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
    Ok(())
}

/// Known gap (docs/ACCURACY.md, "Physical sky"): with the sun 10° high our sky is darker than
/// Hosek–Wilkie's near the horizon (median error 0.153, p95 0.301 since the scattering orders;
/// 0.217 / 0.414 before) and its diffuse-to-global ratio 0.042 above theirs: this atmosphere's sun
/// at 10° is 32 % dimmer than theirs, and the tables now match the brute-force tracer of the same
/// atmosphere (`sky_brute_force`), so what is left is the model: Hosek–Wilkie fits another
/// atmosphere. Run with `--run-ignored all` to measure; it fails today.
#[test]
#[ignore = "known gap: at 10° sun elevation the low sky is darker than Hosek–Wilkie's and the diffuse-to-global ratio higher: the model, not the tables (sky_brute_force, docs/ACCURACY.md)"]
fn sky_luminance_at_a_low_sun_matches_mitsuba() -> anyhow::Result<()> {
    let c = compare(10)?;
    assert!(
        (c.ratio - c.ratio_ref).abs() <= 0.03,
        "10°: DHI/GHI {:.4} vs Mitsuba {:.4}",
        c.ratio,
        c.ratio_ref
    );
    assert!(
        c.luminance_median <= 0.15 && c.luminance_p95 <= 0.35,
        "10°: sky luminance median {:.3} p95 {:.3}",
        c.luminance_median,
        c.luminance_p95
    );
    Ok(())
}

/// What drives the gap at 10° (docs/ACCURACY.md, "Physical sky"): prints our luminance over
/// Hosek–Wilkie's (median per band of elevation and of azimuth from the sun), and the median
/// and p95 errors of our sky scaled as a whole by s — s = 1.46 is Hosek–Wilkie's direct normal
/// irradiance over ours, the sky Mitsuba's sun would light if the sky followed the sun's light
/// at the ground. Diagnostic: it prints, checks nothing; `--run-ignored all` to run.
#[test]
#[ignore = "diagnostic: prints the error pattern of the sky at 10° (docs/ACCURACY.md)"]
fn sky_at_a_low_sun_error_pattern() -> anyhow::Result<()> {
    let elevation = 10;
    let (tables, ours) = figures(elevation, HAZE_TURBIDITY_3)?;
    let reference = json(elevation)?;
    let dni_ref = number(&reference, &["sun", "direct_normal_irradiance_Y"])?;
    let (_, pixels) = read_sky_exr(&reference_dir(elevation).join("sky.exr"))?;
    let sun = Horizontal {
        elevation_deg: elevation as f64,
        azimuth_deg: 0.0,
    }
    .direction();
    // (elevation°, azimuth from the sun°, ours / reference)
    let mut samples = Vec::new();
    for row in 0..128 {
        for col in 0..512 {
            let h = Horizontal {
                elevation_deg: 90.0 * row as f64 / 127.0,
                azimuth_deg: 360.0 * col as f64 / 512.0,
            };
            let d = h.direction();
            if d.dot(sun).clamp(-1.0, 1.0).acos().to_degrees() <= 5.0 {
                continue;
            }
            let r = luminance(tables.radiance(d).as_dvec3()) / luminance(pixels[row * 512 + col]);
            let az = h.azimuth_deg.min(360.0 - h.azimuth_deg);
            samples.push((h.elevation_deg, az, r));
        }
    }
    let median = |mut v: Vec<f64>| -> f64 {
        v.sort_by(f64::total_cmp);
        if v.is_empty() {
            f64::NAN
        } else {
            percentile(&v, 0.5)
        }
    };
    let bands: [f64; 6] = [0.0, 5.0, 15.0, 30.0, 60.0, 90.1];
    let sectors: [f64; 5] = [0.0, 30.0, 90.0, 150.0, 180.1];
    println!("ours / Hosek–Wilkie, median; rows: elevation, columns: azimuth from the sun");
    for b in bands.windows(2) {
        let mut line = format!("{:>4.0}–{:<4.0}°", b[0], b[1].floor());
        for s in sectors.windows(2) {
            let v: Vec<f64> = samples
                .iter()
                .filter(|(e, a, _)| (b[0]..b[1]).contains(e) && (s[0]..s[1]).contains(a))
                .map(|x| x.2)
                .collect();
            line += &format!("  {:>5.0}–{:<4.0}° {:.3}", s[0], s[1].floor(), median(v));
        }
        println!("{line}");
    }
    let scale_dni = dni_ref / luminance(ours.dni);
    for s in [1.0, 1.1, 1.2, 1.3, scale_dni] {
        let mut e: Vec<f64> = samples.iter().map(|x| (x.2 * s - 1.0).abs()).collect();
        e.sort_by(f64::total_cmp);
        println!(
            "sky × {s:.3}: median {:.3} p95 {:.3}",
            percentile(&e, 0.5),
            percentile(&e, 0.95)
        );
    }
    Ok(())
}

/// The calibration itself (a development aid; `--run-ignored all --no-capture`): bisects the
/// haze on Mitsuba's diffuse-to-global ratio at 60°, then prints the solar irradiance per
/// channel that gives Mitsuba's direct normal irradiance there (`SOLAR_IRRADIANCE` ×
/// reference / ours), and the diffuse-to-global ratio at 10° that calibration would give. Rerun
/// when the sky model changes; `HAZE_TURBIDITY_3` and `SOLAR_IRRADIANCE` then take the printed
/// values.
#[test]
#[ignore = "development aid: recalibrates the haze and the solar irradiance (docs/ACCURACY.md)"]
fn calibrate_haze_and_solar_irradiance_at_60_degrees() -> anyhow::Result<()> {
    let reference = json(60)?;
    let ratio_ref = number(&reference, &["diffuse_to_global_ratio", "Y"])?;
    let (mut lo, mut hi) = (1.0f32, 12.0f32);
    for _ in 0..14 {
        let mid = 0.5 * (lo + hi);
        let (_, f) = figures(60, mid)?;
        // More haze: more diffuse light, a dimmer sun.
        if ratio(&f, 60) < ratio_ref {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let haze = 0.5 * (lo + hi);
    let (_, f) = figures(60, haze)?;
    let dni_ref =
        rgb(&reference, &["sun_horizontal_irradiance", "rgb"])? / 60f64.to_radians().sin();
    let solar = candela::sky::SOLAR_IRRADIANCE.as_dvec3() * dni_ref / f.dni;
    println!(
        "haze {haze:.4}: DHI/GHI {:.4} (Mitsuba {ratio_ref:.4}); solar irradiance {solar:.4?}",
        ratio(&f, 60)
    );
    // What that calibration gives at 10° (the sky and the sun are linear in the solar
    // irradiance per channel), against the constants in use.
    let scale = solar / candela::sky::SOLAR_IRRADIANCE.as_dvec3();
    let (_, now) = figures(10, HAZE_TURBIDITY_3)?;
    let (_, low) = figures(10, haze)?;
    let recalibrated = Figures {
        dni: low.dni * scale,
        dhi: low.dhi * scale,
    };
    let ratio_10 = number(&json(10)?, &["diffuse_to_global_ratio", "Y"])?;
    println!(
        "10°: DHI/GHI {:.4} with haze {HAZE_TURBIDITY_3}, {:.4} recalibrated (Mitsuba {ratio_10:.4}); \
         DNI Y {:.4} → {:.4}, DHI Y {:.4} → {:.4}",
        ratio(&now, 10),
        ratio(&recalibrated, 10),
        luminance(now.dni),
        luminance(recalibrated.dni),
        luminance(now.dhi),
        luminance(recalibrated.dhi),
    );
    Ok(())
}
