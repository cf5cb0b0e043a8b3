//! The scripted explorer's ways through the ruins ([`Task`] lists for [`crate::bot::Bot`]):
//! one per puzzle from the start, and the whole game (every puzzle in turn, then the temple).
//! The replays in `assets/its_about_time/replays/` are recorded from them
//! (`examples/record_replay.rs`); each way is straight walks between waypoints chosen clear of
//! the ruins' stones (`layout/ruins_layout.py`, `layout/puzzles.py`).
//!
//! Pure data, any thread. Must not: read the level (the waypoints follow its layout by hand:
//! re-check them when the layout moves). Metres; x east, z south.

use glam::Vec2;

use crate::bot::Task;

/// The recordings, by name: `full_game` and one per puzzle.
pub const NAMES: [&str; 6] = [
    "full_game",
    "sun_gate",
    "water_stair",
    "rolling_stone",
    "weights",
    "night_shrine",
];

/// The way of the recording `name` (see [`NAMES`]), or `None`.
pub fn route(name: &str) -> Option<Vec<Task>> {
    let mut tasks = vec![Task::Wait { steps: 20 }];
    match name {
        "full_game" => {
            tasks.extend(sun_gate());
            tasks.extend(water_stair(true));
            tasks.extend(rolling_stone());
            tasks.extend(weights());
            tasks.extend(night_shrine(true));
            tasks.extend(temple());
        }
        "sun_gate" => tasks.extend(sun_gate()),
        "water_stair" => tasks.extend(water_stair(false)),
        "rolling_stone" => tasks.extend(rolling_stone()),
        "weights" => tasks.extend(weights()),
        "night_shrine" => tasks.extend(night_shrine(false)),
        _ => return None,
    }
    Some(tasks)
}

fn walk(x: f32, z: f32, within: f32) -> Task {
    Task::Walk {
        to: Vec2::new(x, z),
        within,
    }
}

fn use_it(event: &str) -> Task {
    Task::Use {
        event: event.into(),
    }
}

/// From the start: turn time at the sun altar until the gate opens, take the Sun Disc, leave
/// the court (ends at (14.5, 4)).
fn sun_gate() -> Vec<Task> {
    vec![
        walk(5.0, 6.6, 0.25),
        Task::TurnUntil {
            rule: "sun_gate".into(),
            forward: true,
        },
        walk(14.5, 4.0, 0.4),
        walk(14.5, 0.0, 0.3),
        Task::Rule {
            name: "sun_gate".into(),
        },
        Task::Wait { steps: 150 },
        walk(20.6, 0.0, 0.15),
        use_it("artifact_sun"),
        walk(14.5, 0.0, 0.4),
        walk(14.5, 4.0, 0.4),
    ]
}

/// North to the pool (from the sun gate's court, or from the start), drain it at the sluice,
/// walk in and stand on the float facing the fill lever, fill the pool and ride up, take the
/// Rain Jar on the terrace, drain the pool from there, step down off the terrace and leave by
/// the door (ends at (14.5, 4)).
fn water_stair(from_sun_gate: bool) -> Vec<Task> {
    let mut tasks = if from_sun_gate {
        vec![walk(14.5, -8.0, 0.4)]
    } else {
        vec![
            walk(6.0, 8.0, 0.5),
            walk(14.5, 4.0, 0.4),
            walk(14.5, -8.0, 0.4),
        ]
    };
    tasks.extend([
        walk(21.0, -11.4, 0.3),
        walk(23.2, -11.4, 0.2),
        walk(23.2, -11.9, 0.15),
        use_it("sluice_lever"),
        walk(21.0, -11.9, 0.3),
        Task::Wait { steps: 480 },
        walk(21.0, -15.0, 0.3),
        walk(21.0, -17.4, 0.25),
        walk(21.8, -17.4, 0.12),
        use_it("fill_lever"),
        Task::Wait { steps: 420 },
        walk(21.0, -17.6, 0.2),
        walk(21.0, -19.7, 0.2),
        use_it("artifact_water"),
        walk(23.6, -19.2, 0.2),
        walk(23.6, -19.7, 0.15),
        use_it("terrace_lever"),
        Task::Wait { steps: 480 },
        walk(21.0, -17.0, 0.3),
        walk(21.0, -15.0, 0.3),
        walk(21.0, -11.5, 0.3),
        walk(14.5, -8.0, 0.4),
        walk(14.5, 4.0, 0.4),
    ]);
    tasks
}

/// Round the stone vault's west side to the lever at the ramp's foot, release the boulder,
/// wait for it to break the wall, take the Thunder Stone (ends at (20.4, 17)).
fn rolling_stone() -> Vec<Task> {
    vec![
        walk(14.0, 8.0, 0.4),
        walk(14.0, 18.0, 0.4),
        walk(22.6, 18.0, 0.3),
        walk(22.6, 18.9, 0.2),
        use_it("boulder_lever"),
        Task::Wait { steps: 300 },
        walk(20.4, 17.0, 0.3),
        walk(20.4, 12.6, 0.3),
        use_it("artifact_stone"),
        walk(20.4, 17.0, 0.4),
    ]
}

/// West to the court of weights: block A straight north onto the sun plate, block B east off
/// the eye plate's line and north onto the serpent plate, then the Balance Stone (ends in the
/// vault's doorway).
fn weights() -> Vec<Task> {
    vec![
        walk(0.0, 16.0, 0.5),
        walk(-20.0, 9.0, 0.5),
        walk(-31.0, 4.4, 0.2),
        walk(-31.0, -1.1, 0.3),
        walk(-31.0, 4.4, 0.3),
        walk(-27.6, 4.4, 0.3),
        walk(-27.6, 2.5, 0.2),
        walk(-24.4, 2.5, 0.2),
        walk(-23.5, 4.4, 0.3),
        walk(-23.5, -1.1, 0.3),
        Task::Rule {
            name: "weights_open".into(),
        },
        walk(-27.25, -1.0, 0.3),
        Task::Wait { steps: 150 },
        walk(-27.25, -7.6, 0.25),
        use_it("artifact_weights"),
        walk(-27.25, -4.5, 0.4),
    ]
}

/// To the shrine's altar, arriving from the south so the explorer faces it (from the court of
/// weights, or from the start round the low walls' north end),
/// turn time on to night, light the torches — one wrong first, to show the reset — then in the
/// wall's order (eye, sun, serpent, fret), take the Moon Mirror.
fn night_shrine(from_weights: bool) -> Vec<Task> {
    let mut tasks = if from_weights {
        vec![walk(-21.0, -4.5, 0.4)]
    } else {
        vec![
            walk(-7.0, 0.0, 0.5),
            walk(-8.0, -6.5, 0.5),
            walk(-19.0, -7.5, 0.4),
        ]
    };
    tasks.extend([
        walk(-19.0, -10.4, 0.25),
        Task::TurnUntil {
            rule: "night_falls".into(),
            forward: true,
        },
    ]);
    let torch = |x: f32, name: &str| {
        [
            walk(x, -15.6, 0.3),
            walk(x, -17.0, 0.2),
            use_it(&format!("torch_{name}")),
        ]
    };
    for (x, name) in [
        (-22.5, "eye"),
        (-26.5, "fret"),
        (-22.5, "eye"),
        (-29.5, "sun"),
        (-19.5, "serpent"),
        (-26.5, "fret"),
    ] {
        tasks.extend(torch(x, name));
    }
    tasks.extend([
        Task::Rule {
            name: "shrine_open".into(),
        },
        walk(-24.5, -20.5, 0.3),
        Task::Wait { steps: 150 },
        walk(-24.5, -24.1, 0.25),
        use_it("artifact_night"),
        walk(-24.5, -20.5, 0.4),
    ]);
    tasks
}

/// From the night shrine to the temple altar, past the fallen stones.
fn temple() -> Vec<Task> {
    vec![
        walk(-14.0, -12.0, 0.5),
        walk(-6.0, -11.0, 0.5),
        walk(0.0, -12.3, 0.3),
        Task::Ending,
    ]
}
