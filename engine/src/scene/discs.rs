//! The physical sky's two discs and its night in the frame uniforms: the sun and the moon
//! (with its phase), the brighter of the two (after the air's transmittance) in the primary
//! slot that next-event estimation samples (`sun_*`), the other in the second slot that only
//! escaping rays see (`second_*`), the stars, airglow and celestial frame, the moonlit sky's
//! frame and scale (`moon_sky`), and the cloud layer
//! (`cloud_*`: its plane, the wind's drift at the sky's time, the light an opaque cloud sends).
//!
//! Any thread; pure functions. Units: irradiance W·m⁻²·nm⁻¹ per channel, radiance
//! W·m⁻²·sr⁻¹·nm⁻¹, directions unit vectors in engine space. The moon's disc is uniform over
//! its lit part (the visible hemisphere facing the sun; `render/cpu/night.rs::disc_lit`), so
//! its radiance is E / (π sin² r · f) with f = (1 − moon·sun) / 2 the lit share: the disc's
//! integrated irradiance is the phase law's E whatever the lit share. Must not: trace or
//! sample (the tracers read what is written here).

use glam::Vec3;

use crate::layout::GpuFrameUniforms;
use crate::sky::{
    MOON_ANGULAR_RADIUS_DEG, PhysicalSky, STAR_ANGULAR_RADIUS_DEG, SUN_ANGULAR_RADIUS_DEG,
    cloud_seconds,
};

use super::materials::luminance;

/// Lit shares below this leave the disc dark (a new moon).
const MIN_LIT_SHARE: f32 = 1e-4;

/// A sky disc seen from the viewer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Disc {
    /// Unit vector towards the centre.
    pub direction: Vec3,
    /// Irradiance normal to `direction` at the viewer (all of the lit part).
    pub irradiance: Vec3,
    /// Angular radius, radians.
    pub radius: f32,
    /// Unit vector towards what lights the disc (zero: lit whole).
    pub terminator: Vec3,
}

impl Disc {
    /// The lit share of the disc's area, (1 + cos α) / 2 with cos α = −direction·terminator.
    pub fn lit_share(&self) -> f32 {
        if self.terminator == Vec3::ZERO {
            1.0
        } else {
            ((1.0 - self.direction.dot(self.terminator)) * 0.5).clamp(0.0, 1.0)
        }
    }

    /// The cosine of the radius as the tracers hold it (f32) and the sine² of that very cone,
    /// (1 − c)(1 + c) in f64: near 1 an f32 cosine is off by up to 0.3 % of 1 − cos r, and
    /// next-event estimation samples the cone of the f32 cosine, so the radiance is set for
    /// that cone and the disc's irradiance comes out exact.
    pub fn cone(&self) -> (f32, f32) {
        let c = self.radius.cos();
        let sin2 = (1.0 - f64::from(c)) * (1.0 + f64::from(c));
        (c, sin2 as f32)
    }

    /// Radiance of the lit part: E / (π sin² r · lit share); zero for a new moon.
    pub fn radiance(&self) -> Vec3 {
        let share = self.lit_share();
        if share < MIN_LIT_SHARE || self.radius <= 0.0 {
            return Vec3::ZERO;
        }
        self.irradiance / (std::f32::consts::PI * self.cone().1 * share)
    }
}

/// The sun and (with a date) the moon of `sky`, brighter first by luminance; none of the sky's
/// checks fail here (the level loader refused those first; a bad sky gives no discs).
pub fn discs(sky: &PhysicalSky) -> (Option<Disc>, Option<Disc>) {
    let sun = sky.sun_horizontal().ok().and_then(|h| {
        let irradiance = sky.sun_irradiance().ok()? * sky.sun_scale;
        Some(Disc {
            direction: h.direction(),
            irradiance,
            radius: SUN_ANGULAR_RADIUS_DEG.to_radians(),
            terminator: Vec3::ZERO,
        })
    });
    let moon = sky.moon_light().ok().flatten().map(|m| Disc {
        direction: m.direction,
        irradiance: m.irradiance,
        radius: MOON_ANGULAR_RADIUS_DEG.to_radians(),
        terminator: m.sun_direction,
    });
    let bright = |d: &Option<Disc>| d.map_or(0.0, |d| luminance(d.irradiance));
    let (first, second) = if bright(&moon) > bright(&sun) {
        (moon, sun)
    } else {
        (sun, moon)
    };
    let lit = |d: Option<Disc>| d.filter(|d| d.radiance().max_element() > 0.0);
    (lit(first), lit(second))
}

/// Writes the discs, stars, airglow and celestial frame of a physical sky into `u`.
pub fn fill_physical(u: &mut GpuFrameUniforms, sky: &PhysicalSky) {
    let (first, second) = discs(sky);
    match first {
        Some(d) => {
            let (cos, sin2) = d.cone();
            u.sun_direction = d.direction.to_array();
            u.sun_cos_radius = cos;
            u.sun_sin_radius = sin2.sqrt();
            u.sun_solid_angle = 2.0 * std::f32::consts::PI * (1.0 - cos);
            u.sun_radiance = d.radiance().to_array();
            u.sun_terminator = d.terminator.to_array();
        }
        None => {
            u.sun_direction = [0.0, 1.0, 0.0];
            u.sun_cos_radius = 1.0;
            u.sun_sin_radius = 0.0;
            u.sun_solid_angle = -1.0;
            u.sun_radiance = [0.0; 3];
            u.sun_terminator = [0.0; 3];
        }
    }
    match second {
        Some(d) => {
            let (cos, sin2) = d.cone();
            u.second_direction = d.direction.to_array();
            u.second_cos_radius = cos;
            u.second_sin_radius = sin2.sqrt();
            u.second_radiance = d.radiance().to_array();
            u.second_terminator = d.terminator.to_array();
        }
        None => {
            u.second_direction = [0.0, 1.0, 0.0];
            u.second_cos_radius = 1.0;
            u.second_sin_radius = 0.0;
            u.second_radiance = [0.0; 3];
            u.second_terminator = [0.0; 3];
        }
    }
    let star_radius = STAR_ANGULAR_RADIUS_DEG.to_radians();
    u.star_sin_radius = star_radius.sin();
    u.star_radiance =
        sky.star_zero_irradiance() / (std::f32::consts::PI * star_radius.sin().powi(2));
    u.airglow = sky.airglow_zenith().to_array();
    u.zenith_transmittance = sky.zenith_transmittance().to_array();
    let [x, y, z] = sky.celestial_frame().unwrap_or([Vec3::X, Vec3::Y, Vec3::Z]);
    u.celestial_x = x.extend(0.0).to_array();
    u.celestial_y = y.extend(0.0).to_array();
    u.celestial_z = z.extend(0.0).to_array();
    // The moonlit sky: its table follows the sun's (`scene::SkyTable`), read by both tracers.
    u.moon_sky = crate::sky::moon_uniform(sky.moon_sky().ok().flatten());
    fill_clouds(u, sky, first);
}

/// Reflectance of the cloud layer's in-scatter: an opaque cloud seen from below has the
/// radiance of a Lambertian sheet of this albedo lit by the primary disc.
pub const CLOUD_ALBEDO: f32 = 0.8;

/// The cloud layer in the uniforms (world space; `render/camera.rs` moves it into render
/// space): its plane, where the wind has carried it at the sky's time, its texel count, and
/// the radiance of an opaque cloud, `CLOUD_ALBEDO` · E · max(ω_disc · y, 0) / π of the primary
/// disc (`primary`). No clouds (or a layer that fails its checks): all zero.
fn fill_clouds(u: &mut GpuFrameUniforms, sky: &PhysicalSky, primary: Option<Disc>) {
    u.cloud_plane = [0.0; 4];
    u.cloud_light = [0.0; 3];
    u.cloud_texels = 0;
    let Some(layer) = sky.clouds.filter(|l| l.validate().is_ok()) else {
        return;
    };
    let offset = layer.offset_m(cloud_seconds(sky.time.as_ref()));
    u.cloud_plane = [layer.height_m, offset.x, offset.y, layer.size_m];
    u.cloud_texels = layer.texels;
    if let Some(d) = primary {
        let light = d.irradiance * d.direction.y.max(0.0) * CLOUD_ALBEDO / std::f32::consts::PI;
        u.cloud_light = light.to_array();
    }
}
