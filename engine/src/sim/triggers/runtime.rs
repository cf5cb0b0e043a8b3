//! [`LevelLogic`]: a level's gameplay running: clips on entities, laser beams, trigger volumes
//! and rules, one fixed step at a time.
//!
//! Owns: the instance → entity map of the level, the [`EntityAnimations`], the
//! [`VolumeTracker`], the [`RuleBook`], the level's sounds, the outcome (won or lost) and the
//! log of the last step. A step, in order: advance clips (writing door and lift transforms,
//! collecting clip events) → trace laser beams → lay their visible pieces → update volumes →
//! evaluate rules → carry out what touches only the world (clips, materials, win or lose) and
//! hand the rest back as [`Effect`]s (light groups, sounds) for the engine, which owns the
//! scene and the audio.
//! Main thread, fixed step, after physics. Deterministic: no clocks, no hash order.
//! Must not: touch the upkeep, the audio device or the render thread.

use glam::{Mat4, Vec3};
use hecs::{Entity, World};

use super::beam_geometry::{is_beam, update_beams};
use super::laser::{LaserBeam, LaserPath, trace_laser};
use super::logic::{Facts, RuleBook, RuleFiring};
use super::plan::{Action, Condition, GameplayPlan, PlannedSound};
use super::volumes::{VolumeEvent, VolumeTracker};
use crate::ecs::{GlobalTransform, Parent, Renderable, Restyled, Transform};
use crate::query::Queries;
use crate::sim::animation::{EntityAnimations, FiredEvent};
use crate::sim::physics::PhysicsWorld;
use crate::trace::Ray;

/// How the level ended.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// A rule with a `Win` action fired; its name.
    Won(String),
    /// A rule with a `Lose` action fired; its name.
    Lost(String),
}

/// What the engine carries out for a step's rules.
#[derive(Clone, Debug, PartialEq)]
pub enum Effect {
    Lights {
        group: u32,
        on: bool,
    },
    ToggleLights(u32),
    /// Sound `sound` (index into [`LevelLogic::sounds`]) at an entity's position or
    /// everywhere, at linear `volume`.
    Sound {
        sound: usize,
        at: Option<Entity>,
        volume: f32,
    },
    /// Break breakable (index into the plan's `breakables`) now.
    Break(usize),
}

/// What happened in the last step.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct StepLog {
    pub volume_events: Vec<VolumeEvent>,
    pub clip_events: Vec<FiredEvent>,
    pub firings: Vec<RuleFiring>,
}

/// A level's gameplay, running.
#[derive(Default)]
pub struct LevelLogic {
    pub animations: EntityAnimations,
    entities: Vec<Entity>,
    volumes: VolumeTracker,
    volume_names: Vec<String>,
    /// Per volume: its sensor's entity, and whether a `SunLit` condition reads it.
    volume_entities: Vec<(Option<Entity>, bool)>,
    rules: RuleBook,
    counter_names: Vec<String>,
    sounds: Vec<PlannedSound>,
    outcome: Option<Outcome>,
    last: StepLog,
    steps: u64,
    /// Events sent by the game ([`LevelLogic::send_event`]) for the next step's rules.
    sent: Vec<String>,
}

impl LevelLogic {
    /// Runs `plan` on the level whose instances became `entities` (level order). Puts a
    /// [`LaserBeam`] on every laser's entity and starts the autoplay clips.
    pub fn new(plan: &GameplayPlan, entities: &[Entity], world: &mut World) -> Self {
        let entity = |i: usize| entities.get(i).copied();
        let targets: Vec<Entity> = plan
            .clip_targets
            .iter()
            .filter_map(|&i| entity(i))
            .collect();
        let mut animations = if targets.len() == plan.clip_targets.len() {
            EntityAnimations::new(plan.clips.clone(), targets, world)
        } else {
            EntityAnimations::default()
        };
        for &(clip, mode) in &plan.autoplay {
            animations.play(clip, mode);
        }
        for laser in &plan.lasers {
            if let Some(e) = entity(laser.instance) {
                let beam = LaserBeam {
                    origin: laser.origin,
                    direction: laser.direction,
                    max_reflections: laser.max_reflections,
                    max_length: laser.max_length,
                };
                let _ = world.insert(e, (beam, LaserPath::default()));
            }
        }
        let volumes = VolumeTracker::new(
            plan.volumes
                .iter()
                .filter_map(|v| Some((entity(v.instance)?, v.detects.clone()))),
        );
        Self {
            animations,
            entities: entities.to_vec(),
            volumes,
            volume_names: plan.volumes.iter().map(|v| v.name.clone()).collect(),
            volume_entities: {
                let mut read = vec![false; plan.volumes.len()];
                plan.rules
                    .iter()
                    .for_each(|r| sun_volumes(&r.when, &mut read));
                (plan.volumes.iter().zip(read))
                    .map(|(v, read)| (entity(v.instance), read))
                    .collect()
            },
            rules: RuleBook::new(plan.rules.clone())
                .with_counters(plan.counters.iter().map(|(_, start)| *start).collect()),
            counter_names: plan.counters.iter().map(|(name, _)| name.clone()).collect(),
            sounds: plan.sounds.clone(),
            outcome: None,
            last: StepLog::default(),
            steps: 0,
            sent: Vec::new(),
        }
    }

    /// The level's sounds, by index.
    pub fn sounds(&self) -> &[PlannedSound] {
        &self.sounds
    }

    /// The entity of level instance `index`.
    pub fn entity(&self, index: usize) -> Option<Entity> {
        self.entities.get(index).copied()
    }

    /// The index of the volume named `name`.
    pub fn volume_index(&self, name: &str) -> Option<usize> {
        self.volume_names.iter().position(|n| n == name)
    }

    /// The volumes and who is in them.
    pub fn volumes(&self) -> &VolumeTracker {
        &self.volumes
    }

    /// Won or lost, once a rule said so (the first one counts).
    pub fn outcome(&self) -> Option<&Outcome> {
        self.outcome.as_ref()
    }

    /// What happened in the last step.
    pub fn last_step(&self) -> &StepLog {
        &self.last
    }

    /// Sends event `name` to the rules: `Event(name)` conditions see it in the next
    /// [`LevelLogic::step`], as they see clip events (a "use" on a switch, a game's own
    /// trigger).
    pub fn send_event(&mut self, name: impl Into<String>) {
        self.sent.push(name.into());
    }

    /// The name of rule `index` (level order).
    pub fn rule_name(&self, index: usize) -> Option<&str> {
        self.rules.rules().get(index).map(|r| r.name.as_str())
    }

    /// The value of the rules' counter `name` (`gameplay.counters`).
    pub fn counter(&self, name: &str) -> Option<i32> {
        let index = self.counter_names.iter().position(|n| n == name)?;
        self.rules.counters().get(index).copied()
    }

    /// Whether the condition of the rule named `name` held in the last step.
    pub fn rule_holds(&self, name: &str) -> bool {
        (self.rules.rules().iter())
            .position(|r| r.name == name)
            .is_some_and(|i| self.rules.holds(i))
    }

    /// Whether the rule named `name` has run its `then` at least once.
    pub fn rule_fired(&self, name: &str) -> bool {
        (self.rules.rules().iter())
            .position(|r| r.name == name)
            .is_some_and(|i| self.rules.fired(i))
    }

    /// The name of volume `index` (level order).
    pub fn volume_name(&self, index: usize) -> Option<&str> {
        self.volume_names.get(index).map(String::as_str)
    }

    /// Fixed steps run so far.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// The logic's state as words in a fixed order, for state hashes: steps, outcome, each
    /// rule's state, each volume's occupants (entity bits and kind, in the tracker's order),
    /// each clip's playhead (time bits, direction, paused, finished) and the events waiting
    /// for the next step.
    pub fn state_words(&self) -> Vec<u64> {
        let mut out = vec![self.steps];
        out.push(match &self.outcome {
            None => 0,
            Some(Outcome::Won(r)) => 1 | super::logic::text_bits(r) << 2,
            Some(Outcome::Lost(r)) => 2 | super::logic::text_bits(r) << 2,
        });
        self.rules.state_words(&mut out);
        for v in 0..self.volumes.len() {
            out.push(u64::MAX);
            for (e, kind) in self.volumes.occupants(v) {
                out.push(e.to_bits().get());
                out.push(kind as u64);
            }
        }
        for c in 0..self.animations.clips().len() {
            match self.animations.playhead(c) {
                None => out.push(u64::MAX - 1),
                Some(p) => {
                    out.push(p.time_seconds.to_bits());
                    out.push(
                        u64::from(p.reversed)
                            | u64::from(p.paused) << 1
                            | u64::from(p.finished) << 2,
                    );
                }
            }
        }
        out.extend(self.sent.iter().map(|s| super::logic::text_bits(s)));
        out
    }

    /// One fixed step of `dt_seconds`, with light groups `lights_off` switched off (as the
    /// engine has them before the step; `LightsOn` conditions read them) and the sun towards
    /// `sun` (world space, unit; `SunLit` conditions cast a query ray that way) at
    /// `sun_elevation_deg` above the horizon (`SunElevation` conditions; `None` without a
    /// sun, while `sun` is also `None` for a sun below the horizon); returns the effects the
    /// engine carries out.
    #[allow(clippy::too_many_arguments)]
    pub fn step(
        &mut self,
        world: &mut World,
        physics: &PhysicsWorld,
        queries: Queries<'_>,
        lights_off: &[u32],
        sun: Option<Vec3>,
        sun_elevation_deg: Option<f32>,
        dt_seconds: f64,
    ) -> Vec<Effect> {
        self.steps += 1;
        let clip_events = self.animations.step(world, dt_seconds);
        let beams = trace_beams(world, &queries);
        update_beams(world);
        let mut volume_events = Vec::new();
        let facts = self
            .volumes
            .step(world, physics, &beams, &mut volume_events);
        let names: Vec<String> = clip_events
            .iter()
            .map(|e| e.name.clone())
            .chain(self.sent.drain(..))
            .collect();
        let sun_lit: Vec<bool> = (self.volume_entities.iter())
            .map(|&(entity, read)| match (entity, sun, read) {
                (Some(e), Some(towards), true) => sees_sun(world, &queries, e, towards),
                _ => false,
            })
            .collect();
        let (firings, actions) = self.rules.step(&Facts {
            volumes: &facts,
            events: &names,
            lights_off,
            sun_lit: &sun_lit,
            sun_elevation_deg,
        });
        let mut effects = Vec::new();
        let mut action_rule = firings.iter().flat_map(|f| {
            let rule = &self.rules.rules()[f.rule];
            let list = if f.rising {
                &rule.then
            } else {
                &rule.otherwise
            };
            std::iter::repeat_n(rule.name.clone(), list.len())
        });
        for action in actions {
            let rule = action_rule.next().unwrap_or_default();
            match action {
                Action::Lights { group, on } => effects.push(Effect::Lights { group, on }),
                Action::ToggleLights(group) => effects.push(Effect::ToggleLights(group)),
                Action::Play { clip, mode } => self.animations.play(clip, mode),
                Action::Reverse { clip } => self.animations.reverse(clip),
                Action::Pause { clip } => self.animations.pause(clip),
                Action::Sound { sound, at, volume } => effects.push(Effect::Sound {
                    sound,
                    at: at.and_then(|i| self.entity(i)),
                    volume,
                }),
                Action::Material { instance, material } => {
                    if let Some(e) = self.entity(instance) {
                        set_material(world, e, material);
                    }
                }
                // Carried out by the rule book as the rule fired.
                Action::Count { .. } | Action::SetCounter { .. } => {}
                Action::Break(index) => effects.push(Effect::Break(index)),
                Action::Win => {
                    self.outcome.get_or_insert(Outcome::Won(rule));
                }
                Action::Lose => {
                    self.outcome.get_or_insert(Outcome::Lost(rule));
                }
            }
        }
        self.last = StepLog {
            volume_events,
            clip_events,
            firings,
        };
        effects
    }
}

/// Marks the volumes `SunLit` conditions in `c` read.
fn sun_volumes(c: &Condition, read: &mut [bool]) {
    match c {
        Condition::SunLit(v) => {
            if let Some(r) = read.get_mut(*v) {
                *r = true;
            }
        }
        Condition::All(cs)
        | Condition::Any(cs)
        | Condition::AtLeast { of: cs, .. }
        | Condition::Sequence(cs) => cs.iter().for_each(|c| sun_volumes(c, read)),
        Condition::Not(c) | Condition::Times { of: c, .. } => sun_volumes(c, read),
        _ => {}
    }
}

/// Whether the centre of `volume`'s entity sees the sun towards `sun` (unit): a query ray
/// meets nothing but the volume's own instance and laser beams. Never before the scene holds
/// the level (the steps before the first commit would otherwise see the sun through
/// everything).
fn sees_sun(world: &World, queries: &Queries<'_>, volume: Entity, sun: Vec3) -> bool {
    let Some(placed) = world_from_model(world, volume) else {
        return false;
    };
    if queries.is_empty() {
        return false;
    }
    let ray = Ray::new(placed.w_axis.truncate(), sun);
    queries
        .closest_where(&ray, |e| {
            e != Some(volume) && !e.is_some_and(|e| is_beam(world, e))
        })
        .is_none()
}

/// Gives `entity` level material `material` (or its model's own back) and tells the extractor
/// to look at it again even if it is static (the `Material` rule action; a game's mirror gun).
pub fn set_material(world: &mut World, entity: Entity, material: Option<u32>) {
    let changed = match world.get::<&mut Renderable>(entity) {
        Ok(mut r) if r.material_override != material => {
            r.material_override = material;
            true
        }
        _ => false,
    };
    if changed {
        let _ = world.insert_one(entity, Restyled);
    }
}

/// `world_from_model` of `entity` now: its `Transform` for a root entity (current within the
/// frame's steps), else its last propagated `GlobalTransform`.
pub fn world_from_model(world: &World, entity: Entity) -> Option<Mat4> {
    if world.get::<&Parent>(entity).is_err()
        && let Ok(t) = world.get::<&Transform>(entity)
    {
        return Some(t.matrix());
    }
    world.get::<&GlobalTransform>(entity).ok().map(|g| g.0)
}

/// Traces every laser beam, stores its path on its entity, and returns (entity, path) in
/// entity order.
fn trace_beams(world: &mut World, queries: &Queries<'_>) -> Vec<(Entity, LaserPath)> {
    let mut lasers: Vec<(Entity, LaserBeam)> = world
        .query::<(Entity, &LaserBeam)>()
        .iter()
        .map(|(e, b)| (e, *b))
        .collect();
    lasers.sort_by_key(|(e, _)| e.to_bits());
    let mut beams = Vec::with_capacity(lasers.len());
    for (entity, beam) in lasers {
        let Some(placed) = world_from_model(world, entity) else {
            continue;
        };
        let path = trace_laser(queries, placed, &beam, entity, |e| is_beam(world, e));
        if let Ok(mut stored) = world.get::<&mut LaserPath>(entity) {
            stored.clone_from(&path);
        }
        beams.push((entity, path));
    }
    beams
}
