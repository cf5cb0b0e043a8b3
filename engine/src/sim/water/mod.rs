//! Simulated water: ripples on a level's grid water ([`crate::assets::WaterSimDesc`]), a
//! damped wave equation stepped in the fixed steps ([`HeightField`]) and pushed one way by
//! whatever wades ([`waders`]). Deterministic: same steps, same bodies, same heights (the
//! engine's state hash covers them).
//!
//! Owns: the [`WaterSim`] component and [`water_system`], which steps every one. Main thread,
//! inside the fixed steps, after physics. Must not: deform meshes or touch the BVH (the app's
//! waves system adds the heights to the swell on the `Deformable` in the pose phase, and the
//! upkeep refits it), or move bodies.

mod field;
mod waders;

use hecs::World;

pub use field::{GridLayout, HeightField};
pub use waders::{Wader, add_push, waders};

use crate::assets::WaterSimDesc;
use crate::ecs::Transform;

/// A simulated water on an entity whose `Transform` places its grid (object space → world).
#[derive(Clone, Debug, PartialEq)]
pub struct WaterSim {
    pub field: HeightField,
}

impl WaterSim {
    /// Still water on the grid of rest positions `base` (object space, metres), or `None` when
    /// `base` is not a regular grid of at least 3 × 3 vertices (see [`GridLayout::infer`]).
    pub fn on_grid(base: &[glam::Vec3], desc: WaterSimDesc) -> Option<Self> {
        let layout = GridLayout::infer(base)?;
        Some(Self {
            field: HeightField::new(layout, desc),
        })
    }
}

/// One fixed step of `step_seconds` for every [`WaterSim`]: the waders' push from the bodies'
/// poses after this step's physics, then the wave equation.
pub fn water_system(world: &mut World, step_seconds: f64) {
    if world.query::<&WaterSim>().iter().next().is_none() {
        return;
    }
    let found = waders(world);
    let mut push = Vec::new();
    for (transform, sim) in world.query_mut::<(&Transform, &mut WaterSim)>() {
        let field = &mut sim.field;
        push.clear();
        push.resize(field.layout.len(), 0.0);
        add_push(&mut push, &field.layout, transform, &found, field.desc.push);
        field.step(step_seconds as f32, &push);
    }
}
