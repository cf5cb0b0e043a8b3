//! Loading a level to play: the level's rules checked (`validate_level`), what it renders
//! (`assets::load_scene`), its bodies, its gameplay, and the check that its declared `needs`
//! cover what it uses.
//!
//! Owns: [`PlayableLevel`], [`load_level`], [`playable_from_level`] and [`level_problems`].
//! Every problem is an [`AssetError`] naming the level file and the item; [`level_problems`]
//! gives the same problems typed ([`LevelProblem`]). Main thread (or a loader thread).
//! Must not: spawn entities (`Engine::spawn_level` does) or touch the GPU.

use std::path::Path;

use super::body::{InstanceBody, resolve_body};
use super::character::{PlayableCharacter, load_characters};
use super::gameplay_plan::plan_gameplay;
use super::item::ItemRef;
use super::problem::LevelProblem;
use super::validate::validate_level;
use crate::assets::{
    AssetError, AssetResult, AssetRoot, Level, Needs, SceneDesc, scene_from_level,
};
use crate::sim::triggers::{Action, GameplayPlan};

/// A level ready to spawn: its scene, the physics components of its instances and its
/// gameplay, every name resolved.
#[derive(Clone, Debug)]
pub struct PlayableLevel {
    pub scene: SceneDesc,
    /// Per instance (in `scene.instances` order), its body and collider.
    pub bodies: Vec<Option<InstanceBody>>,
    /// Sounds, clips, trigger volumes, lasers and rules, by index.
    pub gameplay: GameplayPlan,
    /// Skinned characters with their bodies and animation states (`characters` in the file).
    pub characters: Vec<PlayableCharacter>,
    /// Boxes naming the light groups sampled while the camera is inside (`render_areas`).
    pub render_areas: Vec<crate::assets::RenderArea>,
}

impl PlayableLevel {
    /// A level of `scene` with no bodies and no gameplay (scenes built in code).
    pub fn of_scene(scene: SceneDesc) -> Self {
        Self {
            bodies: vec![None; scene.instances.len()],
            scene,
            gameplay: GameplayPlan::default(),
            characters: Vec::new(),
            render_areas: Vec::new(),
        }
    }
}

/// Reads `level_path` and loads everything it names from `root`: models (in parallel),
/// bodies, gameplay (sounds decoded), characters (skinned models, animation states); checks
/// `needs`.
pub fn load_level(level_path: &Path, root: &AssetRoot) -> AssetResult<PlayableLevel> {
    let level = Level::read(level_path)?;
    playable_from_level(level_path, &level, root)
}

/// [`load_level`] of an already parsed `level` (read from `level_path`): the first problem
/// [`validate_level`] finds, or the first the load finds, is the error.
pub fn playable_from_level(
    level_path: &Path,
    level: &Level,
    root: &AssetRoot,
) -> AssetResult<PlayableLevel> {
    load_checked(level_path, level, root).map_err(|failure| match failure {
        LoadFailure::Problem(problem) => problem.into_error(level_path),
        LoadFailure::Asset(error) => error,
    })
}

/// Every problem that keeps `level` (as if read from `level_path`) from loading: all those
/// [`validate_level`] finds, or else the first one the full load from `root` finds (models,
/// bodies, sounds, clips, `needs`, characters). Empty: the level loads.
pub fn level_problems(level_path: &Path, level: &Level, root: &AssetRoot) -> Vec<LevelProblem> {
    let problems = validate_level(level);
    if !problems.is_empty() {
        return problems;
    }
    match load_checked(level_path, level, root) {
        Ok(_) => Vec::new(),
        Err(LoadFailure::Problem(problem)) => vec![problem],
        Err(LoadFailure::Asset(AssetError::Level { message, .. })) => {
            vec![LevelProblem::of_level(message)]
        }
        Err(LoadFailure::Asset(other)) => vec![LevelProblem::of_level(other.to_string())],
    }
}

/// Why [`load_checked`] stopped: a problem of one item, or an error of the files it reads.
#[derive(Debug, thiserror::Error)]
enum LoadFailure {
    #[error(transparent)]
    Problem(#[from] LevelProblem),
    #[error(transparent)]
    Asset(#[from] AssetError),
}

fn load_checked(
    level_path: &Path,
    level: &Level,
    root: &AssetRoot,
) -> Result<PlayableLevel, LoadFailure> {
    if let Some(problem) = validate_level(level).into_iter().next() {
        return Err(problem.into());
    }
    let scene = scene_from_level(level_path, level, root)?;
    let mut bodies = Vec::with_capacity(level.instances.len());
    for (i, (entry, instance)) in level.instances.iter().zip(&scene.instances).enumerate() {
        let body = match (&entry.body, scene.models.get(instance.model)) {
            (Some(body), Some(model)) => Some(
                resolve_body(body, model, instance.world_from_model).map_err(|message| {
                    let name = entry.name.as_deref().unwrap_or(&entry.model);
                    let message = format!("instance {i} ({name:?}): body: {message}");
                    LevelProblem::new(ItemRef::Instance(i), "body", message)
                })?,
            ),
            _ => None,
        };
        bodies.push(body);
    }
    let gameplay = plan_gameplay(level_path, level, root)?;
    check_needs(level_path, level, &scene, &gameplay)?;
    let characters = load_characters(level_path, level, root)?;
    Ok(PlayableLevel {
        scene,
        bodies,
        gameplay,
        characters,
        render_areas: level.render_areas.clone(),
    })
}

/// The level's declared `needs` must cover what its content and its rules' material switches
/// use; a level that declares none is told what it uses.
fn check_needs(
    level_path: &Path,
    level: &Level,
    scene: &SceneDesc,
    gameplay: &GameplayPlan,
) -> AssetResult<()> {
    let mut used = Needs::of_scene(scene);
    let switched = gameplay
        .rules
        .iter()
        .flat_map(|rule| rule.then.iter().chain(&rule.otherwise))
        .filter_map(|action| match action {
            Action::Material {
                material: Some(m), ..
            } => Some(*m as usize),
            _ => None,
        });
    used.add_switched_materials(scene, switched);
    match level.needs {
        Some(declared) => {
            let missing = declared.undeclared(&used);
            if !missing.is_empty() {
                return Err(AssetError::Level {
                    path: level_path.to_path_buf(),
                    message: format!(
                        "the level uses {} but its `needs` does not declare {}",
                        missing.join(", "),
                        if missing.len() == 1 { "it" } else { "them" }
                    ),
                });
            }
        }
        None => log::info!(
            "{}: declares no `needs`; its content uses: {used}",
            level_path.display()
        ),
    }
    Ok(())
}
