//! UTC calendar instants and their Julian day (Meeus, *Astronomical Algorithms*, ch. 7).
//!
//! Any thread; pure functions. Owns [`UtcInstant`] and its checks. Must not: know about
//! positions on the sky (`solar`, `lunar`) or the engine's axes (`horizon`).

use super::error::SkyError;

/// A moment in Coordinated Universal Time, Gregorian calendar. Seconds may be fractional.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UtcInstant {
    pub year: i32,
    /// 1..=12
    pub month: u32,
    /// 1..=31 (checked against the month)
    pub day: u32,
    /// 0..=23
    pub hour: u32,
    /// 0..=59
    pub minute: u32,
    /// 0 ≤ second < 60
    pub second: f64,
}

impl UtcInstant {
    /// Checks the instant: a real Gregorian date in 1800..=2200 (the span the low-precision
    /// series are good for) and a time of day inside one day.
    pub fn new(
        year: i32,
        month: u32,
        day: u32,
        hour: u32,
        minute: u32,
        second: f64,
    ) -> Result<Self, SkyError> {
        let bad_date = SkyError::Date { year, month, day };
        if !(1800..=2200).contains(&year) || !(1..=12).contains(&month) || day == 0 {
            return Err(bad_date);
        }
        if day > days_in_month(year, month) {
            return Err(bad_date);
        }
        if hour > 23 || minute > 59 || !second.is_finite() || !(0.0..60.0).contains(&second) {
            return Err(SkyError::Time {
                hour,
                minute,
                second,
            });
        }
        Ok(Self {
            year,
            month,
            day,
            hour,
            minute,
            second,
        })
    }

    /// Julian day (UT) of the instant, Meeus eq. 7.1.
    pub fn julian_day(&self) -> f64 {
        let (mut y, mut m) = (self.year as f64, self.month as f64);
        if self.month <= 2 {
            y -= 1.0;
            m += 12.0;
        }
        let a = (y / 100.0).floor();
        let b = 2.0 - a + (a / 4.0).floor();
        let day_fraction =
            (self.hour as f64 + self.minute as f64 / 60.0 + self.second / 3600.0) / 24.0;
        (365.25 * (y + 4716.0)).floor()
            + (30.6001 * (m + 1.0)).floor()
            + self.day as f64
            + day_fraction
            + b
            - 1524.5
    }
}

fn days_in_month(year: i32, month: u32) -> u32 {
    let leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
    match month {
        2 if leap => 29,
        2 => 28,
        4 | 6 | 9 | 11 => 30,
        _ => 31,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn julian_day_matches_meeus_examples() {
        // Meeus example 7.a: 1957 October 4.81 = JD 2436116.31.
        let t = UtcInstant::new(1957, 10, 4, 19, 26, 24.0).unwrap();
        assert!((t.julian_day() - 2436116.31).abs() < 1e-6);
        // J2000.0 = 2000 January 1, 12h = JD 2451545.0.
        let j2000 = UtcInstant::new(2000, 1, 1, 12, 0, 0.0).unwrap();
        assert_eq!(j2000.julian_day(), 2451545.0);
    }

    #[test]
    fn bad_dates_and_times_are_refused() {
        assert!(UtcInstant::new(2023, 2, 29, 0, 0, 0.0).is_err());
        assert!(UtcInstant::new(2024, 2, 29, 0, 0, 0.0).is_ok());
        assert!(UtcInstant::new(2024, 13, 1, 0, 0, 0.0).is_err());
        assert!(UtcInstant::new(2024, 4, 31, 0, 0, 0.0).is_err());
        assert!(UtcInstant::new(2024, 4, 30, 24, 0, 0.0).is_err());
        assert!(UtcInstant::new(2024, 4, 30, 0, 0, 60.0).is_err());
        assert!(UtcInstant::new(2024, 4, 30, 0, 0, f64::NAN).is_err());
        assert!(UtcInstant::new(1700, 1, 1, 0, 0, 0.0).is_err());
    }
}
