//! The profiler (issue 30, F5): with puffin's scopes on, engine frames run headless record the
//! frame's phases and systems nested as `Engine::frame` runs them on the main thread, and the
//! render thread's apply / trace / denoise scopes inside its "render frame"; with the scopes
//! off nothing is recorded. The view lays the scope and thread names out in an egui pass.

use candela::app::{
    Engine, Environment, FrameTime, Phase, ProfileFrame, ProfileRecorder, ProfilerState, ScopeBar,
    Step, ThreadScopes, profiler_window,
};
use candela::assets::AssetRoot;
use candela::level::load_level;
use candela::render::RenderConfig;

/// A glowing crate falling on a floor: a physics step, an instance move, a TLAS and a light
/// table build every frame.
const LEVEL: &str = r#"Level(
    materials: [(name: "grey", kind: Diffuse), (name: "glow", kind: Diffuse, emission: (5, 5, 5))],
    grids: [(name: "floor", size: (10, 10), divisions: (1, 1), material: "grey")],
    boxes: [(name: "crate", size: (0.6, 0.6, 0.6), material: "glow")],
    instances: [
        (model: "floor", body: Static(shape: Trimesh)),
        (model: "crate", name: "crate", transform: (translation: (0, 3, 0)), body: Dynamic(shape: Box, mass: 20)),
    ],
    camera: (position: (0, 2, 6), look_at: (0, 0, 0), vertical_fov_deg: 45),
)"#;

/// Every recorded frame still kept, oldest first.
fn kept_frames(recorder: &ProfileRecorder) -> Vec<ProfileFrame> {
    recorder
        .recent(1000)
        .iter()
        .filter_map(|f| recorder.frame(Some(f.index)))
        .collect()
}

/// The first kept frame whose thread holding `top` holds all of `scopes`.
fn frame_with<'a>(frames: &'a [ProfileFrame], top: &str, scopes: &[&str]) -> &'a ThreadScopes {
    frames
        .iter()
        .filter_map(|f| f.thread_with(top))
        .find(|t| scopes.iter().all(|s| t.find(s).is_some()))
        .unwrap_or_else(|| {
            let seen: Vec<Vec<&str>> = frames
                .iter()
                .flat_map(|f| &f.threads)
                .map(|t| t.scopes.iter().map(|s| s.name.as_str()).collect())
                .collect();
            panic!("no recorded frame has {top:?} with {scopes:?}; seen: {seen:?}")
        })
}

#[test]
fn engine_frames_record_the_phases_and_systems_nested_on_both_threads() -> anyhow::Result<()> {
    let dir = std::env::temp_dir().join(format!("candela_profiler_{}", std::process::id()));
    std::fs::create_dir_all(&dir)?;
    let path = dir.join("drop.ron");
    std::fs::write(&path, LEVEL)?;
    let scene = load_level(&path, &AssetRoot::new(&dir)?)?;
    let config = RenderConfig {
        seed: 3,
        denoise: true,
        ..RenderConfig::cpu(32, 16)
    };
    let mut engine = Engine::new(config, Environment::of(&scene.scene))?;
    engine.spawn_level(&scene);
    let mut recorder = ProfileRecorder::default();

    // Scopes off: frames record nothing.
    recorder.set_on(false);
    for _ in 0..3 {
        engine.frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})?;
        engine.wait_rendered();
    }
    recorder.set_on(true);
    assert!(
        kept_frames(&recorder).is_empty(),
        "frames with the scopes off were recorded"
    );

    // Scopes on: each frame waits for its render so that the render thread's scopes end
    // before the next frame closes puffin's frame.
    for _ in 0..6 {
        engine.frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})?;
        engine.wait_rendered();
    }
    engine.frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})?;
    recorder.set_on(false);
    let frames = kept_frames(&recorder);
    assert!(frames.len() >= 5, "{} frames recorded", frames.len());

    let phases: Vec<&str> = Phase::ALL.iter().map(|p| p.name()).collect();
    let main = frame_with(&frames, "frame", &phases);
    assert_eq!(main.scopes[0].name, "frame");
    assert_eq!(main.scopes[0].depth, 0);
    // Every phase directly inside "frame", in frame order.
    let starts: Vec<f64> = phases
        .iter()
        .map(|name| {
            let (_, bar) = main.find(name).expect("checked above");
            assert_eq!(
                bar.parent,
                Some(0),
                "{name} is not directly inside \"frame\""
            );
            bar.start_ms
        })
        .collect();
    assert!(
        starts.windows(2).all(|w| w[0] <= w[1]),
        "phases out of frame order: {phases:?} start at {starts:?} ms"
    );
    let systems = [
        ("fixed steps", "game rules"),
        ("fixed steps", "physics step"),
        ("fixed steps", "animation"),
        ("fixed steps", "level logic"),
        ("fixed steps", "audio"),
        ("pose", "skinned deform"),
        ("pose", "transforms"),
        ("scene upkeep", "extract"),
        ("scene upkeep", "instances and BLAS"),
    ];
    // The falling crate emits: its light moves rigidly, so the table is refitted, not rebuilt.
    let main = frame_with(&frames, "frame", &["physics step", "TLAS", "light refit"]);
    for (phase, system) in systems {
        assert!(
            main.nests(phase, system),
            "{system:?} is not inside {phase:?}"
        );
    }
    assert!(main.nests("scene upkeep", "TLAS"));
    assert!(main.nests("scene upkeep", "light refit"));
    assert!(!main.nests("pose", "physics step"));

    let render = frame_with(&frames, "render frame", &["trace", "denoise"]);
    assert_eq!(render.name, "candela-render");
    assert_ne!(main.name, render.name, "both threads' scopes in one stream");
    for (outer, inner) in [
        ("render frame", "apply commit"),
        ("render frame", "trace"),
        ("trace", "trace tiles"),
        ("trace", "film blend"),
        ("render frame", "denoise"),
        ("denoise", "guides"),
        ("denoise", "svgf"),
    ] {
        assert!(
            render.nests(outer, inner),
            "{inner:?} is not inside {outer:?}"
        );
    }
    drop(engine.shutdown());
    let _ = std::fs::remove_dir_all(&dir);
    Ok(())
}

fn bar(name: &str, depth: usize, parent: Option<usize>, start_ms: f64, ms: f64) -> ScopeBar {
    ScopeBar {
        name: name.into(),
        data: String::new(),
        depth,
        parent,
        start_ms,
        duration_ms: ms,
    }
}

/// Every piece of text in `shapes`.
fn texts(shapes: &[egui::epaint::ClippedShape]) -> Vec<String> {
    fn walk(shape: &egui::Shape, out: &mut Vec<String>) {
        match shape {
            egui::Shape::Text(t) => out.push(t.galley.text().to_string()),
            egui::Shape::Vec(v) => v.iter().for_each(|s| walk(s, out)),
            _ => {}
        }
    }
    let mut out = Vec::new();
    shapes.iter().for_each(|c| walk(&c.shape, &mut out));
    out
}

#[test]
fn the_view_lays_out_the_threads_and_their_scopes() {
    let frame = ProfileFrame {
        index: 41,
        duration_ms: 20.0,
        threads: vec![
            ThreadScopes {
                name: "main".into(),
                scopes: vec![
                    bar("frame", 0, None, 0.0, 12.0),
                    bar("fixed steps", 1, Some(0), 0.5, 8.0),
                    bar("physics step", 2, Some(1), 1.0, 5.0),
                ],
            },
            ThreadScopes {
                name: "candela-render".into(),
                scopes: vec![
                    bar("render frame", 0, None, 2.0, 18.0),
                    bar("trace", 1, Some(0), 3.0, 14.0),
                ],
            },
        ],
    };
    let frames: Vec<FrameTime> = (30..42)
        .map(|index| FrameTime {
            index,
            duration_ms: 15.0 + index as f64 * 0.1,
        })
        .collect();
    let context = egui::Context::default();
    let mut state = ProfilerState::default();
    let mut shown = Vec::new();
    // Two passes: egui sizes a new window in the first.
    for _ in 0..2 {
        let input = egui::RawInput {
            screen_rect: Some(egui::Rect::from_min_size(
                egui::Pos2::ZERO,
                egui::vec2(1280.0, 720.0),
            )),
            ..Default::default()
        };
        let output = context.run_pass(input, |ctx| {
            profiler_window(ctx, &mut state, &frames, Some(&frame));
        });
        shown = texts(&output.shapes);
    }
    for wanted in [
        "Profiler (F5)",
        "frame 41: 20.00 ms, 2 threads",
        "main",
        "candela-render",
        "frame 12.00 ms",
        "fixed steps 8.00 ms",
        "physics step 5.00 ms",
        "render frame 18.00 ms",
        "trace 14.00 ms",
    ] {
        assert!(
            shown.iter().any(|t| t == wanted),
            "{wanted:?} is not laid out; the texts are {shown:?}"
        );
    }
    assert_eq!(state, ProfilerState::default(), "drawing changed the state");
}

/// Opens and closes `n` scopes inside one top scope ("cost loop"); returns the nanoseconds per
/// inner scope.
fn scope_loop(n: u32) -> f64 {
    let started = std::time::Instant::now();
    {
        puffin::profile_scope!("cost loop");
        for i in 0..n {
            puffin::profile_scope!("cost scope");
            std::hint::black_box(i);
        }
    }
    started.elapsed().as_secs_f64() * 1e9 / f64::from(n)
}

/// What a scope costs, off and on, printed (`--no-capture`; `docs/PERFORMANCE.md`, "The
/// profiler's cost"); asserted is only what is recorded: nothing off, every scope on.
#[test]
fn scopes_off_record_nothing_and_scopes_on_record_each_one() {
    const N: u32 = 100_000;
    let mut recorder = ProfileRecorder::default();
    recorder.set_on(false);
    let off_ns = scope_loop(N);
    puffin::GlobalProfiler::lock().new_frame();
    assert!(recorder.recent(10).is_empty(), "scopes off were recorded");
    recorder.set_on(true);
    let on_ns = scope_loop(N);
    puffin::GlobalProfiler::lock().new_frame();
    recorder.set_on(false);
    let frame = recorder.frame(None).expect("a frame was recorded");
    let thread = frame.thread_with("cost loop").expect("the loop's thread");
    let inner = thread
        .scopes
        .iter()
        .filter(|s| s.name == "cost scope")
        .count();
    assert_eq!(inner, N as usize);
    assert!(thread.nests("cost loop", "cost scope"));
    println!("one scope: {off_ns:.2} ns with the scopes off, {on_ns:.1} ns on");
}
