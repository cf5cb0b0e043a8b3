//! Simulated water in a level: the `simulate` field of an instance's `waves`
//! ([`WaterSimDesc`]) and the checks it must pass when the level loads.
//!
//! Owns: the serde type and its validation (finite, positive speed; non-negative damping and
//! push; substeps in range; a grid model with at least 2 divisions per axis; the CFL limit at
//! the engine's 60 Hz step), each refusal naming the instance and the field (the caller adds
//! the level file). Main thread or a loader thread. Must not: simulate anything (see
//! `sim::water`).

use serde::{Deserialize, Serialize};

use super::level::{InstanceEntry, Level};

/// The fixed step the level check assumes: the engine's default clock, 60 Hz (seconds). An
/// engine run at another rate still stays stable: the simulation adds substeps as needed.
pub const VALIDATED_STEP_SECONDS: f32 = 1.0 / 60.0;

/// Most substeps a level may ask for per fixed step.
pub const MAX_SUBSTEPS: u32 = 16;

/// A height-field wave simulation on a grid water (Müller-Fischer, "Real Time Fluids in
/// Games", GDC 2008): per grid vertex a height `h` (metres, added to the swell) and vertical
/// speed `v` (m/s); each substep `v += c²·∇²h·dt`, `v *= exp(−damping·dt)`, `h += v·dt`, with
/// the grid's edges held at 0. Whatever wades (a character's capsule, a dynamic or kinematic
/// body below the rest surface, within the grid) pushes the surface down by `push` times its
/// submerged depth under a smooth kernel of its radius; only a change of that push makes
/// waves, so a wader at rest stops making them.
///
/// ```ron
/// waves: Some((amplitude: 0.02, wavelength: 3, speed: 0.6,
///              simulate: Some((wave_speed: 1.5, damping: 0.4, start_at_rest: true)))),
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WaterSimDesc {
    /// Speed `c` of the ripples, metres per second; positive and finite, and with the grid's
    /// spacing within the CFL limit (see [`WaterSimDesc::courant`]).
    pub wave_speed: f32,
    /// Per second (1/s): vertical speeds decay as `exp(−damping·t)`; 0 keeps the energy.
    pub damping: f32,
    /// Substeps per fixed step, 1 to 16 (default 1): more allow a faster `wave_speed`.
    #[serde(default = "one")]
    pub substeps: u32,
    /// How hard waders push: the surface goes down by `push` × submerged depth (metres)
    /// under a wader's centre (dimensionless, ≥ 0; default 0.1: a wader 0.6 m deep walking
    /// makes a trough of about 6 cm around it).
    #[serde(default = "push")]
    pub push: f32,
    /// The surface starts at rest under whatever wades in it when the level starts (default
    /// false): the first fixed step takes the waders' push as the rest state instead of
    /// dropping the surface under them, so a body placed in the water (It's About Time's
    /// kinematic reed float) leaves no entry ring to ring out (about 20 s, refitted and
    /// committed every frame meanwhile). The damped wave equation with its edges held at 0
    /// rests flat, so this is the state the old start reached once settled, without the
    /// ripples on the way.
    #[serde(default)]
    pub start_at_rest: bool,
}

fn one() -> u32 {
    1
}

fn push() -> f32 {
    0.1
}

impl WaterSimDesc {
    /// The CFL number of one substep of `step_seconds / substeps` on cells `dx` by `dz`
    /// metres: `c·dt·√(1/dx² + 1/dz²)`, which must stay below 1 (on square cells,
    /// `c·dt/dx < 1/√2`).
    pub fn courant(&self, step_seconds: f32, dx: f32, dz: f32) -> f32 {
        let dt = step_seconds / self.substeps.max(1) as f32;
        self.wave_speed * dt * (1.0 / (dx * dx) + 1.0 / (dz * dz)).sqrt()
    }
}

/// Checks instance `index`'s `waves.simulate`, if any, against the level's grids. The message
/// names the instance and the field; the caller adds the level file.
pub(super) fn check_simulated_water(
    level: &Level,
    index: usize,
    instance: &InstanceEntry,
) -> Result<(), String> {
    let Some(sim) = instance.waves.and_then(|w| w.simulate) else {
        return Ok(());
    };
    let who = format!("instance {index} ({:?})", instance.model);
    let field = |name: &str| format!("{who}: waves.simulate.{name}");
    if !(sim.wave_speed.is_finite() && sim.wave_speed > 0.0) {
        return Err(format!(
            "{} must be a positive, finite speed in m/s, not {}",
            field("wave_speed"),
            sim.wave_speed
        ));
    }
    if !(sim.damping.is_finite() && sim.damping >= 0.0) {
        return Err(format!(
            "{} must be finite and at least 0 (1/s), not {}",
            field("damping"),
            sim.damping
        ));
    }
    if !(sim.push.is_finite() && sim.push >= 0.0) {
        return Err(format!(
            "{} must be finite and at least 0, not {}",
            field("push"),
            sim.push
        ));
    }
    if !(1..=MAX_SUBSTEPS).contains(&sim.substeps) {
        return Err(format!(
            "{} must be within 1..={MAX_SUBSTEPS}, not {}",
            field("substeps"),
            sim.substeps
        ));
    }
    let Some(grid) = level.grids.iter().find(|g| g.name == instance.model) else {
        return Err(format!(
            "{who}: waves.simulate needs a grid model (the level's `grids`), and {:?} is not one",
            instance.model
        ));
    };
    let [nx, nz] = grid.divisions;
    if nx < 2 || nz < 2 {
        return Err(format!(
            "{who}: waves.simulate needs at least 2 divisions per axis on grid {:?}, not {:?}",
            grid.name, grid.divisions
        ));
    }
    let (dx, dz) = (grid.size[0] / nx as f32, grid.size[1] / nz as f32);
    let courant = sim.courant(VALIDATED_STEP_SECONDS, dx, dz);
    if courant.is_nan() || courant >= 1.0 {
        let limit = sim.wave_speed / courant;
        return Err(format!(
            "{}: {} m/s breaks the CFL limit on grid {:?} (cells {dx} × {dz} m, 1/60 s step, \
             {} substeps): c·dt·√(1/dx² + 1/dz²) = {courant:.3}, must be below 1; lower the \
             speed below {limit:.3} m/s or raise substeps",
            field("wave_speed"),
            sim.wave_speed,
            grid.name,
            sim.substeps
        ));
    }
    Ok(())
}
