//! What the bot does in each chamber (see `bot`): the committed replays are recorded from
//! these lists (`examples/record_replays.rs`). Positions come from the chamber files (metres,
//! world space); change them together.
//!
//! Owns: [`chamber_tasks`]. Main thread. Must not: read the level files (the lists are data).

use glam::{Vec2, Vec3};

use crate::bot::Task;

fn walk(x: f32, z: f32) -> Task {
    Task::Walk {
        to: Vec2::new(x, z),
        within: 0.15,
    }
}

fn pick(body: &str) -> Task {
    Task::Pick { body: body.into() }
}

fn rule(name: &str) -> Task {
    Task::Rule { name: name.into() }
}

/// The tasks that solve chamber `index` (0-based) from its start and walk into the next.
pub fn chamber_tasks(index: usize) -> Vec<Task> {
    match index {
        0 => vec![
            pick("cube_1"),
            Task::Carry {
                over: Vec3::new(3.0, 0.08, -11.0),
                within: 0.15,
                yaw: None,
            },
            rule("door_1"),
            walk(0.0, -14.5),
            walk(0.0, -19.0),
            Task::Entered { index: 1 },
        ],
        1 => vec![
            walk(2.0, -24.0),
            Task::Shoot {
                at: Vec3::new(6.2, 1.0, -29.0),
                panel: "panel_2".into(),
                mirror: true,
            },
            rule("solve_2"),
            Task::Wait { steps: 60 },
            walk(0.0, -30.5),
            walk(0.0, -35.0),
            Task::Entered { index: 2 },
        ],
        2 => vec![
            walk(-6.6, -34.0),
            Task::Use {
                at: Vec3::new(-7.85, 1.1, -34.0),
            },
            rule("turn_3"),
            Task::Wait { steps: 100 },
            pick("cube_3"),
            Task::Carry {
                over: Vec3::new(-6.75, 1.05, -40.0),
                within: 0.1,
                yaw: Some(std::f32::consts::FRAC_PI_2),
            },
            rule("solve_3"),
            walk(-1.0, -44.0),
            walk(0.0, -46.5),
            walk(0.0, -51.0),
            Task::Entered { index: 3 },
        ],
        3 => vec![
            Task::Shoot {
                at: Vec3::new(5.0, 3.0, -50.0),
                panel: "panel_4a".into(),
                mirror: true,
            },
            Task::Shoot {
                at: Vec3::new(5.0, 3.0, -61.0),
                panel: "panel_4b".into(),
                mirror: true,
            },
            pick("cube_4"),
            Task::Carry {
                over: Vec3::new(-3.0, 0.08, -57.0),
                within: 0.15,
                yaw: None,
            },
            rule("door_4"),
            walk(0.0, -62.5),
            walk(0.0, -67.0),
            Task::Entered { index: 4 },
        ],
        4 => vec![
            Task::Walk {
                to: Vec2::new(0.0, -74.0),
                within: 0.3,
            },
            rule("ride_5"),
            Task::Ending,
        ],
        _ => Vec::new(),
    }
}
