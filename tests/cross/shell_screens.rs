//! The shell's screens in a real window under Xvfb (CPU tracer, 960×540): a small test game on
//! the Cornell box runs inside `run_game`, and scripted cues walk it through the title menu,
//! playing (the HUD), the pause menu, the settings screen, the editor hook and the ending,
//! with a screenshot of each
//! (written to `target/shell_screens/`), a settings change on the way, and Quit. One window run
//! per process (winit allows one event loop), so the test runs alone in its process
//! under any runner (`candela_tests::alone`).
//!
//! The screenshots are checked by what each screen must draw, against the HUD screenshot (the
//! same view without a menu), with margins far from the picture's noise:
//!
//! * title: the menus' colours cover over 30 % of its box (under 5 % of the same box in
//!   the HUD frame); the game's name in the accent colour fills hundreds of pixels in the top
//!   band;
//! * HUD: the crosshair's four white arms are at the centre (the brightest pixel of 3×3 at the
//!   middle of each arm ≥ 225 in every channel), its accent dot at the centre, and the
//!   objective box's accent-coloured heading at the top left;
//! * pause: the picture is dimmed (the side walls, beside the panel, under 80 % of the HUD's),
//!   the menus' colours cover over 30 % of its box, and "Paused" is drawn in the accent
//!   colour;
//! * settings: the panel covers most of the centre (≥ 40 % of its pixels the menus' colours;
//!   the HUD frame under 5 %), with the accent heading.
//!
//! The editor hook's placeholder and the ending screen (after a won level, which then is in
//! the progress save) are shot and checked the same way.
//!
//! Then the restart: the settings file holds the change and a fresh (headless) engine and shell
//! load it.

use std::path::Path;
use std::sync::Arc;
use std::sync::atomic::AtomicBool;
use std::time::{Duration, Instant};

use candela::app::shell::{
    Cue, GameSummary, HudInfo, LevelEntry, LevelStart, ShellConfig, ShellHooks, ShellInfo,
    ShellInput, ShellRun,
};
use candela::app::{
    Binding, Engine, Environment, Game, InputMap, KeyCode, Progress, Settings, SetupError,
    UserDirs, WindowConfig, WindowEnd, game_actions, run_game,
};
use candela::assets::AssetRoot;
use candela::level::{PlayableLevel, load_level};
use candela::render::RenderConfig;
use candela::sim::triggers::Outcome;
use candela_tests::repo;
use candela_tests::xvfb::{set_environment, start_xvfb};
use image::RgbImage;

const WIDTH: u32 = 960;
const HEIGHT: u32 = 540;

struct RoomGame {
    level: PlayableLevel,
}

impl Game for RoomGame {
    fn setup(&mut self, engine: &mut Engine) -> Result<(), SetupError> {
        engine.spawn_level(&self.level);
        Ok(())
    }

    fn shell(&mut self) -> Option<&mut dyn ShellHooks> {
        Some(self)
    }
}

impl ShellHooks for RoomGame {
    fn shell_info(&self) -> ShellInfo {
        ShellInfo {
            title: "Candela Test Room".into(),
            subtitle: "A lit room for the shell's screenshots".into(),
            levels: vec![LevelEntry {
                id: "room".into(),
                name: "The room".into(),
            }],
            finished_only: false,
        }
    }

    fn summary(&self) -> GameSummary {
        GameSummary {
            headline: String::new(),
            lines: vec![
                "Lights switched on   3 / 3".into(),
                "Secrets found   0 / 1".into(),
            ],
        }
    }

    fn hud(&self) -> HudInfo {
        HudInfo {
            crosshair: true,
            objective: Some("Switch on every light".into()),
            prompt: Some("E   use the switch".into()),
            counters: vec![("Lights".into(), "1 / 3".into())],
            ..HudInfo::default()
        }
    }
}

/// Rec. 709 luma of an sRGB pixel, 0–255.
fn luma(p: &image::Rgb<u8>) -> f64 {
    0.2126 * p[0] as f64 + 0.7152 * p[1] as f64 + 0.0722 * p[2] as f64
}

/// Mean luma over the box [x0, x1) × [y0, y1) given as fractions of the image.
fn mean_luma(img: &RgbImage, x: (f64, f64), y: (f64, f64)) -> f64 {
    let (w, h) = (img.width() as f64, img.height() as f64);
    let (mut sum, mut n) = (0.0, 0u32);
    for py in (y.0 * h) as u32..(y.1 * h) as u32 {
        for px in (x.0 * w) as u32..(x.1 * w) as u32 {
            sum += luma(img.get_pixel(px, py));
            n += 1;
        }
    }
    sum / n.max(1) as f64
}

/// Pixels close to the accent colour (255, 183, 77) in the box.
fn accent_pixels(img: &RgbImage, x: (f64, f64), y: (f64, f64)) -> u32 {
    let (w, h) = (img.width() as f64, img.height() as f64);
    let mut n = 0;
    for py in (y.0 * h) as u32..(y.1 * h) as u32 {
        for px in (x.0 * w) as u32..(x.1 * w) as u32 {
            let p = img.get_pixel(px, py);
            if p[0] > 200 && (130..=215).contains(&p[1]) && p[2] < 130 {
                n += 1;
            }
        }
    }
    n
}

/// Fraction of pixels in the box of the menus' colours: the panel's near-black fill
/// (10, 11, 16) and the buttons' slate (34, 36, 44), both dark and bluish — unlike the room's
/// black outside (no blue) and the lit room, dimmed or not (yellow-grey, red, green).
fn panel_fraction(img: &RgbImage, x: (f64, f64), y: (f64, f64)) -> f64 {
    let (w, h) = (img.width() as f64, img.height() as f64);
    let (mut panel, mut n) = (0u32, 0u32);
    for py in (y.0 * h) as u32..(y.1 * h) as u32 {
        for px in (x.0 * w) as u32..(x.1 * w) as u32 {
            let [r, g, b] = img.get_pixel(px, py).0;
            let menu = r <= 45 && (12..=56).contains(&b) && b >= r + 3 && b >= g + 2;
            panel += u32::from(menu);
            n += 1;
        }
    }
    panel as f64 / n.max(1) as f64
}

fn open(path: &Path) -> RgbImage {
    let img = image::open(path)
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
        .to_rgb8();
    assert_eq!(img.dimensions(), (WIDTH, HEIGHT), "{}", path.display());
    img
}

#[test]
fn title_hud_pause_and_settings_are_drawn_and_a_setting_survives_a_restart() {
    // Changes process-wide state: alone in its process under any test runner.
    if !candela_tests::alone::alone_in_process(
        "shell_screens::title_hud_pause_and_settings_are_drawn_and_a_setting_survives_a_restart",
    ) {
        return;
    }
    let scratch = std::env::temp_dir().join(format!("candela_shell_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&scratch);
    std::fs::create_dir_all(&scratch).expect("scratch folder");
    let out = repo().join("target/shell_screens");
    std::fs::create_dir_all(&out).expect("screenshot folder");
    let shot = |name: &str| out.join(format!("{name}.png"));
    for name in ["title", "hud", "pause", "settings", "editor", "ending"] {
        let _ = std::fs::remove_file(shot(name));
    }
    let xvfb = start_xvfb();
    set_environment(&xvfb.display, &scratch);
    let root = AssetRoot::new(repo().join("assets/test_scenes")).expect("asset root");
    let level = load_level(&repo().join("assets/test_scenes/cornell_box.ron"), &root)
        .expect("the Cornell box loads");
    let environment = Environment::of(&level.scene);
    let dirs = UserDirs::under(&scratch.join("user"), "shellscreens").expect("dirs");
    let cues = vec![
        Cue::screenshot(24, shot("title")),
        Cue::input(
            2,
            ShellInput::Start(LevelStart {
                level: "room".into(),
                checkpoint: None,
            }),
        ),
        Cue::screenshot(24, shot("hud")),
        Cue::input(2, ShellInput::Pause),
        Cue::screenshot(16, shot("pause")),
        Cue::input(2, ShellInput::OpenSettings),
        Cue::edit(2, |e| {
            e.draft.music_volume = 0.35;
            e.start_rebind(game_actions::USE);
            e.offer(Binding::Key(KeyCode::KeyF));
        }),
        Cue::screenshot(12, shot("settings")),
        Cue::input(3, ShellInput::CloseSettings),
        Cue::input(2, ShellInput::Resume),
        Cue::input(4, ShellInput::EditorToggle),
        Cue::screenshot(8, shot("editor")),
        Cue::input(2, ShellInput::EditorToggle),
        Cue::input(4, ShellInput::LevelEnded(Outcome::Won("exit".into()))),
        Cue::screenshot(10, shot("ending")),
        Cue::input(2, ShellInput::Quit),
    ];
    let config = WindowConfig {
        title: "Candela shell".into(),
        size: (WIDTH, HEIGHT),
        show_stats: false,
        stop: Arc::new(AtomicBool::new(false)),
        ..WindowConfig::default()
    };
    let shell = ShellConfig {
        dirs: dirs.clone(),
        cues,
    };
    let render = RenderConfig {
        seed: 5,
        ..RenderConfig::cpu(WIDTH, HEIGHT)
    };
    let started = Instant::now();
    let mut game = RoomGame { level };
    let report = run_game(config, shell, render, environment, &mut game)
        .expect("the game runs in the Xvfb window");
    eprintln!(
        "{} frames in {:.1} s, ended by {:?}",
        report.frames, report.seconds, report.ended_by
    );
    assert_eq!(
        report.ended_by,
        WindowEnd::Quit,
        "the Quit cue ends the run"
    );
    assert!(started.elapsed() < Duration::from_secs(600));

    let title = open(&shot("title"));
    let hud = open(&shot("hud"));
    let pause = open(&shot("pause"));
    let settings = open(&shot("settings"));
    let centre = ((0.42, 0.58), (0.45, 0.65));
    let hud_centre = mean_luma(&hud, centre.0, centre.1);
    eprintln!("HUD centre luma {hud_centre:.1}");
    assert!(
        hud_centre > 40.0,
        "the room is lit behind the HUD: {hud_centre}"
    );

    // Title: the menu panel and buttons; the name in the accent colour.
    let menu_box = ((0.36, 0.64), (0.5, 0.68));
    let hud_panel = panel_fraction(&hud, menu_box.0, menu_box.1);
    assert!(hud_panel < 0.05, "no panel while playing: {hud_panel:.2}");
    let title_panel = panel_fraction(&title, menu_box.0, menu_box.1);
    assert!(
        title_panel > 0.3,
        "the title's menu panel: {title_panel:.2}"
    );
    let name = accent_pixels(&title, (0.1, 0.9), (0.05, 0.3));
    assert!(name > 300, "{name} accent pixels of the title");

    // HUD: the crosshair at the centre, the objective box top left.
    let (cx, cy) = (WIDTH as i32 / 2, HEIGHT as i32 / 2);
    // The middle of each arm: (gap + arm / 2) points at UI scale 540 / 720, in pixels.
    let arm = ((5.0 + 10.0 / 2.0) * HEIGHT as f32 / 720.0).round() as i32;
    let brightest = |x: i32, y: i32| {
        let mut best = image::Rgb([0u8; 3]);
        for (ox, oy) in (-1..=1).flat_map(|ox| (-1..=1).map(move |oy| (ox, oy))) {
            let p = *hud.get_pixel((x + ox) as u32, (y + oy) as u32);
            if luma(&p) > luma(&best) {
                best = p;
            }
        }
        best
    };
    for (dx, dy) in [(arm, 0i32), (-arm, 0), (0, arm), (0, -arm)] {
        let p = brightest(cx + dx, cy + dy);
        assert!(
            p.0.iter().all(|&c| c >= 225),
            "crosshair arm at ({dx}, {dy}): {p:?}"
        );
    }
    let (cx, cy) = (cx as u32, cy as u32);
    let dot = hud.get_pixel(cx, cy);
    assert!(
        dot[0] > 200 && dot[2] < 150,
        "the accent dot at the centre: {dot:?}"
    );
    let objective = accent_pixels(&hud, (0.0, 0.3), (0.0, 0.15));
    assert!(objective > 20, "{objective} accent pixels of OBJECTIVE");

    // Pause: dimmed, the panel in the centre, its heading.
    let walls = |img: &RgbImage| {
        mean_luma(img, (0.24, 0.32), (0.4, 0.8)) + mean_luma(img, (0.68, 0.76), (0.4, 0.8))
    };
    let (paused, playing) = (walls(&pause), walls(&hud));
    assert!(
        paused < 0.8 * playing,
        "pause dims the walls: {paused} vs {playing}"
    );
    let pause_panel = panel_fraction(&pause, menu_box.0, (0.3, 0.7));
    assert!(
        pause_panel > 0.3,
        "the pause menu's panel: {pause_panel:.2}"
    );
    let heading = accent_pixels(&pause, (0.3, 0.7), (0.1, 0.5));
    assert!(heading > 150, "{heading} accent pixels of Paused");

    // Settings: a large panel with the heading.
    let panel = panel_fraction(&settings, (0.2, 0.8), (0.2, 0.8));
    assert!(
        panel > 0.4,
        "settings panel covers {panel:.2} of the centre"
    );
    let heading = accent_pixels(&settings, (0.3, 0.7), (0.0, 0.3));
    assert!(heading > 100, "{heading} accent pixels of Settings");
    assert!(
        panel_fraction(&hud, (0.2, 0.8), (0.2, 0.8)) < 0.05,
        "the HUD has no panel"
    );

    // The editor hook and the ending: a panel with an accent heading each; the won level is
    // in the progress save.
    for (name, img) in [
        ("editor", open(&shot("editor"))),
        ("ending", open(&shot("ending"))),
    ] {
        let panel = panel_fraction(&img, menu_box.0, (0.3, 0.7));
        assert!(panel > 0.3, "the {name} panel: {panel:.2}");
        let heading = accent_pixels(&img, (0.25, 0.75), (0.1, 0.5));
        assert!(
            heading > 150,
            "{heading} accent pixels of the {name} heading"
        );
    }
    let progress = Progress::load(&dirs.progress_file());
    assert_eq!(progress.warning, None);
    assert!(progress.value.is_finished("room"), "{:?}", progress.value);

    // A changed setting survives a restart: on disk, and loaded by a fresh shell.
    let saved = Settings::load(&dirs.settings_file(), &candela::app::ActionSet::standard());
    assert_eq!(saved.warning, None);
    assert_eq!(saved.value.music_volume, 0.35);
    let mut engine = Engine::new(RenderConfig::cpu(16, 9), Environment::of(&game.level.scene))
        .expect("headless engine");
    game.setup(&mut engine).expect("setup");
    let config = ShellConfig {
        dirs,
        cues: Vec::new(),
    };
    let shell = ShellRun::new(config, &mut engine, &mut game, InputMap::runner_keys());
    assert_eq!(shell.files().settings.music_volume, 0.35);
    assert_eq!(engine.settings().music_volume, 0.35);
    engine.input_mut().key(KeyCode::KeyF, true);
    assert!(
        engine.input().held(game_actions::USE),
        "F uses after the restart"
    );
    drop(shell);
    let _ = engine.shutdown();
    let _ = std::fs::remove_dir_all(&scratch);
}
