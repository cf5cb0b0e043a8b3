//! Reading and writing the player's RON files (settings, progress) so that nothing the player
//! has can crash the game: a missing file gives defaults; an unreadable, corrupt or invalid one
//! gives defaults *and* a [`LoadWarning`] naming the file and the problem, with the bad file
//! kept aside (`<name>.corrupt`) rather than overwritten by the next save. Writes are atomic.
//!
//! Also: [`describe_ron_error`], one short line for a RON error (line, column, what was wrong;
//! an unknown key or button name is named without listing the hundreds it could have been).
//! Main thread. Must not: know what the files hold (callers pass the type and its check).

use std::fmt;
use std::path::{Path, PathBuf};

use serde::Serialize;
use serde::de::DeserializeOwned;

use crate::assets::atomic_file::{AtomicFileError, keep_aside, write_atomic};

/// A value read from a player's file, and what went wrong if it could not be used.
#[derive(Clone, Debug, PartialEq)]
pub struct Loaded<T> {
    /// The file's content, or the defaults.
    pub value: T,
    /// Set when the file existed but could not be used (the defaults are in `value`).
    pub warning: Option<LoadWarning>,
}

/// A player's file that could not be used: reported, kept aside, replaced by defaults.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LoadWarning {
    pub path: PathBuf,
    /// What was wrong, for example `line 3, column 12: expected a number`.
    pub problem: String,
    /// Where the bad file now is (`None` if it could not be moved; see `aside_error`).
    pub kept_aside: Option<PathBuf>,
    /// Why the bad file could not be moved aside, if it could not.
    pub aside_error: Option<String>,
}

impl fmt::Display for LoadWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}: {}; using defaults",
            self.path.display(),
            self.problem
        )?;
        if let Some(aside) = &self.kept_aside {
            write!(f, " (the file is kept as {})", aside.display())?;
        }
        if let Some(e) = &self.aside_error {
            write!(f, " (and it could not be moved aside: {e})")?;
        }
        Ok(())
    }
}

/// A player's file that could not be saved; the previous file is intact.
#[derive(Debug, thiserror::Error)]
pub enum StoreError {
    #[error("{path}: cannot serialise: {message}")]
    Serialise { path: PathBuf, message: String },
    /// The value would not load again (an out-of-range setting, an unknown action).
    #[error("{path}: not saved: {problem}")]
    Invalid { path: PathBuf, problem: String },
    #[error(transparent)]
    Write(#[from] AtomicFileError),
}

/// How many alternatives an error may list before they are left out (a key has ~190).
const MAX_LISTED: usize = 12;

/// Human names for the enums whose unknown variants players type.
fn kind_of(outer: Option<&str>) -> &'static str {
    match outer {
        Some("KeyCode") => "key name",
        Some("MouseButton") => "mouse button",
        Some("PadButton") => "gamepad button",
        Some("PadAxis") => "gamepad axis",
        Some("Binding") => "binding kind",
        _ => "name",
    }
}

/// One line for a RON error: `line L, column C: …`.
pub fn describe_ron_error(e: &ron::error::SpannedError) -> String {
    use ron::Error;
    let what = match &e.code {
        Error::NoSuchEnumVariant {
            expected,
            found,
            outer,
        } if expected.len() > MAX_LISTED => {
            format!("unknown {} `{found}`", kind_of(outer.as_deref()))
        }
        Error::NoSuchEnumVariant {
            expected,
            found,
            outer,
        } => format!(
            "unknown {} `{found}` (expected one of {})",
            kind_of(outer.as_deref()),
            expected.join(", ")
        ),
        Error::NoSuchStructField {
            expected,
            found,
            outer,
        } => format!(
            "unknown field `{found}`{} (expected one of {})",
            outer
                .as_deref()
                .map(|o| format!(" in `{o}`"))
                .unwrap_or_default(),
            expected.join(", ")
        ),
        other => other.to_string(),
    };
    format!(
        "line {}, column {}: {what}",
        e.span.start.line, e.span.start.col
    )
}

/// The RON options every player file is read and written with (`Some(x)` may be written `x`).
fn options() -> ron::Options {
    ron::Options::default().with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME)
}

/// Parses `text` as `T`, then runs `check`; errors are one line (no file name: callers add it).
pub fn parse_checked<T: DeserializeOwned>(
    text: &str,
    check: impl FnOnce(&T) -> Result<(), String>,
) -> Result<T, String> {
    let value: T = options()
        .from_str(text)
        .map_err(|e| describe_ron_error(&e))?;
    check(&value)?;
    Ok(value)
}

/// Reads `path` as RON: missing → `T::default()` silently; unreadable, corrupt, or rejected
/// by `check` → `T::default()` with a warning (logged too) and the file kept aside.
pub fn load_or_default<T: DeserializeOwned + Default>(
    path: &Path,
    check: impl FnOnce(&T) -> Result<(), String>,
) -> Loaded<T> {
    let bytes = match std::fs::read(path) {
        Ok(b) => b,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            return Loaded {
                value: T::default(),
                warning: None,
            };
        }
        Err(e) => {
            // Unreadable (permissions, a folder in its place): not provably corrupt, left alone.
            let warning = LoadWarning {
                path: path.to_path_buf(),
                problem: format!("cannot read: {e}"),
                kept_aside: None,
                aside_error: None,
            };
            log::warn!("{warning}");
            return Loaded {
                value: T::default(),
                warning: Some(warning),
            };
        }
    };
    let parsed = String::from_utf8(bytes)
        .map_err(|e| format!("not UTF-8 text ({e})"))
        .and_then(|text| parse_checked(&text, check));
    match parsed {
        Ok(value) => Loaded {
            value,
            warning: None,
        },
        Err(problem) => {
            let (kept_aside, aside_error) = match keep_aside(path) {
                Ok(p) => (Some(p), None),
                Err(e) => (None, Some(e.source.to_string())),
            };
            let warning = LoadWarning {
                path: path.to_path_buf(),
                problem,
                kept_aside,
                aside_error,
            };
            log::warn!("{warning}");
            Loaded {
                value: T::default(),
                warning: Some(warning),
            }
        }
    }
}

/// `value` as pretty RON (what [`load_or_default`] reads back).
pub fn to_ron<T: Serialize>(path: &Path, value: &T) -> Result<String, StoreError> {
    let pretty =
        ron::ser::PrettyConfig::default().extensions(ron::extensions::Extensions::IMPLICIT_SOME);
    options()
        .to_string_pretty(value, pretty)
        .map_err(|e| StoreError::Serialise {
            path: path.to_path_buf(),
            message: e.to_string(),
        })
}

/// Writes `value` to `path` as pretty RON, atomically.
pub fn save_ron<T: Serialize>(path: &Path, value: &T) -> Result<(), StoreError> {
    let text = to_ron(path, value)?;
    write_atomic(path, text.as_bytes())?;
    Ok(())
}
