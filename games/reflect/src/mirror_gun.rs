//! The mirror gun: the left mouse button turns the mirrorable panel under the crosshair into a
//! mirror (a per-instance material override, no geometry change), the right button turns it
//! back. Each chamber caps how many of its panels may be mirrors at once.
//!
//! Owns: [`MirrorGun`] (which panels are mirrors, which chamber each belongs to, how many
//! mirrors were made in all). Main thread, Reflect's fixed step, with ray queries on the scene
//! as of the last commit (so a laser sees a new mirror one step later).
//! Must not: draw or play anything itself (the game sends the level an event for the sound).

use std::collections::BTreeMap;

use candela::query::Queries;
use candela::sim::triggers::{is_beam, set_material};
use candela::trace::Ray;
use glam::Vec3;
use hecs::{Entity, World};

/// How far the gun reaches, metres.
pub const RANGE: f32 = 40.0;

/// What a trigger pull did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GunShot {
    /// The panel became a mirror.
    Mirrored(Entity),
    /// The panel is a plain panel again.
    Reverted(Entity),
    /// The chamber already has as many mirrors as it allows.
    AtCap,
    /// Nothing mirrorable under the crosshair (or it already was what was asked).
    Nothing,
}

/// A mirrorable panel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Panel {
    /// Index of the chamber that holds it (`None`: outside every chamber, never capped).
    chamber: Option<usize>,
    /// Its level material override before it became a mirror.
    original: Option<u32>,
    mirror: bool,
}

/// The mirror gun's state.
#[derive(Clone, Debug, Default)]
pub struct MirrorGun {
    /// Ordered by entity for deterministic iteration.
    panels: BTreeMap<u64, (Entity, Panel)>,
    mirror_material: u32,
    /// Mirrors made since the game started (reverting does not subtract).
    pub made: u32,
}

impl MirrorGun {
    /// A gun for the panels `panels` (entity, its chamber, its original material override)
    /// that turns them into level material `mirror_material`.
    pub fn new(
        panels: impl IntoIterator<Item = (Entity, Option<usize>, Option<u32>)>,
        mirror_material: u32,
    ) -> Self {
        let panels = panels
            .into_iter()
            .map(|(e, chamber, original)| {
                let panel = Panel {
                    chamber,
                    original,
                    mirror: false,
                };
                (e.to_bits().get(), (e, panel))
            })
            .collect();
        Self {
            panels,
            mirror_material,
            made: 0,
        }
    }

    /// How many mirrorable panels it knows.
    pub fn panel_count(&self) -> usize {
        self.panels.len()
    }

    /// Whether `entity` is a mirrorable panel.
    pub fn is_panel(&self, entity: Entity) -> bool {
        self.panels.contains_key(&entity.to_bits().get())
    }

    /// Whether `entity` is a panel that is a mirror now.
    pub fn is_mirror(&self, entity: Entity) -> bool {
        self.panels
            .get(&entity.to_bits().get())
            .is_some_and(|(_, p)| p.mirror)
    }

    /// The chamber that holds panel `entity` (`None`: not a panel, or outside every chamber).
    pub fn chamber_of(&self, entity: Entity) -> Option<usize> {
        self.panels
            .get(&entity.to_bits().get())
            .and_then(|(_, p)| p.chamber)
    }

    /// Mirrors active now in chamber `chamber`.
    pub fn active_in(&self, chamber: usize) -> u32 {
        self.panels
            .values()
            .filter(|(_, p)| p.mirror && p.chamber == Some(chamber))
            .count() as u32
    }

    /// The mirrorable panel the ray from `eye` along `view` hits first within [`RANGE`]
    /// (visible laser beams are looked through), if the first thing it hits is one.
    pub fn aimed(
        &self,
        world: &World,
        queries: &Queries<'_>,
        eye: Vec3,
        view: Vec3,
    ) -> Option<Entity> {
        let mut ray = Ray::new(eye, view);
        ray.t_max = RANGE;
        let hit = queries.closest_where(&ray, |e| !e.is_some_and(|e| is_beam(world, e)))?;
        hit.entity.filter(|&e| self.is_panel(e))
    }

    /// Pulls the trigger: `mirror` (left button) or revert (right button) on `target`, with
    /// at most `cap` mirrors in the panel's chamber.
    pub fn shoot(
        &mut self,
        world: &mut World,
        target: Option<Entity>,
        mirror: bool,
        cap: impl Fn(usize) -> u32,
    ) -> GunShot {
        let Some(target) = target else {
            return GunShot::Nothing;
        };
        let Some(&(_, panel)) = self.panels.get(&target.to_bits().get()) else {
            return GunShot::Nothing;
        };
        if panel.mirror == mirror {
            return GunShot::Nothing;
        }
        if mirror
            && let Some(chamber) = panel.chamber
            && self.active_in(chamber) >= cap(chamber)
        {
            return GunShot::AtCap;
        }
        let material = if mirror {
            Some(self.mirror_material)
        } else {
            panel.original
        };
        set_material(world, target, material);
        if let Some((_, p)) = self.panels.get_mut(&target.to_bits().get()) {
            p.mirror = mirror;
        }
        if mirror {
            self.made += 1;
            GunShot::Mirrored(target)
        } else {
            GunShot::Reverted(target)
        }
    }
}
