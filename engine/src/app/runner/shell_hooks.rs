//! The shell's hooks ([`ShellHooks`], offered by a game through `Game::shell`) and the plain
//! data they exchange: the title menu's entries ([`ShellInfo`], [`LevelEntry`]), where a level
//! starts ([`LevelStart`]), the HUD's lines ([`HudInfo`]: objective, prompt, counters,
//! messages, a flash) and the ending screen's summary ([`GameSummary`]).
//!
//! They live in the runner, not in `app::shell`, because the first-person game (`app::play`,
//! a layer below the shell) implements them; `app::shell` re-exports them. Main thread.
//! Must not: hold engine state or draw anything.

use super::engine::Engine;
use super::game::SetupError;

/// What the shell (`app::shell`, `run_game`) asks of a game, besides the core `Game` hooks.
/// Every hook has a default.
pub trait ShellHooks {
    /// The game's name and levels for the title menu.
    fn shell_info(&self) -> ShellInfo {
        ShellInfo::default()
    }

    /// The player chose to play `start` (New game, Continue, a level): put the level and the
    /// player in place (at `start.checkpoint` when given). An error returns to the title with
    /// a notice.
    fn begin_level(&mut self, _engine: &mut Engine, _start: &LevelStart) -> Result<(), SetupError> {
        Ok(())
    }

    /// What the HUD shows this frame (crosshair, objective, prompt, counters).
    fn hud(&self) -> HudInfo {
        HudInfo::default()
    }

    /// What the ending screen shows once the level ended.
    fn summary(&self) -> GameSummary {
        GameSummary::default()
    }
}

/// The game as the title menu shows it.
#[derive(Clone, Debug, PartialEq)]
pub struct ShellInfo {
    /// The game's name, large on the title screen.
    pub title: String,
    /// One line under the title (may be empty).
    pub subtitle: String,
    /// The levels in play order; the title menu offers Continue (the first unfinished one, from
    /// its checkpoint), New game (the first from the start) and each level by name.
    pub levels: Vec<LevelEntry>,
    /// The level list offers only finished levels (a chamber select: levels are reached by
    /// playing on, not picked ahead); Continue and New game are always there.
    pub finished_only: bool,
}

impl Default for ShellInfo {
    fn default() -> Self {
        Self {
            title: "Candela".into(),
            subtitle: String::new(),
            levels: vec![LevelEntry {
                id: "main".into(),
                name: "Play".into(),
            }],
            finished_only: false,
        }
    }
}

/// One level of the game.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LevelEntry {
    /// Stable id, the key in the progress save (`Progress::finished`, `checkpoints`).
    pub id: String,
    /// What the menu shows.
    pub name: String,
}

/// Where the shell asks the game to start playing.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LevelStart {
    /// A [`LevelEntry::id`].
    pub level: String,
    /// The checkpoint to start from (`None`: the level's start).
    pub checkpoint: Option<String>,
}

/// What the HUD shows while playing; the game fills it every frame (`Game::hud`).
#[derive(Clone, Debug, PartialEq)]
pub struct HudInfo {
    /// Draw the crosshair at the centre of the screen.
    pub crosshair: bool,
    /// The current objective, top left (`None`: nothing).
    pub objective: Option<String>,
    /// An interaction prompt under the crosshair ("E  open the door").
    pub prompt: Option<String>,
    /// Counters, top right: (label, value), e.g. ("Lights", "2 / 3").
    pub counters: Vec<(String, String)>,
    /// Lines drawn over the picture (the outline of where a held body will land), each end
    /// in view-plane units: x right, y up, 1 = from the centre to the top edge
    /// (`player::drop_outline`).
    pub outline: Vec<[[f32; 2]; 2]>,
    /// Short lines about what just happened ("Plate pressed", "Too far"), oldest first,
    /// centred near the top; the game keeps each for a moment and then leaves it out.
    pub messages: Vec<String>,
    /// A full-screen flash over the picture (a laser hit the player), 0 (none) to 1 (full);
    /// the game fades it out over a few steps.
    pub flash: f32,
}

impl Default for HudInfo {
    fn default() -> Self {
        Self {
            crosshair: true,
            objective: None,
            prompt: None,
            counters: Vec::new(),
            outline: Vec::new(),
            messages: Vec::new(),
            flash: 0.0,
        }
    }
}

/// What the ending screen shows.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GameSummary {
    /// The headline; empty: "Level complete" or "Level failed" from the outcome.
    pub headline: String,
    /// Lines under it (score, secrets found…).
    pub lines: Vec<String>,
}
