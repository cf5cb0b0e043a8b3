//! [`SkyError`]: what the sky module refuses (bad observer, date, time or atmosphere values).
//!
//! Any thread. Plain data; each variant carries the value it refused so that the level
//! loader can name the file and the field beside it.

/// A bad input to the ephemeris or the physical sky.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SkyError {
    /// Latitude outside [−90°, 90°] or not finite.
    #[error("time.latitude_deg = {0} is outside [-90, 90] (degrees, north positive)")]
    Latitude(f64),
    /// Longitude outside [−180°, 180°] or not finite.
    #[error("time.longitude_deg = {0} is outside [-180, 180] (degrees, east positive)")]
    Longitude(f64),
    /// A calendar date that does not exist, or a year outside the formulas' range.
    #[error(
        "date {year}-{month:02}-{day:02} (time.year, time.month, time.day) is not a valid date in 1800..=2200"
    )]
    Date { year: i32, month: u32, day: u32 },
    /// A time of day outside 00:00:00 ≤ t < 24:00:00 (UTC).
    #[error("time {hour:02}:{minute:02}:{second} is not a valid UTC time of day")]
    Time { hour: u32, minute: u32, second: f64 },
    /// A physical-sky parameter that is negative, too large or not finite.
    #[error("{field} = {value} is out of range ({range})")]
    Parameter {
        field: &'static str,
        value: f64,
        range: &'static str,
    },
}
