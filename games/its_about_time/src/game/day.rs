//! The day as the player reads it: local solar time from the sky's UTC time and longitude,
//! the dial's label, and the words for artifacts and for the level's rules that the HUD shows.
//!
//! Pure functions, any thread. Must not: change the sky (the game queues
//! `Commands::advance_time`).

use candela::sky::SkyNow;

/// Local mean solar time in hours, 0 ≤ h < 24: UTC hours plus longitude / 15 (east positive).
/// `None` when the sky is placed by angles, not by a time.
pub fn local_hours(sky: &SkyNow) -> Option<f64> {
    let t = sky.time?;
    Some((t.utc_hours + t.longitude_deg / 15.0).rem_euclid(24.0))
}

/// "14:05" for 14.08 hours.
pub fn clock_label(hours: f64) -> String {
    let minutes = (hours.rem_euclid(24.0) * 60.0).floor() as u32;
    format!("{:02}:{:02}", (minutes / 60) % 24, minutes % 60)
}

/// "Morning", "Noon" … for the HUD beside the clock, from the sun's elevation (degrees) and
/// whether it is before local noon.
pub fn part_of_day(sun_elevation_deg: f64, morning: bool) -> &'static str {
    match sun_elevation_deg {
        e if e < -6.0 => "Night",
        e if e < 0.0 => {
            if morning {
                "Dawn"
            } else {
                "Dusk"
            }
        }
        e if e < 60.0 => {
            if morning {
                "Morning"
            } else {
                "Afternoon"
            }
        }
        _ => "Noon",
    }
}

/// The artifact's name for messages: `artifact_sun` → "Sun Disc".
pub fn artifact_name(event: &str) -> String {
    match event.trim_start_matches(super::ARTIFACT_PREFIX) {
        "sun" => "Sun Disc".into(),
        "water" => "Rain Jar".into(),
        "weights" => "Balance Stone".into(),
        "stone" => "Thunder Stone".into(),
        "night" => "Moon Mirror".into(),
        other => other.replace('_', " "),
    }
}

/// Where an artifact lies and how it is won, for the objective line (by its event, as the
/// ruins level names them).
pub fn artifact_hint(event: &str) -> &'static str {
    match event.trim_start_matches(super::ARTIFACT_PREFIX) {
        "sun" => {
            "the sun gate (east): turn time at the sun altar until sunlight falls on its glyph"
        }
        "weights" => "the court of weights (west): weigh down the plates carved beside its vault",
        "stone" => "the rolling stone (south-east): pull the lever by the ramp",
        "night" => {
            "the night shrine (north-west): after dark, light the torches in the wall's order"
        }
        "water" => {
            "the water stair (north-east): drain the pool at its sluice, then ride the float up"
        }
        _ => "somewhere in the ruins",
    }
}

/// What the HUD says when one of the level's rules rises or falls (by the rule's name, as
/// the ruins level names them), or nothing.
pub fn rule_message(rule: &str, rising: bool) -> Option<&'static str> {
    match (rule, rising) {
        ("sun_gate", true) => Some("Sunlight falls on the glyph · the sun gate opens"),
        ("sun_gate", false) => Some("The glyph falls into shadow · the gate closes"),
        ("weights_open", true) => Some("Stone grinds on stone · the vault of weights opens"),
        ("boulder_released", true) => Some("The chock slides away · the boulder rolls"),
        ("night_falls", true) => Some("Night falls over the ruins"),
        ("night_falls", false) => Some("The sky pales · day returns"),
        ("shrine_open", true) => Some("The torches burn in order · the shrine opens"),
        (r, true) if r.starts_with("pool_drains_") => {
            Some("The sluice groans open · the pool drains")
        }
        ("pool_fills", true) => Some("The sluice shuts · the pool fills: stand on the float"),
        ("ending", true) => Some("The temple accepts the artifacts"),
        (r, true) if r.starts_with("torch_") && r.ends_with("_daylight") => {
            Some("The torch will not take in daylight · come back after dark")
        }
        (r, true) if r.starts_with("torch_") && r.ends_with("_wrong") => {
            Some("The flames die · that was not the order on the wall")
        }
        (r, true) if r.starts_with("torch_") && r.ends_with("_lit") => Some("The torch catches"),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_clock_reads_hours_and_minutes() {
        assert_eq!(clock_label(14.0833), "14:04");
        assert_eq!(clock_label(0.0), "00:00");
        assert_eq!(clock_label(23.999), "23:59");
        assert_eq!(clock_label(-1.0), "23:00");
    }

    #[test]
    fn parts_of_the_day_follow_the_sun() {
        assert_eq!(part_of_day(-20.0, true), "Night");
        assert_eq!(part_of_day(-3.0, true), "Dawn");
        assert_eq!(part_of_day(-3.0, false), "Dusk");
        assert_eq!(part_of_day(30.0, false), "Afternoon");
        assert_eq!(part_of_day(75.0, true), "Noon");
    }

    #[test]
    fn artifacts_have_names() {
        assert_eq!(artifact_name("artifact_sun"), "Sun Disc");
        assert_eq!(artifact_name("artifact_odd_one"), "odd one");
        assert!(artifact_hint("artifact_night").contains("after dark"));
    }

    #[test]
    fn the_torches_rules_have_words() {
        assert!(rule_message("torch_eye_daylight", true).is_some_and(|m| m.contains("after dark")));
        assert!(rule_message("torch_sun_wrong", true).is_some_and(|m| m.contains("order")));
        assert_eq!(
            rule_message("torch_sun_lit", true),
            Some("The torch catches")
        );
        assert_eq!(rule_message("torch_sun_lit", false), None);
    }
}
