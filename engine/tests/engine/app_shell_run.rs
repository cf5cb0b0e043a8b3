//! The shell's loop headless (`run_headless`, the same calls per frame as the window runner)
//! around a small test game on the CPU tracer:
//!
//! * a setting changed on the settings screen applies at once (audio buses, `Engine::settings`,
//!   the input map, the scaling goal), is saved atomically, and survives a restart (a new
//!   engine and shell read it back);
//! * off the Playing screen the game is held: no `frame` or `fixed_step` hooks, no game time;
//! * a checkpoint and a won level reach the progress save, and Continue then has nothing left;
//! * corrupt settings and progress files are reported (notices naming the file, the problem
//!   and the kept `.corrupt` backup), replaced by defaults, and the game runs on.

use crate::app_common;

use anyhow::Result;
use app_common::Scratch;
use candela::app::shell::{
    Cue, GameSummary, HudInfo, LevelStart, Screen, ShellConfig, ShellHooks, ShellInput, ShellRun,
    continue_point, run_headless,
};
use candela::app::{
    Binding, Engine, Environment, FrameInput, Game, InputMap, KeyCode, Progress, Settings,
    SetupError, Step, UserDirs, game_actions,
};
use candela::assets::{CameraDesc, RenderSettings, SkyDesc};
use candela::audio::Bus;
use candela::render::RenderConfig;
use candela::sim::triggers::Outcome;

/// Counts its hooks; reports a checkpoint and a win at given steps of play.
#[derive(Default)]
struct TestGame {
    frames: u32,
    steps: u32,
    begun: Vec<LevelStart>,
    checkpoint_at: Option<u32>,
    win_at: Option<u32>,
}

impl Game for TestGame {
    fn frame(&mut self, _frame: &mut FrameInput<'_>) {
        self.frames += 1;
    }

    fn fixed_step(&mut self, step: &mut Step<'_>) {
        self.steps += 1;
        if self.checkpoint_at == Some(self.steps) {
            step.commands.checkpoint("hall");
        }
        if self.win_at == Some(self.steps) {
            step.commands.end_level(Outcome::Won("exit".into()));
        }
    }

    fn shell(&mut self) -> Option<&mut dyn ShellHooks> {
        Some(self)
    }
}

impl ShellHooks for TestGame {
    fn begin_level(&mut self, _engine: &mut Engine, start: &LevelStart) -> Result<(), SetupError> {
        self.begun.push(start.clone());
        Ok(())
    }

    fn hud(&self) -> HudInfo {
        HudInfo {
            objective: Some("Reach the exit".into()),
            ..HudInfo::default()
        }
    }

    fn summary(&self) -> GameSummary {
        GameSummary {
            headline: String::new(),
            lines: vec![format!("{} steps", self.steps)],
        }
    }
}

fn engine() -> Engine {
    let environment = Environment {
        sun: None,
        sky: SkyDesc::Constant([0.3, 0.3, 0.3]),
        render: RenderSettings {
            max_bounces: 1,
            roulette_start: 1,
            ..Default::default()
        },
        default_camera: CameraDesc {
            position: [0.0, 1.0, 3.0],
            look_at: [0.0, 0.0, 0.0],
            up: [0.0, 1.0, 0.0],
            vertical_fov_deg: 50.0,
            aperture_radius: 0.0,
            focus_distance: None,
        },
    };
    Engine::new(RenderConfig::cpu(16, 9), environment).expect("engine starts")
}

/// A set-up engine, game and shell on `dirs` with `cues`.
fn start(dirs: &UserDirs, game: &mut TestGame, cues: Vec<Cue>) -> (Engine, ShellRun) {
    let mut engine = engine();
    game.setup(&mut engine).expect("setup");
    let config = ShellConfig {
        dirs: dirs.clone(),
        cues,
    };
    let shell = ShellRun::new(config, &mut engine, game, InputMap::runner_keys());
    (engine, shell)
}

fn run(engine: &mut Engine, game: &mut TestGame, shell: &mut ShellRun, frames: u32) -> u32 {
    run_headless(engine, game, shell, frames, 1.0 / 60.0, (1280, 720)).expect("frames run")
}

#[test]
fn a_changed_setting_applies_live_is_saved_and_survives_a_restart() -> Result<()> {
    let scratch = Scratch::new("shell_restart");
    let dirs = UserDirs::under(scratch.path(), "shelltest")?;
    let mut game = TestGame::default();
    let cues = vec![
        Cue::input(2, ShellInput::OpenSettings),
        Cue::edit(1, |e| {
            e.draft.master_volume = 0.3;
            e.draft.music_volume = 0.5;
            e.draft.invert_y = true;
            e.draft.target_fps = Some(60.0);
            e.draft.resolution_scale = 0.5;
            e.start_rebind(game_actions::JUMP);
            e.offer(Binding::Key(KeyCode::KeyJ));
        }),
        Cue::input(1, ShellInput::CloseSettings),
    ];
    let (mut engine, mut shell) = start(&dirs, &mut game, cues);
    assert_eq!(shell.screen(), Screen::Title);
    assert!(shell.files().notices.is_empty());
    run(&mut engine, &mut game, &mut shell, 8);
    assert_eq!(
        shell.screen(),
        Screen::Title,
        "settings closed back to the title"
    );
    // Applied live.
    assert_eq!(engine.settings().master_volume, 0.3);
    assert_eq!(engine.settings().look_y_sign(), -1.0);
    assert_eq!(engine.audio().volume(Bus::Master), 0.3);
    assert_eq!(engine.audio().volume(Bus::Music), 0.5);
    let goal = shell.scaling_goal();
    assert_eq!(goal.frame_seconds, Some(1.0 / 60.0));
    assert_eq!(goal.max_resolution, 0.5);
    assert_eq!(shell.wants().max_fps, Some(60.0));
    engine.input_mut().key(KeyCode::KeyJ, true);
    assert!(engine.input().held(game_actions::JUMP), "J now jumps");
    engine.input_mut().key(KeyCode::Space, true);
    assert!(engine.input().held(game_actions::JUMP));
    engine.input_mut().key(KeyCode::KeyJ, false);
    assert!(
        !engine.input().held(game_actions::JUMP),
        "Space no longer jumps"
    );
    // Saved.
    let on_disk = Settings::load(&dirs.settings_file(), engine.actions());
    assert_eq!(on_disk.warning, None);
    assert_eq!(on_disk.value.master_volume, 0.3);
    drop(shell);
    let _ = engine.shutdown();

    // Restart: a new engine and shell read the file.
    let mut game = TestGame::default();
    let (engine, shell) = start(&dirs, &mut game, Vec::new());
    assert!(shell.files().notices.is_empty());
    assert_eq!(shell.files().settings.master_volume, 0.3);
    assert!(shell.files().settings.invert_y);
    assert_eq!(engine.settings().target_fps, Some(60.0));
    assert_eq!(engine.audio().volume(Bus::Master), 0.3);
    assert_eq!(
        shell
            .files()
            .settings
            .bindings
            .0
            .get(game_actions::JUMP)
            .map(|b| b[0]),
        Some(Binding::Key(KeyCode::KeyJ))
    );
    let _ = engine.shutdown();
    Ok(())
}

#[test]
fn menus_hold_the_game_and_playing_runs_it() -> Result<()> {
    let scratch = Scratch::new("shell_hold");
    let dirs = UserDirs::under(scratch.path(), "shelltest")?;
    let mut game = TestGame::default();
    let (mut engine, mut shell) = start(&dirs, &mut game, Vec::new());
    run(&mut engine, &mut game, &mut shell, 5);
    assert_eq!(
        (game.frames, game.steps),
        (0, 0),
        "the title holds the game"
    );
    assert_eq!(engine.time_seconds(), 0.0);
    assert!(engine.frames() >= 5, "but frames render");
    shell.push(ShellInput::Start(LevelStart {
        level: "main".into(),
        checkpoint: None,
    }));
    run(&mut engine, &mut game, &mut shell, 10);
    assert_eq!(shell.screen(), Screen::Playing);
    assert_eq!(game.begun.len(), 1);
    assert_eq!(game.frames, 10);
    assert!(
        game.steps >= 9,
        "about one step per 1/60 s frame: {}",
        game.steps
    );
    // Escape (the pause action) pauses: time stands still.
    engine.input_mut().key(KeyCode::Escape, true);
    run(&mut engine, &mut game, &mut shell, 1);
    engine.input_mut().key(KeyCode::Escape, false);
    assert_eq!(shell.screen(), Screen::Paused);
    assert!(!shell.wants().captured, "paused frees the mouse");
    let (frames, steps, time) = (game.frames, game.steps, engine.time_seconds());
    run(&mut engine, &mut game, &mut shell, 10);
    assert_eq!((game.frames, game.steps), (frames, steps));
    assert_eq!(engine.time_seconds(), time);
    // Resume: it runs again and wants the mouse.
    shell.push(ShellInput::Resume);
    run(&mut engine, &mut game, &mut shell, 5);
    assert_eq!(shell.screen(), Screen::Playing);
    assert!(shell.wants().captured);
    assert!(game.steps > steps && engine.time_seconds() > time);
    // The editor hook holds it too.
    engine.input_mut().key(KeyCode::F1, true);
    run(&mut engine, &mut game, &mut shell, 3);
    assert_eq!(shell.screen(), Screen::Editor);
    let steps = game.steps;
    run(&mut engine, &mut game, &mut shell, 3);
    assert_eq!(game.steps, steps);
    let _ = engine.shutdown();
    Ok(())
}

#[test]
fn a_checkpoint_and_a_win_reach_the_progress_save() -> Result<()> {
    let scratch = Scratch::new("shell_progress");
    let dirs = UserDirs::under(scratch.path(), "shelltest")?;
    let mut game = TestGame {
        checkpoint_at: Some(5),
        win_at: Some(20),
        ..TestGame::default()
    };
    let (mut engine, mut shell) = start(
        &dirs,
        &mut game,
        vec![Cue::input(
            1,
            ShellInput::Start(LevelStart {
                level: "main".into(),
                checkpoint: None,
            }),
        )],
    );
    run(&mut engine, &mut game, &mut shell, 12);
    let saved = Progress::load(&dirs.progress_file());
    assert_eq!(saved.warning, None);
    assert_eq!(saved.value.checkpoint("main"), Some("hall"));
    run(&mut engine, &mut game, &mut shell, 20);
    assert_eq!(shell.screen(), Screen::Ending);
    assert_eq!(shell.state().outcome(), Some(&Outcome::Won("exit".into())));
    let steps = game.steps;
    run(&mut engine, &mut game, &mut shell, 5);
    assert_eq!(game.steps, steps, "the ending holds the game");
    let saved = Progress::load(&dirs.progress_file()).value;
    assert!(saved.is_finished("main"));
    assert_eq!(saved.checkpoint("main"), None);
    assert!(saved.play_seconds > 0.3, "{} s played", saved.play_seconds);
    let info = game.shell_info();
    assert_eq!(
        continue_point(&info, &saved),
        None,
        "nothing left to continue"
    );
    shell.push(ShellInput::QuitToTitle);
    run(&mut engine, &mut game, &mut shell, 2);
    assert_eq!(shell.screen(), Screen::Title);
    let _ = engine.shutdown();
    Ok(())
}

#[test]
fn corrupt_files_are_reported_kept_aside_and_replaced_by_defaults() -> Result<()> {
    let scratch = Scratch::new("shell_corrupt");
    let dirs = UserDirs::under(scratch.path(), "shelltest")?;
    std::fs::create_dir_all(&dirs.config)?;
    std::fs::create_dir_all(&dirs.data)?;
    std::fs::write(dirs.settings_file(), "(master_volume: loud)")?;
    std::fs::write(dirs.progress_file(), [0xff, 0xfe, 0x00, 0x01])?;
    let mut game = TestGame::default();
    let (mut engine, mut shell) = start(&dirs, &mut game, Vec::new());
    let notices = shell.files().notices.clone();
    assert_eq!(notices.len(), 2, "{notices:?}");
    assert!(notices[0].title.contains("Settings"), "{notices:?}");
    assert!(notices[0].detail.contains("settings.ron"), "{notices:?}");
    assert!(
        notices[0].detail.contains("line 1"),
        "the problem is named: {notices:?}"
    );
    assert!(
        notices[0].detail.contains("settings.ron.corrupt"),
        "{notices:?}"
    );
    assert!(notices[1].detail.contains("progress.ron"), "{notices:?}");
    assert!(notices[1].detail.contains("UTF-8"), "{notices:?}");
    assert_eq!(shell.files().settings, Settings::default());
    assert_eq!(shell.files().progress, Progress::default());
    assert!(dirs.config.join("settings.ron.corrupt").exists());
    assert!(dirs.data.join("progress.ron.corrupt").exists());
    // The game runs on, and the next save writes good files.
    shell.push(ShellInput::Start(LevelStart {
        level: "main".into(),
        checkpoint: None,
    }));
    run(&mut engine, &mut game, &mut shell, 5);
    assert_eq!(shell.screen(), Screen::Playing);
    shell.editor_mut().draft.effects_volume = 0.4;
    shell.push(ShellInput::Quit);
    run(&mut engine, &mut game, &mut shell, 3);
    let settings = Settings::load(&dirs.settings_file(), engine.actions());
    assert_eq!(
        (settings.warning, settings.value.effects_volume),
        (None, 0.4)
    );
    assert_eq!(Progress::load(&dirs.progress_file()).warning, None);
    assert_eq!(
        std::fs::read_to_string(dirs.config.join("settings.ron.corrupt"))?,
        "(master_volume: loud)",
        "the bad file is kept as it was"
    );
    let _ = engine.shutdown();
    Ok(())
}
