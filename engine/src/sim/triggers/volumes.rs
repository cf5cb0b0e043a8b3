//! Trigger volumes: who is inside each volume this step, and who entered, stayed and left.
//!
//! Owns: [`VolumeTracker`] (the occupants of each volume as of the last step), the per-step
//! [`VolumeEvent`]s and [`VolumeFacts`] the rules read. Occupants come from the volume's sensor
//! contacts (characters count as the player, dynamic bodies as bodies) and from laser beams
//! whose path crosses the volume's collider. Lists are kept sorted by (entity, kind), so events
//! come out in the same order on every run. Main thread, fixed step, after physics.
//! Must not: act on what it finds (rules do).

use hecs::{Entity, World};

use super::laser::LaserPath;
use crate::assets::Detect;
use crate::sim::physics::{BodyKind, CharacterController, PhysicsWorld, RigidBody, SensorContacts};

/// What kind of thing is in a volume.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum OccupantKind {
    Player,
    Body,
    /// A laser beam (the occupant is the laser's entity).
    Laser,
}

/// The phase of an occupant's stay in a volume.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Phase {
    /// It came in during this step.
    Enter,
    /// It was inside at the last step and still is.
    Stay,
    /// It left (or was despawned) during this step.
    Exit,
}

/// One occupant's event in one volume in one step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct VolumeEvent {
    /// Index of the volume in the level's list.
    pub volume: usize,
    pub occupant: Entity,
    pub kind: OccupantKind,
    pub phase: Phase,
}

/// Counts for one volume in one step.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct VolumeFacts {
    pub inside: u32,
    pub entered: u32,
    pub exited: u32,
}

#[derive(Clone, Debug)]
struct Tracked {
    entity: Entity,
    detects: [bool; 3],
    inside: Vec<(u64, OccupantKind, Entity)>,
}

/// Occupancy of every volume.
#[derive(Clone, Debug, Default)]
pub struct VolumeTracker {
    volumes: Vec<Tracked>,
}

impl VolumeTracker {
    /// Volumes on the sensor entities `entities`, each noticing `detects`.
    pub fn new(volumes: impl IntoIterator<Item = (Entity, Vec<Detect>)>) -> Self {
        let volumes = volumes
            .into_iter()
            .map(|(entity, detects)| Tracked {
                entity,
                detects: [Detect::Player, Detect::Bodies, Detect::Lasers]
                    .map(|d| detects.contains(&d)),
                inside: Vec::new(),
            })
            .collect();
        Self { volumes }
    }

    /// Number of volumes.
    pub fn len(&self) -> usize {
        self.volumes.len()
    }

    /// Whether there are no volumes.
    pub fn is_empty(&self) -> bool {
        self.volumes.is_empty()
    }

    /// The occupants of volume `volume` as of the last step.
    pub fn occupants(&self, volume: usize) -> impl Iterator<Item = (Entity, OccupantKind)> + '_ {
        self.volumes
            .get(volume)
            .into_iter()
            .flat_map(|v| v.inside.iter().map(|&(_, kind, e)| (e, kind)))
    }

    /// Updates every volume from sensor contacts and `beams` (laser entity, traced path);
    /// appends this step's events to `events` and returns the counts per volume.
    pub fn step(
        &mut self,
        world: &World,
        physics: &PhysicsWorld,
        beams: &[(Entity, LaserPath)],
        events: &mut Vec<VolumeEvent>,
    ) -> Vec<VolumeFacts> {
        let mut facts = Vec::with_capacity(self.volumes.len());
        for (index, volume) in self.volumes.iter_mut().enumerate() {
            let mut now: Vec<(u64, OccupantKind, Entity)> = Vec::new();
            if let Ok(contacts) = world.get::<&SensorContacts>(volume.entity) {
                for &e in &contacts.inside {
                    if let Some(kind) = classify(world, e)
                        && volume.detects[kind as usize]
                    {
                        now.push((e.to_bits().get(), kind, e));
                    }
                }
            }
            if volume.detects[2] {
                for (laser, path) in beams {
                    if path
                        .segments()
                        .any(|(a, b)| physics.segment_touches(volume.entity, a, b))
                    {
                        now.push((laser.to_bits().get(), OccupantKind::Laser, *laser));
                    }
                }
            }
            now.sort_unstable_by_key(|&(bits, kind, _)| (bits, kind));
            now.dedup_by_key(|&mut (bits, kind, _)| (bits, kind));
            let mut f = VolumeFacts {
                inside: now.len() as u32,
                ..Default::default()
            };
            let key = |x: &(u64, OccupantKind, Entity)| (x.0, x.1);
            for item in &now {
                let was = volume.inside.binary_search_by_key(&key(item), key).is_ok();
                f.entered += u32::from(!was);
                events.push(VolumeEvent {
                    volume: index,
                    occupant: item.2,
                    kind: item.1,
                    phase: if was { Phase::Stay } else { Phase::Enter },
                });
            }
            for item in &volume.inside {
                if now.binary_search_by_key(&key(item), key).is_err() {
                    f.exited += 1;
                    events.push(VolumeEvent {
                        volume: index,
                        occupant: item.2,
                        kind: item.1,
                        phase: Phase::Exit,
                    });
                }
            }
            volume.inside = now;
            facts.push(f);
        }
        facts
    }
}

/// What a volume sees `entity` as: characters are the player, dynamic bodies are bodies;
/// anything else (static geometry, kinematic doors) is not an occupant.
fn classify(world: &World, entity: Entity) -> Option<OccupantKind> {
    if world.get::<&CharacterController>(entity).is_ok() {
        return Some(OccupantKind::Player);
    }
    match world.get::<&RigidBody>(entity).map(|b| b.kind) {
        Ok(BodyKind::Dynamic) => Some(OccupantKind::Body),
        _ => None,
    }
}
