//! The shell soak: a [`Game`] played headless inside its shell ([`ShellRun`], the same calls
//! per frame as the window runner) for many frames, with the seeded game [`Monkey`] at the
//! controls and the [`MenuMonkey`] around it — pausing and resuming, the settings screen (a
//! setting changed, applied and saved), the level editor (F1: select, drag by the gizmo, undo,
//! F1 again: play from here), quitting to the title (the progress saved) and continuing from
//! the save read back, and starting another level. Every frame gets the soak's checks
//! (`soak.rs`: finite transforms, nothing out of the world, the film every
//! [`FILM_EVERY`] frames, memory after the warm-up and at the end), on every screen; the
//! report counts each action that took effect, the frames checked per screen, and each
//! frame's wall time (for the distribution only: nothing asserts on it).
//!
//! Owns: [`soak_shell`], [`ShellSoak`] (the report is `soak_shell_report.rs`, the editor's
//! gestures `soak_gestures.rs`). Main thread
//! (the render thread renders). Must not: change the game or its level files (the editor's
//! edits are never saved and it keeps no recovery file) or the player's real folders (the
//! caller passes scratch [`UserDirs`]).

use std::collections::BTreeMap;
use std::time::Instant;

use glam::Vec2;

use super::menu_monkey::{Episode, MenuMonkey, MenuStep};
use super::soak::{FILM, FILM_EVERY, SoakError, SoakReport, check_film_of, check_world, rss_bytes};
use super::soak_gestures::{Gesture, VIEW, drag, select, translation};
use super::soak_shell_report::{ActionCounts, ShellSoakReport};
use crate::app::edit::EditMode;
use crate::app::input::InputMap;
use crate::app::persist::{Progress, Settings, UserDirs};
use crate::app::replay::{Monkey, StepInput};
use crate::app::runner::{Engine, Environment, Game};
use crate::app::shell::{LevelStart, Screen, ShellConfig, ShellInput, ShellRun, continue_point};
use crate::render::RenderConfig;

/// Frames a stuck screen (no episode under way, not playing) is left before the soak steps in.
const STUCK: u32 = 120;

/// How a shell soak runs.
#[derive(Debug)]
pub struct ShellSoak {
    pub frames: u64,
    pub seed: u64,
    /// Mean frames of play between the menu monkey's episodes.
    pub every: u32,
    /// Episodes the menu monkey never starts (to show that the counts catch a missing one).
    pub disabled: Vec<Episode>,
    /// Where the settings and the progress save go (scratch folders, not the player's).
    pub dirs: UserDirs,
}

/// What the soak waits to see after a step.
enum Expect {
    Saved(String),
    Playing(LevelStart),
    Loaded(LevelStart),
}

/// Soaks `game` (not yet set up) in `environment` inside its shell, as [`ShellSoak`] says.
pub fn soak_shell<G: Game>(
    game: &mut G,
    environment: Environment,
    how: ShellSoak,
) -> Result<ShellSoakReport, SoakError> {
    let mut engine = Engine::new(RenderConfig::cpu(FILM.0, FILM.1), environment)?;
    game.setup(&mut engine)
        .map_err(|e| SoakError::Setup(e.to_string()))?;
    engine.set_step_input(StepInput::Monkey(Monkey::new(how.seed)));
    let config = ShellConfig {
        dirs: how.dirs,
        cues: Vec::new(),
    };
    let mut shell = ShellRun::new(config, &mut engine, game, InputMap::runner_keys());
    let levels: Vec<String> = game
        .shell()
        .map(|s| s.shell_info().levels.iter().map(|l| l.id.clone()).collect())
        .unwrap_or_default();
    let info = game.shell().map(|s| s.shell_info()).unwrap_or_default();
    let mut menus = MenuMonkey::new(how.seed, how.every);
    menus.disabled = how.disabled;
    let ctx = egui::Context::default();
    let mut edit: Option<EditMode> = None;
    let mut gesture: Option<Gesture> = None;
    // After a counted drag: the instance and where it was, for the undo to put it back.
    let mut undo_target: Option<(usize, [f32; 3])> = None;
    // The level last played (the shell forgets it at the title).
    let mut last_level: Option<String> = None;
    let mut expect: Option<Expect> = None;
    let mut counts = ActionCounts::default();
    let mut checked = BTreeMap::new();
    let mut frame_ms = Vec::with_capacity(how.frames as usize);
    let mut soak = SoakReport {
        frames: 0,
        film_checks: 0,
        rss_warm: 0,
        rss_end: 0,
    };
    let mut stuck = 0u32;
    let mut changed_setting: Option<Settings> = None;
    for frame in 0..how.frames {
        let started = Instant::now();
        let before = shell.screen();
        // The menu monkey's step, or the soak stepping in on a screen nobody leaves.
        let mut step = menus.frame(before).map(|(_, s)| s);
        stuck = if before == Screen::Playing || menus.busy() || step.is_some() {
            0
        } else {
            stuck + 1
        };
        if stuck > STUCK || (before == Screen::Title && !menus.busy() && step.is_none()) {
            stuck = 0;
            step = Some(match before {
                Screen::Title => MenuStep::StartLevel { pick: 0 },
                Screen::Paused => MenuStep::Shell(ShellInput::Resume),
                Screen::Settings => MenuStep::Shell(ShellInput::CloseSettings),
                Screen::Editor => MenuStep::Shell(ShellInput::EditorToggle),
                Screen::Ending | Screen::Playing => MenuStep::Shell(ShellInput::QuitToTitle),
            });
        }
        let mut events = Vec::new();
        let mut modifiers = egui::Modifiers::NONE;
        let undo_pass = step == Some(MenuStep::EditorUndo);
        match step {
            Some(MenuStep::Shell(input)) => {
                if input == ShellInput::QuitToTitle {
                    expect = shell
                        .state()
                        .level()
                        .map(|l| Expect::Saved(l.level.clone()));
                }
                shell.push(input);
            }
            Some(MenuStep::ChangeSetting { pick }) if before == Screen::Settings => {
                let draft = &mut shell.editor_mut().draft;
                match pick % 3 {
                    0 => draft.master_volume = (pick % 11) as f32 / 10.0,
                    1 => draft.mouse_sensitivity = 0.5 + (pick % 7) as f32 * 0.25,
                    _ => draft.invert_y = !draft.invert_y,
                }
                changed_setting = Some(draft.clone());
            }
            Some(MenuStep::LoadSave) if before == Screen::Title => {
                let path = shell.files().dirs().progress_file();
                let loaded = Progress::load(&path);
                let start = match (loaded.warning, continue_point(&info, &loaded.value)) {
                    (None, Some(start)) => Some(start),
                    _ => None,
                };
                if let Some(start) = start {
                    expect = Some(Expect::Loaded(start.clone()));
                    shell.push(ShellInput::Start(start));
                }
            }
            Some(MenuStep::StartLevel { pick })
                if before == Screen::Title && !levels.is_empty() =>
            {
                let mut k = pick as usize % levels.len();
                let current = last_level.clone();
                if levels.len() > 1 && current.as_ref() == Some(&levels[k]) {
                    k = (k + 1) % levels.len();
                }
                let start = LevelStart {
                    level: levels[k].clone(),
                    checkpoint: None,
                };
                if current.is_some_and(|c| c != start.level) {
                    expect = Some(Expect::Playing(start.clone()));
                }
                shell.push(ShellInput::Start(start));
            }
            Some(MenuStep::EditorSelect { pick }) => {
                if let Some(mode) = edit.as_ref().filter(|m| m.active()) {
                    gesture = select(mode, pick);
                }
            }
            Some(MenuStep::EditorDrag { axis, points }) => {
                if let Some(mode) = edit.as_ref().filter(|m| m.active()) {
                    gesture = drag(mode, axis, Vec2::from(points));
                }
            }
            Some(MenuStep::EditorUndo) => {
                modifiers = egui::Modifiers::COMMAND;
                events.push(egui::Event::Key {
                    key: egui::Key::Z,
                    physical_key: None,
                    pressed: true,
                    repeat: false,
                    modifiers,
                });
            }
            _ => {}
        }
        shell.before_frame(&mut engine, game);
        // The window runner's editor hook (`window/edit.rs`), headless.
        let want = shell.screen() == Screen::Editor;
        let active = edit.as_ref().is_some_and(EditMode::active);
        if want && !active {
            if edit.is_none()
                && let Some((target, spawned)) = game.editor().and_then(|h| h.edit_target())
                && let Ok(mode) = EditMode::open(target, spawned)
            {
                edit = Some(mode.without_recovery_files());
            }
            shell.set_editor_drawn(edit.is_some());
            if let Some(mode) = edit.as_mut() {
                mode.enter_with(&mut engine, game.editor());
                counts.editor_opened += 1;
            }
        } else if !want
            && active
            && let Some(mode) = edit.as_mut()
        {
            mode.play_from_here(&mut engine, game.editor());
            counts.editor_closed += 1;
        }
        let editing = edit.as_ref().is_some_and(EditMode::active);
        if editing
            && let Some(g) = gesture.as_mut()
            && let Some((e, m)) = g.passes.pop_front()
        {
            events.extend(e);
            modifiers = m;
        }
        let input = egui::RawInput {
            screen_rect: Some(egui::Rect::from_min_size(
                egui::Pos2::ZERO,
                egui::vec2(VIEW.x, VIEW.y),
            )),
            time: Some(frame as f64 / 60.0),
            events: std::iter::once(egui::Event::ModifiersChanged(modifiers))
                .chain(events)
                .collect(),
            ..Default::default()
        };
        let mut respawned = false;
        let playing = shell.screen() == Screen::Playing;
        let _ = ctx.run_pass(input, |ctx| {
            if playing && game.has_ui() {
                game.ui(ctx);
            }
            shell.ui(ctx);
            if editing && let Some(mode) = edit.as_mut() {
                respawned = mode.ui(ctx, &mut engine).respawned;
            }
        });
        shell.after_ui(&mut engine, game);
        if respawned
            && let Some(mode) = edit.as_ref()
            && let Some(hooks) = game.editor()
        {
            hooks.level_respawned(&mut engine, mode.world.spawned());
        }
        let check_film = frame % FILM_EVERY == FILM_EVERY - 1;
        if check_film {
            engine.capture_next();
        }
        let report = engine.frame(1.0 / 60.0, game)?;
        shell.after_frame(&mut engine, &report);
        // The checks, on every screen.
        check_world(&engine, frame)?;
        if check_film {
            check_film_of(&engine, frame)?;
            soak.film_checks += 1;
        } else {
            for result in engine.rendered() {
                result.map_err(|source| SoakError::Render { frame, source })?;
            }
        }
        let after = shell.screen();
        *checked.entry(format!("{after:?}")).or_insert(0u64) += 1;
        // What took effect.
        match (before, after) {
            (Screen::Playing, Screen::Paused) => counts.paused += 1,
            (Screen::Paused, Screen::Playing) => counts.resumed += 1,
            (b, Screen::Settings) if b != Screen::Settings => counts.settings_opened += 1,
            (Screen::Settings, a) if a != Screen::Settings => counts.settings_closed += 1,
            _ => {}
        }
        if let Some(want) = changed_setting.take()
            && shell.files().settings == want
        {
            counts.settings_changed += 1;
        }
        if let Some(mode) = edit.as_ref().filter(|m| m.active()) {
            if let Some(g) = gesture.take_if(|g| g.passes.is_empty()) {
                match g.dragged {
                    Some((index, from)) => {
                        let moved = translation(mode, index).is_some_and(|t| t != from);
                        if moved && mode.state.history.can_undo() {
                            counts.dragged += 1;
                            undo_target = Some((index, from));
                        }
                    }
                    None if mode.state.selection.primary().is_some() => counts.selected += 1,
                    None => {}
                }
            }
            if undo_pass
                && let Some((index, from)) = undo_target.take()
                && translation(mode, index) == Some(from)
            {
                counts.undone += 1;
            }
        } else {
            gesture = None;
            undo_target = None;
        }
        if let Some(level) = shell.state().level() {
            last_level = Some(level.level.clone());
        }
        match expect.take() {
            Some(Expect::Saved(level)) if after == Screen::Title => {
                let path = shell.files().dirs().progress_file();
                let on_disk = Progress::load(&path);
                let has = on_disk.value.checkpoints.contains_key(&level)
                    || on_disk.value.finished.contains(&level);
                if on_disk.warning.is_none() && on_disk.value == shell.files().progress && has {
                    counts.saved += 1;
                }
            }
            Some(Expect::Playing(start))
                if after == Screen::Playing && shell.state().level() == Some(&start) =>
            {
                counts.levels_changed += 1;
            }
            Some(Expect::Loaded(start))
                if after == Screen::Playing && shell.state().level() == Some(&start) =>
            {
                counts.loaded += 1;
            }
            Some(Expect::Saved(_)) | Some(Expect::Playing(_)) | Some(Expect::Loaded(_)) => {}
            None => {}
        }
        if frame == how.frames / 10 {
            soak.rss_warm = rss_bytes();
        }
        soak.frames = frame + 1;
        frame_ms.push(started.elapsed().as_secs_f32() * 1e3);
    }
    soak.rss_end = rss_bytes();
    let _ = engine.shutdown();
    Ok(ShellSoakReport {
        soak,
        counts,
        checked,
        frame_ms,
    })
}
