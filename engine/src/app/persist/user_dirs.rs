//! Where a game keeps the player's files: settings in the config folder, progress saves (and
//! anything else the game accumulates) in the data folder, one pair per game.
//!
//! Follows the XDG base directory rules: `$XDG_CONFIG_HOME/candela/<game>/` (else
//! `$HOME/.config/candela/<game>/`) and `$XDG_DATA_HOME/candela/<game>/` (else
//! `$HOME/.local/share/candela/<game>/`); a relative `XDG_*` value is ignored, as the spec says.
//! Tests and portable installs use [`UserDirs::under`] instead. Main thread. Must not: create
//! the folders (writing does, see `atomic_file`) or read files.

use std::path::{Path, PathBuf};

/// Errors of finding the user's folders.
#[derive(Debug, thiserror::Error)]
pub enum UserDirsError {
    #[error(
        "game name {0:?} cannot name a folder (use letters, digits, '-', '_' or '.', not only dots)"
    )]
    BadGameName(String),
    #[error("neither ${xdg} (absolute) nor $HOME is set: no folder for the player's {what}")]
    NoHome {
        xdg: &'static str,
        what: &'static str,
    },
}

/// The config and data folders of one game.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UserDirs {
    /// Settings live here (`settings.ron`).
    pub config: PathBuf,
    /// Progress saves live here (`progress.ron`).
    pub data: PathBuf,
}

/// Whether `game` is one harmless path component.
fn check_game(game: &str) -> Result<(), UserDirsError> {
    let ok = !game.is_empty()
        && game.len() <= 64
        && !game.chars().all(|c| c == '.')
        && game
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || matches!(c, '-' | '_' | '.'));
    if ok {
        Ok(())
    } else {
        Err(UserDirsError::BadGameName(game.to_string()))
    }
}

fn base(
    xdg: Option<String>,
    home: Option<String>,
    xdg_name: &'static str,
    home_rel: &str,
    what: &'static str,
) -> Result<PathBuf, UserDirsError> {
    if let Some(x) = xdg.filter(|x| Path::new(x).is_absolute()) {
        return Ok(PathBuf::from(x));
    }
    match home.filter(|h| !h.is_empty()) {
        Some(h) => Ok(Path::new(&h).join(home_rel)),
        None => Err(UserDirsError::NoHome {
            xdg: xdg_name,
            what,
        }),
    }
}

impl UserDirs {
    /// The folders of `game` from the environment (`XDG_CONFIG_HOME`, `XDG_DATA_HOME`, `HOME`).
    pub fn from_env(game: &str) -> Result<Self, UserDirsError> {
        let var = |name: &str| std::env::var(name).ok();
        Self::from_vars(
            game,
            var("XDG_CONFIG_HOME"),
            var("XDG_DATA_HOME"),
            var("HOME"),
        )
    }

    /// [`UserDirs::from_env`] with the variables passed in (so tests need not change the
    /// process environment).
    pub fn from_vars(
        game: &str,
        xdg_config_home: Option<String>,
        xdg_data_home: Option<String>,
        home: Option<String>,
    ) -> Result<Self, UserDirsError> {
        check_game(game)?;
        let config = base(
            xdg_config_home,
            home.clone(),
            "XDG_CONFIG_HOME",
            ".config",
            "settings",
        )?;
        let data = base(
            xdg_data_home,
            home,
            "XDG_DATA_HOME",
            ".local/share",
            "saves",
        )?;
        Ok(Self {
            config: config.join("candela").join(game),
            data: data.join("candela").join(game),
        })
    }

    /// Both folders below `root` (`root/config/candela/<game>`, `root/data/candela/<game>`):
    /// the override for tests and portable installs.
    pub fn under(root: &Path, game: &str) -> Result<Self, UserDirsError> {
        check_game(game)?;
        Ok(Self {
            config: root.join("config").join("candela").join(game),
            data: root.join("data").join("candela").join(game),
        })
    }

    /// The settings file (`<config>/settings.ron`).
    pub fn settings_file(&self) -> PathBuf {
        self.config.join("settings.ron")
    }

    /// The progress save (`<data>/progress.ron`).
    pub fn progress_file(&self) -> PathBuf {
        self.data.join("progress.ron")
    }
}
