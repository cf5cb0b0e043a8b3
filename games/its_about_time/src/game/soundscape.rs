//! [`Soundscape`]: what the ruins sound like, step by step — a footstep every stride on sand or
//! on stone by what lies under the explorer's feet, wind everywhere, the day and night music
//! pads crossfading by the sun's elevation, and the time warp while an altar turns time.
//!
//! Sounds are the level's (`gameplay.sounds`, made by `assetgen ruins-sounds`): one-shots go out
//! as `Commands::play_sound`, loops as `Commands::set_loop_volume` every step. Neither is part
//! of the simulation's state, so replays and state hashes do not see them. Positional loops
//! (the water, the torches) are the level's `gameplay.emitters`, not this file's.
//!
//! Main thread, inside `TimeGame::fixed_step`. Must not: change the world, the physics or the
//! level's logic (reads the explorer's position and casts one ray a stride).

use std::collections::HashMap;
use std::path::Path;

use candela::app::{SpawnedLevel, Step};
use candela::level::PlayableLevel;
use candela::trace::Ray;
use glam::Vec3;
use hecs::Entity;

/// Metres walked between two footsteps (the explorer's stride at a walk).
pub const STRIDE_METERS: f32 = 0.8;

/// Models (level names, or the file stems of their glTF) whose surface is sand; any other
/// model under the feet is stone.
pub const SAND_MODELS: [&str; 2] = ["plaza", "sand_terrain"];

/// The footstep variants on each surface (`footstep_sand_1` … `_3`).
const VARIANTS: u32 = 3;

/// Footstep volume at a run and more (linear); a walk is quieter in proportion to speed, never
/// below [`MIN_STEP_VOLUME`].
const STEP_VOLUME: f32 = 0.6;
const MIN_STEP_VOLUME: f32 = 0.25;
/// Metres per second that count as a run (full footstep volume).
const RUN_SPEED: f32 = 5.0;

/// Loudest a music pad plays (linear): under the effects.
pub const PAD_VOLUME: f32 = 0.35;
/// Wind by day and by night (linear): the night wind is louder, with fewer other sounds.
const WIND_DAY: f32 = 0.25;
const WIND_NIGHT: f32 = 0.4;
/// The time warp's volume while time turns.
const WARP_VOLUME: f32 = 0.6;
/// Sun elevations, degrees, between which the pads crossfade: all night pad below the first,
/// all day pad above the second.
pub const PAD_FADE_DEG: (f64, f64) = (-8.0, 4.0);

/// What is under the explorer's feet.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Surface {
    Sand,
    Stone,
}

/// Loop volumes (linear) for one step.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Mix {
    pub wind: f32,
    pub pad_day: f32,
    pub pad_night: f32,
    pub time_warp: f32,
}

/// The loops' volumes for a sun at `sun_elevation_deg` (`None`: no sky time, counted as day)
/// and whether time is turning: the pads crossfade at equal power across [`PAD_FADE_DEG`].
pub fn mix(sun_elevation_deg: Option<f64>, turning: bool) -> Mix {
    let (low, high) = PAD_FADE_DEG;
    let day = sun_elevation_deg.map_or(1.0, |e| ((e - low) / (high - low)).clamp(0.0, 1.0));
    let angle = day as f32 * std::f32::consts::FRAC_PI_2;
    Mix {
        wind: WIND_NIGHT + (WIND_DAY - WIND_NIGHT) * day as f32,
        pad_day: PAD_VOLUME * angle.sin(),
        pad_night: PAD_VOLUME * angle.cos(),
        time_warp: if turning { WARP_VOLUME } else { 0.0 },
    }
}

/// The ruins' sounds for one game (see the module doc).
#[derive(Debug, Default)]
pub struct Soundscape {
    /// The surface of each level instance's entity (built at the first step of a level).
    surfaces: HashMap<Entity, Surface>,
    /// Feet at the last step, and metres walked since the last footstep.
    last_feet: Option<Vec3>,
    walked: f32,
    /// Footsteps played.
    footsteps: u32,
    /// The last footstep's sound name and volume.
    last_footstep: Option<(String, f32)>,
    /// Every footstep: the fixed step it came in and the surface.
    log: Vec<(u64, Surface)>,
    /// The loops' volumes as last set.
    mix: Mix,
}

impl Soundscape {
    /// Forgets the level (its entities): after a respawn the surfaces are rebuilt.
    pub fn level_changed(&mut self) {
        self.surfaces.clear();
        self.last_feet = None;
        self.walked = 0.0;
    }

    /// The last footstep's sound name and volume.
    pub fn last_footstep(&self) -> Option<(&str, f32)> {
        self.last_footstep.as_ref().map(|(n, v)| (n.as_str(), *v))
    }

    /// Every footstep so far: the fixed step it came in and the surface (8 bytes a stride).
    pub fn footsteps(&self) -> &[(u64, Surface)] {
        &self.log
    }

    /// The loops' volumes as last set.
    pub fn mix(&self) -> Mix {
        self.mix
    }

    /// One fixed step: the loops' volumes and, each [`STRIDE_METERS`] walked, a footstep.
    /// `centre` is the explorer's capsule centre (`None`: no explorer), `turning` whether an
    /// altar turns time this step.
    pub fn step(
        &mut self,
        step: &mut Step<'_>,
        level: (&PlayableLevel, &SpawnedLevel),
        centre: Option<Vec3>,
        turning: bool,
    ) {
        self.mix = mix(step.sky.as_ref().map(|s| s.sun.elevation_deg), turning);
        step.commands.set_loop_volume("wind", self.mix.wind);
        step.commands.set_loop_volume("pad_day", self.mix.pad_day);
        step.commands
            .set_loop_volume("pad_night", self.mix.pad_night);
        step.commands
            .set_loop_volume("time_warp", self.mix.time_warp);
        let Some(centre) = centre else {
            return;
        };
        let moved = self
            .last_feet
            .map_or(0.0, |last| (centre - last).with_y(0.0).length());
        self.last_feet = Some(centre);
        // More than a metre in one step is a teleport (a restart, a checkpoint), not a walk.
        if moved >= 1.0 {
            return;
        }
        self.walked += moved;
        if self.walked < STRIDE_METERS {
            return;
        }
        self.walked -= STRIDE_METERS;
        if self.surfaces.is_empty() {
            self.surfaces = surfaces(level.0, level.1);
        }
        let surface = self.surface_under(step, centre);
        let speed = moved / step.step_seconds as f32;
        let volume = (STEP_VOLUME * speed / RUN_SPEED).clamp(MIN_STEP_VOLUME, STEP_VOLUME);
        let kind = match surface {
            Surface::Sand => "sand",
            Surface::Stone => "stone",
        };
        let name = format!("footstep_{kind}_{}", self.footsteps % VARIANTS + 1);
        self.footsteps += 1;
        self.log.push((step.index, surface));
        step.commands.play_sound(name.clone(), volume);
        self.last_footstep = Some((name, volume));
    }

    /// The surface of the nearest level instance straight below `centre` (within 3 m); sand
    /// when nothing is there (the desert beyond the level).
    fn surface_under(&self, step: &Step<'_>, centre: Vec3) -> Surface {
        let ray = Ray::with_range(centre, Vec3::NEG_Y, 0.0, 3.0);
        let known = |e: Option<Entity>| e.is_some_and(|e| self.surfaces.contains_key(&e));
        step.queries
            .closest_where(&ray, known)
            .and_then(|hit| hit.entity)
            .and_then(|e| self.surfaces.get(&e).copied())
            .unwrap_or(Surface::Sand)
    }
}

/// The surface of each of the level's instances that one can stand on (sensors left out):
/// sand for [`SAND_MODELS`], stone for the rest.
fn surfaces(level: &PlayableLevel, spawned: &SpawnedLevel) -> HashMap<Entity, Surface> {
    let scene = &level.scene;
    scene
        .instances
        .iter()
        .zip(&spawned.entities)
        .filter_map(|(instance, &entity)| {
            let name = &scene.models.get(instance.model)?.name;
            let stem = Path::new(name)
                .file_stem()
                .and_then(|s| s.to_str())
                .unwrap_or(name);
            if stem == "sensor" {
                return None;
            }
            let sand = SAND_MODELS.contains(&stem);
            Some((entity, if sand { Surface::Sand } else { Surface::Stone }))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Noon is all day pad, midnight all night pad, and the crossfade keeps the power.
    #[test]
    fn the_pads_follow_the_sun() {
        let noon = mix(Some(60.0), false);
        let midnight = mix(Some(-40.0), false);
        assert!(noon.pad_day == PAD_VOLUME && noon.pad_night.abs() < 1e-6);
        assert!(midnight.pad_day.abs() < 1e-6 && midnight.pad_night == PAD_VOLUME);
        let dusk = mix(Some(-2.0), false);
        let power = dusk.pad_day.powi(2) + dusk.pad_night.powi(2);
        assert!((power - PAD_VOLUME.powi(2)).abs() < 1e-5, "power {power}");
        assert!(dusk.pad_day > 0.1 && dusk.pad_night > 0.1);
        assert!(midnight.wind > noon.wind);
        assert_eq!(mix(None, true).time_warp, WARP_VOLUME);
        assert_eq!(noon.time_warp, 0.0);
    }
}
