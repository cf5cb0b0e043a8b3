//! The level editor over path-traced Reflect in a real window under Xvfb (issue 12): the second
//! chamber is played for a moment, F1 opens the editor (the game holds, the tracer keeps
//! converging), the door ahead (`door_2`) is selected, and the editor is closed again to play
//! from there before Quit ends the run. One window run per process, so one test.
//!
//! Checked on the screenshots (`target/editor_window/*.png`), 1280 × 720:
//! - the outliner, the inspector and the toolbar are drawn: where each window stands, the edit
//!   shot is the shell's panel fill over the play shot (PANEL composited over what was there,
//!   pixel by pixel) on a large share of the box, and the shot after the editor closed is not;
//! - the selection highlight and the gizmo are drawn: once `door_2` is selected, many more
//!   pixels are the highlight's colour and each gizmo axis's colour than with nothing selected
//!   (the same view, so the chamber's own orange and red cancel out);
//! - the chamber stays lit under the editor, and the run ends by Quit.

use std::path::Path;
use std::sync::Arc;
use std::sync::atomic::AtomicBool;

use candela::app::edit::PRIMARY_COLOUR;
use candela::app::shell::{Cue, LevelStart, ShellConfig, ShellInput};
use candela::app::{UserDirs, WindowConfig, WindowEnd, run_game};
use candela::render::RenderConfig;
use candela::render::scaling::ScalingTarget;
use candela_tests::repo;
use candela_tests::xvfb::{set_environment, start_xvfb};
use image::RgbImage;
use reflect::game::ReflectGame;
use reflect::world::ReflectWorld;

const WIDTH: u32 = 1280;
const HEIGHT: u32 = 720;

fn open(path: &Path) -> RgbImage {
    let img = image::open(path)
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
        .to_rgb8();
    assert_eq!(img.dimensions(), (WIDTH, HEIGHT), "{}", path.display());
    img
}

/// Pixels of `img` within `tolerance` (per channel) of `colour`.
fn near(img: &RgbImage, colour: [u8; 3], tolerance: i32) -> usize {
    img.pixels()
        .filter(|p| {
            p.0.iter()
                .zip(colour)
                .all(|(&a, b)| (i32::from(a) - i32::from(b)).abs() <= tolerance)
        })
        .count()
}

/// Share of the pixel box (x0, y0, x1, y1) where `shot` is the shell's window fill composited
/// over `under` (premultiplied PANEL: 10, 11, 16 at alpha 232), within 10 per channel.
fn panel_over(shot: &RgbImage, under: &RgbImage, b: (u32, u32, u32, u32)) -> f64 {
    let fill = [10.0, 11.0, 16.0];
    let keep = 1.0 - 232.0 / 255.0;
    let (mut hits, mut n) = (0usize, 0usize);
    for y in b.1..b.3 {
        for x in b.0..b.2 {
            let (s, u) = (shot.get_pixel(x, y).0, under.get_pixel(x, y).0);
            let ok = (0..3).all(|c| {
                let expected = fill[c] + keep * f64::from(u[c]);
                (f64::from(s[c]) - expected).abs() <= 10.0
            });
            hits += usize::from(ok);
            n += 1;
        }
    }
    hits as f64 / n.max(1) as f64
}

fn mean_luma(img: &RgbImage) -> f64 {
    let sum: f64 = img
        .pixels()
        .map(|p| 0.2126 * f64::from(p[0]) + 0.7152 * f64::from(p[1]) + 0.0722 * f64::from(p[2]))
        .sum();
    sum / f64::from(WIDTH * HEIGHT)
}

#[test]
fn the_editor_draws_its_windows_highlight_and_gizmo_over_the_traced_chamber() {
    // Changes process-wide state: alone in its process under any test runner.
    if !candela_tests::alone::alone_in_process(
        "editor_window::the_editor_draws_its_windows_highlight_and_gizmo_over_the_traced_chamber",
    ) {
        return;
    }
    let out = repo().join("target/editor_window");
    let _ = std::fs::remove_dir_all(&out);
    std::fs::create_dir_all(&out).expect("screenshot folder");
    let shot = |name: &str| out.join(format!("{name}.png"));
    let xvfb = start_xvfb();
    set_environment(&xvfb.display, &out);
    let (path, root) =
        reflect::cli::locate(Some(&repo().join("assets/reflect/reflect.ron"))).expect("game file");
    let world = ReflectWorld::load(&path, &root).expect("the world loads");
    let cues = vec![
        Cue::input(
            10,
            ShellInput::Start(LevelStart {
                level: "chamber_2".into(),
                checkpoint: None,
            }),
        ),
        Cue::screenshot(60, shot("play")),
        Cue::input(2, ShellInput::EditorToggle),
        Cue::screenshot(40, shot("edit")),
        Cue::editor(2, |mode| {
            let state = &mut mode.state;
            let panel = state
                .doc
                .level
                .instances
                .iter()
                .position(|i| i.name.as_deref() == Some("door_2"));
            state.selection.set(panel);
        }),
        Cue::screenshot(40, shot("selected")),
        Cue::input(2, ShellInput::EditorToggle),
        Cue::screenshot(20, shot("played_from_here")),
        Cue::input(2, ShellInput::Quit),
    ];
    play_in_window(world, &out, cues);

    let play = open(&shot("play"));
    let edit = open(&shot("edit"));
    let selected = open(&shot("selected"));
    let after = open(&shot("played_from_here"));
    let lit = mean_luma(&selected);
    eprintln!("luma under the editor {lit:.1}");
    assert!(lit > 15.0, "the chamber is lit under the editor: {lit}");
    // The windows, at their default places (points are pixels at 720 px high).
    for (name, b) in [
        ("outliner", (20, 100, 250, 300)),
        ("inspector", (980, 100, 1260, 200)),
        ("toolbar", (560, 660, 720, 700)),
    ] {
        let open = panel_over(&edit, &play, b);
        // The negative control: the same measure once the editor is closed again.
        let closed = panel_over(&after, &play, b);
        eprintln!("{name}: panel fill over the play shot on {open:.3}, closed {closed:.3}");
        assert!(open > 0.4, "the {name} window is drawn: {open:.3}");
        assert!(
            open > closed + 0.25,
            "the {name} window goes with the editor: {open:.3} open, {closed:.3} closed"
        );
    }
    // The highlight and the gizmo's axes appear with the selection. The axis under the
    // pointer is drawn in the hot colour instead of its own, so each axis counts either.
    let p = PRIMARY_COLOUR;
    let hot = [255, 220, 60];
    let count = |img: &RgbImage, colour: [u8; 3]| near(img, colour, 24);
    let either = |img: &RgbImage, colour: [u8; 3]| near(img, colour, 24) + near(img, hot, 10);
    let checks: [(&str, usize, usize, usize); 4] = [
        (
            "highlight",
            count(&selected, [p.r(), p.g(), p.b()]),
            count(&edit, [p.r(), p.g(), p.b()]),
            150,
        ),
        (
            "gizmo X",
            either(&selected, [230, 70, 70]),
            either(&edit, [230, 70, 70]),
            40,
        ),
        (
            "gizmo Y",
            either(&selected, [90, 210, 90]),
            either(&edit, [90, 210, 90]),
            40,
        ),
        (
            "gizmo Z",
            either(&selected, [80, 130, 240]),
            either(&edit, [80, 130, 240]),
            20,
        ),
    ];
    for (name, with, without, least) in checks {
        eprintln!("{name}: {with} pixels selected, {without} before");
        assert!(
            with >= without + least,
            "the {name} is drawn: {with} pixels with the selection, {without} without"
        );
    }
}

/// Plays Reflect's second chamber (index 1) in a 1280 × 720 window on the Xvfb display already
/// set, running `cues` with the shell's user folders under `out/user`, on the CPU tracer with
/// workload scaling holding 30 fps; asserts that the run ended by Quit. The editor tests in a
/// window (this file's and `editor_session.rs`) share it.
pub(crate) fn play_in_window(world: ReflectWorld, out: &Path, cues: Vec<Cue>) {
    let mut game = ReflectGame::new(world, 1);
    game.inner_mut().use_shell_hud();
    let config = WindowConfig {
        title: "Reflect".into(),
        size: (WIDTH, HEIGHT),
        show_stats: false,
        stop: Arc::new(AtomicBool::new(false)),
        ..WindowConfig::default()
    };
    let shell = ShellConfig {
        dirs: UserDirs::under(&out.join("user"), "reflect").expect("dirs"),
        cues,
    };
    let render = RenderConfig {
        scaling: Some(ScalingTarget::new(1.0 / 30.0)),
        ..RenderConfig::cpu(WIDTH, HEIGHT)
    };
    let environment = game.inner().environment();
    let report = run_game(config, shell, render, environment, &mut game)
        .expect("Reflect runs in the Xvfb window");
    eprintln!("{} frames in {:.1} s", report.frames, report.seconds);
    assert_eq!(report.ended_by, WindowEnd::Quit);
}
