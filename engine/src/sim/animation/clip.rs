//! Keyframe clips: channels of key times and values, each driving one property (translation,
//! rotation, scale or morph weights) of one target, and the checks every clip passes before
//! use, whichever file it came from (glTF or a level file).
//!
//! Owns: [`Clip`], [`Channel`] and [`check_clip`] (the vocabulary files spell clips in —
//! [`Interpolation`], [`Property`], [`ClipEvent`] — is `assets::clip_desc`'s). Sampling lives in `sample`; applying samples to a pose in `pose`.
//! Must not: read files, or know about nodes beyond their index (`target`).
//! Units: key times in seconds (float32, as glTF stores them); translation in metres,
//! rotation as an (x, y, z, w) quaternion, scale as a factor, weights unitless.

use std::path::Path;

use super::error::{AnimError, AnimResult};
pub use crate::assets::{ClipEvent, Interpolation, Property};

/// One animated property of one target.
#[derive(Clone, Debug, PartialEq)]
pub struct Channel {
    /// The target: a glTF node index, or an index into an authored clip set's targets.
    pub target: usize,
    pub property: Property,
    pub interpolation: Interpolation,
    /// Key times in seconds, strictly increasing (checked by [`check_clip`]).
    pub times_seconds: Vec<f32>,
    /// Flat values: `width` floats per element, one element per key (three per key for
    /// [`Interpolation::CubicSpline`]: in-tangent, value, out-tangent; tangents in units
    /// per second).
    pub values: Vec<f32>,
    /// Floats per element: 3, 4, or the morph target count.
    pub width: usize,
}

impl Channel {
    /// Elements stored per key: 3 for cubic splines, else 1.
    pub fn elements_per_key(&self) -> usize {
        match self.interpolation {
            Interpolation::CubicSpline => 3,
            _ => 1,
        }
    }
}

/// A named set of channels played together, with events at times.
#[derive(Clone, Debug, PartialEq)]
pub struct Clip {
    pub name: String,
    pub channels: Vec<Channel>,
    pub events: Vec<ClipEvent>,
    /// The largest key time over all channels, seconds (as three.js's `resetDuration` and
    /// most engines define a glTF clip's length).
    pub duration_seconds: f64,
}

impl Clip {
    /// A clip of `channels`; its duration is their largest key time.
    pub fn new(name: impl Into<String>, channels: Vec<Channel>) -> Self {
        let duration_seconds = channels
            .iter()
            .filter_map(|c| c.times_seconds.last())
            .fold(0.0f64, |d, &t| d.max(f64::from(t)));
        Self {
            name: name.into(),
            channels,
            events: Vec::new(),
            duration_seconds,
        }
    }
}

/// Checks `clip` (from `file`) against `target_count` targets: every channel names an
/// existing target, has at least one key, strictly increasing finite times, finite values,
/// and as many values as its keys need. Morph-weight widths are checked by the loader, which
/// knows the mesh.
pub fn check_clip(file: &Path, clip: &Clip, target_count: usize) -> AnimResult<()> {
    for (index, channel) in clip.channels.iter().enumerate() {
        check_channel(file, &clip.name, index, channel, target_count)?;
    }
    for event in &clip.events {
        if !event.time_seconds.is_finite() {
            return Err(AnimError::BadChannel {
                file: file.to_path_buf(),
                clip: clip.name.clone(),
                channel: 0,
                message: format!("event {:?} has a non-finite time", event.name),
            });
        }
    }
    Ok(())
}

/// Checks one channel (see [`check_clip`]).
pub(crate) fn check_channel(
    file: &Path,
    clip: &str,
    index: usize,
    channel: &Channel,
    target_count: usize,
) -> AnimResult<()> {
    let file = file.to_path_buf();
    let clip = clip.to_string();
    if channel.target >= target_count {
        return Err(AnimError::MissingNode {
            file,
            clip,
            channel: index,
            node: channel.target,
            node_count: target_count,
        });
    }
    let bad = |message: String| AnimError::BadChannel {
        file: file.clone(),
        clip: clip.clone(),
        channel: index,
        message,
    };
    if let Some(width) = channel.property.components()
        && width != channel.width
    {
        return Err(bad(format!(
            "{} values need {width} components, got {}",
            channel.property.name(),
            channel.width
        )));
    }
    if channel.width == 0 {
        return Err(bad("values have no components".to_string()));
    }
    let inputs = channel.times_seconds.len();
    if inputs == 0 {
        return Err(bad("has no keys".to_string()));
    }
    let expected = inputs * channel.elements_per_key() * channel.width;
    if channel.values.len() != expected {
        return Err(AnimError::KeyCountMismatch {
            file,
            clip,
            channel: index,
            inputs,
            outputs: channel.values.len() / channel.width,
            expected: expected / channel.width,
        });
    }
    for (key, &time) in channel.times_seconds.iter().enumerate() {
        if !time.is_finite() {
            return Err(AnimError::NonFiniteKey {
                file,
                clip,
                channel: index,
                key,
                what: "time",
            });
        }
        if key > 0 && time <= channel.times_seconds[key - 1] {
            return Err(AnimError::TimesNotIncreasing {
                file,
                clip,
                channel: index,
                key,
                time,
            });
        }
    }
    let per_key = channel.elements_per_key() * channel.width;
    if let Some(at) = channel.values.iter().position(|v| !v.is_finite()) {
        return Err(AnimError::NonFiniteKey {
            file,
            clip,
            channel: index,
            key: at / per_key,
            what: "value",
        });
    }
    Ok(())
}
