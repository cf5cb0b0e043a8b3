//! Loading Reflect's world: the game file, then the base level and every chamber's level file
//! merged into one level (`candela::level::load_composed`), so the chambers stand side by side
//! in one world whose light groups switch as the player walks through.
//!
//! Owns: [`ReflectWorld`] (the loaded level, the chambers, what the mirror gun may touch) and
//! [`world_hash`] (what a replay must match). Main thread, at start.
//! Must not: spawn anything (`ReflectGame::setup` does).

use std::path::{Path, PathBuf};

use candela::app::fnv1a64;
use candela::assets::ActionEntry;
use candela::assets::{AssetError, AssetRoot, Level};
use candela::level::{PlayableLevel, load_composed, playable_from_level};

use crate::chambers::{Chamber, GameFile, GameFileError};

/// Why the world did not load.
#[derive(Debug, thiserror::Error)]
pub enum WorldError {
    #[error(transparent)]
    GameFile(#[from] GameFileError),
    #[error(transparent)]
    Asset(#[from] AssetError),
    #[error("{path}: {message}")]
    Invalid { path: PathBuf, message: String },
}

/// The loaded world.
#[derive(Clone, Debug)]
pub struct ReflectWorld {
    /// The game file.
    pub game_path: PathBuf,
    /// The base level file and the chambers' files, in order (for messages and hashes).
    pub files: Vec<PathBuf>,
    pub chambers: Vec<Chamber>,
    /// The merged level as written (names of materials and instances).
    pub level: Level,
    pub playable: PlayableLevel,
    /// Index of the mirror material among the level's materials.
    pub mirror_material: u32,
    /// Instances (by index) the mirror gun may turn into mirrors.
    pub mirrorable: Vec<usize>,
    /// The models (by index in the composed scene's models) whose instances are mirrorable:
    /// how the gun finds its panels after the editor inserted or removed instances.
    pub mirrorable_models: Vec<usize>,
    /// The folder every file of the world stays in (the editor saves through it).
    pub root: AssetRoot,
}

impl ReflectWorld {
    /// Reads `game_path` and loads every level file it names from `root`.
    pub fn load(game_path: &Path, root: &AssetRoot) -> Result<Self, WorldError> {
        let game = GameFile::read(game_path)?;
        let chambers = game.chambers(game_path)?;
        let invalid = |message: String| WorldError::Invalid {
            path: game_path.to_path_buf(),
            message,
        };
        let base = root.resolve(game_path, None, &game.base)?;
        let mut parts = Vec::with_capacity(chambers.len());
        for chamber in &chambers {
            parts.push(root.resolve(game_path, None, &chamber.file)?);
        }
        let (level, playable) = load_composed(&base, &parts, root)?;
        let mirror_material = level
            .materials
            .iter()
            .position(|m| m.name == game.mirror_material)
            .ok_or_else(|| {
                invalid(format!(
                    "mirror_material: no level file defines the material {:?}",
                    game.mirror_material
                ))
            })? as u32;
        for model in &game.mirrorable_models {
            if !level.models.iter().any(|m| &m.name == model)
                && !level.boxes.iter().any(|b| &b.name == model)
            {
                return Err(invalid(format!(
                    "mirrorable_models: no level file defines the model {model:?}"
                )));
            }
        }
        let mirrorable: Vec<usize> = level
            .instances
            .iter()
            .enumerate()
            .filter(|(_, i)| game.mirrorable_models.contains(&i.model))
            .map(|(index, _)| index)
            .collect();
        let mut mirrorable_models: Vec<usize> = mirrorable
            .iter()
            .filter_map(|&i| playable.scene.instances.get(i).map(|s| s.model))
            .collect();
        mirrorable_models.sort_unstable();
        mirrorable_models.dedup();
        let mut files = vec![base];
        files.extend(parts);
        Ok(Self {
            game_path: game_path.to_path_buf(),
            files,
            chambers,
            level,
            playable,
            mirror_material,
            mirrorable,
            mirrorable_models,
            root: root.clone(),
        })
    }

    /// The same world with every light group on for good: no chamber switches lights (the
    /// bench's comparison of how many emitters the light sampling sees).
    pub fn without_room_switching(&self, root: &AssetRoot) -> Result<Self, WorldError> {
        let mut level = self.level.clone();
        level.gameplay.lights_off.clear();
        for rule in &mut level.gameplay.rules {
            rule.then
                .retain(|a| !matches!(a, ActionEntry::Lights { .. }));
            rule.otherwise
                .retain(|a| !matches!(a, ActionEntry::Lights { .. }));
        }
        let playable = playable_from_level(&self.files[0], &level, root)?;
        Ok(Self {
            level,
            playable,
            ..self.clone()
        })
    }

    /// Index of the chamber with id `id`.
    pub fn chamber_index(&self, id: &str) -> Option<usize> {
        self.chambers.iter().position(|c| c.id == id)
    }
}

/// The content hash of the game file and every level file it names, in order: a replay
/// recorded before any of them changed is refused.
pub fn world_hash(world: &ReflectWorld) -> Result<u64, std::io::Error> {
    let mut words = Vec::new();
    for path in std::iter::once(&world.game_path).chain(&world.files) {
        words.extend_from_slice(&fnv1a64(&std::fs::read(path)?).to_le_bytes());
    }
    Ok(fnv1a64(&words))
}
