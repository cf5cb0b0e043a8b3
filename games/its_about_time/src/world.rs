//! [`RuinsWorld`]: It's About Time's world loaded once — the ruins level
//! (`assets/its_about_time/ruins.ron`, asset root `assets/`) with its bodies, gameplay and the
//! explorer, and the game's actions (the engine's standard set, then Q / R to turn time at a
//! sun altar).
//!
//! Owns: locating and loading the level, [`actions`]. Main thread. Must not: hold game state.

use std::path::{Path, PathBuf};

use anyhow::Context;
use candela::app::{ActionDef, ActionKind, ActionSet, Binding, KeyCode, PadButton};
use candela::assets::AssetRoot;
use candela::level::{PlayableLevel, load_level};

/// The action that turns time backward while held at a sun altar.
pub const TIME_BACK: &str = "time_back";
/// The action that turns time forward while held at a sun altar.
pub const TIME_FORWARD: &str = "time_forward";

/// The level id replays of the whole game carry.
pub const LEVEL_ID: &str = "ruins";

/// The game's actions: the standard set, then `time_back` (Q, LB) and `time_forward` (R, RB).
pub fn actions() -> ActionSet {
    let button = |name: &str, key, pad| ActionDef {
        name: name.into(),
        kind: ActionKind::Button,
        defaults: vec![Binding::Key(key), Binding::Pad(pad)],
    };
    ActionSet::standard()
        .with(button(TIME_BACK, KeyCode::KeyQ, PadButton::LeftTrigger))
        .and_then(|s| s.with(button(TIME_FORWARD, KeyCode::KeyR, PadButton::RightTrigger)))
        .unwrap_or_else(|_| ActionSet::standard())
}

/// The ruins, loaded.
#[derive(Clone, Debug)]
pub struct RuinsWorld {
    /// The level file.
    pub path: PathBuf,
    /// The folder every path of the level stays in (`assets/`).
    pub root: AssetRoot,
    pub level: PlayableLevel,
}

impl RuinsWorld {
    /// Loads the level at `path` (its paths confined to `root`).
    pub fn load(path: &Path, root: &AssetRoot) -> anyhow::Result<Self> {
        let level = load_level(path, root)?;
        anyhow::ensure!(
            !level.characters.is_empty(),
            "{}: the ruins need a character (the explorer) in `characters`",
            path.display()
        );
        Ok(Self {
            path: path.to_path_buf(),
            root: root.clone(),
            level,
        })
    }

    /// The level file `level` (default: `assets/its_about_time/ruins.ron` under the current
    /// folder, else next to the source) and the asset root two folders above it.
    pub fn locate(level: Option<&Path>) -> anyhow::Result<(PathBuf, AssetRoot)> {
        let path = match level {
            Some(p) => p.to_path_buf(),
            None => {
                let here = PathBuf::from("assets/its_about_time/ruins.ron");
                if here.is_file() {
                    here
                } else {
                    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
                        .join("../../assets/its_about_time/ruins.ron")
                }
            }
        };
        let root = path
            .parent()
            .and_then(Path::parent)
            .context("the level must sit in <asset root>/its_about_time/")?;
        let root = if root.as_os_str().is_empty() {
            Path::new(".")
        } else {
            root
        };
        Ok((path.clone(), AssetRoot::new(root)?))
    }

    /// Locates and loads the world.
    pub fn open(level: Option<&Path>) -> anyhow::Result<Self> {
        let (path, root) = Self::locate(level)?;
        Self::load(&path, &root)
    }
}
