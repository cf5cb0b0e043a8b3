//! Scripted shell input for tests and demos: a list of [`Cue`]s, each run a number of frames
//! after the previous one — a menu choice or action ([`ShellInput`]), a change to the settings
//! draft as the settings screen's widgets would make it, a change to the level editor's state
//! (a selection, snapping) as its panels would make it, a step of the test's own (sending the
//! window X input, reading where a gizmo handle is drawn), or a screenshot of the window (menus
//! and HUD included).
//!
//! Data; the runner plays them. Main thread. Must not: reach the engine or the window.

use std::path::PathBuf;

use super::settings_edit::SettingsEditor;
use super::state::ShellInput;
use crate::app::edit::EditMode;

/// What a cue does.
pub enum CueAction {
    /// As if the player chose this in a menu or pressed the action.
    Input(ShellInput),
    /// Changes the settings draft (applied and saved as a widget's change is).
    Edit(Box<dyn FnMut(&mut SettingsEditor) + Send>),
    /// Writes what the window shows this frame to this PNG (windowed runs only).
    Screenshot(PathBuf),
    /// Changes the level editor's state (a selection, snapping, the current palette piece; not
    /// the document) or reads it (the camera, where the gizmo is drawn) while the editor is open
    /// (windowed runs with an editor only; dropped otherwise).
    Editor(EditorCue),
    /// Runs a step of the caller's own at this frame, on the main thread (a window test sends
    /// its X input here, so that the input lands between known frames).
    Call(Box<dyn FnMut() + Send>),
}

/// A change to the level editor's state, or a look at it, for [`CueAction::Editor`].
pub type EditorCue = Box<dyn FnMut(&mut EditMode) + Send>;

impl std::fmt::Debug for CueAction {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            CueAction::Input(i) => write!(f, "Input({i:?})"),
            CueAction::Edit(_) => write!(f, "Edit(..)"),
            CueAction::Screenshot(p) => write!(f, "Screenshot({})", p.display()),
            CueAction::Editor(_) => write!(f, "Editor(..)"),
            CueAction::Call(_) => write!(f, "Call(..)"),
        }
    }
}

/// One scripted step.
#[derive(Debug)]
pub struct Cue {
    /// Frames to wait after the previous cue (0: the same frame).
    pub wait_frames: u32,
    pub action: CueAction,
}

impl Cue {
    pub fn input(wait_frames: u32, input: ShellInput) -> Self {
        Self {
            wait_frames,
            action: CueAction::Input(input),
        }
    }

    pub fn edit(wait_frames: u32, edit: impl FnMut(&mut SettingsEditor) + Send + 'static) -> Self {
        Self {
            wait_frames,
            action: CueAction::Edit(Box::new(edit)),
        }
    }

    pub fn editor(wait_frames: u32, cue: impl FnMut(&mut EditMode) + Send + 'static) -> Self {
        Self {
            wait_frames,
            action: CueAction::Editor(Box::new(cue)),
        }
    }

    pub fn call(wait_frames: u32, step: impl FnMut() + Send + 'static) -> Self {
        Self {
            wait_frames,
            action: CueAction::Call(Box::new(step)),
        }
    }

    pub fn screenshot(wait_frames: u32, path: impl Into<PathBuf>) -> Self {
        Self {
            wait_frames,
            action: CueAction::Screenshot(path.into()),
        }
    }
}
