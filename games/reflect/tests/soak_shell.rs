//! The shell soak in CI (`reflect --soak-shell 100000` is the same code with a larger count
//! and an episode every 10 s): 4,000 frames of the whole game inside its shell with the
//! monkey playing and, about every 2 s of play, pausing, opening the settings (a setting
//! changed and saved), the editor (a click that selects, a gizmo drag, Ctrl+Z), quitting to
//! the title to continue from the save read back, or starting another chamber. Every action
//! must have taken effect at least once (`ActionCounts::missing`: with the editor's episodes
//! disabled, this test fails naming "editor opened", "editor select", …), the per-frame checks
//! must have run on every screen (playing, paused, settings, editor, title), no NaN, nothing
//! out of the world, and memory after the warm-up must not grow by more than a leak of one
//! small allocation per frame would.

use reflect::world::ReflectWorld;

#[test]
fn the_monkey_pauses_edits_saves_and_changes_chambers_and_every_frame_is_checked()
-> anyhow::Result<()> {
    let (path, root) = reflect::cli::locate(None)?;
    let world = ReflectWorld::load(&path, &root)?;
    let r = reflect::soak::soak_shell(&world, 4000, 1, 120, Vec::new())?;
    println!("{}", reflect::soak::shell_table(&r, 1));
    assert_eq!(r.soak.frames, 4000);
    assert_eq!(r.soak.film_checks, 8, "a film check every 500 frames");
    assert_eq!(
        r.counts.missing(),
        Vec::<&str>::new(),
        "actions that never took effect: {:?}",
        r.counts
    );
    for screen in ["Playing", "Paused", "Settings", "Editor", "Title"] {
        assert!(
            r.checked.get(screen).copied().unwrap_or(0) > 0,
            "no frame checked on the {screen} screen: {:?}",
            r.checked
        );
    }
    assert_eq!(r.checked.values().sum::<u64>(), 4000, "every frame checked");
    assert!(r.soak.rss_warm > 0, "resident memory was not read");
    assert!(
        r.soak.growth() < 64 << 20,
        "resident memory grew by {} MiB after the warm-up",
        r.soak.growth() >> 20
    );
    Ok(())
}
