//! [`EditTarget`]: what a game or tool hands the editor when F1 opens it — the level file to
//! edit and save, the asset root its paths stay in, where the file's instances sit among the
//! world's, and how to build the world to play from the edited file; and [`EditHooks`], the
//! editor's hooks a game offers through `Game::editor`.
//!
//! Both live in the runner, not in `app::edit`, because the first-person game (`app::play`, a
//! layer below the editor) implements them; `app::edit` re-exports them. Main thread.
//! Must not: spawn anything (`EditWorld` does).

use std::path::{Path, PathBuf};
use std::rc::Rc;

use super::engine::Engine;
use super::spawned::SpawnedLevel;
use crate::assets::{AssetResult, AssetRoot, Level};
use crate::editor::{ItemRef, Problem, check_level};
use crate::level::{PlayableLevel, compose_levels, playable_from_level};

/// Builds the playable world from the edited level file and, in a composed world, the edited
/// base file (a single file: the file itself; a composed world: the other parts merged with
/// it over the base; `None` for the base: the base as read when the target was made).
pub type BuildWorld = Rc<dyn Fn(&Level, Option<&Level>) -> AssetResult<PlayableLevel>>;

/// The problems that stop a save of the edited file (and base), when the file alone is not a
/// level (a part of a composed world checks merged with the others over the base).
pub type CheckWorld = Rc<dyn Fn(&Level, Option<&Level>) -> Vec<Problem>>;

/// What the editor (F1, `app::edit`) asks of a game that offers a level to edit.
pub trait EditHooks {
    /// The level file the editor edits and what of the world is spawned now. `None`: F1
    /// shows no editor.
    fn edit_target(&self) -> Option<(EditTarget, SpawnedLevel)>;

    /// The level was spawned again from the edited file (opening the editor, a structural
    /// edit); `spawned` replaces the game's handles of the level's entities.
    fn level_respawned(&mut self, _engine: &mut Engine, _spawned: &SpawnedLevel) {}

    /// "Play from here": the editor was left with its camera's eye at `eye` (world metres)
    /// looking along `forward`; the game starts there (a first-person game stands its player
    /// on the floor below `eye`). By default the game plays on from where it was.
    fn play_from(&mut self, _engine: &mut Engine, _eye: glam::Vec3, _forward: glam::Vec3) {}
}

/// The level the editor edits in a running game.
#[derive(Clone)]
pub struct EditTarget {
    /// The level file the editor opens and saves.
    pub path: PathBuf,
    /// The folder every path of the level stays in (saves run the engine's full check in it).
    pub root: AssetRoot,
    /// Where the file's instances start among the world's level instances
    /// (`SpawnedLevel::entities`): 0 for a level of one file; in a composed world, after the
    /// base's and the earlier parts' instances.
    pub first_instance: usize,
    /// The world to play from the edited file.
    pub build: BuildWorld,
    /// How a save is checked: `None`, the file on its own (`editor::save_document`).
    pub check: Option<CheckWorld>,
    /// The base file of a composed world (Reflect's `common.ron`): the editor opens it with
    /// the part and edits them as one world (its models and materials offered and its
    /// materials edited; a save writes its changes to it). `None` for a level of one file.
    pub base_path: Option<PathBuf>,
}

impl std::fmt::Debug for EditTarget {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("EditTarget")
            .field("path", &self.path)
            .field("root", &self.root)
            .field("first_instance", &self.first_instance)
            .finish_non_exhaustive()
    }
}

impl EditTarget {
    /// A level of one file: the world is the file.
    pub fn single_file(path: &Path, root: AssetRoot) -> Self {
        let level_path = path.to_path_buf();
        let build_root = root.clone();
        Self {
            path: path.to_path_buf(),
            root,
            first_instance: 0,
            build: Rc::new(move |level: &Level, _: Option<&Level>| {
                playable_from_level(&level_path, level, &build_root)
            }),
            check: None,
            base_path: None,
        }
    }

    /// Part `index` of the world composed from `base_path` and `part_paths`
    /// (`level::compose_levels`). The other files are read now; the world and the save's
    /// check merge them with the edited part. A problem names an instance of the part when
    /// it is one.
    pub fn composed_part(
        base_path: &Path,
        part_paths: &[PathBuf],
        index: usize,
        root: AssetRoot,
    ) -> AssetResult<Self> {
        let base = Level::read(base_path)?;
        let mut parts = Vec::with_capacity(part_paths.len());
        for path in part_paths {
            parts.push((path.clone(), Level::read(path)?));
        }
        let Some((path, _)) = parts.get(index).cloned() else {
            return Err(crate::assets::AssetError::Level {
                path: base_path.to_path_buf(),
                message: format!("no part {index} among {} parts", parts.len()),
            });
        };
        let first_instance = base.instances.len()
            + parts[..index]
                .iter()
                .map(|(_, l)| l.instances.len())
                .sum::<usize>();
        let merged = Rc::new((base_path.to_path_buf(), base, parts));
        let with_part = {
            let merged = Rc::clone(&merged);
            move |level: &Level, edited_base: Option<&Level>| {
                let (_, base, parts) = &*merged;
                let mut parts = parts.clone();
                parts[index].1 = level.clone();
                compose_levels(edited_base.unwrap_or(base), &parts)
            }
        };
        let with_part = Rc::new(with_part);
        let build_root = root.clone();
        let build = {
            let with_part = Rc::clone(&with_part);
            let base_path = base_path.to_path_buf();
            Rc::new(move |level: &Level, base: Option<&Level>| {
                playable_from_level(&base_path, &with_part(level, base)?, &build_root)
            })
        };
        let check_root = root.clone();
        let check_path = path.clone();
        let check = Rc::new(move |level: &Level, base: Option<&Level>| {
            let n = level.instances.len();
            match with_part(level, base) {
                Err(e) => vec![Problem::of_level(e.to_string())],
                Ok(world) => check_level(&check_path, &world, Some(&check_root))
                    .into_iter()
                    .map(|mut p| {
                        p.item = match p.item {
                            ItemRef::Instance(i)
                                if i >= first_instance && i < first_instance + n =>
                            {
                                ItemRef::Instance(i - first_instance)
                            }
                            _ => ItemRef::Level,
                        };
                        p
                    })
                    .collect(),
            }
        });
        Ok(Self {
            path,
            root,
            first_instance,
            build,
            check: Some(check),
            base_path: Some(base_path.to_path_buf()),
        })
    }
}
