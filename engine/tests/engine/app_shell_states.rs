//! The shell's pure logic, without a window or an engine: the screens' state machine (Title →
//! Playing ⇄ Paused → Ending → Title, Settings returning where it was opened from, the F1
//! editor hook, focus lost pausing, Quit from anywhere), which screens run the game and
//! capture the mouse, the settings screen's model (rebinding by a press keeps gamepad
//! bindings, Escape cancels, conflicts are found, reset), and where Continue starts.

use candela::app::shell::{
    LevelEntry, LevelStart, Screen, SettingsEditor, ShellEffect, ShellInfo, ShellInput, ShellState,
    action_label, binding_label, continue_label, continue_point,
};
use candela::app::{
    ActionSet, Binding, KeyCode, MouseButton, PadButton, Progress, Settings, game_actions,
};
use candela::sim::triggers::Outcome;

fn start(level: &str) -> LevelStart {
    LevelStart {
        level: level.into(),
        checkpoint: None,
    }
}

#[test]
fn the_screens_follow_the_menus_and_the_pause_action() {
    use ShellInput as I;
    let mut s = ShellState::new();
    assert_eq!(s.screen(), Screen::Title);
    assert!(!s.simulating() && !s.wants_mouse());
    // Pause and Resume mean nothing at the title.
    assert!(s.handle(I::Pause).is_empty());
    assert_eq!(s.screen(), Screen::Title);
    // Title → Settings → back to Title.
    s.handle(I::OpenSettings);
    assert_eq!(s.screen(), Screen::Settings);
    s.handle(I::Pause);
    assert_eq!(s.screen(), Screen::Title, "Escape leaves settings");
    // Start a level.
    let effects = s.handle(I::Start(start("one")));
    assert_eq!(effects, vec![ShellEffect::BeginLevel(start("one"))]);
    assert_eq!(s.screen(), Screen::Playing);
    assert!(s.simulating() && s.wants_mouse());
    // Playing ⇄ Paused by the pause action, Resume, focus lost.
    s.handle(I::Pause);
    assert_eq!(s.screen(), Screen::Paused);
    assert!(!s.simulating() && !s.wants_mouse());
    s.handle(I::Pause);
    assert_eq!(s.screen(), Screen::Playing);
    s.handle(I::FocusLost);
    assert_eq!(s.screen(), Screen::Paused);
    s.handle(I::Resume);
    assert_eq!(s.screen(), Screen::Playing);
    // Paused → Settings → CloseSettings returns to Paused, not Title.
    s.handle(I::Pause);
    s.handle(I::OpenSettings);
    assert_eq!(s.screen(), Screen::Settings);
    assert!(!s.simulating());
    s.handle(I::CloseSettings);
    assert_eq!(s.screen(), Screen::Paused);
    // The editor hook: from Paused and from Playing, F1 goes back where it came from.
    s.handle(I::EditorToggle);
    assert_eq!(s.screen(), Screen::Editor);
    assert!(!s.simulating(), "the editor hook holds the game");
    s.handle(I::EditorToggle);
    assert_eq!(s.screen(), Screen::Paused);
    s.handle(I::Resume);
    s.handle(I::EditorToggle);
    assert_eq!(s.screen(), Screen::Editor);
    s.handle(I::EditorToggle);
    assert_eq!(s.screen(), Screen::Playing);
    // Settings are not reachable while playing (pause first).
    s.handle(I::OpenSettings);
    assert_eq!(s.screen(), Screen::Playing);
    // The level ends: Ending, with the outcome recorded; Continue goes to the title.
    let won = Outcome::Won("exit".into());
    let effects = s.handle(I::LevelEnded(won.clone()));
    assert_eq!(effects, vec![ShellEffect::RecordEnd(won.clone())]);
    assert_eq!(s.screen(), Screen::Ending);
    assert_eq!(s.outcome(), Some(&won));
    assert_eq!(s.level(), Some(&start("one")));
    assert!(s.handle(I::Pause).is_empty());
    assert_eq!(
        s.screen(),
        Screen::Ending,
        "Escape does not skip the ending"
    );
    s.handle(I::QuitToTitle);
    assert_eq!(s.screen(), Screen::Title);
    // Quit to title from the pause menu saves progress; Quit exits from anywhere.
    s.handle(I::Start(start("two")));
    s.handle(I::Pause);
    assert_eq!(s.handle(I::QuitToTitle), vec![ShellEffect::SaveProgress]);
    assert_eq!(s.screen(), Screen::Title);
    assert_eq!(s.handle(I::Quit), vec![ShellEffect::Exit]);
    s.handle(I::Start(start("two")));
    assert_eq!(s.handle(I::Quit), vec![ShellEffect::Exit]);
    // A level end outside play (at the title) changes nothing.
    let mut t = ShellState::new();
    assert!(t.handle(I::LevelEnded(won)).is_empty());
    assert_eq!(t.screen(), Screen::Title);
}

#[test]
fn a_gamepad_button_rebinds_the_pad_binding_and_keeps_the_keys() {
    let set = ActionSet::standard();
    let mut e = SettingsEditor::new(Settings::default(), set.clone());
    // Click "Jump", press the pad's North: it replaces South, Space stays.
    e.start_rebind(game_actions::JUMP);
    assert!(e.offer(Binding::Pad(PadButton::North)));
    assert_eq!(e.capturing(), None);
    assert_eq!(
        e.bindings_of(game_actions::JUMP),
        vec![Binding::Key(KeyCode::Space), Binding::Pad(PadButton::North)]
    );
    assert!(e.draft.check(&set).is_ok());
    // A key afterwards replaces the key and keeps the new pad button.
    e.start_rebind(game_actions::JUMP);
    e.offer(Binding::Key(KeyCode::KeyJ));
    assert_eq!(
        e.bindings_of(game_actions::JUMP),
        vec![Binding::Key(KeyCode::KeyJ), Binding::Pad(PadButton::North)]
    );
    // Pressing the defaults again stores nothing: the settings file stays clean.
    e.start_rebind(game_actions::JUMP);
    e.offer(Binding::Pad(PadButton::South));
    e.start_rebind(game_actions::JUMP);
    e.offer(Binding::Key(KeyCode::Space));
    assert_eq!(e.draft.bindings.0.get(game_actions::JUMP), None);
    // Two actions on one pad button are a conflict like two on one key.
    let pad_of_use = e
        .bindings_of(game_actions::USE)
        .into_iter()
        .find(|b| matches!(b, Binding::Pad(_)))
        .expect("Use has a default pad button");
    e.start_rebind(game_actions::JUMP);
    e.offer(pad_of_use);
    assert_eq!(e.conflicts().len(), 1, "{:?}", e.conflicts());
    assert_eq!(e.conflicts()[0].binding, pad_of_use);
}

#[test]
fn rebinding_takes_the_next_press_keeps_pad_bindings_and_finds_conflicts() {
    let set = ActionSet::standard();
    let mut e = SettingsEditor::new(Settings::default(), set.clone());
    let buttons = e.rebindable();
    assert!(buttons.iter().any(|a| a == game_actions::JUMP));
    assert!(
        !buttons.iter().any(|a| a == game_actions::LOOK_X),
        "motion actions are not rebound by a press"
    );
    assert!(
        e.conflicts().is_empty(),
        "the standard set has no conflicts"
    );
    // A press with nothing waiting is not used.
    assert!(!e.offer(Binding::Key(KeyCode::KeyJ)));
    // Click "Jump", press J: the key replaces Space, the pad's South stays.
    e.start_rebind(game_actions::JUMP);
    assert_eq!(e.capturing(), Some(game_actions::JUMP));
    assert!(e.offer(Binding::Key(KeyCode::KeyJ)));
    assert_eq!(e.capturing(), None);
    assert_eq!(
        e.bindings_of(game_actions::JUMP),
        vec![Binding::Key(KeyCode::KeyJ), Binding::Pad(PadButton::South)]
    );
    assert!(e.draft.check(&set).is_ok());
    // Escape cancels: nothing changes.
    e.start_rebind(game_actions::USE);
    assert!(e.offer(Binding::Key(KeyCode::Escape)));
    assert_eq!(e.draft.bindings.0.get(game_actions::USE), None);
    // Bind Use to J as well: a conflict naming both actions.
    e.start_rebind(game_actions::USE);
    e.offer(Binding::Key(KeyCode::KeyJ));
    let conflicts = e.conflicts();
    assert_eq!(conflicts.len(), 1, "{conflicts:?}");
    assert_eq!(conflicts[0].binding, Binding::Key(KeyCode::KeyJ));
    assert_eq!(
        conflicts[0].actions,
        vec![
            game_actions::JUMP.to_string(),
            game_actions::USE.to_string()
        ]
    );
    assert!(e.in_conflict(game_actions::USE) && !e.in_conflict(game_actions::RUN));
    // A mouse button works too; binding back to the default stores nothing.
    e.start_rebind(game_actions::USE);
    e.offer(Binding::Mouse(MouseButton::Middle));
    assert!(e.conflicts().is_empty());
    e.start_rebind(game_actions::JUMP);
    e.offer(Binding::Key(KeyCode::Space));
    assert_eq!(e.draft.bindings.0.get(game_actions::JUMP), None);
    // Unknown actions cannot be picked; reset brings back every default.
    e.start_rebind("no_such_action");
    assert_eq!(e.capturing(), None);
    e.draft.master_volume = 0.25;
    e.reset_all();
    assert_eq!(e.draft, Settings::default());
    // Labels.
    assert_eq!(binding_label(&Binding::Key(KeyCode::KeyW)), "W");
    assert_eq!(binding_label(&Binding::Key(KeyCode::Space)), "Space");
    assert_eq!(
        binding_label(&Binding::Key(KeyCode::ShiftLeft)),
        "Left Shift"
    );
    assert_eq!(binding_label(&Binding::Key(KeyCode::ArrowUp)), "Up");
    assert_eq!(
        binding_label(&Binding::Mouse(MouseButton::Left)),
        "Mouse left"
    );
    assert_eq!(action_label("primary_fire"), "Primary fire");
}

#[test]
fn continue_starts_at_the_first_unfinished_level_and_its_checkpoint() {
    let info = ShellInfo {
        title: "Test".into(),
        subtitle: String::new(),
        levels: ["a", "b", "c"]
            .into_iter()
            .map(|id| LevelEntry {
                id: id.into(),
                name: id.to_uppercase(),
            })
            .collect(),
        finished_only: false,
    };
    let mut progress = Progress::default();
    assert_eq!(continue_point(&info, &progress), None, "nothing played yet");
    progress.reach_checkpoint("a", "hall");
    assert_eq!(
        continue_point(&info, &progress),
        Some(LevelStart {
            level: "a".into(),
            checkpoint: Some("hall".into())
        })
    );
    let hall = continue_point(&info, &progress).expect("a checkpoint was reached");
    assert_eq!(continue_label(&info, &hall), "Continue  ·  A  ·  hall");
    // A checkpoint that names a level (Reflect's chambers) shows that level's name, not its id.
    progress.reach_checkpoint("a", "b");
    let at_b = continue_point(&info, &progress).expect("a checkpoint was reached");
    assert_eq!(continue_label(&info, &at_b), "Continue  ·  B");
    progress.finish_level("a");
    assert_eq!(continue_point(&info, &progress), Some(start("b")));
    assert_eq!(continue_label(&info, &start("b")), "Continue  ·  B");
    progress.finish_level("b");
    progress.finish_level("c");
    assert_eq!(continue_point(&info, &progress), None, "all finished");
}
