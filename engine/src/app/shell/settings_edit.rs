//! The settings screen's model, without egui: a draft of the player's [`Settings`] that the
//! widgets change, rebinding (pick an action, then the next key or mouse button pressed
//! becomes its keyboard/mouse binding and the other kind's bindings are kept, the next gamepad
//! button its gamepad binding and the keyboard/mouse ones are kept; Escape cancels), conflicts
//! (one key bound to two actions), and reset to the defaults.
//!
//! The runner applies the draft live whenever it differs from what was applied, and saves it
//! when it changed and no drag is under way. Main thread. Must not: draw, read devices or
//! write files.

use crate::app::input::{ActionKind, ActionSet};
use crate::app::input::{Binding, KeyCode};
use crate::app::persist::Settings;

/// Frame rates the settings screen offers (`None`: unlimited).
pub const FRAME_RATES: [Option<f32>; 6] = [
    Some(30.0),
    Some(60.0),
    Some(90.0),
    Some(120.0),
    Some(144.0),
    None,
];

/// One binding used by several actions.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Conflict {
    pub binding: Binding,
    pub actions: Vec<String>,
}

/// The settings being edited.
#[derive(Clone, Debug)]
pub struct SettingsEditor {
    /// What the widgets show and change.
    pub draft: Settings,
    set: ActionSet,
    /// The action waiting for a key (after "click an action").
    capturing: Option<String>,
}

/// Whether `binding` is a keyboard or mouse button (what rebinding by a press replaces).
fn desk(binding: &Binding) -> bool {
    matches!(binding, Binding::Key(_) | Binding::Mouse(_))
}

impl SettingsEditor {
    /// Edits `settings` of a game with actions `set`.
    pub fn new(settings: Settings, set: ActionSet) -> Self {
        Self {
            draft: settings,
            set,
            capturing: None,
        }
    }

    /// The game's actions.
    pub fn actions(&self) -> &ActionSet {
        &self.set
    }

    /// Button actions, in the set's order: the ones a press can rebind.
    pub fn rebindable(&self) -> Vec<String> {
        self.set
            .defs()
            .iter()
            .filter(|d| d.kind == ActionKind::Button)
            .map(|d| d.name.clone())
            .collect()
    }

    /// The bindings `action` has now (the player's, else the default).
    pub fn bindings_of(&self, action: &str) -> Vec<Binding> {
        self.draft
            .input_map(&self.set)
            .actions
            .get(action)
            .cloned()
            .unwrap_or_default()
    }

    /// Starts waiting for a press for `action` (unknown or non-button actions are ignored).
    pub fn start_rebind(&mut self, action: &str) {
        if self.rebindable().iter().any(|a| a == action) {
            self.capturing = Some(action.to_string());
        }
    }

    /// The action waiting for a press, if any.
    pub fn capturing(&self) -> Option<&str> {
        self.capturing.as_deref()
    }

    /// Offers a pressed key, mouse button or gamepad button. While waiting: Escape cancels; a
    /// key or mouse button replaces the action's keyboard and mouse bindings (its gamepad ones
    /// stay), a gamepad button its gamepad buttons (its keyboard and mouse ones stay); returns
    /// true (the press was used). Not waiting: false.
    pub fn offer(&mut self, pressed: Binding) -> bool {
        let Some(action) = self.capturing.take() else {
            return false;
        };
        let pad = matches!(pressed, Binding::Pad(_));
        if pressed == Binding::Key(KeyCode::Escape) || !(desk(&pressed) || pad) {
            return true;
        }
        // Keep the bindings of the other kind than the press.
        let same_kind = |b: &Binding| {
            if pad {
                matches!(b, Binding::Pad(_))
            } else {
                desk(b)
            }
        };
        let mut bindings: Vec<Binding> = self
            .bindings_of(&action)
            .into_iter()
            .filter(|b| !same_kind(b))
            .collect();
        if pad {
            bindings.push(pressed);
        } else {
            bindings.insert(0, pressed);
        }
        let defaults = self.set.default_map().actions.get(&action).cloned();
        if defaults.as_ref() == Some(&bindings) {
            self.draft.bindings.reset(&action);
        } else {
            self.draft.bindings.rebind(&action, bindings);
        }
        true
    }

    /// Bindings that trigger more than one button action, in binding order of appearance.
    pub fn conflicts(&self) -> Vec<Conflict> {
        let map = self.draft.input_map(&self.set);
        let mut found: Vec<Conflict> = Vec::new();
        for action in self.rebindable() {
            for binding in map.actions.get(&action).into_iter().flatten() {
                match found.iter_mut().find(|c| c.binding == *binding) {
                    Some(c) => c.actions.push(action.clone()),
                    None => found.push(Conflict {
                        binding: *binding,
                        actions: vec![action.clone()],
                    }),
                }
            }
        }
        found.retain(|c| c.actions.len() > 1);
        found
    }

    /// Whether `action` shares a binding with another action.
    pub fn in_conflict(&self, action: &str) -> bool {
        self.conflicts()
            .iter()
            .any(|c| c.actions.iter().any(|a| a == action))
    }

    /// Every setting back to its default, bindings included.
    pub fn reset_all(&mut self) {
        self.draft = Settings::default();
        self.capturing = None;
    }

    /// `action` back to its default bindings.
    pub fn reset_action(&mut self, action: &str) {
        self.draft.bindings.reset(action);
    }
}

/// A binding as the settings screen shows it ("E", "Mouse left", "Pad South").
pub fn binding_label(binding: &Binding) -> String {
    match binding {
        Binding::Key(code) => {
            let name = format!("{code:?}");
            if let Some(letter) = name
                .strip_prefix("Key")
                .or_else(|| name.strip_prefix("Digit"))
            {
                return letter.to_string();
            }
            for (prefix, shown) in [
                ("Arrow", ""),
                ("Shift", "Shift"),
                ("Control", "Ctrl"),
                ("Alt", "Alt"),
            ] {
                if let Some(side) = name.strip_prefix(prefix) {
                    return if shown.is_empty() {
                        side.to_string()
                    } else {
                        format!("{side} {shown}")
                    };
                }
            }
            name
        }
        Binding::Mouse(button) => format!("Mouse {button:?}")
            .to_lowercase()
            .replacen('m', "M", 1),
        Binding::MouseX => "Mouse X".into(),
        Binding::MouseY => "Mouse Y".into(),
        Binding::Wheel => "Wheel".into(),
        Binding::Pad(button) => format!("Pad {button:?}"),
        Binding::PadAxis(axis) => format!("Pad {axis:?}"),
    }
}

/// An action name as the settings screen shows it (`primary_fire` → "Primary fire").
pub fn action_label(name: &str) -> String {
    let spaced = name.replace('_', " ");
    let mut chars = spaced.chars();
    match chars.next() {
        Some(first) => first.to_uppercase().chain(chars).collect(),
        None => String::new(),
    }
}
