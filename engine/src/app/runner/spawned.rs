//! [`SpawnedLevel`]: the handles of what `Engine::spawn_level` (`level.rs`) created, by index
//! and by name, and the two entities of a level character ([`SpawnedCharacter`]).
//!
//! Kept apart from the spawning so that the `Game` hooks that receive it
//! (`EditHooks::level_respawned`) do not depend on the engine's spawning code. Plain data, main
//! thread. Must not: spawn or despawn anything.

use std::collections::HashMap;

use hecs::Entity;

use crate::ecs::ModelHandle;

/// What [`Engine::spawn_level`](super::Engine::spawn_level) created.
#[derive(Clone, Debug, Default)]
pub struct SpawnedLevel {
    /// Handle of each of the level's models, in `SceneDesc::models` order.
    pub models: Vec<ModelHandle>,
    /// The entity of each of the level's instances, in `SceneDesc::instances` order.
    pub entities: Vec<Entity>,
    /// Entities of the instances the level names.
    pub by_name: HashMap<String, Entity>,
    /// The level's characters by name.
    pub characters: HashMap<String, SpawnedCharacter>,
}

/// The two entities of a level character.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SpawnedCharacter {
    /// The capsule the controller moves: `Transform` (the capsule's centre), kinematic body,
    /// collider, `CharacterController`, `CharacterInput`, `CharacterState`,
    /// `CharacterAnimation`.
    pub body: Entity,
    /// Its drawn model, a child of the body: `Renderable`, `SkinnedAnimator`, `Deformable`.
    pub visual: Entity,
}
