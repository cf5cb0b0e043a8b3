//! The game-facing API: what a game implements ([`Game`]) and what it gets in each hook
//! ([`Step`], [`FrameInput`]), the level events delivered to it ([`LevelEvent`]) and the
//! commands it queues for the engine ([`Commands`]). [`Engine`]'s public methods are the
//! rest of the surface (spawning levels, light groups, physics, audio, queries).
//!
//! A game is a thin crate over this module and [`Engine`]'s public methods: it never
//! reaches into the renderer, the upkeep or the commit. Hooks run on the main thread, inside
//! [`Engine::frame`]: `frame` once per frame (phase `Input`), `fixed_step` and then
//! `level_event` for each event of that step (phase `Steps`), all before the scene is posed
//! and sealed. The window runner also calls `ui` while it builds the frame's overlay.
//!
//! The trait keeps the core hooks only. The shell's and the editor's hooks are traits of their
//! own ([`ShellHooks`], `shell_hooks.rs`; [`EditHooks`], `edit_target.rs`) that a game offers
//! through [`Game::shell`] and [`Game::editor`] (`None` by default: the shell's defaults, no
//! editor). A game reports checkpoints and its own end through [`Commands::checkpoint`] and
//! [`Commands::end_level`]; a level's `Win`/`Lose` rule ends it too. While the shell is not
//! playing (title, pause, settings, editor, ending) `frame` and `fixed_step` do not run.
//!
//! Game rules see only replayable input: [`Step`] carries the step's [`ActionFrame`] (from the
//! devices, a recording or a replay), never the devices' state; [`FrameInput`] (per frame, not
//! replayed) does. Must not: hold references into the engine between hooks (everything is lent
//! per call).

use hecs::World;

use super::commands::Commands;
use super::edit_target::EditHooks;
use super::engine::Engine;
use super::shell_hooks::ShellHooks;
use crate::app::input::ActionFrame;
use crate::app::input::ActionSet;
use crate::app::input::InputState;
use crate::app::persist::Settings;
use crate::query::Queries;
use crate::sim::animation::FiredEvent;
use crate::sim::physics::PhysicsWorld;
use crate::sim::triggers::{Outcome, RuleFiring, VolumeEvent};

/// Why a game could not set itself up (a level that does not load, a missing asset).
pub type SetupError = Box<dyn std::error::Error + Send + Sync>;

/// What a game does, hook by hook. Every hook has a default that does nothing.
pub trait Game {
    /// Once the engine exists (and, in a window, the window): spawn the level, cameras,
    /// players. Runs before the first frame.
    fn setup(&mut self, _engine: &mut Engine) -> Result<(), SetupError> {
        Ok(())
    }

    /// Every frame, before its fixed steps (cameras that follow frames, menus that read the
    /// frame's input).
    fn frame(&mut self, _frame: &mut FrameInput<'_>) {}

    /// Every fixed step (1/60 s by default), before physics: the game's rules, with ray
    /// queries on the scene as of the last commit.
    fn fixed_step(&mut self, _step: &mut Step<'_>) {}

    /// Each thing the level's logic reported in the step that just ran (after physics and the
    /// level's rules): rule firings, volume and clip events, winning or losing.
    fn level_event(&mut self, _step: &mut Step<'_>, _event: &LevelEvent) {}

    /// Whether the game draws a UI: the window runner then runs egui every frame and calls
    /// [`Game::ui`] (egui costs a few milliseconds a frame on a software adapter).
    fn has_ui(&self) -> bool {
        false
    }

    /// Windowed only, when [`Game::has_ui`]: the game's HUD and menus, drawn over the frame.
    /// Under the shell it runs while playing, before the shell's HUD.
    fn ui(&mut self, _ctx: &egui::Context) {}

    /// The shell's hooks (title menu, starting a level, HUD, ending), when the game has them;
    /// `None` (the default): the shell shows its defaults and starts nothing.
    fn shell(&mut self) -> Option<&mut dyn ShellHooks> {
        None
    }

    /// The editor's hooks (F1, `app::edit`), when the game offers a level to edit; `None` (the
    /// default): F1 shows no editor.
    fn editor(&mut self) -> Option<&mut dyn EditHooks> {
        None
    }
}

/// A [`Game`] that is one closure run every fixed step (tools, tests, scripts).
impl<F: FnMut(&mut Step<'_>)> Game for F {
    fn fixed_step(&mut self, step: &mut Step<'_>) {
        self(step)
    }
}

/// What a fixed-step hook gets: the world, ray queries, physics and input, for one step.
pub struct Step<'a> {
    pub world: &'a mut World,
    /// Ray queries on the flattened scene (full detail) as the previous fixed step left it,
    /// physics not interpolated, however many steps the frame runs (`app/step_scene.rs`).
    pub queries: Queries<'a>,
    /// Characters, carrying, bodies; stepped after `fixed_step` returns.
    pub physics: &'a mut PhysicsWorld,
    /// This step's actions: held and pressed buttons, fixed-point axes and look motion —
    /// from the devices, or from a replay.
    pub actions: &'a ActionFrame,
    /// Names and ids of the actions (`action_set.id("jump")`).
    pub action_set: &'a ActionSet,
    /// Index of this step since the engine started (0-based).
    pub index: u64,
    /// Length of a step, seconds.
    pub step_seconds: f64,
    /// Work for the engine after the step.
    pub commands: &'a mut Commands,
    /// The player's settings as they are now, except while recording or replaying: then the
    /// look (mouse sensitivity, invert Y) is the recording's, so a replay turns as it did.
    pub settings: &'a Settings,
    /// Where the sun and the moon stand at the start of this step (engine space: north −Z,
    /// east +X, up +Y), the moon's phase and the time of day (`Engine::sky_now`); a time the
    /// game sets (`Commands::set_time_of_day`) shows from the next step (or the next hook) on.
    pub sky: Option<crate::sky::SkyNow>,
}

/// What the per-frame hook gets.
pub struct FrameInput<'a> {
    pub world: &'a mut World,
    /// Actions as of this frame (pressed-this-frame flags clear after it).
    pub input: &'a InputState,
    /// Wall-clock seconds since the previous frame.
    pub frame_seconds: f64,
    pub commands: &'a mut Commands,
}

/// Something the level's logic did in a step, for the game.
#[derive(Clone, Debug, PartialEq)]
pub enum LevelEvent {
    /// A rule's condition changed: `rising` ran its `then`, falling its `otherwise`.
    Rule { name: String, firing: RuleFiring },
    /// Something entered, stayed in or left a trigger volume.
    Volume { name: String, event: VolumeEvent },
    /// A clip passed one of its named events.
    Clip(FiredEvent),
    /// A rule with a `Win` or `Lose` action fired.
    Ended(Outcome),
}
