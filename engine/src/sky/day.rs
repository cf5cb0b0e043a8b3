//! Turning the time of day: a [`SkyTime`] moved by seconds (across midnights, months and years
//! of the Gregorian calendar, forwards or backwards) or set to an hour, its day rate's check,
//! and [`SkyNow`] — where the sun and the moon stand for a [`PhysicalSky`], in engine space.
//!
//! Any thread; pure functions (the same time gives the same bits, so replays repeat). Must not:
//! know the engine's clock or commands (the runner steps the time, `app/runner/time_of_day.rs`).

use glam::Vec3;

use super::error::SkyError;
use super::horizon::{Horizontal, Observer};
use super::lunar::{MoonState, moon_position};
use super::physical::{PhysicalSky, SkyTime};

const DAY_SECONDS: f64 = 86_400.0;

/// Where the sun and the moon stand now (engine space: north = −Z, east = +X, up = +Y).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SkyNow {
    /// Unit vector towards the sun's centre.
    pub sun_direction: Vec3,
    /// The sun's elevation above the geometric horizon and azimuth from north towards east,
    /// degrees.
    pub sun: Horizontal,
    /// The moon (direction from `horizontal.direction()`, phase angle, lit fraction); `None`
    /// when the sky is placed by angles, not by a date.
    pub moon: Option<MoonState>,
    /// The time of day, when the sky is placed by one.
    pub time: Option<SkyTime>,
}

impl SkyNow {
    /// Unit vector towards the moon's centre, engine space (`None` without a date).
    pub fn moon_direction(&self) -> Option<Vec3> {
        self.moon.map(|m| m.horizontal.direction())
    }
}

impl PhysicalSky {
    /// Where the sun (and, with a `time`, the moon) stands for this sky.
    pub fn now(&self) -> Result<SkyNow, SkyError> {
        let sun = self.sun_horizontal()?;
        let moon = match &self.time {
            Some(t) => Some(moon_position(
                &Observer::new(t.latitude_deg, t.longitude_deg)?,
                &t.instant()?,
            )),
            None => None,
        };
        Ok(SkyNow {
            sun_direction: sun.direction(),
            sun,
            moon,
            time: self.time,
        })
    }
}

/// Days since 1970-01-01 of a Gregorian date (the clouds' clock, `clouds.rs`).
pub(super) fn days_since_1970(year: i32, month: u32, day: u32) -> i64 {
    days_from_civil(year, month, day)
}

/// Days since 1970-01-01 of a Gregorian date (H. Hinnant's `days_from_civil`).
fn days_from_civil(year: i32, month: u32, day: u32) -> i64 {
    let y = i64::from(year) - i64::from(month <= 2);
    let era = y.div_euclid(400);
    let yoe = y - era * 400;
    let m = i64::from(month);
    let doy = (153 * (if m > 2 { m - 3 } else { m + 9 }) + 2) / 5 + i64::from(day) - 1;
    let doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    era * 146_097 + doe - 719_468
}

/// The Gregorian date of a day count since 1970-01-01 (H. Hinnant's `civil_from_days`).
fn civil_from_days(days: i64) -> (i32, u32, u32) {
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let month = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    let year = (yoe + era * 400 + i64::from(month <= 2)) as i32;
    (year, month, day)
}

impl SkyTime {
    /// This time moved by `seconds` (negative: backwards), the date rolling over midnights,
    /// months and years. Fails when the date leaves 1800..=2200 or `seconds` is not finite.
    pub fn advanced(&self, seconds: f64) -> Result<SkyTime, SkyError> {
        self.instant()?;
        if !seconds.is_finite() {
            return Err(SkyError::Parameter {
                field: "advance_time seconds",
                value: seconds,
                range: "finite",
            });
        }
        let of_day = self.utc_hours * 3600.0 + seconds;
        let whole_days = (of_day / DAY_SECONDS).floor();
        let mut left = of_day - whole_days * DAY_SECONDS;
        // Rounding can leave exactly one day: that is midnight of the next day.
        let mut days = days_from_civil(self.year, self.month, self.day) + whole_days as i64;
        if left >= DAY_SECONDS {
            left -= DAY_SECONDS;
            days += 1;
        }
        let (year, month, day) = civil_from_days(days);
        let moved = SkyTime {
            year,
            month,
            day,
            utc_hours: (left / 3600.0).clamp(0.0, 24.0 - 1e-12),
            ..*self
        };
        moved.instant()?;
        Ok(moved)
    }

    /// This date and place at `hours` UTC (0 ≤ hours < 24).
    pub fn at_hours(&self, hours: f64) -> Result<SkyTime, SkyError> {
        let set = SkyTime {
            utc_hours: hours,
            ..*self
        };
        set.instant()?;
        Ok(set)
    }

    /// Checks the day rate (`time_rate`: finite, 0..=1e6 seconds of day per simulated second).
    pub(super) fn check_rate(&self) -> Result<(), SkyError> {
        if self.time_rate.is_finite() && (0.0..=1e6).contains(&self.time_rate) {
            Ok(())
        } else {
            Err(SkyError::Parameter {
                field: "time.time_rate",
                value: self.time_rate,
                range: "0..=1e6",
            })
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn noon() -> SkyTime {
        SkyTime {
            latitude_deg: 48.1,
            longitude_deg: 11.6,
            year: 2026,
            month: 12,
            day: 31,
            utc_hours: 23.5,
            time_rate: 0.0,
        }
    }

    #[test]
    fn advancing_rolls_dates_both_ways() {
        let t = noon().advanced(3600.0).unwrap();
        assert_eq!((t.year, t.month, t.day), (2027, 1, 1));
        assert!((t.utc_hours - 0.5).abs() < 1e-9);
        let back = t.advanced(-3600.0).unwrap();
        assert_eq!((back.year, back.month, back.day), (2026, 12, 31));
        assert!((back.utc_hours - 23.5).abs() < 1e-9);
        let leap = SkyTime {
            year: 2028,
            month: 2,
            day: 28,
            utc_hours: 12.0,
            ..noon()
        }
        .advanced(DAY_SECONDS)
        .unwrap();
        assert_eq!((leap.month, leap.day), (2, 29));
        for days in [-800i64, -1, 0, 1, 59, 365, 10_000] {
            let (y, m, d) = civil_from_days(days);
            assert_eq!(days_from_civil(y, m, d), days);
        }
        assert!(noon().advanced(f64::NAN).is_err());
        assert!(noon().at_hours(24.0).is_err());
    }

    #[test]
    fn now_gives_the_sun_and_the_moon() {
        let sky = PhysicalSky {
            time: Some(noon().at_hours(11.0).unwrap()),
            ..crate::sky::PhysicalSky::default()
        };
        let now = sky.now().unwrap();
        assert!((now.sun_direction.length() - 1.0).abs() < 1e-5);
        assert!(now.sun.elevation_deg > 0.0, "{now:?}");
        let moon = now.moon_direction().unwrap();
        assert!((moon.length() - 1.0).abs() < 1e-5);
    }
}
