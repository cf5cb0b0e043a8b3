//! A level's skinned characters, loaded to play: the glTF model (what the renderer draws and
//! what animation deforms), the capsule and controller tuning, and the animation state
//! machine with every clip name resolved — or an error naming the level file, the character
//! and the model file.
//!
//! Owns: [`PlayableCharacter`] and [`load_characters`]. Main thread (or a loader thread).
//! Must not: spawn entities (`Engine::spawn_level` does) or touch the GPU.
//! Units: metres, seconds, radians (the level writes degrees).

use std::path::Path;
use std::sync::Arc;

use glam::Vec3;

use crate::assets::{
    AnimStateEntry, AssetError, AssetResult, AssetRoot, BlendEntry, CharacterEntry, Level, Model,
    load_model,
};
use crate::sim::animation::{
    AnimState, AnimatedModel, SkinnedAnimator, SpeedBlend, StateCondition, StateMachine,
    load_animation,
};
use crate::sim::physics::CharacterController;

/// A character ready to spawn.
#[derive(Clone, Debug)]
pub struct PlayableCharacter {
    pub name: String,
    /// The model path as the level writes it.
    pub model_path: String,
    /// What the renderer draws (one skinned mesh).
    pub model: Model,
    /// What animation reads from the same file.
    pub animated: Arc<AnimatedModel>,
    /// Uniform scale of the model.
    pub scale: f32,
    /// Turn of the model about +Y so that it faces −Z, radians.
    pub model_yaw_rad: f32,
    /// Where the feet stand at the start, metres.
    pub spawn_feet: Vec3,
    /// Facing at the start, radians about +Y from −Z (positive turns right, towards +X).
    pub yaw_rad: f32,
    /// Capsule feet to head, metres.
    pub height: f32,
    /// Capsule radius, metres.
    pub radius: f32,
    pub controller: CharacterController,
    /// The animation states, clip names resolved (not yet run).
    pub machine: StateMachine,
}

/// Loads every character `level` (read from `level_path`) declares, through `root`.
pub fn load_characters(
    level_path: &Path,
    level: &Level,
    root: &AssetRoot,
) -> AssetResult<Vec<PlayableCharacter>> {
    let mut names = std::collections::HashSet::new();
    let mut out = Vec::with_capacity(level.characters.len());
    for entry in &level.characters {
        let error = |message: String| AssetError::Level {
            path: level_path.to_path_buf(),
            message: format!("character {:?}: {message}", entry.name),
        };
        if !names.insert(entry.name.as_str()) {
            return Err(error("the name is used twice".into()));
        }
        out.push(load_one(level_path, entry, root).map_err(error)?);
    }
    Ok(out)
}

/// One character; the error is a sentence the caller prefixes with the level and the name.
fn load_one(
    level_path: &Path,
    entry: &CharacterEntry,
    root: &AssetRoot,
) -> Result<PlayableCharacter, String> {
    let file = &entry.model;
    let model = load_model(root, level_path, file).map_err(|e| format!("model {file:?}: {e}"))?;
    let animated = load_animation(root, level_path, file)
        .map_err(|e| format!("model {file:?}: animation: {e}"))?;
    let animated = Arc::new(animated);
    if SkinnedAnimator::single(animated.clone(), &model).is_none() {
        return Err(format!(
            "model {file:?} must have exactly one mesh node, drawn once (a character)"
        ));
    }
    let positive = |what: &str, v: f32| {
        if v.is_finite() && v > 0.0 {
            Ok(v)
        } else {
            Err(format!("{what} must be finite and above 0, not {v}"))
        }
    };
    let scale = positive("scale", entry.scale)?;
    let height = positive("capsule.height", entry.capsule.height)?;
    let radius = positive("capsule.radius", entry.capsule.radius)?;
    if radius * 2.0 > height {
        return Err(format!(
            "capsule.radius ({radius}) must be at most half of capsule.height ({height})"
        ));
    }
    let spawn_feet = Vec3::from(entry.spawn);
    if !spawn_feet.is_finite() || !entry.yaw_deg.is_finite() || !entry.model_yaw_deg.is_finite() {
        return Err("spawn, yaw_deg and model_yaw_deg must be finite".into());
    }
    let c = &entry.controller;
    let mut controller = CharacterController::default();
    for (field, value, name) in [
        (&mut controller.walk_speed, c.walk_speed, "walk_speed"),
        (&mut controller.run_speed, c.run_speed, "run_speed"),
        (&mut controller.jump_speed, c.jump_speed, "jump_speed"),
        (&mut controller.gravity, c.gravity, "gravity"),
        (
            &mut controller.max_step_height,
            c.max_step_height,
            "max_step_height",
        ),
        (
            &mut controller.max_slope_deg,
            c.max_slope_deg,
            "max_slope_deg",
        ),
    ] {
        if let Some(v) = value {
            *field = positive(&format!("controller.{name}"), v)?;
        }
    }
    let states = entry
        .states
        .iter()
        .map(|s| anim_state(&animated, file, s))
        .collect::<Result<Vec<_>, _>>()?;
    let machine = StateMachine::new(states, entry.hysteresis_mps).map_err(|e| e.to_string())?;
    Ok(PlayableCharacter {
        name: entry.name.clone(),
        model_path: file.clone(),
        model,
        animated,
        scale,
        model_yaw_rad: entry.model_yaw_deg.to_radians(),
        spawn_feet,
        yaw_rad: entry.yaw_deg.to_radians(),
        height,
        radius,
        controller,
        machine,
    })
}

fn anim_state(
    animated: &AnimatedModel,
    file: &str,
    s: &AnimStateEntry,
) -> Result<AnimState, String> {
    let clip = animated.find_clip(&s.clip).map_err(|_| {
        let names: Vec<&str> = animated.clips.iter().map(|c| c.name.as_str()).collect();
        format!(
            "state {:?}: the model {file:?} has no clip {:?} (it has {names:?})",
            s.name, s.clip
        )
    })?;
    Ok(AnimState {
        name: s.name.clone(),
        clip,
        mode: s.mode,
        when: StateCondition {
            contact: s.contact,
            min_speed_mps: s.min_speed_mps,
            max_speed_mps: s.max_speed_mps.unwrap_or(f32::INFINITY),
        },
        reference_speed_mps: s.reference_speed_mps,
        min_rate: s.min_rate,
        max_rate: s.max_rate,
        fade_in_seconds: s.fade_seconds,
        blend: s
            .blend
            .as_ref()
            .map(|b| speed_blend(animated, file, s, clip, b))
            .transpose()?,
    })
}

/// The blend of state `s` (whose clip is `own`): its clip found and the cycle ratio measured.
fn speed_blend(
    animated: &AnimatedModel,
    file: &str,
    s: &AnimStateEntry,
    own: usize,
    b: &BlendEntry,
) -> Result<SpeedBlend, String> {
    let clip = animated.find_clip(&b.clip).map_err(|_| {
        format!(
            "state {:?}, blend: the model {file:?} has no clip {:?}",
            s.name, b.clip
        )
    })?;
    let duration = |i: usize| animated.clips.get(i).map_or(0.0, |c| c.duration_seconds);
    Ok(SpeedBlend {
        clip,
        reference_speed_mps: b.reference_speed_mps,
        from_speed_mps: b.from_speed_mps,
        to_speed_mps: b.to_speed_mps,
        cycle_ratio: (duration(clip) / duration(own)) as f32,
    })
}
