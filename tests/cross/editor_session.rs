//! A short edit session in Reflect's window under Xvfb, played with real X input (`xdotool`,
//! issue 33): chamber 1 is played for a moment, F1 opens the editor, P over the floor places
//! the palette's current piece (a `pillar`) there, a drag on the gizmo's X handle moves it,
//! Ctrl+Z and Ctrl+Shift+Z undo and redo the move, and Ctrl+S saves. One window run per
//! process, so one test.
//!
//! The game runs on a scratch copy of Reflect's and the common assets
//! (`target/editor_session/assets/`), never on `assets/`. Checked:
//! - each step did what it should (the piece appears, moves along X only, undo puts it back,
//!   redo moves it again, the save leaves the document clean);
//! - the saved `chamber_1.ron` differs from the committed one by exactly one added line, the
//!   placed piece's instance with the moved transform, and reads as the committed level plus
//!   that instance; `common.ron` keeps its bytes;
//! - the last screenshot (`target/editor_session/session.png`) shows the editor's windows.
//!   With `CANDELA_WRITE_DOCS=1` it is also copied to `docs/editor.png`, the picture of
//!   `docs/EDITOR.md` and `docs/LEVELS.md` (the command is written there).
//!
//! The X input is sent from `Cue::call` steps, so it lands between known frames; the editor's
//! camera and gizmo are read from `Cue::editor` steps to know where to point.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::{Arc, Mutex};

use candela::app::shell::{Cue, LevelStart, ShellInput};
use candela::assets::Level;
use candela::editor::PaletteItem;
use candela_tests::repo;
use candela_tests::xvfb::{set_environment, start_xvfb};
use glam::{Vec2, Vec3};
use reflect::world::ReflectWorld;

const WIDTH: u32 = 1280;
const HEIGHT: u32 = 720;
const PIECE: &str = "pillar";
/// How far the drag moves the pointer along the X handle's screen direction, in pixels.
const DRAG_PIXELS: f32 = 80.0;

/// What the editor steps saw, read after the run.
#[derive(Default, Debug)]
struct Seen {
    /// Where to point at the floor (window pixels), and where the X handle's grab point is.
    floor_px: Option<Vec2>,
    handle: Option<(Vec2, Vec2)>,
    /// The instance count when the editor opened.
    count: usize,
    placed: Option<Vec3>,
    moved: Option<Vec3>,
    undone: Option<Vec3>,
    redone: Option<Vec3>,
    dirty_after_save: Option<bool>,
}

fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).expect("scratch folder");
    for entry in std::fs::read_dir(from).expect("asset folder") {
        let entry = entry.expect("entry");
        let target = to.join(entry.file_name());
        if entry.file_type().expect("type").is_dir() {
            copy_dir(&entry.path(), &target);
        } else {
            std::fs::copy(entry.path(), &target).expect("copy");
        }
    }
}

/// Runs `xdotool` with `args` on `display` (XTEST input, as a person's); panics when it fails.
fn xdotool(display: &str, args: &[&str]) {
    let status = Command::new("xdotool")
        .args(args)
        .env("DISPLAY", display)
        .status()
        .unwrap_or_else(|e| panic!("xdotool is not installed (Debian package xdotool): {e}"));
    assert!(status.success(), "xdotool {args:?}: {status}");
}

/// Moves the pointer to window pixel `p` (the window sits at the screen's origin).
fn point(display: &str, p: Vec2) {
    let (x, y) = (format!("{:.0}", p.x), format!("{:.0}", p.y));
    xdotool(display, &["mousemove", "--sync", &x, &y]);
}

/// The instance `index`'s translation, metres.
fn translation(mode: &candela::app::edit::EditMode, index: usize) -> Option<Vec3> {
    let entry = mode.state.doc.level.instances.get(index)?;
    Some(Vec3::from(entry.transform.translation))
}

#[test]
fn an_edit_session_in_reflects_window_saves_exactly_the_placed_and_moved_piece() {
    // Changes process-wide state: alone in its process under any test runner.
    if !candela_tests::alone::alone_in_process(
        "editor_session::an_edit_session_in_reflects_window_saves_exactly_the_placed_and_moved_piece",
    ) {
        return;
    }
    let out = repo().join("target/editor_session");
    let _ = std::fs::remove_dir_all(&out);
    let assets = out.join("assets");
    for folder in ["reflect", "common"] {
        copy_dir(&repo().join("assets").join(folder), &assets.join(folder));
    }
    let shot: PathBuf = out.join("session.png");
    let xvfb = start_xvfb();
    set_environment(&xvfb.display, &out);
    let display = xvfb.display.clone();
    let (path, root) =
        reflect::cli::locate(Some(&assets.join("reflect/reflect.ron"))).expect("game file");
    let world = ReflectWorld::load(&path, &root).expect("the world loads");
    let seen = Arc::new(Mutex::new(Seen::default()));
    let size = Vec2::new(WIDTH as f32, HEIGHT as f32);

    let d = display.clone();
    let key = move |wait: u32, keys: &'static str| {
        let d = d.clone();
        Cue::call(wait, move || xdotool(&d, &["key", keys]))
    };
    let d = display.clone();
    let s = seen.clone();
    let to_floor = Cue::call(2, move || {
        let p = s
            .lock()
            .expect("seen")
            .floor_px
            .expect("F1 opened the editor");
        point(&d, p);
    });
    let d = display.clone();
    let s = seen.clone();
    let to_handle = Cue::call(2, move || {
        let (grab, _) = s.lock().expect("seen").handle.expect("the X handle");
        point(&d, grab);
    });
    let d = display.clone();
    let press = Cue::call(3, move || xdotool(&d, &["mousedown", "1"]));
    let d = display.clone();
    let release = Cue::call(3, move || xdotool(&d, &["mouseup", "1"]));
    let drag_step = |k: u32| {
        let (d, s) = (display.clone(), seen.clone());
        Cue::call(3, move || {
            let (grab, dir) = s.lock().expect("seen").handle.expect("the X handle");
            point(&d, grab + dir * DRAG_PIXELS * k as f32 / 4.0);
        })
    };
    let record = |wait: u32, what: fn(&mut Seen, Option<Vec3>)| {
        let s = seen.clone();
        Cue::editor(wait, move |mode| {
            let mut seen = s.lock().expect("seen");
            let at = translation(mode, seen.count);
            what(&mut seen, at);
        })
    };
    let s = seen.clone();
    let opened = Cue::editor(20, move |mode| {
        // The piece P places, and the floor 9 m ahead of the editor camera (in the view above
        // the toolbar, which takes the pointer where it stands).
        mode.state.palette.current = Some(PaletteItem::Model(PIECE.into()));
        let camera = mode.camera.expect("the editor camera");
        let flat = Vec3::new(1.0, 0.0, 1.0);
        let ahead = (camera.forward() * flat).normalize();
        let floor = Vec3::from(camera.desc().position) * flat + ahead * 9.0;
        let px = candela::app::edit::project(&camera.desc(), size, floor).expect("in view");
        let mut seen = s.lock().expect("seen");
        seen.floor_px = Some(px);
        seen.count = mode.state.doc.level.instances.len();
    });
    let s = seen.clone();
    let placed = Cue::editor(10, move |mode| {
        let mut seen = s.lock().expect("seen");
        seen.placed = translation(mode, seen.count);
        let entry = mode.state.doc.level.instances.get(seen.count);
        let camera = mode.camera.expect("the editor camera").desc();
        let handles = entry.and_then(|e| mode.gizmo.handles(&camera, size, e));
        seen.handle = handles.and_then(|h| {
            let end = h.ends_px[0]?;
            let dir = (end - h.centre_px).normalize_or_zero();
            Some((h.centre_px.lerp(end, 0.7), dir))
        });
    });
    let s = seen.clone();
    let saved = Cue::editor(10, move |mode| {
        s.lock().expect("seen").dirty_after_save = Some(mode.state.dirty());
    });
    let d = display.clone();
    let cues = vec![
        Cue::input(
            10,
            ShellInput::Start(LevelStart {
                level: "chamber_1".into(),
                checkpoint: None,
            }),
        ),
        // No window manager: the test gives the window the keyboard.
        Cue::call(40, move || {
            xdotool(&d, &["search", "--name", "^Reflect$", "windowfocus"]);
            point(&d, Vec2::new(640.0, 360.0));
        }),
        key(2, "F1"),
        opened,
        to_floor,
        key(3, "p"),
        placed,
        to_handle,
        press,
        drag_step(1),
        drag_step(2),
        drag_step(3),
        drag_step(4),
        release,
        record(10, |s, at| s.moved = at),
        key(2, "ctrl+z"),
        record(10, |s, at| s.undone = at),
        key(2, "ctrl+shift+z"),
        record(10, |s, at| s.redone = at),
        key(2, "ctrl+s"),
        saved,
        Cue::screenshot(30, &shot),
        Cue::input(2, ShellInput::Quit),
    ];
    crate::editor_window::play_in_window(world, &out, cues);

    let seen = seen.lock().expect("seen");
    eprintln!("{seen:?}");
    let placed = seen.placed.expect("P placed the piece");
    let moved = seen.moved.expect("the piece is there after the drag");
    assert!(placed.y.abs() < 0.1, "placed on the floor: {placed}");
    assert!(
        (moved.x - placed.x).abs() > 0.1,
        "the drag moved it along X: {placed} → {moved}"
    );
    assert!(
        (moved.y - placed.y).abs() < 1e-4 && (moved.z - placed.z).abs() < 1e-4,
        "along X only: {placed} → {moved}"
    );
    assert_eq!(seen.undone, Some(placed), "Ctrl+Z undid the move");
    assert_eq!(seen.redone, Some(moved), "Ctrl+Shift+Z redid it");
    assert_eq!(seen.dirty_after_save, Some(false), "Ctrl+S saved");

    // The saved file against the expected edit.
    let committed = repo().join("assets/reflect/levels");
    let scratch = assets.join("reflect/levels");
    let before = std::fs::read_to_string(committed.join("chamber_1.ron")).expect("committed");
    let after = std::fs::read_to_string(scratch.join("chamber_1.ron")).expect("saved");
    let (added, removed) = line_diff(&before, &after);
    eprintln!("added {added:?}, removed {removed:?}");
    assert!(removed.is_empty(), "no line removed: {removed:?}");
    assert_eq!(added.len(), 1, "one line added: {added:?}");
    assert!(
        added[0].contains(&format!("model: \"{PIECE}\"")),
        "{}",
        added[0]
    );
    let old = Level::read(&committed.join("chamber_1.ron")).expect("committed level");
    let new = Level::read(&scratch.join("chamber_1.ron")).expect("saved level");
    let mut expected = old.clone();
    let entry = new.instances.last().expect("an instance").clone();
    assert_eq!(entry.model, PIECE);
    let at = Vec3::from(entry.transform.translation);
    assert!(
        (at - moved).length() < 1e-3,
        "saved at {at}, moved to {moved}"
    );
    expected.instances.push(entry);
    assert_eq!(
        new, expected,
        "the saved level is the committed one plus the piece"
    );
    for file in ["common.ron", "chamber_2.ron"] {
        let a = std::fs::read(committed.join(file)).expect("committed");
        let b = std::fs::read(scratch.join(file)).expect("scratch");
        assert!(a == b, "{file} keeps its bytes");
    }

    // The picture: the editor's windows over the chamber.
    let img = image::open(&shot).expect("the screenshot").to_rgb8();
    assert_eq!(img.dimensions(), (WIDTH, HEIGHT));
    let luma: f64 = img
        .pixels()
        .map(|p| f64::from(p[0]) + f64::from(p[1]) + f64::from(p[2]))
        .sum::<f64>()
        / f64::from(3 * WIDTH * HEIGHT);
    assert!(luma > 10.0, "the chamber is lit under the editor: {luma}");
    if std::env::var_os("CANDELA_WRITE_DOCS").is_some_and(|v| v == "1") {
        let docs = repo().join("docs/editor.png");
        std::fs::copy(&shot, &docs).expect("docs/editor.png");
        eprintln!("wrote {}", docs.display());
    }
}

/// The lines of `after` that `before` lacks and the lines of `before` that `after` lacks, each
/// counted (a multiset difference: the order of unchanged lines is checked by the parse).
fn line_diff(before: &str, after: &str) -> (Vec<String>, Vec<String>) {
    use std::collections::HashMap;
    let mut count: HashMap<&str, i64> = HashMap::new();
    for line in before.lines() {
        *count.entry(line).or_default() += 1;
    }
    for line in after.lines() {
        *count.entry(line).or_default() -= 1;
    }
    let mut added = Vec::new();
    let mut removed = Vec::new();
    for line in after.lines() {
        if let Some(c) = count.get_mut(line)
            && *c < 0
        {
            added.push(line.to_string());
            *c += 1;
        }
    }
    for line in before.lines() {
        if let Some(c) = count.get_mut(line)
            && *c > 0
        {
            removed.push(line.to_string());
            *c -= 1;
        }
    }
    (added, removed)
}
