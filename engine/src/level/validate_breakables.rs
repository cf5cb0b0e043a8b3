//! Breakables in [`super::validate_level`]: each named once and not empty, its pieces named
//! instances with a `Static` or `Kinematic` body whose shape can fall (not `Trimesh`), no piece
//! in two breakables, a positive finite impact speed and piece mass, a scatter speed ≥ 0, and every `Break` action
//! naming a breakable that exists.
//!
//! Any thread (reads the level only). Must not: read files or modify the level.

use std::collections::HashMap;

use crate::assets::{ActionEntry, BodyEntry, Level, ShapeEntry};

use super::item::ItemRef;
use super::validate::Problems;

/// Checks `level.gameplay.breakables` and the `Break` actions of its rules.
pub(super) fn breakables(c: &mut Problems, level: &Level) {
    let g = &level.gameplay;
    let names = c.unique(
        "breakable",
        (g.breakables.iter().enumerate()).map(|(i, b)| (ItemRef::Breakable(i), b.name.as_str())),
    );
    let mut owner: HashMap<&str, &str> = HashMap::new();
    for (i, b) in g.breakables.iter().enumerate() {
        let item = ItemRef::Breakable(i);
        let user = format!("breakable {:?}", b.name);
        if b.name.trim().is_empty() {
            c.report(item, "name", "a breakable has an empty name".into());
        }
        if b.pieces.is_empty() {
            c.report(item, "pieces", format!("{user} has no pieces"));
        }
        if let Some(speed) = b.impact_speed
            && !(speed.is_finite() && speed > 0.0)
        {
            let message = format!("{user} has impact_speed {speed} (give metres per second > 0)");
            c.report(item, "impact_speed", message);
        }
        if !(b.piece_mass.is_finite() && b.piece_mass > 0.0) {
            let message = format!(
                "{user} has piece_mass {} (give kilograms > 0)",
                b.piece_mass
            );
            c.report(item, "piece_mass", message);
        }
        if !(b.scatter_speed.is_finite() && b.scatter_speed >= 0.0) {
            let message = format!(
                "{user} has scatter_speed {} (give metres per second ≥ 0)",
                b.scatter_speed
            );
            c.report(item, "scatter_speed", message);
        }
        for piece in &b.pieces {
            if let Some(other) = owner.insert(piece.as_str(), b.name.as_str()) {
                let message = format!("{user} takes the piece {piece:?}, already in {other:?}");
                c.report(item, "pieces", message);
            }
            let Some((index, instance)) = (level.instances.iter().enumerate())
                .find(|(_, e)| e.name.as_deref() == Some(piece.as_str()))
            else {
                let message = format!("{user} names the piece {piece:?}, which no instance is");
                c.report(item, "pieces", message);
                continue;
            };
            let why = match &instance.body {
                None => Some("has no body (give it a Static or Kinematic body)"),
                Some(BodyEntry::Static { shape } | BodyEntry::Kinematic { shape })
                    if *shape == ShapeEntry::Trimesh =>
                {
                    Some("uses a Trimesh shape, which cannot fall (use Box, Cuboid or ConvexHull)")
                }
                Some(BodyEntry::Static { .. } | BodyEntry::Kinematic { .. }) => None,
                Some(BodyEntry::Dynamic { .. }) => {
                    Some("is already Dynamic (a piece stands until it breaks)")
                }
                Some(BodyEntry::Sensor { .. }) => Some("is a sensor, which nothing can hit"),
            };
            if let Some(why) = why {
                let message = format!("the piece {piece:?} of {user} {why}");
                c.report(ItemRef::Instance(index), "body", message);
            }
        }
    }
    for (i, rule) in g.rules.iter().enumerate() {
        let actions = (rule.then.iter().map(|a| ("then", a)))
            .chain(rule.otherwise.iter().map(|a| ("otherwise", a)));
        for (field, action) in actions {
            if let ActionEntry::Break(name) = action
                && !names.contains(name.as_str())
            {
                let message = format!(
                    "rule {:?} breaks {name:?}, which `breakables` does not declare",
                    rule.name
                );
                c.report(ItemRef::Rule(i), field, message);
            }
        }
    }
}
