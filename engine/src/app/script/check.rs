//! Checking a parsed [`Script`] without the level: frames in range, keys in increasing order,
//! finite values and times of day, positive periods and sizes, non-zero axes and scales, safe and unique
//! screenshot names. Every failure names the script file and the item (`camera[2]`,
//! `motions[1] ("car_*") key[3]`, `screenshots[0]`).
//!
//! Owns: [`Script::validate`]. Main thread. Must not: look at the level (`bind` does).

use std::collections::HashSet;

use super::desc::{Motion, MotionEntry, Script, ScriptError};

impl Script {
    fn invalid(&self, item: impl Into<String>, message: impl Into<String>) -> ScriptError {
        ScriptError::Invalid {
            path: self.source.clone(),
            item: item.into(),
            message: message.into(),
        }
    }

    fn check_frame(&self, item: &str, frame: u32) -> Result<(), ScriptError> {
        if frame >= self.frames {
            return Err(ScriptError::FrameOutOfRange {
                path: self.source.clone(),
                item: item.into(),
                frame,
                frames: self.frames,
            });
        }
        Ok(())
    }

    fn check_increasing(&self, item: &str, frames: &[u32]) -> Result<(), ScriptError> {
        for (i, w) in frames.windows(2).enumerate() {
            if w[1] <= w[0] {
                return Err(self.invalid(
                    format!("{item}[{}]", i + 1),
                    format!("key frames must increase: {} after {}", w[1], w[0]),
                ));
            }
        }
        for (i, &f) in frames.iter().enumerate() {
            self.check_frame(&format!("{item}[{i}]"), f)?;
        }
        Ok(())
    }

    /// Checks everything that does not need the level (see the module doc).
    pub fn validate(&self) -> Result<(), ScriptError> {
        if self.frames == 0 {
            return Err(self.invalid("frames", "must be at least 1"));
        }
        if !(self.seconds_per_frame.is_finite() && self.seconds_per_frame > 0.0) {
            return Err(self.invalid("seconds_per_frame", "must be a positive number"));
        }
        if let Some(frame) = self.hold_from_frame {
            self.check_frame("hold_from_frame", frame)?;
        }
        let r = &self.render;
        if r.width == 0 || r.height == 0 || r.spp == 0 || r.width > 16384 || r.height > 16384 {
            return Err(self.invalid(
                "render",
                "width and height must be in 1..=16384 and spp at least 1",
            ));
        }
        if r.max_exposure_ev.is_some_and(|ev| !ev.is_finite()) {
            return Err(self.invalid("render.max_exposure_ev", "must be a finite number of stops"));
        }
        let frames: Vec<u32> = self.camera.iter().map(|k| k.frame).collect();
        self.check_increasing("camera", &frames)?;
        for (i, k) in self.camera.iter().enumerate() {
            let finite = k.position.iter().chain(&k.look_at).all(|v| v.is_finite());
            if !finite || k.position == k.look_at {
                return Err(self.invalid(
                    format!("camera[{i}]"),
                    "position and look_at must be finite and differ",
                ));
            }
            if k.fov_deg.is_some_and(|f| !(f > 0.0 && f < 180.0)) {
                return Err(self.invalid(format!("camera[{i}]"), "fov_deg must be in (0, 180)"));
            }
        }
        for (i, entry) in self.motions.iter().enumerate() {
            self.validate_motion(&format!("motions[{i}] ({:?})", entry.instance), entry)?;
        }
        for (i, s) in self.lights.iter().enumerate() {
            self.check_frame(&format!("lights[{i}]"), s.frame)?;
        }
        let frames: Vec<u32> = self.times.iter().map(|k| k.frame).collect();
        self.check_increasing("times", &frames)?;
        for (i, k) in self.times.iter().enumerate() {
            if !(k.utc_hours.is_finite() && (0.0..24.0).contains(&k.utc_hours)) {
                return Err(self.invalid(format!("times[{i}]"), "utc_hours must be in 0..24"));
            }
        }
        let mut names = HashSet::new();
        for (i, s) in self.screenshots.iter().enumerate() {
            let item = format!("screenshots[{i}]");
            self.check_frame(&item, s.frame)?;
            if !s.exposure_compensation_ev.is_finite() {
                return Err(self.invalid(item, "exposure_compensation_ev must be finite"));
            }
            let stem = s.stem();
            let safe = !stem.is_empty()
                && !stem.starts_with('.')
                && stem
                    .chars()
                    .all(|c| c.is_ascii_alphanumeric() || matches!(c, '_' | '-' | '.'));
            if !safe {
                return Err(self.invalid(
                    item,
                    format!("name {stem:?} may hold only letters, digits, '_', '-' and '.'"),
                ));
            }
            if !names.insert(stem.clone()) {
                return Err(self.invalid(item, format!("name {stem:?} is used twice")));
            }
        }
        Ok(())
    }

    fn validate_motion(&self, item: &str, entry: &MotionEntry) -> Result<(), ScriptError> {
        let name = entry.instance.trim_end_matches('*');
        if name.is_empty() || name.contains('*') {
            return Err(self.invalid(
                item,
                "instance must be a name, or a non-empty prefix ending in '*'",
            ));
        }
        if !entry.stagger_seconds.is_finite() {
            return Err(self.invalid(item, "stagger_seconds must be finite"));
        }
        let period_ok = |p: f32| p.is_finite() && p > 0.0;
        let axis_ok = |a: &[f32; 3]| a.iter().all(|v| v.is_finite()) && a.iter().any(|v| *v != 0.0);
        let ok = match &entry.motion {
            Motion::Keyframes(keys) => {
                if keys.is_empty() {
                    return Err(self.invalid(item, "Keyframes needs at least one key"));
                }
                let frames: Vec<u32> = keys.iter().map(|k| k.frame).collect();
                self.check_increasing(&format!("{item} key"), &frames)?;
                keys.iter().all(|k| {
                    [k.translation, k.rotation_deg, k.scale]
                        .iter()
                        .flatten()
                        .flatten()
                        .all(|v| v.is_finite())
                        && k.scale.is_none_or(|s| s.iter().all(|v| *v != 0.0))
                })
            }
            Motion::Orbit {
                center,
                radius,
                period_seconds,
                axis,
                phase_deg,
            } => {
                period_ok(*period_seconds)
                    && axis_ok(axis)
                    && radius.is_finite()
                    && phase_deg.is_finite()
                    && center.is_none_or(|c| c.iter().all(|v| v.is_finite()))
            }
            Motion::Bob {
                amplitude,
                period_seconds,
                axis,
                phase_deg,
            } => {
                period_ok(*period_seconds)
                    && axis_ok(axis)
                    && amplitude.is_finite()
                    && phase_deg.is_finite()
            }
            Motion::Slide {
                offset,
                period_seconds,
                phase_deg,
            } => {
                period_ok(*period_seconds)
                    && offset.iter().all(|v| v.is_finite())
                    && phase_deg.is_finite()
            }
            Motion::Spin {
                axis,
                deg_per_second,
            } => axis_ok(axis) && deg_per_second.is_finite(),
        };
        if !ok {
            return Err(self.invalid(
                item,
                "values must be finite, periods positive, axes and scales non-zero",
            ));
        }
        Ok(())
    }
}
