//! What a level declares about how it is played in real time, and its checks: the frame rate
//! workload scaling holds and the lowest resolution it may go to (`render: (target_fps: 30,
//! min_scale: 0.25)`), how many pixels share one indirect path (`indirect_every: 4`), beside the bounce count and roulette start every render of the level
//! uses (games and converged captures alike).
//!
//! Owns: the defaults of the real-time fields of [`RenderSettings`] and
//! [`RenderSettings::check`] (called by `Level::parse`, so a bad value never reaches a game).
//! Main thread, at load. Must not: build the scaling controller (`render::scaling` does, from
//! these numbers) or change the serialised form (absent fields stay absent).

use std::path::Path;

use super::error::{AssetError, AssetResult};
use super::level::RenderSettings;

/// Frames per second held when a level declares none (the games' default on two CPU cores).
pub const DEFAULT_TARGET_FPS: f32 = 30.0;
/// Lowest render resolution (fraction of the output per axis) when a level declares none.
pub const DEFAULT_MIN_SCALE: f32 = 0.25;
/// Most bounces a level may ask for.
pub const MAX_BOUNCES: u32 = 64;

impl RenderSettings {
    /// Seconds per frame workload scaling holds (1 / `target_fps`, default 1/30 s).
    pub fn frame_seconds(&self) -> f32 {
        1.0 / self.target_fps.unwrap_or(DEFAULT_TARGET_FPS)
    }

    /// Lowest render resolution workload scaling may go to, fraction of the output per axis.
    pub fn min_resolution(&self) -> f32 {
        self.min_scale.unwrap_or(DEFAULT_MIN_SCALE)
    }

    /// The `layout::METHOD_INDIRECT_*` bit of `indirect_every` (none for 1 or absent).
    pub fn indirect_method(&self) -> u32 {
        match self.indirect_every {
            Some(2) => crate::layout::METHOD_INDIRECT_HALF,
            Some(4) => crate::layout::METHOD_INDIRECT_QUARTER,
            _ => 0,
        }
    }

    /// The first value a level may not declare, naming `path` and the field: a frame rate that
    /// is not above 0 (or not finite), a `min_scale` outside (0, 1], `max_bounces` 0 or above
    /// `MAX_BOUNCES` (64), an `indirect_every` other than 1, 2 or 4.
    pub fn check(&self, path: &Path) -> AssetResult<()> {
        let bad = |message: String| {
            Err(AssetError::Level {
                path: path.to_path_buf(),
                message: format!("render: {message}"),
            })
        };
        if let Some(fps) = self.target_fps
            && !(fps.is_finite() && fps > 0.0)
        {
            return bad(format!(
                "target_fps is {fps}; a frame rate must be above 0 frames per second"
            ));
        }
        if let Some(scale) = self.min_scale
            && !(scale > 0.0 && scale <= 1.0)
        {
            return bad(format!(
                "min_scale is {scale}; a fraction of the output resolution must be in (0, 1]"
            ));
        }
        if let Some(every) = self.indirect_every
            && ![1, 2, 4].contains(&every)
        {
            return bad(format!(
                "indirect_every is {every}; one pixel in 1, 2 or 4 traces indirect light"
            ));
        }
        if self.max_bounces == 0 || self.max_bounces > MAX_BOUNCES {
            return bad(format!(
                "max_bounces is {}; it must be 1 to {MAX_BOUNCES}",
                self.max_bounces
            ));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use crate::assets::{AssetError, Level, RenderSettings};
    use std::path::Path;

    fn level(render: &str) -> String {
        format!(
            "Level(camera: (position: (0, 1, 3), look_at: (0, 1, 0), vertical_fov_deg: 40), \
             render: {render})"
        )
    }

    /// The message of the error parsing a level with `render` gives, checking it names the file.
    fn refusal(render: &str) -> String {
        let path = Path::new("levels/fast.ron");
        match Level::parse(path, &level(render)) {
            Err(AssetError::Level { path: p, message }) => {
                assert_eq!(p, path);
                message
            }
            other => panic!("{render}: expected a level error, got {other:?}"),
        }
    }

    #[test]
    fn absent_fields_give_todays_defaults_and_stay_absent() -> Result<(), Box<dyn std::error::Error>>
    {
        let parsed = Level::parse(Path::new("a.ron"), &level("(max_bounces: 3)"))?;
        assert_eq!(parsed.render.frame_seconds(), 1.0 / 30.0);
        assert_eq!(parsed.render.min_resolution(), 0.25);
        let text = ron::to_string(&parsed.render)?;
        assert!(
            !text.contains("target_fps")
                && !text.contains("min_scale")
                && !text.contains("indirect_every"),
            "{text}"
        );
        Ok(())
    }

    #[test]
    fn declared_fields_are_read_and_written_back() -> Result<(), Box<dyn std::error::Error>> {
        let parsed = Level::parse(
            Path::new("a.ron"),
            &level("(max_bounces: 2, target_fps: 20, min_scale: 0.5, indirect_every: 4)"),
        )?;
        let r = parsed.render;
        assert_eq!(
            (r.max_bounces, r.target_fps, r.min_scale, r.indirect_every),
            (2, Some(20.0), Some(0.5), Some(4))
        );
        assert_eq!(r.indirect_method(), crate::layout::METHOD_INDIRECT_QUARTER);
        assert_eq!(r.frame_seconds(), 1.0 / 20.0);
        let again: RenderSettings = ron::from_str(&ron::to_string(&r)?)?;
        assert_eq!(again, r);
        Ok(())
    }

    #[test]
    fn bad_values_are_refused_naming_the_field() {
        for (render, field) in [
            ("(target_fps: 0)", "target_fps is 0"),
            ("(target_fps: -30)", "target_fps is -30"),
            ("(target_fps: NaN)", "target_fps is NaN"),
            ("(target_fps: inf)", "target_fps is inf"),
            ("(min_scale: 0)", "min_scale is 0"),
            ("(min_scale: 1.5)", "min_scale is 1.5"),
            ("(min_scale: NaN)", "min_scale is NaN"),
            ("(max_bounces: 0)", "max_bounces is 0"),
            ("(max_bounces: 65)", "max_bounces is 65"),
            ("(indirect_every: 3)", "indirect_every is 3"),
            ("(indirect_every: 0)", "indirect_every is 0"),
        ] {
            let message = refusal(render);
            assert!(
                message.starts_with("render: ") && message.contains(field),
                "{render}: {message}"
            );
        }
    }

    #[test]
    fn edge_values_are_accepted() -> Result<(), Box<dyn std::error::Error>> {
        for render in [
            "(min_scale: 1)",
            "(max_bounces: 64)",
            "(max_bounces: 1)",
            "(target_fps: 0.5)",
            "(indirect_every: 1)",
            "(indirect_every: 4)",
        ] {
            Level::parse(Path::new("a.ron"), &level(render))?;
        }
        Ok(())
    }
}
