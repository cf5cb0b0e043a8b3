//! Reflect in a real window under Xvfb (CPU tracer, workload scaling at 30 fps): the game
//! starts at its title menu, the first chamber's committed replay plays in the window for 460
//! frames, screenshot at 400 (the steps follow wall time, as for a player: about two a frame at
//! the 30 fps the scaling holds), and the Quit cue ends the run cleanly.
//! One window run per process (winit allows one event loop), so the test runs alone in its process
//! under any runner (`candela_tests::alone`).
//!
//! Checked: the run ends by Quit; the title screenshot has the menu (the shell's panel colours
//! over a third of its centre box) and the game's name in the accent colour in its top band;
//! the play screenshot is the lit chamber (mean brightness well above black) with the HUD's
//! objective heading; the game entered the first chamber, the replay got past the plate (step
//! 460) and the door's rule rose as it does headless. A run too short to get there fails (it
//! used to skip the door check).

use std::path::Path;
use std::sync::Arc;
use std::sync::atomic::AtomicBool;

use candela::app::shell::{Cue, ShellConfig, ShellInput};
use candela::app::{StepInput, UserDirs, WindowConfig, WindowEnd, run_game};
use candela::render::RenderConfig;
use candela::render::scaling::ScalingTarget;
use candela_tests::repo;
use candela_tests::xvfb::{set_environment, start_xvfb};
use image::RgbImage;
use reflect::game::{ReflectEvent, ReflectGame};
use reflect::replays::open_replay;
use reflect::world::ReflectWorld;

fn open(path: &Path) -> RgbImage {
    image::open(path)
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
        .to_rgb8()
}

/// Mean luma over the box (fractions of the width and height).
fn mean_luma(img: &RgbImage, xs: (f32, f32), ys: (f32, f32)) -> f64 {
    let (w, h) = img.dimensions();
    let (mut sum, mut n) = (0.0f64, 0.0f64);
    for y in (ys.0 * h as f32) as u32..(ys.1 * h as f32) as u32 {
        for x in (xs.0 * w as f32) as u32..(xs.1 * w as f32) as u32 {
            let p = img.get_pixel(x, y).0;
            sum += 0.2126 * f64::from(p[0]) + 0.7152 * f64::from(p[1]) + 0.0722 * f64::from(p[2]);
            n += 1.0;
        }
    }
    sum / n.max(1.0)
}

/// Fraction of the box's pixels close to the accent colour (the shell theme's orange).
fn accent_fraction(img: &RgbImage, xs: (f32, f32), ys: (f32, f32)) -> f64 {
    let (w, h) = img.dimensions();
    let (mut hits, mut n) = (0.0f64, 0.0f64);
    for y in (ys.0 * h as f32) as u32..(ys.1 * h as f32) as u32 {
        for x in (xs.0 * w as f32) as u32..(xs.1 * w as f32) as u32 {
            let [r, g, b] = img.get_pixel(x, y).0;
            if r > 180 && g > 100 && g < 200 && b < 110 && r > b + 90 {
                hits += 1.0;
            }
            n += 1.0;
        }
    }
    hits / n.max(1.0)
}

#[test]
fn reflect_starts_at_its_menu_plays_a_chamber_replay_and_quits() {
    // Changes process-wide state: alone in its process under any test runner.
    if !candela_tests::alone::alone_in_process(
        "reflect_window::reflect_starts_at_its_menu_plays_a_chamber_replay_and_quits",
    ) {
        return;
    }
    let scratch = repo().join("target/reflect_window");
    let _ = std::fs::remove_dir_all(&scratch);
    std::fs::create_dir_all(&scratch).expect("scratch");
    let xvfb = start_xvfb();
    set_environment(&xvfb.display, &scratch);
    let (path, root) =
        reflect::cli::locate(Some(&repo().join("assets/reflect/reflect.ron"))).expect("game file");
    let world = ReflectWorld::load(&path, &root).expect("the world loads");
    let (replay, start) = open_replay(
        &world,
        &repo().join("assets/reflect/replays/chamber_1.replay"),
    )
    .expect("replay");
    let mut cues = reflect::cli::replay_cues(&scratch, &world.chambers[start].id);
    // Play on 60 frames past the screenshot before quitting (at the 30 fps the scaling holds,
    // two steps a frame: 920 steps, past the plate at 460).
    cues.pop();
    cues.push(Cue::input(60, ShellInput::Quit));
    let mut game = ReflectGame::new(world, start);
    game.inner_mut().start_with(StepInput::Replay(replay));
    game.inner_mut().use_shell_hud();
    let config = WindowConfig {
        title: "Reflect".into(),
        size: (960, 540),
        stop: Arc::new(AtomicBool::new(false)),
        ..WindowConfig::default()
    };
    let shell = ShellConfig {
        dirs: UserDirs::under(&scratch.join("user"), "reflect").expect("dirs"),
        cues,
    };
    let render = RenderConfig {
        scaling: Some(ScalingTarget::new(1.0 / 30.0)),
        ..RenderConfig::cpu(960, 540)
    };
    let environment = game.inner().environment();
    let report = run_game(config, shell, render, environment, &mut game)
        .expect("Reflect runs in the Xvfb window");
    eprintln!("{} frames in {:.1} s", report.frames, report.seconds);
    assert_eq!(report.ended_by, WindowEnd::Quit);

    let title = open(&scratch.join("title.png"));
    let play = open(&scratch.join("play.png"));
    let name = accent_fraction(&title, (0.3, 0.7), (0.05, 0.25));
    eprintln!("title accent fraction {name:.4}");
    assert!(name > 0.01, "the game's name in the accent colour: {name}");
    let lit = mean_luma(&play, (0.2, 0.8), (0.3, 0.9));
    eprintln!("play luma {lit:.1}");
    assert!(lit > 20.0, "the chamber is lit: {lit}");
    let heading = accent_fraction(&play, (0.0, 0.2), (0.0, 0.1));
    assert!(heading > 0.005, "the objective heading: {heading}");

    assert!(
        game.log()
            .iter()
            .any(|(_, e)| *e == ReflectEvent::Entered(0)),
        "{:?}",
        game.log()
    );
    let steps = (game.play_seconds() * 60.0).round() as u64;
    eprintln!("{steps} steps played in the window");
    assert!(
        steps >= 460,
        "the replay reaches the plate at step 460; the window played {steps} steps in {} \
         frames",
        report.frames
    );
    let door = game
        .log()
        .iter()
        .any(|(_, e)| matches!(e, ReflectEvent::Rule { name, rising: true } if name == "door_1"));
    assert!(
        door,
        "the replay carried the cube onto the plate: {:?}",
        game.log()
    );
}
