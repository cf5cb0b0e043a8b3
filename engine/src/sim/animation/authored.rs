//! Clips authored by hand in level files (doors, elevators, moving platforms): a RON
//! description of named targets and keyframe tracks, checked and turned into [`Clip`]s.
//!
//! Owns: [`AuthoredClipSet::load`] / `from_ron` and [`AuthoredClipSet::to_clips`] (the serde
//! types themselves are `assets::clip_desc`'s, since level files embed them). Must not: know what the targets are (the level or the ECS
//! binds target names to entities), or read files other than the one it is given. Level
//! files can embed an `AuthoredClipSet` (targets = instance names) once triggers drive doors;
//! `assets/test_scenes/anim/door_and_lift.ron` is an example.
//! Units: seconds; translation in metres; rotation as a quaternion (x, y, z, w), normalised
//! here (authored by hand, so never trusted to be unit length); scale factors; weights.
//!
//! ```ron
//! AuthoredClipSet(
//!     targets: ["door"],
//!     clips: [AuthoredClip(
//!         name: "open",
//!         tracks: [AuthoredTrack(target: "door", property: Translation, interpolation: Linear,
//!             keys: [AuthoredKey(time_seconds: 0.0, value: [0.0, 0.0, 0.0]),
//!                    AuthoredKey(time_seconds: 1.5, value: [0.0, 2.5, 0.0])])],
//!         events: [ClipEvent(time_seconds: 1.5, name: "opened")],
//!     )],
//! )
//! ```

use std::path::Path;

use super::clip::{Channel, Clip, Interpolation, Property, check_clip};
use super::error::{AnimError, AnimResult};
use crate::assets::{AssetError, AuthoredClipSet};

/// Reading, checking and sampling authored clips (the types are `assets::clip_desc`'s: level
/// files embed them).
impl AuthoredClipSet {
    /// Reads and parses the RON file at `path`.
    pub fn load(path: &Path) -> AnimResult<Self> {
        let text = std::fs::read_to_string(path).map_err(|source| AssetError::io(path, source))?;
        Self::from_ron(path, &text)
    }

    /// Parses RON `text` read from `file` (named in errors).
    pub fn from_ron(file: &Path, text: &str) -> AnimResult<Self> {
        ron::from_str(text).map_err(|e| AnimError::BadRon {
            file: file.to_path_buf(),
            message: e.to_string(),
        })
    }

    /// The clips, checked like glTF clips (targets exist, counts match, finite increasing
    /// times, finite values), plus: each key's value has the property's width (the first
    /// key's, for weights), and rotations are not zero.
    pub fn to_clips(&self, file: &Path) -> AnimResult<Vec<Clip>> {
        let mut clips = Vec::with_capacity(self.clips.len());
        for authored in &self.clips {
            let mut channels = Vec::with_capacity(authored.tracks.len());
            for (index, track) in authored.tracks.iter().enumerate() {
                let bad = |message: String| AnimError::BadChannel {
                    file: file.to_path_buf(),
                    clip: authored.name.clone(),
                    channel: index,
                    message,
                };
                let Some(target) = self.targets.iter().position(|t| *t == track.target) else {
                    return Err(AnimError::UnknownTarget {
                        file: file.to_path_buf(),
                        clip: authored.name.clone(),
                        track: index,
                        target: track.target.clone(),
                    });
                };
                let width = track
                    .property
                    .components()
                    .or_else(|| track.keys.first().map(|k| k.value.len()))
                    .unwrap_or(0);
                let mut values = Vec::new();
                for (k, key) in track.keys.iter().enumerate() {
                    let zero = vec![0.0; width];
                    let mut value = key.value.clone();
                    if track.property == Property::Rotation && value.len() == 4 {
                        let length = value.iter().map(|c| c * c).sum::<f32>().sqrt();
                        if length.is_nan() || length <= 0.0 {
                            return Err(bad(format!("key {k}: the rotation is zero")));
                        }
                        value.iter_mut().for_each(|c| *c /= length);
                    }
                    let elements = match track.interpolation {
                        Interpolation::CubicSpline => vec![
                            key.in_tangent.clone().unwrap_or_else(|| zero.clone()),
                            value,
                            key.out_tangent.clone().unwrap_or_else(|| zero.clone()),
                        ],
                        _ => vec![value],
                    };
                    for element in elements {
                        if element.len() != width {
                            return Err(bad(format!(
                                "key {k}: {} values where {} needs {width}",
                                element.len(),
                                track.property.name()
                            )));
                        }
                        values.extend(element);
                    }
                }
                channels.push(Channel {
                    target,
                    property: track.property,
                    interpolation: track.interpolation,
                    times_seconds: track.keys.iter().map(|k| k.time_seconds).collect(),
                    values,
                    width,
                });
            }
            let mut clip = Clip::new(authored.name.clone(), channels);
            clip.events = authored.events.clone();
            check_clip(file, &clip, self.targets.len())?;
            clips.push(clip);
        }
        Ok(clips)
    }
}
