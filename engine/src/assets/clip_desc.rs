//! The words level files and glTF use for keyframe clips, as plain serde data: how values
//! between keys are found ([`Interpolation`]), which property a channel drives ([`Property`]),
//! named events at times ([`ClipEvent`]), what happens at a clip's ends ([`PlayMode`]), and
//! clips authored by hand in RON ([`AuthoredClipSet`] and its parts).
//!
//! Owns: these types only. Checking authored clips and turning them into sampled `Clip`s is
//! `sim::animation`'s (`AuthoredClipSet::to_clips`); so is playing them. Any thread.
//! Must not: sample, play or check anything.
//! Units: seconds; translation in metres; rotation as an (x, y, z, w) quaternion; scale
//! factors; weights unitless.

use serde::{Deserialize, Serialize};

/// How values between two keys are found (glTF 2.0 §3.11 "interpolation").
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Interpolation {
    /// The value of the key at or before the time.
    Step,
    /// Component-wise lerp; rotations by slerp (shortest path).
    Linear,
    /// Hermite spline; each key stores (in-tangent, value, out-tangent).
    CubicSpline,
}

/// The property a channel drives.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Property {
    /// Local translation, metres (3 components).
    Translation,
    /// Local rotation quaternion x, y, z, w (4 components).
    Rotation,
    /// Local scale factors (3 components).
    Scale,
    /// Morph target weights (one component per target).
    Weights,
}

impl Property {
    /// Components per value, `None` for weights (one per morph target, set by the mesh).
    pub fn components(self) -> Option<usize> {
        match self {
            Property::Translation | Property::Scale => Some(3),
            Property::Rotation => Some(4),
            Property::Weights => None,
        }
    }

    /// The glTF name of the property.
    pub fn name(self) -> &'static str {
        match self {
            Property::Translation => "translation",
            Property::Rotation => "rotation",
            Property::Scale => "scale",
            Property::Weights => "weights",
        }
    }
}

/// Something a game wants to hear about when playback passes a time in a clip (a door's
/// "latched" sound, a footstep).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ClipEvent {
    /// When, in seconds from the start of the clip.
    pub time_seconds: f64,
    pub name: String,
}

/// What happens at the ends of a clip.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum PlayMode {
    /// Play to the end (the start, if reversed) and hold there; the playback is finished.
    Once,
    /// Wrap around to the other end.
    Loop,
    /// Turn around at each end.
    PingPong,
}

/// Targets and the clips that animate them.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AuthoredClipSet {
    /// Target names; a clip's channel target is an index into this list.
    pub targets: Vec<String>,
    pub clips: Vec<AuthoredClip>,
}

/// One authored clip.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AuthoredClip {
    pub name: String,
    pub tracks: Vec<AuthoredTrack>,
    #[serde(default)]
    pub events: Vec<ClipEvent>,
}

/// One property of one target over time.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AuthoredTrack {
    pub target: String,
    pub property: Property,
    pub interpolation: Interpolation,
    pub keys: Vec<AuthoredKey>,
}

/// One key: a time and a value (3 floats for translation and scale, 4 for rotation, one per
/// weight), with tangents (units per second) for cubic splines, zero when left out.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AuthoredKey {
    pub time_seconds: f32,
    pub value: Vec<f32>,
    #[serde(default)]
    pub in_tangent: Option<Vec<f32>>,
    #[serde(default)]
    pub out_tangent: Option<Vec<f32>>,
}
