//! Capture scripts: a RON file that drives the engine for a fixed number of frames — camera
//! keyframes, object motions by instance name, light-group switches, screenshots — so that a
//! flythrough, a benchmark or a CI check is the same run every time.
//!
//! Owns: the serde types of a script and parsing them (unknown fields refused, with line and
//! column). Parsing also runs the checks that need no level (`check`: frames in range,
//! keys in order, positive periods and sizes, safe screenshot names); names are checked against
//! the loaded level by `bind`, evaluation is `motion`, running is `run`.
//! Main thread. Must not: touch the engine or the file system beyond reading the script.
//!
//! Units: metres, seconds, degrees where a field name says `_deg`. Frames count from 0; frame
//! `n` shows the world at `n × seconds_per_frame` seconds.
//!
//! ```ron
//! Script(
//!     level: (path: "demo.ron"),             // relative to the script's folder
//!     frames: 120,
//!     seconds_per_frame: 0.033333335,         // fixed: runs are deterministic
//!     render: (tracer: Cpu, width: 320, height: 180, spp: 2, seed: 7),
//!     camera: [
//!         (frame: 0, position: (0, 40, 120), look_at: (0, 0, 0), fov_deg: 50),
//!         (frame: 59, position: (60, 20, 60), look_at: (0, 5, 0), interpolation: Linear),
//!         (frame: 60, position: (0, 3, 20), look_at: (0, 2, 0), cut: true),
//!     ],
//!     motions: [
//!         (instance: "drone_*", motion: Orbit(radius: 6, period_seconds: 8), stagger_seconds: 0.25),
//!         (instance: "drone_*", motion: Spin(deg_per_second: 90)),
//!         (instance: "gate", motion: Keyframes([
//!             (frame: 0),
//!             (frame: 90, translation: (0, 4, 0), rotation_deg: (0, 90, 0)),
//!         ])),
//!     ],
//!     lights: [(frame: 30, group: 2, on: false)],
//!     times: [(frame: 0, utc_hours: 5.5), (frame: 60, utc_hours: 12)],
//!     screenshots: [(frame: 59, name: "overview"), (frame: 119, exr: true)],
//!     hold_from_frame: None,                 // Some(n): the world stands still from frame n
//! )
//! ```
//!
//! * `camera`: keys in increasing frame order. Before the first key the camera holds it; after
//!   the last it holds the last. `interpolation` (default `Smooth`) says how the camera moves from
//!   a key to the next: `Linear`, or `Smooth` (cubic Hermite with Catmull–Rom tangents scaled by
//!   the key spacing, zero at the ends of a shot). A key with `cut: true` starts a new shot: the
//!   camera jumps there at its frame, the frames before hold the previous key, and the converged
//!   image restarts. `fov_deg` (vertical) defaults to the previous key's, the first key's to the
//!   level camera's. No keys: the level's camera.
//! * `motions`: each entry moves the instances named `instance` (a name from the level, or a
//!   prefix ending in `*` for every named instance that starts with it, in level order; the
//!   `k`-th match runs `k × stagger_seconds` ahead). Entries apply in list order to the
//!   instance's rest transform (the level's): `Keyframes` sets translation/rotation/scale (a
//!   missing field keeps the rest value; same `interpolation` as the camera, rotations slerped
//!   with a smoothstep for `Smooth`); `Orbit` sets the translation on a circle of `radius` about
//!   `center` (default: the rest position) in the plane normal to `axis` (default +Y); `Bob` adds
//!   `axis × amplitude × sin(phase)`; `Slide` adds `offset × (1 − cos(phase))/2` (there and back);
//!   `Spin` turns about `axis` through the object's origin. Phases are
//!   `phase_deg + 360° × t / period_seconds`. Moved instances must be `dynamic` in the level.
//! * `lights`: at `frame`, light group `group` turns on or off (the group must exist).
//! * `times`: at `frame`, the physical sky's time of day is set to `utc_hours` (0 ≤ h < 24, same
//!   date and place; the level's sky must be `Physical` with a `time`); keys in increasing frame
//!   order. Between keys the day flows at the sky's `time_rate` (0: it stands still).
//! * `screenshots`: at `frame`, the converged film is written as `<name>.png` (tonemapped,
//!   `render.exposure_ev`, or with `render.auto_exposure: true` the exposure the physical sky's
//!   horizontal illuminance calls for at that frame, `sky::exposure_ev`, at most
//!   `render.max_exposure_ev` when set; plus the shot's `exposure_compensation_ev`) and, with `exr: true`, `<name>.exr` (linear radiance). `name`
//!   defaults to `frame_NNNNN`; it may hold only letters, digits, `_`, `-` and `.`.
//! * `hold_from_frame`: from that frame on (it must be below `frames`) the engine is paused:
//!   no fixed steps, so physics, characters, water ripples and the day stand still, and a
//!   screenshot taken later is that moment converged (keep the camera and motions still too).

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

pub use super::error::ScriptError;

/// A whole capture script.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Script {
    /// The level to load; `None` when the caller provides the scene.
    #[serde(default)]
    pub level: Option<ScriptLevel>,
    /// Frames to run (frames `0..frames`).
    pub frames: u32,
    /// Simulated seconds per frame, fixed.
    pub seconds_per_frame: f64,
    #[serde(default)]
    pub render: ScriptRender,
    #[serde(default)]
    pub camera: Vec<CameraKey>,
    #[serde(default)]
    pub motions: Vec<MotionEntry>,
    #[serde(default)]
    pub lights: Vec<LightSwitch>,
    #[serde(default)]
    pub times: Vec<TimeKey>,
    #[serde(default)]
    pub screenshots: Vec<Screenshot>,
    /// From this frame on the world's clock stands still (the engine is paused: no fixed
    /// steps, no game time; the camera and motions still follow their keys): a moment of
    /// moving things — water rippling round a wader — held while the film converges on it.
    #[serde(default)]
    pub hold_from_frame: Option<u32>,
    /// The file the script was read from (for messages and relative paths); not in the file.
    #[serde(skip)]
    pub source: PathBuf,
}

/// Where the level is, relative to the script's folder.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ScriptLevel {
    pub path: String,
    /// Folder every path of the level must stay in (default: the level's folder).
    #[serde(default)]
    pub asset_root: Option<String>,
}

/// Which tracer renders the script.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum ScriptTracer {
    /// The Rust tracer: bit-identical images run after run.
    #[default]
    Cpu,
    /// wgpu compute (lavapipe without a GPU).
    Gpu,
}

/// How the script renders.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ScriptRender {
    pub tracer: ScriptTracer,
    /// Pixels.
    pub width: u32,
    pub height: u32,
    /// Samples per pixel per frame.
    pub spp: u32,
    pub seed: u32,
    /// Exposure of the PNG screenshots, stops.
    pub exposure_ev: f32,
    /// Expose the PNG screenshots for the physical sky's horizontal illuminance at their frame
    /// instead (`Engine::sky_exposure_ev`; `exposure_ev` for other skies).
    pub auto_exposure: bool,
    /// With `auto_exposure`: the most stops the sky's meter may set, stops (`None`: no cap).
    /// The meter reads the sky alone, so after dusk it exposes for moonlight or starlight and
    /// would blow out a scene lit by torches (`WindowedPlay::max_exposure_ev` alike).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_exposure_ev: Option<f32>,
}

impl Default for ScriptRender {
    fn default() -> Self {
        Self {
            tracer: ScriptTracer::Cpu,
            width: 640,
            height: 360,
            spp: 4,
            seed: 0,
            exposure_ev: 0.0,
            auto_exposure: false,
            max_exposure_ev: None,
        }
    }
}

/// How a keyframed value gets from one key to the next.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Interpolation {
    Linear,
    /// Cubic Hermite, Catmull–Rom tangents (see the module doc).
    #[default]
    Smooth,
}

/// A camera keyframe.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CameraKey {
    pub frame: u32,
    /// Metres, world space.
    pub position: [f32; 3],
    pub look_at: [f32; 3],
    /// Vertical field of view, degrees (default: the previous key's).
    #[serde(default)]
    pub fov_deg: Option<f32>,
    /// Start a new shot here (jump, restart the converged image).
    #[serde(default)]
    pub cut: bool,
    /// How the camera moves from this key to the next.
    #[serde(default)]
    pub interpolation: Interpolation,
}

/// Motions of the instances `instance` names.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MotionEntry {
    /// An instance name, or a prefix ending in `*`.
    pub instance: String,
    pub motion: Motion,
    /// Seconds the `k`-th matched instance runs ahead of the first.
    #[serde(default)]
    pub stagger_seconds: f32,
}

/// One motion (see the module doc for how motions compose).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum Motion {
    Keyframes(Vec<ObjectKey>),
    Orbit {
        /// Metres; default: the rest position.
        #[serde(default)]
        center: Option<[f32; 3]>,
        /// Metres.
        radius: f32,
        period_seconds: f32,
        #[serde(default = "up")]
        axis: [f32; 3],
        #[serde(default)]
        phase_deg: f32,
    },
    Bob {
        /// Metres.
        amplitude: f32,
        period_seconds: f32,
        #[serde(default = "up")]
        axis: [f32; 3],
        #[serde(default)]
        phase_deg: f32,
    },
    Slide {
        /// Metres: the far end of the slide, relative to the rest position.
        offset: [f32; 3],
        period_seconds: f32,
        #[serde(default)]
        phase_deg: f32,
    },
    Spin {
        #[serde(default = "up")]
        axis: [f32; 3],
        deg_per_second: f32,
    },
}

fn up() -> [f32; 3] {
    [0.0, 1.0, 0.0]
}

/// A keyframe of an object's transform; missing parts keep the rest transform's.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ObjectKey {
    pub frame: u32,
    /// Metres.
    #[serde(default)]
    pub translation: Option<[f32; 3]>,
    /// Degrees about (X, Y, Z), applied yaw, pitch, roll as in the level format.
    #[serde(default)]
    pub rotation_deg: Option<[f32; 3]>,
    #[serde(default)]
    pub scale: Option<[f32; 3]>,
    #[serde(default)]
    pub interpolation: Interpolation,
}

/// A light group switched at a frame.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LightSwitch {
    pub frame: u32,
    pub group: u32,
    pub on: bool,
}

/// The time of day set at a frame.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TimeKey {
    pub frame: u32,
    /// Hours since midnight UTC, 0 ≤ h < 24.
    pub utc_hours: f64,
}

/// A screenshot at a frame.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Screenshot {
    pub frame: u32,
    #[serde(default)]
    pub name: Option<String>,
    /// Also write linear radiance as OpenEXR.
    #[serde(default)]
    pub exr: bool,
    /// Stops added to this PNG's exposure, metered or manual (a photographer's exposure
    /// compensation: −1.5 keeps a dusk sky towards the sun from clipping); finite, default 0.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub exposure_compensation_ev: f32,
}

fn is_zero(v: &f32) -> bool {
    *v == 0.0
}

impl Screenshot {
    /// The file stem: `name`, or `frame_NNNNN`.
    pub fn stem(&self) -> String {
        self.name
            .clone()
            .unwrap_or_else(|| format!("frame_{:05}", self.frame))
    }
}

fn ron_options() -> ron::Options {
    ron::Options::default().with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME)
}

impl Script {
    /// Parses and checks a script from RON text; `path` names the file in errors and anchors
    /// its relative paths.
    pub fn parse(path: &Path, text: &str) -> Result<Script, ScriptError> {
        let mut script: Script = ron_options()
            .from_str(text)
            .map_err(|e| ScriptError::Parse {
                path: path.to_path_buf(),
                line: e.span.start.line,
                column: e.span.start.col,
                message: e.code.to_string(),
            })?;
        script.source = path.to_path_buf();
        script.validate()?;
        Ok(script)
    }

    /// Reads, parses and checks a script file.
    pub fn read(path: &Path) -> Result<Script, ScriptError> {
        let text = std::fs::read_to_string(path).map_err(|source| ScriptError::Io {
            path: path.to_path_buf(),
            source,
        })?;
        Script::parse(path, &text)
    }

    /// The script as pretty RON (what [`Script::parse`] reads back to an equal script).
    pub fn to_ron(&self) -> Result<String, ScriptError> {
        ron::ser::to_string_pretty(
            self,
            ron::ser::PrettyConfig::default()
                .extensions(ron::extensions::Extensions::IMPLICIT_SOME),
        )
        .map_err(|e| ScriptError::Invalid {
            path: self.source.clone(),
            item: "script".into(),
            message: format!("cannot serialise: {e}"),
        })
    }
}
