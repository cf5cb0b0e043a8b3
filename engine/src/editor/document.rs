//! [`Document`]: what the editor edits — a parsed [`Level`] and the comments of the file it
//! came from (see `comments`), opened from a level file's text; for a part of a composed world
//! (a Reflect chamber), also the base file it is composed over (`common.ron`), edited with it
//! as one world ([`Document::base`], `Edit::Base`) and saved to its own file.
//!
//! Main thread. Must not: write files (`save`, `recovery`) or check references (`check`).

use std::path::Path;

use crate::assets::{AssetError, Level};

use super::comment_scan::scan;
use super::comments::Comments;

/// A level being edited, with its file's comments.
#[derive(Clone, Debug, PartialEq)]
pub struct Document {
    pub level: Level,
    pub comments: Comments,
    /// The base file of a composed world, edited with this part (`Edit::Base`); `None` for a
    /// level of one file. Saves write it to its own file (`EditorState::base_path`).
    pub base: Option<Box<Document>>,
}

/// A level file that could not be opened.
#[derive(Debug, thiserror::Error)]
pub enum DocumentError {
    /// Reading or parsing it failed (the error names the file, and the line and column).
    #[error(transparent)]
    Level(#[from] AssetError),
}

impl Document {
    /// A document of `level` without comments (a level made in code).
    pub fn new(level: Level) -> Self {
        Self {
            level,
            comments: Comments::default(),
            base: None,
        }
    }

    /// Parses level `text` (`path` only names the file in errors) and reads its comments.
    pub fn parse(path: &Path, text: &str) -> Result<Self, DocumentError> {
        Ok(Self {
            level: Level::parse(path, text)?,
            comments: scan(text),
            base: None,
        })
    }

    /// Reads and parses the level file at `path`.
    pub fn open(path: &Path) -> Result<Self, DocumentError> {
        let text = std::fs::read_to_string(path).map_err(|e| AssetError::io(path, e))?;
        Self::parse(path, &text)
    }
}
