//! The level file: a RON description of what a scene is made of and how it is rendered.
//!
//! Owns: the serde types of a level (models and where they are placed, level materials,
//! camera, sun, sky, render settings and areas) and parsing them with clear errors (file,
//! line, column; unknown fields are refused). Must not: load the models it names (see `level_load`).
//!
//! Paths in a level are relative to the asset root, `/`-separated, and may not leave it.
//! Units: metres, degrees where a field name says `_deg`, linear RGB colours.
//!
//! ```ron
//! Level(
//!     models: [(name: "box", path: "cornell/cornell_box.obj")],
//!     instances: [(model: "box")],
//!     camera: (position: (0, 1, 3.8), look_at: (0, 1, 0), vertical_fov_deg: 40),
//!     sky: Constant((0, 0, 0)),
//!     render: (max_bounces: 7, target_fps: 30, min_scale: 0.25),
//!     needs: (emitters: true),
//! )
//! ```

use std::path::Path;

use glam::{EulerRot, Mat4, Quat, Vec3};
use serde::{Deserialize, Serialize};

use super::error::{AssetError, AssetResult};
use super::model::MaterialKind;

/// A whole level as written in its RON file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Level {
    /// Model files (OBJ or glTF) this level uses, each under a name.
    #[serde(default)]
    pub models: Vec<ModelEntry>,
    /// Materials defined by the level, usable as instance overrides.
    #[serde(default)]
    pub materials: Vec<LevelMaterial>,
    /// Grids the engine makes (usable as models by name).
    #[serde(default)]
    pub grids: Vec<GridEntry>,
    /// Boxes the engine makes (usable as models by name).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub boxes: Vec<super::shapes::BoxEntry>,
    /// Heightfield terrains the engine makes (usable as models by name).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub terrains: Vec<super::shapes::TerrainEntry>,
    /// Box cities the engine makes (usable as models by name).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub cities: Vec<super::city::CityEntry>,
    /// Placed copies of models.
    #[serde(default)]
    pub instances: Vec<InstanceEntry>,
    pub camera: CameraDesc,
    /// The sun; `None` for indoor scenes.
    #[serde(default)]
    pub sun: Option<SunDesc>,
    /// What rays that leave the scene see.
    #[serde(default)]
    pub sky: SkyDesc,
    #[serde(default)]
    pub render: RenderSettings,
    /// Boxes in world space, each naming the light groups sampled while the camera is inside
    /// (see `level_render_areas`); none: every group is sampled everywhere.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub render_areas: Vec<super::RenderArea>,
    /// Renderer features the level may use (see [`super::Needs`]); absent: derived from content.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub needs: Option<super::Needs>,
    /// Sounds, animations, trigger volumes, lasers and rules (see `level_gameplay`).
    #[serde(default, skip_serializing_if = "super::GameplayEntry::is_empty")]
    pub gameplay: super::GameplayEntry,
    /// Skinned characters with a capsule body and animation states (see `level_character`).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub characters: Vec<super::CharacterEntry>,
}

/// A model file under a name.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ModelEntry {
    pub name: String,
    /// Relative to the asset root.
    pub path: String,
}

/// One placed copy of a model.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct InstanceEntry {
    /// Name of a [`ModelEntry`] or of an engine-made model (grid, box, terrain, city).
    pub model: String,
    /// A name game code and capture scripts refer to the instance by.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    #[serde(default)]
    pub transform: TransformDesc,
    /// Name of a [`LevelMaterial`] that replaces every material of the model.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub material: Option<String>,
    /// The instance moves (its transform is compared every frame); otherwise it is static.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub dynamic: bool,
    /// The light group its emitters belong to.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub light_group: Option<u32>,
    /// Animate the model's first mesh with travelling waves (deforming every frame).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub waves: Option<WaveDesc>,
    /// Physics: a static collider, a dynamic or kinematic body, or a sensor (see
    /// `level_body`); none by default.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub body: Option<super::level_body::BodyEntry>,
}

/// A flat grid made by the engine (water surfaces, test floors): `size` metres in x and z,
/// `divisions` quads along each, facing +Y, with normals and texture coordinates.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GridEntry {
    pub name: String,
    pub size: [f32; 2],
    pub divisions: [u32; 2],
    /// Name of a [`LevelMaterial`].
    pub material: String,
}

/// Two travelling sine waves displacing a grid vertically: height
/// `a·sin(k·x − ω·t) + a/2·sin(k·1.7·(x + z)·0.7 − 1.3·ω·t)` with `k = 2π/wavelength`,
/// `ω = k·speed`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WaveDesc {
    /// Metres.
    pub amplitude: f32,
    /// Metres.
    pub wavelength: f32,
    /// Metres per second.
    pub speed: f32,
    /// Also simulate ripples on the grid (a damped wave equation in the fixed steps, pushed by
    /// whatever wades), added on top of the two sine waves; none by default. See
    /// [`super::WaterSimDesc`].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub simulate: Option<super::WaterSimDesc>,
}

/// Scale, then rotate, then translate. Rotation: Euler angles in degrees, applied as yaw about
/// +Y, then pitch about +X, then roll about +Z (glam `EulerRot::YXZ`).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct TransformDesc {
    /// Metres.
    pub translation: [f32; 3],
    /// Degrees about (X, Y, Z).
    #[serde(skip_serializing_if = "is_zero3")]
    pub rotation_deg: [f32; 3],
    #[serde(skip_serializing_if = "is_one3")]
    pub scale: [f32; 3],
}

fn is_zero3(v: &[f32; 3]) -> bool {
    *v == [0.0; 3]
}

fn is_one3(v: &[f32; 3]) -> bool {
    *v == [1.0; 3]
}

impl Default for TransformDesc {
    fn default() -> Self {
        Self {
            translation: [0.0; 3],
            rotation_deg: [0.0; 3],
            scale: [1.0; 3],
        }
    }
}

impl TransformDesc {
    /// The affine matrix mapping model space to world space.
    pub fn world_from_model(&self) -> Mat4 {
        let [x, y, z] = self.rotation_deg.map(f32::to_radians);
        Mat4::from_scale_rotation_translation(
            Vec3::from(self.scale),
            Quat::from_euler(EulerRot::YXZ, y, x, z),
            Vec3::from(self.translation),
        )
    }
}

/// A perspective camera (pinhole, or thin lens when `aperture_radius > 0`).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CameraDesc {
    /// Metres, world space.
    pub position: [f32; 3],
    pub look_at: [f32; 3],
    #[serde(default = "default_up")]
    pub up: [f32; 3],
    /// Vertical field of view, degrees.
    pub vertical_fov_deg: f32,
    /// Lens radius in metres (0: pinhole).
    #[serde(default)]
    pub aperture_radius: f32,
    /// Metres to the plane in focus; default: the distance to `look_at`.
    #[serde(default)]
    pub focus_distance: Option<f32>,
}

fn default_up() -> [f32; 3] {
    [0.0, 1.0, 0.0]
}

/// A distant light source: a disc of the given angular radius.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SunDesc {
    /// Direction *towards* the sun (need not be unit length).
    pub direction: [f32; 3],
    /// Irradiance on a surface perpendicular to the beam, W·m⁻², linear RGB.
    pub irradiance: [f32; 3],
    /// Angular radius in degrees; 0 makes the sun a delta (directional) light.
    #[serde(default = "default_sun_radius")]
    pub angular_radius_deg: f32,
}

fn default_sun_radius() -> f32 {
    0.2665
}

/// Radiance seen by rays that leave the scene (W·sr⁻¹·m⁻², linear RGB).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum SkyDesc {
    /// The same radiance in every direction.
    Constant([f32; 3]),
    /// Blends zenith → horizon above the horizon and horizon → ground below it.
    Gradient {
        zenith: [f32; 3],
        horizon: [f32; 3],
        ground: [f32; 3],
    },
    /// A physically based sky with its sun (Hillaire 2020, `crate::sky`): the level's `sun`
    /// must be `None` (this sky places and colours the sun). The GPU tracer refuses it for now.
    Physical(crate::sky::PhysicalSky),
}

impl Default for SkyDesc {
    fn default() -> Self {
        SkyDesc::Constant([0.0; 3])
    }
}

/// How the level is rendered.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct RenderSettings {
    /// Maximum scattering events on a path (Mitsuba's `max_depth` minus one).
    pub max_bounces: u32,
    /// Scattering events before Russian roulette may end a path.
    pub roulette_start: u32,
    /// How next-event estimation picks an emissive triangle (`light_sampling: Tree`).
    #[serde(skip_serializing_if = "LightSampling::is_power")]
    pub light_sampling: LightSampling,
    /// Frames per second workload scaling holds while the level is played (`None`: 30, the
    /// games' default; see `level_render`). A player's own target frame rate wins.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub target_fps: Option<f32>,
    /// Lowest render resolution workload scaling may go to, as a fraction of the output per
    /// axis, in (0, 1] (`None`: ¼, 320×180 of a 1280×720 window).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub min_scale: Option<f32>,
    /// Interleaved indirect light: one pixel in this many (1, 2 or 4) traces a path's first
    /// diffuse or glossy bounce each frame, weighted to stay unbiased; direct light, mirrors
    /// and glass stay at every pixel (`render/cpu/interleave.rs`; `None`: 1, every pixel).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub indirect_every: Option<u32>,
}

impl Default for RenderSettings {
    fn default() -> Self {
        Self {
            max_bounces: 7,
            roulette_start: 4,
            light_sampling: LightSampling::Power,
            target_fps: None,
            min_scale: None,
            indirect_every: None,
        }
    }
}

/// How next-event estimation picks the emissive triangle it samples. Both are unbiased; they
/// differ in noise (see `docs/ACCURACY.md`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum LightSampling {
    /// In proportion to power (area × emitted luminance), from one table for the whole scene.
    #[default]
    Power,
    /// By importance from the shading point: a walk down the light tree (PBRT-v4's BVH light
    /// sampler), favouring near, bright emitters facing the point.
    Tree,
}

impl LightSampling {
    /// True for [`LightSampling::Power`] (the default, left out when levels are written).
    pub fn is_power(&self) -> bool {
        *self == LightSampling::Power
    }

    /// The name on command lines and in reports (`power`, `tree`).
    pub fn name(&self) -> &'static str {
        match self {
            LightSampling::Power => "power",
            LightSampling::Tree => "tree",
        }
    }
}

/// A material defined in the level (all colours linear RGB).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LevelMaterial {
    pub name: String,
    pub kind: MaterialKind,
    #[serde(default = "default_base_color")]
    pub base_color: [f32; 3],
    /// Emitted radiance, W·sr⁻¹·m⁻².
    #[serde(default)]
    pub emission: [f32; 3],
    #[serde(default)]
    pub two_sided_emission: bool,
    #[serde(default)]
    pub roughness: f32,
    #[serde(default)]
    pub metallic: f32,
    #[serde(default = "default_ior")]
    pub ior: f32,
    /// Beer–Lambert: colour left after `attenuation_distance` metres inside.
    #[serde(default = "default_attenuation_color")]
    pub attenuation_color: [f32; 3],
    #[serde(default)]
    pub attenuation_distance: Option<f32>,
}

fn default_base_color() -> [f32; 3] {
    [0.8; 3]
}
fn default_ior() -> f32 {
    1.5
}
fn default_attenuation_color() -> [f32; 3] {
    [1.0; 3]
}

impl Level {
    /// Parses a level from RON text; `path` only names the file in errors.
    pub fn parse(path: &Path, text: &str) -> AssetResult<Level> {
        ron::Options::default()
            .with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME)
            .from_str::<Level>(text)
            .map_err(|e| AssetError::Level {
                path: path.to_path_buf(),
                message: format!(
                    "line {}, column {}: {}",
                    e.span.start.line, e.span.start.col, e.code
                ),
            })
            .and_then(|level| level.render.check(path).map(|()| level))
            .and_then(|level| super::check_render_areas(&level, path).map(|()| level))
    }

    /// Reads and parses a level file.
    pub fn read(path: &Path) -> AssetResult<Level> {
        let text = std::fs::read_to_string(path).map_err(|source| AssetError::io(path, source))?;
        Level::parse(path, &text)
    }

    /// Writes the level as pretty RON, atomically (a temporary file renamed over the target),
    /// so that a crash never leaves a half-written level.
    pub fn write_atomic(&self, path: &Path) -> AssetResult<()> {
        let io = |source| AssetError::Io {
            path: path.to_path_buf(),
            source,
        };
        let text = ron::ser::to_string_pretty(
            self,
            ron::ser::PrettyConfig::default()
                .extensions(ron::extensions::Extensions::IMPLICIT_SOME),
        )
        .map_err(|e| AssetError::Level {
            path: path.to_path_buf(),
            message: format!("cannot serialise: {e}"),
        })?;
        super::atomic_file::write_atomic(path, text.as_bytes()).map_err(|e| io(e.source))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const MINIMAL: &str = r#"Level(
        models: [(name: "box", path: "cornell/box.obj")],
        instances: [(model: "box", transform: (translation: (1, 2, 3)))],
        camera: (position: (0, 1, 3.8), look_at: (0, 1, 0), vertical_fov_deg: 40),
    )"#;

    #[test]
    fn parses_with_defaults() -> AssetResult<()> {
        let level = Level::parse(Path::new("min.ron"), MINIMAL)?;
        assert_eq!(level.models[0].path, "cornell/box.obj");
        assert_eq!(level.instances[0].transform.translation, [1.0, 2.0, 3.0]);
        assert_eq!(level.instances[0].transform.scale, [1.0; 3]);
        assert_eq!(level.camera.up, [0.0, 1.0, 0.0]);
        assert_eq!(level.render, RenderSettings::default());
        assert_eq!(level.sky, SkyDesc::Constant([0.0; 3]));
        assert!(level.sun.is_none());
        Ok(())
    }

    #[test]
    fn unknown_field_names_file_line_and_field() {
        let text = MINIMAL.replace("vertical_fov_deg: 40", "vertical_fov_deg: 40, fov: 3");
        match Level::parse(Path::new("levels/bad.ron"), &text) {
            Err(AssetError::Level { path, message }) => {
                assert_eq!(path, Path::new("levels/bad.ron"));
                assert!(message.contains("fov"), "{message}");
                assert!(message.starts_with("line 4,"), "{message}");
            }
            other => panic!("expected a level error, got {other:?}"),
        }
    }

    #[test]
    fn round_trips_through_atomic_write() -> Result<(), Box<dyn std::error::Error>> {
        let level = Level::parse(Path::new("min.ron"), MINIMAL)?;
        let path = std::env::temp_dir().join(format!("candela_level_{}.ron", std::process::id()));
        level.write_atomic(&path)?;
        assert_eq!(Level::read(&path)?, level);
        std::fs::remove_file(&path)?;
        Ok(())
    }

    #[test]
    fn transform_applies_scale_rotation_translation_in_order() {
        let t = TransformDesc {
            translation: [1.0, 0.0, 0.0],
            rotation_deg: [0.0, 90.0, 0.0],
            scale: [2.0, 1.0, 1.0],
        };
        let p = t.world_from_model().transform_point3(Vec3::X);
        // (1,0,0) scaled to (2,0,0), yawed 90° about +Y to (0,0,-2), moved by +X.
        assert!((p - Vec3::new(1.0, 0.0, -2.0)).length() < 1e-5, "{p}");
    }
}
