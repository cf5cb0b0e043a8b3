//! Putting a loaded level into the engine: models registered with the upkeep, one entity per
//! level instance (static unless the level marks it dynamic or gives it a moving body), its
//! physics components when the level gives it a body, level materials, the environment, and
//! the level's gameplay (clips, volumes, lasers and their visible beams, rules; light groups
//! that start off; sound emitters on instances and the music; `Usable` on the instances the
//! player can use), and its characters (a capsule body with the controller and the animation
//! state machine, and a child entity drawing the skinned model).
//!
//! Fills a [`SpawnedLevel`] (the handles of what was spawned, by index and by name), and takes
//! it down again ([`Engine::despawn_level`], before a respawn: the editor, a game restarting a
//! level). Main thread. Must not: load files (assets did) or run systems.

use std::collections::HashSet;

use glam::Vec3;
use hecs::Entity;

use super::engine::Engine;
use super::environment::Environment;
use super::spawned::{SpawnedCharacter, SpawnedLevel};
use super::waves::Waves;
use crate::audio::{Bus, SoundEmitter};
use crate::ecs::{Deformable, LightGroup, ModelHandle, Parent, Renderable, Static, Transform};
use crate::level::{PlayableCharacter, PlayableLevel};
use crate::sim::animation::{CharacterAnimation, SkinnedAnimator};
use crate::sim::physics::{Breakable, SensorContacts, character_bundle};
use crate::sim::triggers::{LevelLogic, beam_model, spawn_beam_pool};
use crate::sim::water::WaterSim;

impl Engine {
    /// Registers the level's models and materials with the upkeep and spawns one entity per
    /// instance (with its body, if it has one); sets the environment from the level; starts
    /// its gameplay; spawns its characters.
    pub fn spawn_level(&mut self, level: &PlayableLevel) -> SpawnedLevel {
        self.spawn_level_models(level, None)
    }

    /// [`Engine::spawn_level`] with the level's models already registered (`models`, one
    /// handle per `SceneDesc::models` entry) or, when `None`, registered now.
    pub(in crate::app) fn spawn_level_models(
        &mut self,
        level: &PlayableLevel,
        models: Option<Vec<ModelHandle>>,
    ) -> SpawnedLevel {
        let desc = &level.scene;
        self.environment = Environment::of(desc);
        self.set_default_camera(desc.camera);
        self.upkeep.add_level_materials(&desc.level_materials);
        self.upkeep.set_render_areas(level.render_areas.clone());
        let models: Vec<ModelHandle> = match models {
            Some(models) if models.len() == desc.models.len() => models,
            _ => desc
                .models
                .iter()
                .map(|m| self.upkeep.add_model(m))
                .collect(),
        };
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
                if let Some(sim) = desc_waves.simulate {
                    match WaterSim::on_grid(&mesh.positions, sim) {
                        Some(water) => drop(self.world.insert_one(entity, water)),
                        None => log::error!(
                            "{}: instance {i}: waves.simulate needs a regular grid mesh",
                            desc.source.display()
                        ),
                    }
                }
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
        for character in &level.characters {
            match self.spawn_character(character) {
                Ok(spawned_character) => {
                    spawned
                        .characters
                        .insert(character.name.clone(), spawned_character);
                }
                Err(message) => log::error!("{}: {message}", desc.source.display()),
            }
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
        let breakables = (level.gameplay.breakables.iter())
            .map(|b| Breakable {
                pieces: (b.pieces.iter())
                    .filter_map(|&i| spawned.entities.get(i).copied())
                    .collect(),
                impact_speed: b.impact_speed,
                piece_mass: b.piece_mass,
                scatter_speed: b.scatter_speed,
            })
            .collect();
        self.physics.set_breakables(breakables);
        for laser in &level.gameplay.lasers {
            if let (Some(beam), Some(&entity)) = (laser.beam, spawned.entities.get(laser.instance))
            {
                // One model per beam colour for the engine's life: spawning the level again
                // (the editor, a restart) must not grow the scene (soak, 2026-12-07).
                let key = beam.radiance.to_array().map(f32::to_bits);
                let model = match self.beam_models.get(&key) {
                    Some(&model) => model,
                    None => {
                        let model = self.upkeep.add_model(&beam_model(&beam));
                        self.beam_models.insert(key, model);
                        model
                    }
                };
                spawn_beam_pool(&mut self.world, entity, model, &beam);
            }
        }
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

    /// Spawns a character's body (capsule centre above the spawn point) and its drawn model.
    /// Loading checked everything, so an error here is a broken invariant, reported as text.
    fn spawn_character(&mut self, c: &PlayableCharacter) -> Result<SpawnedCharacter, String> {
        let (animator, deformable) = SkinnedAnimator::single(c.animated.clone(), &c.model)
            .ok_or_else(|| format!("character {:?}: not a single skinned mesh", c.name))?;
        let model = self.upkeep.add_model(&c.model);
        let centre = c.spawn_feet + Vec3::Y * (c.height * 0.5);
        let bundle = character_bundle(centre, c.height, c.radius, c.controller)
            .map_err(|e| format!("character {:?}: {e}", c.name))?;
        let body = self.world.spawn(bundle);
        let anim = CharacterAnimation::new(body, c.yaw_rad, c.model_yaw_rad, c.machine.clone());
        // The controller keeps `skin` metres between the capsule and the ground: the feet go
        // that much below the capsule's bottom.
        let local = Transform {
            translation: Vec3::Y * (-c.height * 0.5 - c.controller.skin),
            rotation: anim.visual_rotation(),
            scale: Vec3::splat(c.scale),
        };
        let renderable = Renderable {
            model,
            material_override: None,
        };
        let visual = self
            .world
            .spawn((local, Parent(body), renderable, animator, deformable));
        let _ = self
            .world
            .insert_one(body, CharacterAnimation { visual, ..anim });
        Ok(SpawnedCharacter { body, visual })
    }
}

impl Engine {
    /// Despawns what [`Engine::spawn_level`] spawned (`spawned`): the instances' entities, the
    /// characters, and every entity parented to one of them (laser beam prisms, characters'
    /// models); stops the level's logic; turns back on the light groups that `next` (the level
    /// about to be spawned) or the old entities use, so the next spawn starts from the level's
    /// own `lights_off`.
    pub fn despawn_level(&mut self, spawned: &SpawnedLevel, next: &PlayableLevel) {
        let mut doomed: HashSet<Entity> = spawned.entities.iter().copied().collect();
        for c in spawned.characters.values() {
            doomed.insert(c.body);
            doomed.insert(c.visual);
        }
        loop {
            let children: Vec<Entity> = self
                .world
                .query::<(Entity, &Parent)>()
                .iter()
                .filter(|(e, p)| doomed.contains(&p.0) && !doomed.contains(e))
                .map(|(e, _)| e)
                .collect();
            if children.is_empty() {
                break;
            }
            doomed.extend(children);
        }
        let mut groups: HashSet<u32> = next
            .scene
            .instances
            .iter()
            .filter_map(|i| i.light_group)
            .collect();
        groups.extend(next.gameplay.lights_off.iter().copied());
        for e in &doomed {
            if let Ok(g) = self.world.get::<&LightGroup>(*e) {
                groups.insert(g.0);
            }
        }
        for e in doomed {
            let _ = self.world.despawn(e);
        }
        for group in groups {
            self.upkeep.set_light_group(group, true);
        }
        self.upkeep.set_render_areas(Vec::new());
        self.logic = Default::default();
    }

    /// [`Engine::spawn_level`], reusing `models` (the handles a previous spawn registered for
    /// the same model list) instead of registering the level's models again.
    pub fn spawn_level_with(
        &mut self,
        level: &PlayableLevel,
        models: Option<Vec<ModelHandle>>,
    ) -> SpawnedLevel {
        self.spawn_level_models(level, models)
    }
}
