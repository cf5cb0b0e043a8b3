//! The time of day in play: carrying out the game's [`TimeChange`]s, letting the day flow at
//! the sky's `time_rate` in every fixed step, what the game's hooks read ([`Engine::sky_now`]:
//! the sun's and moon's directions and the moon's phase), the sky's words in the state hash,
//! and how far the lighting moved since the last commit ([`lighting_change`], for converging).
//!
//! The time lives in the environment's sky (`SkyDesc::Physical`'s `time`), so the commit carries
//! it and both tracers see the new sun; it changes only inside fixed steps (commands and the
//! flow), so a replay goes through the same times. Main thread. Must not: render or build sky
//! tables (the render side's `scene::SkyTable` does).

use glam::Vec3;

use super::commands::TimeChange;
use super::engine::Engine;
use crate::assets::{SkyDesc, SunDesc};
use crate::sky::{Horizontal, PhysicalSky, SUN_ANGULAR_RADIUS_DEG, SkyError, SkyNow, SkyTime};

/// Why a time of day could not be set.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum TimeError {
    #[error("the sky is not Physical: it has no time of day")]
    NotPhysical,
    #[error("the physical sky has no `time` (a date and place) to turn")]
    NoTime,
    #[error(transparent)]
    Sky(#[from] SkyError),
}

impl Engine {
    /// Where the sun (and, for a physical sky placed by a date, the moon) stands now, engine
    /// space; the time of day when there is one. `None` when the scene has no sun.
    pub fn sky_now(&self) -> Option<SkyNow> {
        sky_now(self.environment.sun, &self.environment.sky)
    }

    /// Changes the physical sky's time of day now (the game's `Commands::set_time_of_day` and
    /// the others come here after their hook; capture scripts call it between frames). A sky
    /// that is not physical, or (but for `Set`) has no `time`, or a time the sky refuses,
    /// leaves the time as it was and says why.
    pub fn change_time(&mut self, change: TimeChange) -> Result<(), TimeError> {
        let SkyDesc::Physical(sky) = &mut self.environment.sky else {
            return Err(TimeError::NotPhysical);
        };
        let changed = match (change, sky.time) {
            (TimeChange::Set(t), _) => t,
            (TimeChange::Hours(h), Some(t)) => t.at_hours(h)?,
            (TimeChange::Advance(s), Some(t)) => t.advanced(s)?,
            (TimeChange::Rate(r), Some(t)) => SkyTime { time_rate: r, ..t },
            (_, None) => return Err(TimeError::NoTime),
        };
        let next = PhysicalSky {
            time: Some(changed),
            ..*sky
        };
        next.validate()?;
        *sky = next;
        Ok(())
    }

    /// Lets the day flow for one fixed step of `seconds`: the physical sky's time moves by
    /// `time_rate × seconds` (nothing when the rate is 0 or there is no time).
    pub(in crate::app) fn flow_time(&mut self, seconds: f64) {
        let SkyDesc::Physical(sky) = &mut self.environment.sky else {
            return;
        };
        let Some(t) = sky.time.filter(|t| t.time_rate > 0.0) else {
            return;
        };
        match t.advanced(t.time_rate * seconds) {
            Ok(next) => sky.time = Some(next),
            Err(e) => log::warn!("the day stops flowing: {e}"),
        }
    }

    /// How far the lighting moved since the last commit ([`lighting_change`]); remembers the
    /// environment's sun and sky as the ones committed now.
    pub(in crate::app) fn take_lighting_change(&mut self) -> f32 {
        let now = (self.environment.sun, self.environment.sky);
        let change = match &self.committed_light {
            Some((sun, sky)) => lighting_change((*sun, sky), (now.0, &now.1)),
            None => 0.0,
        };
        self.committed_light = Some(now);
        change
    }

    /// The direction towards the sun that the level's rules test (`SunLit`): the level's sun,
    /// or a physical sky's while part of its disc is above the horizon.
    pub(in crate::app) fn sun_for_rules(&self) -> Option<Vec3> {
        match &self.environment.sky {
            SkyDesc::Physical(p) => {
                let h = p.sun_horizontal().ok()?;
                (h.elevation_deg > -f64::from(SUN_ANGULAR_RADIUS_DEG)).then(|| h.direction())
            }
            _ => self
                .environment
                .sun
                .and_then(|s| Vec3::from(s.direction).try_normalize()),
        }
    }

    /// The sun's elevation above the horizon in degrees that the level's rules test
    /// (`SunElevation`): a physical sky's sun at any height, or the level's sun; `None` without
    /// a sun.
    pub(in crate::app) fn sun_elevation_for_rules(&self) -> Option<f32> {
        match &self.environment.sky {
            SkyDesc::Physical(p) => p.sun_horizontal().ok().map(|h| h.elevation_deg as f32),
            _ => self
                .environment
                .sun
                .and_then(|s| Vec3::from(s.direction).try_normalize())
                .map(|d| d.y.clamp(-1.0, 1.0).asin().to_degrees()),
        }
    }

    /// The sky's part of the state hash: a physical sky's time (date, UTC hours, day rate) or
    /// its sun angles; nothing for the other skies (the level fixes them).
    pub(in crate::app) fn sky_state_words(&self) -> Vec<u64> {
        match &self.environment.sky {
            SkyDesc::Physical(p) => match &p.time {
                Some(t) => vec![
                    t.year as u64,
                    u64::from(t.month),
                    u64::from(t.day),
                    t.utc_hours.to_bits(),
                    t.time_rate.to_bits(),
                ],
                None => vec![
                    u64::from(p.sun_elevation_deg.to_bits()),
                    u64::from(p.sun_azimuth_deg.to_bits()),
                ],
            },
            _ => Vec::new(),
        }
    }
}

/// [`Engine::sky_now`] for a sun and a sky: a physical sky's own sun and moon, or the level's
/// sun placed on the sky (no moon, no time).
pub(in crate::app) fn sky_now(sun: Option<SunDesc>, sky: &SkyDesc) -> Option<SkyNow> {
    if let SkyDesc::Physical(p) = sky {
        return p.now().ok();
    }
    let d = Vec3::from(sun?.direction).try_normalize()?;
    Some(SkyNow {
        sun_direction: d,
        sun: Horizontal {
            elevation_deg: f64::from(d.y.clamp(-1.0, 1.0).asin().to_degrees()),
            azimuth_deg: f64::from(d.x.atan2(-d.z).to_degrees()).rem_euclid(360.0),
        },
        moon: None,
        time: None,
    })
}

/// How far the lighting moved between two commits' sun and sky, for converging
/// (`commit::Motion::lighting`): 0 when both are the same; the angle in degrees the sun turned
/// when only its place changed (a physical sky's time or angles, the level sun's direction;
/// at least 1e-6 so that a change is never read as none); infinity for any other change (a new
/// atmosphere, a sky of another kind, the sun's strength).
pub fn lighting_change(
    before: (Option<SunDesc>, &SkyDesc),
    after: (Option<SunDesc>, &SkyDesc),
) -> f32 {
    if before.0 == after.0 && before.1 == after.1 {
        return 0.0;
    }
    let only_the_place_moved = match (before.1, after.1) {
        // A physical sky places its own sun (the level's `sun` is unused beside it).
        (SkyDesc::Physical(a), SkyDesc::Physical(b)) => {
            let unplaced = |p: &PhysicalSky| PhysicalSky {
                sun_elevation_deg: 0.0,
                sun_azimuth_deg: 0.0,
                time: None,
                ..*p
            };
            unplaced(a) == unplaced(b) && before.0 == after.0
        }
        (sa, sb) => match (before.0, after.0) {
            (Some(a), Some(b)) => {
                sa == sb
                    && a.irradiance == b.irradiance
                    && a.angular_radius_deg == b.angular_radius_deg
            }
            _ => false,
        },
    };
    let from = sky_now(before.0, before.1);
    let to = sky_now(after.0, after.1);
    match (only_the_place_moved, from, to) {
        (true, Some(from), Some(to)) => from
            .sun_direction
            .dot(to.sun_direction)
            .clamp(-1.0, 1.0)
            .acos()
            .to_degrees()
            .max(1e-6),
        _ => f32::INFINITY,
    }
}
