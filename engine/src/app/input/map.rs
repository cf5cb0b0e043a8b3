//! Input mapped to named actions: an [`InputMap`] (data, not code: games configure it in RON)
//! and the [`InputState`] the window runner feeds from window events and games read.
//!
//! Owns: bindings (keyboard keys by physical position, mouse buttons, mouse motion, the wheel,
//! gamepad buttons and stick axes) and per-action state: held, pressed since the last fixed
//! step, pressed this frame, motion accumulated this frame and since the last fixed step, and
//! the current value of analog axes. Main thread. Must not: know winit's event types (the runner
//! translates them, so tests and scripted input drive this directly) or any game's rules.

use std::collections::{BTreeMap, HashMap, HashSet};
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};
pub use winit::event::MouseButton;
pub use winit::keyboard::KeyCode;

use super::pad::{PadAxis, PadButton};

/// One physical input that can trigger an action.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Binding {
    /// A key by its physical position (`KeyW` is W on QWERTY, Z on AZERTY).
    Key(KeyCode),
    Mouse(MouseButton),
    /// Horizontal mouse motion, raw device counts, positive to the right.
    MouseX,
    /// Vertical mouse motion, raw device counts, positive downward.
    MouseY,
    /// Mouse wheel, lines, positive away from the user.
    Wheel,
    /// A gamepad button (any connected gamepad).
    Pad(PadButton),
    /// A gamepad stick axis, [−1, 1] after the dead zone (any connected gamepad).
    PadAxis(PadAxis),
}

/// Errors of reading an input map, naming the file.
#[derive(Debug, thiserror::Error)]
pub enum InputMapError {
    #[error("{path}: {message}")]
    Read { path: PathBuf, message: String },
    #[error("input map: {0}")]
    Parse(String),
}

/// Action names → the bindings that trigger them (any one of them). RON, for example
/// `(actions: {"forward": [Key(KeyW), Key(ArrowUp)], "look_x": [MouseX]})`.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct InputMap {
    pub actions: BTreeMap<String, Vec<Binding>>,
}

/// Action names the window runner itself reacts to.
pub mod actions {
    /// Show or hide the stats overlay (F3).
    pub const TOGGLE_STATS: &str = "toggle_stats";
    /// Show or hide the profiler view (F5): per-phase and per-system scopes of recent frames.
    pub const TOGGLE_PROFILER: &str = "toggle_profiler";
    /// Switch between windowed and borderless fullscreen (F11).
    pub const TOGGLE_FULLSCREEN: &str = "toggle_fullscreen";
    /// Switch vsync on and off (F4).
    pub const TOGGLE_VSYNC: &str = "toggle_vsync";
    /// Capture the mouse for looking around (left click in the window).
    pub const CAPTURE_MOUSE: &str = "capture_mouse";
    /// Release the captured mouse; with the mouse free, leave (Escape).
    pub const RELEASE_MOUSE: &str = "release_mouse";
}

impl InputMap {
    /// The runner's own keys under the shell: stats overlay (F3), profiler (F5), vsync (F4), fullscreen
    /// (F11). Pausing and the mouse are the game's `pause` action (Escape, Start).
    pub fn runner_keys() -> Self {
        use Binding::Key;
        let entries = [
            (actions::TOGGLE_STATS, vec![Key(KeyCode::F3)]),
            (actions::TOGGLE_PROFILER, vec![Key(KeyCode::F5)]),
            (actions::TOGGLE_FULLSCREEN, vec![Key(KeyCode::F11)]),
            (actions::TOGGLE_VSYNC, vec![Key(KeyCode::F4)]),
        ];
        Self {
            actions: entries
                .into_iter()
                .map(|(name, bindings)| (name.to_string(), bindings))
                .collect(),
        }
    }

    /// The runner's own actions and the fly camera's (WASD + QE, shift to go faster, mouse
    /// look).
    pub fn fly_camera_defaults() -> Self {
        use super::fly_actions as fly;
        use Binding::*;
        let entries: [(&str, Vec<Binding>); 15] = [
            (actions::TOGGLE_STATS, vec![Key(KeyCode::F3)]),
            (actions::TOGGLE_PROFILER, vec![Key(KeyCode::F5)]),
            (actions::TOGGLE_FULLSCREEN, vec![Key(KeyCode::F11)]),
            (actions::TOGGLE_VSYNC, vec![Key(KeyCode::F4)]),
            (actions::CAPTURE_MOUSE, vec![Mouse(MouseButton::Left)]),
            (actions::RELEASE_MOUSE, vec![Key(KeyCode::Escape)]),
            (
                fly::FORWARD,
                vec![Key(KeyCode::KeyW), Key(KeyCode::ArrowUp)],
            ),
            (fly::BACK, vec![Key(KeyCode::KeyS), Key(KeyCode::ArrowDown)]),
            (fly::LEFT, vec![Key(KeyCode::KeyA), Key(KeyCode::ArrowLeft)]),
            (
                fly::RIGHT,
                vec![Key(KeyCode::KeyD), Key(KeyCode::ArrowRight)],
            ),
            (fly::UP, vec![Key(KeyCode::KeyE), Key(KeyCode::Space)]),
            (
                fly::DOWN,
                vec![Key(KeyCode::KeyQ), Key(KeyCode::ControlLeft)],
            ),
            (
                fly::FAST,
                vec![Key(KeyCode::ShiftLeft), Key(KeyCode::ShiftRight)],
            ),
            (fly::LOOK_X, vec![MouseX]),
            (fly::LOOK_Y, vec![MouseY]),
        ];
        Self {
            actions: entries
                .into_iter()
                .map(|(name, bindings)| (name.to_string(), bindings))
                .collect(),
        }
    }

    /// Parses a map from RON.
    pub fn from_ron(text: &str) -> Result<Self, InputMapError> {
        ron::from_str(text).map_err(|e| InputMapError::Parse(e.to_string()))
    }

    /// The map as pretty RON (what [`InputMap::from_ron`] reads back).
    pub fn to_ron(&self) -> String {
        ron::ser::to_string_pretty(self, ron::ser::PrettyConfig::default())
            .unwrap_or_else(|e| format!("// cannot write the input map: {e}"))
    }

    /// Reads a map from a RON file.
    pub fn load(path: &Path) -> Result<Self, InputMapError> {
        let text = std::fs::read_to_string(path).map_err(|e| InputMapError::Read {
            path: path.to_path_buf(),
            message: e.to_string(),
        })?;
        Self::from_ron(&text).map_err(|e| InputMapError::Read {
            path: path.to_path_buf(),
            message: e.to_string(),
        })
    }

    /// Adds `other`'s bindings; an action both maps name takes `other`'s bindings.
    pub fn merged(mut self, other: InputMap) -> Self {
        self.actions.extend(other.actions);
        self
    }
}

/// The state of every action, fed by the runner, read by games and systems.
#[derive(Clone, Debug, Default)]
pub struct InputState {
    /// Binding → the actions it triggers.
    index: HashMap<Binding, Vec<String>>,
    held_bindings: HashSet<Binding>,
    held: HashMap<String, u32>,
    pressed_step: HashSet<String>,
    pressed_frame: HashSet<String>,
    motion: HashMap<String, f32>,
    motion_step: HashMap<String, f32>,
    /// Action → its analog bindings, and each analog binding's current value.
    action_axes: HashMap<String, Vec<Binding>>,
    axis_values: HashMap<Binding, f32>,
}

impl InputState {
    pub fn new(map: &InputMap) -> Self {
        let mut index: HashMap<Binding, Vec<String>> = HashMap::new();
        let mut action_axes: HashMap<String, Vec<Binding>> = HashMap::new();
        for (action, bindings) in &map.actions {
            for binding in bindings {
                index.entry(*binding).or_default().push(action.clone());
                if matches!(binding, Binding::PadAxis(_)) {
                    action_axes
                        .entry(action.clone())
                        .or_default()
                        .push(*binding);
                }
            }
        }
        Self {
            index,
            action_axes,
            ..Default::default()
        }
    }

    fn button(&mut self, binding: Binding, down: bool) {
        let changed = if down {
            self.held_bindings.insert(binding)
        } else {
            self.held_bindings.remove(&binding)
        };
        if !changed {
            return; // key repeat, or a release we never saw pressed
        }
        for action in self.index.get(&binding).into_iter().flatten() {
            let count = self.held.entry(action.clone()).or_insert(0);
            if down {
                *count += 1;
                self.pressed_step.insert(action.clone());
                self.pressed_frame.insert(action.clone());
            } else {
                *count = count.saturating_sub(1);
            }
        }
    }

    fn add_motion(&mut self, binding: Binding, amount: f32) {
        for action in self.index.get(&binding).into_iter().flatten() {
            *self.motion.entry(action.clone()).or_insert(0.0) += amount;
            *self.motion_step.entry(action.clone()).or_insert(0.0) += amount;
        }
    }

    /// A key went down or up (repeats while held are ignored).
    pub fn key(&mut self, code: KeyCode, down: bool) {
        self.button(Binding::Key(code), down);
    }

    /// A mouse button went down or up.
    pub fn mouse_button(&mut self, button: MouseButton, down: bool) {
        self.button(Binding::Mouse(button), down);
    }

    /// Raw mouse motion in device counts (right and down positive).
    pub fn mouse_motion(&mut self, dx: f32, dy: f32) {
        self.add_motion(Binding::MouseX, dx);
        self.add_motion(Binding::MouseY, dy);
    }

    /// Wheel motion in lines (away from the user positive).
    pub fn wheel(&mut self, lines: f32) {
        self.add_motion(Binding::Wheel, lines);
    }

    /// A gamepad button went down or up.
    pub fn pad_button(&mut self, button: PadButton, down: bool) {
        self.button(Binding::Pad(button), down);
    }

    /// A gamepad axis now reads `value` ([−1, 1], dead zone already applied; a value that is
    /// not finite reads as 0).
    pub fn pad_axis(&mut self, axis: PadAxis, value: f32) {
        let value = if value.is_finite() {
            value.clamp(-1.0, 1.0)
        } else {
            0.0
        };
        self.axis_values.insert(Binding::PadAxis(axis), value);
    }

    /// Lets go of everything (the window lost focus: its key releases will not arrive).
    pub fn release_all(&mut self) {
        self.held_bindings.clear();
        self.held.clear();
    }

    /// Whether any binding of `action` is down.
    pub fn held(&self, action: &str) -> bool {
        self.held.get(action).is_some_and(|&n| n > 0)
    }

    /// Whether `action` went down since the last fixed step ended (for game rules).
    pub fn pressed(&self, action: &str) -> bool {
        self.pressed_step.contains(action)
    }

    /// Whether `action` went down during this frame (for per-frame code: cameras, the runner).
    pub fn pressed_this_frame(&self, action: &str) -> bool {
        self.pressed_frame.contains(action)
    }

    /// 1 while `positive` is held, −1 while `negative` is, 0 for both or neither.
    pub fn axis(&self, positive: &str, negative: &str) -> f32 {
        self.held(positive) as i32 as f32 - self.held(negative) as i32 as f32
    }

    /// Motion bound to `action` accumulated this frame (mouse counts, wheel lines).
    pub fn motion(&self, action: &str) -> f32 {
        self.motion.get(action).copied().unwrap_or(0.0)
    }

    /// Motion bound to `action` accumulated since the last fixed step ended (for game rules
    /// and recordings: every count reaches exactly one step, whatever the frame rate).
    pub fn motion_since_step(&self, action: &str) -> f32 {
        self.motion_step.get(action).copied().unwrap_or(0.0)
    }

    /// The value of `action`'s analog bindings now: their sum, clamped to [−1, 1] (0 unbound).
    pub fn analog(&self, action: &str) -> f32 {
        let sum: f32 = self
            .action_axes
            .get(action)
            .into_iter()
            .flatten()
            .map(|b| self.axis_values.get(b).copied().unwrap_or(0.0))
            .sum();
        sum.clamp(-1.0, 1.0)
    }

    /// Ends a fixed step: presses and step motion are now old news for game rules.
    pub fn end_step(&mut self) {
        self.pressed_step.clear();
        self.motion_step.clear();
    }

    /// Ends a frame: per-frame presses and motion start again from zero.
    pub fn end_frame(&mut self) {
        self.pressed_frame.clear();
        self.motion.clear();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_map_round_trips_through_ron() {
        let map = InputMap::fly_camera_defaults();
        let text = map.to_ron();
        assert!(text.contains("KeyW"), "{text}");
        assert_eq!(InputMap::from_ron(&text).expect("parses"), map);
        let custom = InputMap::from_ron(r#"(actions: {"jump": [Key(Space), Mouse(Right)]})"#)
            .expect("hand-written RON parses");
        assert_eq!(
            custom.actions["jump"],
            vec![
                Binding::Key(KeyCode::Space),
                Binding::Mouse(MouseButton::Right)
            ]
        );
        assert!(InputMap::from_ron("(actions: {\"jump\": [Key(NoSuchKey)]})").is_err());
    }

    #[test]
    fn held_pressed_and_motion_follow_their_bindings() {
        let map = InputMap::from_ron(
            r#"(actions: {"forward": [Key(KeyW), Key(ArrowUp)], "back": [Key(KeyS)],
                "fire": [Mouse(Left)], "look_x": [MouseX], "zoom": [Wheel]})"#,
        )
        .expect("map");
        let mut input = InputState::new(&map);
        input.key(KeyCode::KeyW, true);
        input.key(KeyCode::KeyW, true); // repeat: not a second press
        input.key(KeyCode::ArrowUp, true);
        assert!(input.held("forward") && input.pressed("forward"));
        assert_eq!(input.axis("forward", "back"), 1.0);
        input.end_step();
        assert!(!input.pressed("forward") && input.pressed_this_frame("forward"));
        input.key(KeyCode::KeyW, false);
        assert!(input.held("forward"), "the arrow key still holds it");
        input.key(KeyCode::ArrowUp, false);
        assert!(!input.held("forward"));
        input.key(KeyCode::KeyS, true);
        assert_eq!(input.axis("forward", "back"), -1.0);

        input.mouse_button(MouseButton::Left, true);
        assert!(input.pressed("fire"));
        input.mouse_motion(3.0, 1.0);
        input.mouse_motion(-1.0, 0.0);
        input.wheel(2.0);
        assert_eq!(input.motion("look_x"), 2.0);
        assert_eq!(input.motion("zoom"), 2.0);
        input.end_frame();
        assert_eq!(input.motion("look_x"), 0.0);
        assert!(!input.pressed_this_frame("fire") && input.held("fire"));
        assert_eq!(
            input.motion_since_step("look_x"),
            2.0,
            "frames do not end steps"
        );
        input.end_step();
        assert_eq!(input.motion_since_step("look_x"), 0.0);
        input.release_all();
        assert!(!input.held("fire") && !input.held("back"));
        // Unbound input changes nothing.
        input.key(KeyCode::KeyZ, true);
        assert!(!input.held("forward") && !input.held("back"));
    }
}
