//! Putting a loaded level into the engine: models registered with the upkeep, one entity per
//! level instance (static unless the level marks it dynamic or gives it a moving body), its
//! physics components when the level gives it a body, level materials, the environment, and
//! the level's gameplay (clips, volumes, lasers, rules; light groups that start off; sound
//! emitters on instances and the music; `Usable` on the instances the player can use).
//!
//! Owns: [`SpawnedLevel`] (the handles of what was spawned, by index and by name). Main thread.
//! Must not: load files (assets did) or run systems.

use std::collections::HashMap;

use hecs::Entity;

use super::engine::{Engine, Environment};
use super::waves::Waves;
use crate::assets::SceneDesc;
use crate::audio::{Bus, SoundEmitter};
use crate::ecs::{Deformable, LightGroup, ModelHandle, Renderable, Static, Transform};
use crate::level::PlayableLevel;
use crate::sim::physics::SensorContacts;
use crate::sim::triggers::LevelLogic;

/// What [`Engine::spawn_level`] created.
#[derive(Clone, Debug, Default)]
pub struct SpawnedLevel {
    /// Handle of each of the level's models, in `SceneDesc::models` order.
    pub models: Vec<ModelHandle>,
    /// The entity of each of the level's instances, in `SceneDesc::instances` order.
    pub entities: Vec<Entity>,
    /// Entities of the instances the level names.
    pub by_name: HashMap<String, Entity>,
}

impl Environment {
    /// The environment a level describes (its camera becomes the default view).
    pub fn of(desc: &SceneDesc) -> Self {
        Self {
            sun: desc.sun,
            sky: desc.sky,
            render: desc.render,
            default_camera: desc.camera,
        }
    }
}

impl Engine {
    /// Registers the level's models and materials with the upkeep and spawns one entity per
    /// instance (with its body, if it has one); sets the environment from the level; starts
    /// its gameplay.
    pub fn spawn_level(&mut self, level: &PlayableLevel) -> SpawnedLevel {
        let desc = &level.scene;
        self.environment = Environment::of(desc);
        self.set_default_camera(desc.camera);
        self.upkeep.add_level_materials(&desc.level_materials);
        let models: Vec<ModelHandle> = desc
            .models
            .iter()
            .map(|m| self.upkeep.add_model(m))
            .collect();
        let mut spawned = SpawnedLevel {
            models,
            ..Default::default()
        };
        for (i, instance) in desc.instances.iter().enumerate() {
            let Some(&model) = spawned.models.get(instance.model) else {
                continue;
            };
            let renderable = Renderable {
                model,
                material_override: instance.material_override.map(|m| m as u32),
            };
            let transform = Transform::from_matrix(instance.world_from_model);
            let entity = self.world.spawn((transform, renderable));
            if !instance.dynamic {
                let _ = self.world.insert_one(entity, Static);
            }
            if let Some(group) = instance.light_group {
                let _ = self.world.insert_one(entity, LightGroup(group));
            }
            if let Some(desc_waves) = instance.waves
                && let Some(mesh) = desc.models[instance.model].meshes.first()
            {
                let waves = Waves::new(desc_waves, mesh.positions.clone());
                let deformable = Deformable {
                    mesh: 0,
                    positions: mesh.positions.clone(),
                    normals: mesh.normals.clone(),
                    dirty: false,
                };
                let _ = self.world.insert(entity, (waves, deformable));
            }
            if let Some(Some(physics)) = level.bodies.get(i) {
                let _ = self
                    .world
                    .insert(entity, (physics.body, physics.collider.clone()));
                if physics.collider.sensor {
                    let _ = self.world.insert_one(entity, SensorContacts::default());
                }
            }
            if let Some(name) = &instance.name {
                spawned.by_name.insert(name.clone(), entity);
            }
            spawned.entities.push(entity);
        }
        for u in &level.gameplay.usables {
            if let Some(&entity) = spawned.entities.get(u.instance) {
                let _ = self.world.insert_one(entity, u.usable.clone());
            }
        }
        for &group in &level.gameplay.lights_off {
            self.upkeep.set_light_group(group, false);
        }
        self.logic = LevelLogic::new(&level.gameplay, &spawned.entities, &mut self.world);
        let sounds = &level.gameplay.sounds;
        for emitter in &level.gameplay.emitters {
            if let (Some(&entity), Some(sound)) = (
                spawned.entities.get(emitter.instance),
                sounds.get(emitter.sound),
            ) {
                let looping = SoundEmitter::new(sound.sound.clone(), emitter.volume, true);
                let _ = self.world.insert_one(entity, looping);
            }
        }
        if let Some((sound, volume)) = level.gameplay.music
            && let Some(music) = sounds.get(sound)
        {
            self.audio.set_volume(Bus::Music, volume);
            if let Err(e) = self.audio.play_music(&music.sound, true) {
                log::warn!("{}: music {:?}: {e}", desc.source.display(), music.name);
            }
        }
        spawned
    }
}
