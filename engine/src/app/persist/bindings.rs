//! The player's rebinding of actions: action name → the bindings that replace its defaults.
//! Kept in the settings file (`bindings: {"jump": [Key(KeyJ), Pad(South)]}`) or a bindings
//! file of its own (the same map as the whole file); only rebound actions are written, so a
//! game that adds an action or changes a default reaches players who never touched it.
//!
//! RON names: `Key(<winit KeyCode>)` (physical position: `KeyW`, `Space`, `ShiftLeft`, `F1`),
//! `Mouse(Left|Right|Middle|Back|Forward)`, `MouseX`, `MouseY`, `Wheel`, `Pad(<PadButton>)`,
//! `PadAxis(<PadAxis>)`. An action may be bound to nothing (`[]`).
//!
//! Owns: checking bindings against an [`ActionSet`] (unknown action, a binding of the wrong
//! kind) and merging them over the defaults into an [`InputMap`]. Main thread. Must not: hold
//! input state or read devices.

use std::collections::BTreeMap;
use std::fmt;
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use super::stored::parse_checked;
use crate::app::input::ActionSet;
use crate::app::input::{Binding, InputMap};

/// Action name → the bindings that replace its defaults.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(transparent)]
pub struct Bindings(pub BTreeMap<String, Vec<Binding>>);

/// What is wrong with bindings (the file is named by [`BindingsError`] or the settings loader).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum BindingProblem {
    /// No action of this name in the game.
    UnknownAction(String),
    /// The binding cannot drive the action (a key for a stick axis, the mouse X for a button).
    WrongKind {
        action: String,
        kind: &'static str,
        binding: Binding,
    },
}

impl fmt::Display for BindingProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BindingProblem::UnknownAction(name) => write!(f, "unknown action `{name}`"),
            BindingProblem::WrongKind {
                action,
                kind,
                binding,
            } => write!(
                f,
                "action `{action}` takes {kind} input; {binding:?} cannot drive it"
            ),
        }
    }
}

/// Errors of reading a bindings file, each naming it.
#[derive(Debug, thiserror::Error)]
pub enum BindingsError {
    #[error("{path}: cannot read: {source}")]
    Read {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
    /// Bad RON or an unknown key/button name (`line L, column C: unknown key name `KeyQQ``).
    #[error("{path}: {message}")]
    Parse { path: PathBuf, message: String },
    #[error("{path}: {problem}")]
    Invalid {
        path: PathBuf,
        problem: BindingProblem,
    },
}

impl Bindings {
    /// The first problem of these bindings against `set`, if any.
    pub fn check(&self, set: &ActionSet) -> Result<(), BindingProblem> {
        for (action, bindings) in &self.0 {
            let def = set
                .id(action)
                .and_then(|id| set.def(id))
                .ok_or_else(|| BindingProblem::UnknownAction(action.clone()))?;
            if let Some(b) = bindings.iter().find(|b| !def.kind.accepts(b)) {
                return Err(BindingProblem::WrongKind {
                    action: action.clone(),
                    kind: def.kind.name(),
                    binding: *b,
                });
            }
        }
        Ok(())
    }

    /// Parses and checks a bindings map; `path` names the file in errors.
    pub fn parse(path: &Path, text: &str, set: &ActionSet) -> Result<Self, BindingsError> {
        let mut problem = None;
        let parsed = parse_checked::<Bindings>(text, |b| {
            b.check(set).map_err(|p| {
                let line = p.to_string();
                problem = Some(p);
                line
            })
        });
        match (parsed, problem) {
            (Ok(b), _) => Ok(b),
            (Err(_), Some(problem)) => Err(BindingsError::Invalid {
                path: path.to_path_buf(),
                problem,
            }),
            (Err(message), None) => Err(BindingsError::Parse {
                path: path.to_path_buf(),
                message,
            }),
        }
    }

    /// Reads and checks a bindings file.
    pub fn load(path: &Path, set: &ActionSet) -> Result<Self, BindingsError> {
        let text = std::fs::read_to_string(path).map_err(|source| BindingsError::Read {
            path: path.to_path_buf(),
            source,
        })?;
        Self::parse(path, &text, set)
    }

    /// Binds `action` to `bindings` instead of its defaults.
    pub fn rebind(&mut self, action: &str, bindings: Vec<Binding>) {
        self.0.insert(action.to_string(), bindings);
    }

    /// Back to the default for `action`.
    pub fn reset(&mut self, action: &str) {
        self.0.remove(action);
    }

    /// `set`'s defaults with these bindings in place of them (actions not in `set` are left
    /// out: [`Bindings::check`] reports them).
    pub fn input_map(&self, set: &ActionSet) -> InputMap {
        let mut map = set.default_map();
        for (action, bindings) in &self.0 {
            if let Some(slot) = map.actions.get_mut(action) {
                slot.clone_from(bindings);
            }
        }
        map
    }
}
