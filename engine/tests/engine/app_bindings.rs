//! Named game actions and the player's bindings: the standard set, rebinding over the
//! defaults, bindings files with an unknown action, an unknown key name or a binding of the
//! wrong kind (each a clear error naming the file and the name), gamepad buttons and sticks
//! through the input state into per-step action frames, the stick dead zone, and running
//! without gamepad support.

use std::path::Path;

use anyhow::Result;
use candela::app::{
    AXIS_ONE, ActionDef, ActionFrame, ActionKind, ActionSet, ActionSetError, Binding,
    BindingProblem, Bindings, BindingsError, Gamepads, InputState, KeyCode, MAX_ACTIONS,
    MouseButton, PadAxis, PadButton, apply_dead_zone, game_actions as ga, pad_button,
};
use glam::Vec2;

#[test]
fn the_standard_set_has_every_game_action_with_defaults() {
    let set = ActionSet::standard();
    let names = [
        ga::MOVE_FORWARD,
        ga::MOVE_BACK,
        ga::MOVE_LEFT,
        ga::MOVE_RIGHT,
        ga::MOVE_X,
        ga::MOVE_Y,
        ga::LOOK_X,
        ga::LOOK_Y,
        ga::LOOK_PAD_X,
        ga::LOOK_PAD_Y,
        ga::JUMP,
        ga::RUN,
        ga::USE,
        ga::PRIMARY_FIRE,
        ga::SECONDARY_FIRE,
        ga::PAUSE,
        ga::EDITOR_TOGGLE,
    ];
    assert_eq!(set.len(), names.len());
    for (i, name) in names.iter().enumerate() {
        let id = set.id(name).unwrap_or_else(|| panic!("{name} missing"));
        assert_eq!(id.0 as usize, i);
        let def = set.def(id).expect("def");
        assert!(!def.defaults.is_empty(), "{name} has no default binding");
    }
    let kind = |n| set.def(set.id(n).expect("id")).expect("def").kind;
    assert_eq!(kind(ga::LOOK_X), ActionKind::Motion);
    assert_eq!(kind(ga::MOVE_X), ActionKind::Axis);
    assert_eq!(kind(ga::JUMP), ActionKind::Button);
    let map = set.default_map();
    assert!(map.actions[ga::JUMP].contains(&Binding::Key(KeyCode::Space)));
    assert!(map.actions[ga::JUMP].contains(&Binding::Pad(PadButton::South)));
    assert_eq!(
        map.actions[ga::PRIMARY_FIRE][0],
        Binding::Mouse(MouseButton::Left)
    );
}

#[test]
fn action_sets_refuse_duplicates_bad_names_wrong_defaults_and_overflow() {
    let def = |name: &str, kind, defaults| ActionDef {
        name: name.to_string(),
        kind,
        defaults,
    };
    let set = ActionSet::standard();
    assert_eq!(
        set.clone()
            .with(def("jump", ActionKind::Button, vec![]))
            .err(),
        Some(ActionSetError::Duplicate("jump".into()))
    );
    assert_eq!(
        set.clone()
            .with(def("Grab Thing", ActionKind::Button, vec![]))
            .err(),
        Some(ActionSetError::BadName("Grab Thing".into()))
    );
    assert!(matches!(
        set.clone().with(def(
            "aim",
            ActionKind::Axis,
            vec![Binding::Key(KeyCode::KeyQ)]
        )),
        Err(ActionSetError::WrongKind { .. })
    ));
    let many: Vec<ActionDef> = (0..=MAX_ACTIONS)
        .map(|i| def(&format!("a{i}"), ActionKind::Button, vec![]))
        .collect();
    assert_eq!(
        ActionSet::new(many).err(),
        Some(ActionSetError::TooMany { max: MAX_ACTIONS })
    );
}

#[test]
fn a_bindings_file_rebinds_over_the_defaults() -> Result<()> {
    let set = ActionSet::standard();
    let path = Path::new("levels/my_bindings.ron");
    let b = Bindings::parse(
        path,
        r#"{"jump": [Key(KeyJ), Pad(North)], "use": [], "move_x": [PadAxis(RightStickX)]}"#,
        &set,
    )?;
    let map = b.input_map(&set);
    assert_eq!(
        map.actions[ga::JUMP],
        [Binding::Key(KeyCode::KeyJ), Binding::Pad(PadButton::North)]
    );
    assert!(map.actions[ga::USE].is_empty(), "bound to nothing");
    assert_eq!(
        map.actions[ga::MOVE_X],
        [Binding::PadAxis(PadAxis::RightStickX)]
    );
    assert_eq!(
        map.actions[ga::RUN],
        set.default_map().actions[ga::RUN],
        "untouched"
    );
    let mut b = b;
    b.reset(ga::JUMP);
    assert_eq!(
        b.input_map(&set).actions[ga::JUMP],
        set.default_map().actions[ga::JUMP]
    );
    Ok(())
}

#[test]
fn unknown_actions_key_names_and_wrong_kinds_name_the_file_and_the_name() {
    let set = ActionSet::standard();
    let path = Path::new("config/bindings.ron");
    match Bindings::parse(
        path,
        r#"{"jump": [Key(Space)], "grapple": [Key(KeyG)]}"#,
        &set,
    ) {
        Err(BindingsError::Invalid {
            path: p,
            problem: BindingProblem::UnknownAction(name),
        }) => {
            assert_eq!(p, path);
            assert_eq!(name, "grapple");
        }
        other => panic!("expected an unknown action, got {other:?}"),
    }
    let e =
        Bindings::parse(path, "{\n  \"jump\": [Key(Spacebar)],\n}", &set).expect_err("no such key");
    let message = e.to_string();
    assert!(matches!(e, BindingsError::Parse { .. }), "{e:?}");
    assert!(
        message.starts_with("config/bindings.ron: line 2,"),
        "{message}"
    );
    assert!(message.contains("unknown key name `Spacebar`"), "{message}");
    assert!(message.len() < 120, "not the list of every key: {message}");
    let e =
        Bindings::parse(path, r#"{"jump": [Pad(Triangle)]}"#, &set).expect_err("no such button");
    assert!(
        e.to_string().contains("unknown gamepad button `Triangle`"),
        "{e}"
    );
    let e = Bindings::parse(path, r#"{"move_y": [Key(KeyW)]}"#, &set).expect_err("wrong kind");
    assert!(
        e.to_string()
            .contains("config/bindings.ron: action `move_y` takes axis input"),
        "{e}"
    );
    let missing = Bindings::load(Path::new("/no/such/bindings.ron"), &set).expect_err("missing");
    assert!(
        missing.to_string().contains("/no/such/bindings.ron"),
        "{missing}"
    );
}

#[test]
fn gamepad_buttons_and_sticks_reach_the_action_frame() {
    let set = ActionSet::standard();
    let mut input = InputState::new(&set.default_map());
    let id = |n| set.id(n).expect("id");
    input.pad_button(PadButton::South, true);
    input.pad_axis(PadAxis::LeftStickY, 0.5);
    input.pad_axis(PadAxis::RightStickX, -2.0); // clamped
    input.pad_axis(PadAxis::LeftStickX, f32::NAN); // read as centred
    input.mouse_motion(3.25, -1.0);
    let frame = ActionFrame::capture(&input, &set);
    assert!(frame.held(id(ga::JUMP)) && frame.pressed(id(ga::JUMP)));
    assert_eq!(
        frame.raw(id(ga::MOVE_Y)),
        (0.5 * AXIS_ONE as f32).round() as i32
    );
    assert_eq!(frame.axis(id(ga::LOOK_PAD_X)), -1.0);
    assert_eq!(frame.raw(id(ga::MOVE_X)), 0);
    assert_eq!(frame.motion(id(ga::LOOK_X)), 3.25);
    assert_eq!(frame.motion(id(ga::LOOK_Y)), -1.0);
    input.end_step();
    input.pad_button(PadButton::South, false);
    let frame = ActionFrame::capture(&input, &set);
    assert!(!frame.held(id(ga::JUMP)) && !frame.pressed(id(ga::JUMP)));
    assert_eq!(frame.motion(id(ga::LOOK_X)), 0.0, "motion is per step");
    assert_eq!(
        frame.axis(id(ga::MOVE_Y)),
        frame.raw(id(ga::MOVE_Y)) as f32 / AXIS_ONE as f32
    );
    assert!(frame.axis(id(ga::MOVE_Y)) > 0.49, "an axis holds its value");
}

#[test]
fn the_stick_dead_zone_is_radial_and_rescaled() {
    let dz = 0.2;
    assert_eq!(apply_dead_zone(Vec2::new(0.1, 0.1), dz), Vec2::ZERO);
    assert_eq!(apply_dead_zone(Vec2::new(0.2, 0.0), dz), Vec2::ZERO);
    // Halfway through the live range reads one half, in the same direction.
    let v = apply_dead_zone(Vec2::new(0.0, -0.6), dz);
    assert!((v - Vec2::new(0.0, -0.5)).length() < 1e-6, "{v}");
    let diag = apply_dead_zone(Vec2::new(0.6, 0.8), dz);
    assert!((diag.length() - 1.0).abs() < 1e-6, "{diag}");
    assert!((diag.normalize() - Vec2::new(0.6, 0.8)).length() < 1e-6);
    // Past full deflection (some pads report corners beyond 1) stays at 1.
    assert!((apply_dead_zone(Vec2::new(1.0, 1.0), dz).length() - 1.0).abs() < 1e-6);
    assert_eq!(apply_dead_zone(Vec2::new(f32::NAN, 0.5), dz), Vec2::ZERO);
}

#[test]
fn every_engine_pad_button_has_a_gilrs_button_and_no_support_is_no_failure() {
    use gilrs::Button as G;
    let all = [
        G::South,
        G::East,
        G::North,
        G::West,
        G::LeftTrigger,
        G::RightTrigger,
        G::LeftTrigger2,
        G::RightTrigger2,
        G::Select,
        G::Start,
        G::Mode,
        G::LeftThumb,
        G::RightThumb,
        G::DPadUp,
        G::DPadDown,
        G::DPadLeft,
        G::DPadRight,
    ];
    let mapped: std::collections::BTreeSet<PadButton> =
        all.iter().filter_map(|b| pad_button(*b)).collect();
    assert_eq!(
        mapped.len(),
        all.len(),
        "one engine button per gilrs button"
    );
    assert_eq!(pad_button(G::Unknown), None);
    assert_eq!(pad_button(G::C), None);

    // Here (a container, probably no gamepads, maybe no udev) opening and polling must work.
    let mut pads = Gamepads::new();
    let set = ActionSet::standard();
    let mut input = InputState::new(&set.default_map());
    pads.poll(&mut input);
    pads.poll(&mut input);
    let _ = pads.connected();
    let mut off = Gamepads::disabled();
    assert!(!off.available());
    off.poll(&mut input);
    assert_eq!(off.connected(), 0);
}
