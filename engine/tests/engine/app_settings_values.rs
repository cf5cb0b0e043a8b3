//! What the settings hand on to the rest of the engine: the bus gains (master times the bus
//! volume), the sign on vertical look, and the ranges a saved file must keep to, checked at
//! their edges. Written for the mutation run of `settings.rs` (docs/RELIABILITY.md "Mutation
//! scores"): no other test calls the gains, and only `app_shell_run` the look sign.

use candela::app::{ActionSet, Settings};

#[test]
fn bus_gains_are_the_master_times_the_bus_volume() {
    let s = Settings {
        master_volume: 0.5,
        effects_volume: 0.8,
        music_volume: 0.25,
        ..Settings::default()
    };
    assert_eq!(s.effects_gain(), 0.4);
    assert_eq!(s.music_gain(), 0.125);
    let silent = Settings {
        master_volume: 0.0,
        ..s.clone()
    };
    assert_eq!(silent.effects_gain(), 0.0);
    assert_eq!(silent.music_gain(), 0.0);
}

#[test]
fn inverted_look_flips_the_vertical_sign() {
    let s = Settings::default();
    assert_eq!(s.look_y_sign(), 1.0);
    let inverted = Settings {
        invert_y: true,
        ..s
    };
    assert_eq!(inverted.look_y_sign(), -1.0);
}

#[test]
fn every_range_takes_its_edges_and_refuses_just_outside() {
    let set = ActionSet::standard();
    type Field = fn(&mut Settings, f32);
    let fields: [(&str, f32, f32, Field); 6] = [
        ("resolution_scale", 0.1, 1.0, |s, v| s.resolution_scale = v),
        ("target_fps", 10.0, 1000.0, |s, v| s.target_fps = Some(v)),
        ("master_volume", 0.0, 1.0, |s, v| s.master_volume = v),
        ("effects_volume", 0.0, 1.0, |s, v| s.effects_volume = v),
        ("music_volume", 0.0, 1.0, |s, v| s.music_volume = v),
        ("mouse_sensitivity", 0.05, 20.0, |s, v| {
            s.mouse_sensitivity = v
        }),
    ];
    for (name, lo, hi, set_field) in fields {
        for ok in [lo, hi] {
            let mut s = Settings::default();
            set_field(&mut s, ok);
            assert_eq!(s.check(&set), Ok(()), "{name} = {ok}");
        }
        for bad in [lo - 0.01, hi + 0.01, f32::NAN] {
            let mut s = Settings::default();
            set_field(&mut s, bad);
            let problem = s.check(&set).expect_err("out of range");
            assert!(problem.starts_with(name), "{name} = {bad}: {problem}");
        }
    }
    let unlimited = Settings {
        target_fps: None,
        ..Settings::default()
    };
    assert_eq!(unlimited.check(&set), Ok(()));
}
