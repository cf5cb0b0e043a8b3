//! The moonlit sky (`sky/night.rs` `MoonSky`: the moon's sky-view table after the sun's, read
//! by `render/cpu/night.rs` and its WGSL twin): at midnight under a full moon the sky the tracer
//! sees is, towards every direction, the sky of a sun standing where the moon stands times the
//! moon's share of the sun's light (2.5·10⁻⁶ × the phase law) — and the same at a quarter moon,
//! so a full moon's sky is brighter than a quarter moon's by the phase ratio; it is blue beside
//! the moon's own light (Rayleigh scattering); it is far brighter than a new-moon midnight,
//! whose moon is down and whose sky has the airglow alone; and by day there is no moon's table.
//! The floor's energy under a moonlit sky is `sky_night_render.rs` (CPU) and the GPU's
//! agreement `tests/cross/gpu_matches_cpu.rs` (`moonlit_night_agrees`).

use candela::layout::GpuFrameUniforms;
use candela::render::cpu::integrator::sky_radiance;
use candela::sky::{
    MOON_FULL_RATIO, MoonSky, PhysicalSky, SkyNow, SkyTables, VIEW_HEIGHT, VIEW_WIDTH,
    moon_phase_factor,
};
use glam::{DVec3, Vec3};

use crate::sky_night::find;

fn uniforms(sky: &PhysicalSky) -> GpuFrameUniforms {
    let mut u = bytemuck::Zeroable::zeroed();
    candela::scene::lights::fill_sun_and_sky(
        &mut u,
        None,
        &candela::assets::SkyDesc::Physical(*sky),
    );
    u
}

/// The sky an escaping ray sees (the tracer's function), towards directions away from the
/// discs.
struct Seen {
    u: GpuFrameUniforms,
    tables: SkyTables,
}

impl Seen {
    fn new(sky: &PhysicalSky) -> anyhow::Result<Self> {
        Ok(Self {
            u: uniforms(sky),
            tables: SkyTables::build(sky)?,
        })
    }

    fn at(&self, d: Vec3) -> DVec3 {
        sky_radiance(&self.u, &self.tables.texels, d).as_dvec3()
    }
}

fn seen(sky: &PhysicalSky, d: Vec3) -> anyhow::Result<DVec3> {
    Ok(Seen::new(sky)?.at(d))
}

/// 48 directions of the upper hemisphere (elevations 5°…80°, azimuths every 30°).
fn directions() -> Vec<Vec3> {
    let mut out = Vec::new();
    for e in [5.0f32, 20.0, 45.0, 80.0] {
        for k in 0..12 {
            let a = (k as f32 * 30.0 + 7.0).to_radians();
            let e = e.to_radians();
            out.push(Vec3::new(e.cos() * a.sin(), e.sin(), -e.cos() * a.cos()));
        }
    }
    out
}

/// A night (sun below −18°) with the moon over 25° high, at `utc_hours` when given, whose
/// phase angle minimises `score`.
fn night(utc_hours: Option<f64>, score: impl Fn(f64) -> f64) -> PhysicalSky {
    let sky = find(
        |now: &SkyNow| {
            now.sun.elevation_deg < -18.0
                && now.moon.is_some_and(|m| m.horizontal.elevation_deg > 25.0)
                && utc_hours.is_none_or(|h| now.time.is_some_and(|t| t.utc_hours == h))
        },
        |now| now.moon.map_or(f64::MAX, |m| score(m.phase_angle_deg)),
    );
    PhysicalSky {
        night_sky: 0.0,
        ..sky
    }
}

/// The moonlit part of `sky` against the sky of a sun where its moon stands, over
/// [`directions`]: the largest relative error of `ratio` × the sun's sky, per channel.
fn against_a_sun_there(sky: &PhysicalSky, moon: &MoonSky, ratio: f64) -> anyhow::Result<f64> {
    let m = sky.now()?.moon.expect("a moon");
    let sun_there = PhysicalSky {
        sun_elevation_deg: moon.table_elevation_deg as f32,
        sun_azimuth_deg: m.horizontal.azimuth_deg as f32,
        time: None,
        sun_scale: 0.0,
        ..*sky
    };
    let (night, there) = (Seen::new(sky)?, Seen::new(&sun_there)?);
    let mut without_moon = SkyTables::build(sky)?;
    without_moon.moon_sky = [0.0; 4];
    let mut worst: f64 = 0.0;
    for d in directions() {
        let moonlit = night.at(d) - without_moon.radiance(d).as_dvec3();
        let expected = there.at(d) * ratio;
        worst = worst.max(((moonlit - expected).abs() / expected).max_element());
    }
    Ok(worst)
}

#[test]
fn the_moon_lights_the_sky_by_its_phase_and_blue() -> anyhow::Result<()> {
    // A nearly full moon at 23:00 UTC (Munich's midnight, 11.6° E) and a nearly quarter moon.
    let full = night(Some(23.0), |phase| phase);
    let quarter = night(None, |phase| (phase - 90.0).abs());
    let mut shares = Vec::new();
    for sky in [&full, &quarter] {
        let moon = sky.moon_sky()?.expect("a moonlit sky at night");
        let phase = sky.now()?.moon.expect("a moon").phase_angle_deg;
        let ratio = MOON_FULL_RATIO as f64 * moon_phase_factor(phase);
        let worst = against_a_sun_there(sky, &moon, ratio)?;
        println!(
            "phase {phase:.1}°, moon at {:.1}°: share {ratio:.3e} (table scale {:.3e}), worst \
             relative error {worst:.2e} over 48 directions",
            moon.table_elevation_deg, moon.scale
        );
        anyhow::ensure!(
            worst < 0.01,
            "the moonlit sky is not the phase law's: {worst}"
        );
        shares.push((moon.scale as f64, phase));
    }
    let law = moon_phase_factor(shares[0].1) / moon_phase_factor(shares[1].1);
    let brighter = shares[0].0 / shares[1].0;
    println!("full / quarter: {brighter:.3} (phase law {law:.3})");
    anyhow::ensure!(
        (brighter / law - 1.0).abs() < 0.01 && brighter > 5.0,
        "full / quarter {brighter} against the phase law's {law}"
    );
    // Blue: the zenith's moonlit sky against the moon's own light.
    let zenith = seen(&full, Vec3::Y)?;
    let light = full.moon_light()?.expect("a moon").irradiance.as_dvec3();
    let tint = (zenith.z / zenith.x) / (light.z / light.x);
    println!("zenith {zenith:?}, moon light {light:?}: blue/red against the moon's {tint:.2}");
    anyhow::ensure!(tint > 1.5, "the moonlit sky is not blue: {tint}");
    // A new moon's midnight: the moon is down, no moon's table; the airglow alone.
    let new = PhysicalSky {
        night_sky: 1.0,
        ..find(
            |now: &SkyNow| {
                now.sun.elevation_deg < -18.0 && now.time.is_some_and(|t| t.utc_hours == 23.0)
            },
            |now| now.moon.map_or(f64::MAX, |m| -m.phase_angle_deg),
        )
    };
    anyhow::ensure!(
        new.moon_sky()?.is_none(),
        "a new moon lights the midnight sky"
    );
    let n = VIEW_WIDTH * VIEW_HEIGHT;
    anyhow::ensure!(SkyTables::build(&new)?.texels.len() == n);
    let luminance = |l: DVec3| l.dot(DVec3::new(0.2126, 0.7152, 0.0722));
    let full_glow = PhysicalSky {
        night_sky: 1.0,
        ..full
    };
    let (bright, dark) = (
        luminance(seen(&full_glow, Vec3::Y)?),
        luminance(seen(&new, Vec3::Y)?),
    );
    println!("zenith luminance: full moon {bright:.3e}, new moon {dark:.3e}");
    anyhow::ensure!(bright > 10.0 * dark, "full {bright} against new {dark}");
    // By day there is no moon's table, whatever the moon.
    let day = find(
        |now: &SkyNow| {
            now.sun.elevation_deg > 10.0
                && now.moon.is_some_and(|m| m.horizontal.elevation_deg > 20.0)
        },
        |now| now.moon.map_or(f64::MAX, |m| m.phase_angle_deg),
    );
    anyhow::ensure!(day.moon_sky()?.is_none() && SkyTables::build(&day)?.texels.len() == n);
    Ok(())
}
