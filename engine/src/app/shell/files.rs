//! The player's two files as the shell keeps them: settings (`<config>/settings.ron`) and
//! progress (`<data>/progress.ron`), loaded once at start and saved atomically on change.
//!
//! A corrupt or invalid file never stops the game: `persist/stored.rs` gives the defaults, keeps the bad
//! file as `<name>.corrupt` and logs a warning; this keeps each warning as a [`Notice`] that the
//! title menu shows (the file, the problem, where the bad file went) until dismissed. A save
//! that fails is logged and shown the same way; the previous file stays intact.
//! Main thread. Must not: apply settings (the runner does) or decide when to save.

use crate::app::input::ActionSet;
use crate::app::persist::Progress;
use crate::app::persist::Settings;
use crate::app::persist::UserDirs;

/// A problem with one of the player's files, for the title menu.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Notice {
    /// Short: "Settings file replaced by defaults".
    pub title: String,
    /// The whole story (path, problem, the backup's path).
    pub detail: String,
}

/// Settings and progress with where they live.
#[derive(Clone, Debug)]
pub struct PlayerFiles {
    dirs: UserDirs,
    pub settings: Settings,
    pub progress: Progress,
    /// Problems to show, oldest first.
    pub notices: Vec<Notice>,
}

impl PlayerFiles {
    /// Loads both files from `dirs` (defaults and notices for missing or bad ones).
    pub fn load(dirs: UserDirs, set: &ActionSet) -> Self {
        let mut notices = Vec::new();
        let settings = Settings::load(&dirs.settings_file(), set);
        if let Some(w) = settings.warning {
            notices.push(Notice {
                title: "Settings file replaced by defaults".into(),
                detail: w.to_string(),
            });
        }
        let progress = Progress::load(&dirs.progress_file());
        if let Some(w) = progress.warning {
            notices.push(Notice {
                title: "Save file replaced by a new game".into(),
                detail: w.to_string(),
            });
        }
        Self {
            dirs,
            settings: settings.value,
            progress: progress.value,
            notices,
        }
    }

    pub fn dirs(&self) -> &UserDirs {
        &self.dirs
    }

    /// Writes the settings file (atomically); a failure is logged and noticed.
    pub fn save_settings(&mut self, set: &ActionSet) -> bool {
        match self.settings.save(&self.dirs.settings_file(), set) {
            Ok(()) => true,
            Err(e) => {
                log::error!("{e}");
                self.notices.push(Notice {
                    title: "Settings not saved".into(),
                    detail: e.to_string(),
                });
                false
            }
        }
    }

    /// Writes the progress save (atomically); a failure is logged and noticed.
    pub fn save_progress(&mut self) -> bool {
        match self.progress.save(&self.dirs.progress_file()) {
            Ok(()) => true,
            Err(e) => {
                log::error!("{e}");
                self.notices.push(Notice {
                    title: "Progress not saved".into(),
                    detail: e.to_string(),
                });
                false
            }
        }
    }
}
