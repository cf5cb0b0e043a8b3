//! Snapping for the transform tools: translations to a grid (metres), rotations to an angle
//! step (degrees), scales to a step (never to zero). A step that is not positive and finite
//! leaves values as they are; results never carry a negative zero (`-0.0` → `0.0`).
//!
//! Main thread. Must not: read the level or the world.

use crate::assets::TransformDesc;

/// `v` rounded to the nearest multiple of `step`.
pub fn snap_value(v: f32, step: f32) -> f32 {
    if step > 0.0 && step.is_finite() && v.is_finite() {
        (v / step).round() * step + 0.0
    } else {
        v
    }
}

/// An angle in degrees rounded to a multiple of `step_deg`.
pub fn snap_angle_deg(angle_deg: f32, step_deg: f32) -> f32 {
    snap_value(angle_deg, step_deg)
}

/// A scale factor rounded to a multiple of `step`, at least `step` in magnitude (a scale of
/// zero would make the transform degenerate); the sign (a mirror) is kept.
pub fn snap_scale(scale: f32, step: f32) -> f32 {
    let snapped = snap_value(scale, step);
    if snapped == 0.0 && step > 0.0 && step.is_finite() {
        step.copysign(scale)
    } else {
        snapped
    }
}

/// The snapping in effect: each step `None` when its snapping is off.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Snap {
    /// Grid spacing, metres.
    pub grid: Option<f32>,
    /// Angle step, degrees.
    pub angle_deg: Option<f32>,
    /// Scale step (a factor).
    pub scale: Option<f32>,
}

impl Snap {
    /// `t` with each part snapped whose snapping is on.
    pub fn transform(&self, t: TransformDesc) -> TransformDesc {
        TransformDesc {
            translation: self
                .grid
                .map_or(t.translation, |s| t.translation.map(|v| snap_value(v, s))),
            rotation_deg: self.angle_deg.map_or(t.rotation_deg, |s| {
                t.rotation_deg.map(|v| snap_angle_deg(v, s))
            }),
            scale: self
                .scale
                .map_or(t.scale, |s| t.scale.map(|v| snap_scale(v, s))),
        }
    }
}
