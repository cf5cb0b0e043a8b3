//! The inspector's body widgets for one instance: its kind (none, static, dynamic, kinematic,
//! sensor), its shape (the model's box, a cuboid, sphere or capsule in metres, the convex
//! hull, the triangles) with the shape's sizes, and a dynamic body's mass (kilograms) and
//! continuous collision detection. Each change is one `InstanceField::Body` edit. The level
//! format has no per-body friction, so there is none to edit.
//!
//! Main thread, inside an egui pass. Must not: change the document (it only asks, `Pending`).

use crate::assets::{BodyEntry, ShapeEntry};

use super::super::command::{Edit, InstanceField};
use super::Pending;
use super::inspector::vec3;

const KINDS: [&str; 5] = ["none", "Static", "Dynamic", "Kinematic", "Sensor"];
const SHAPES: [&str; 6] = [
    "Box",
    "Cuboid",
    "Sphere",
    "Capsule",
    "ConvexHull",
    "Trimesh",
];

/// The kind's name as [`KINDS`] spells it.
fn kind_of(body: Option<&BodyEntry>) -> &'static str {
    match body {
        None => "none",
        Some(BodyEntry::Static { .. }) => "Static",
        Some(BodyEntry::Dynamic { .. }) => "Dynamic",
        Some(BodyEntry::Kinematic { .. }) => "Kinematic",
        Some(BodyEntry::Sensor { .. }) => "Sensor",
    }
}

fn shape_name(shape: &ShapeEntry) -> &'static str {
    match shape {
        ShapeEntry::Box => "Box",
        ShapeEntry::Cuboid { .. } => "Cuboid",
        ShapeEntry::Sphere { .. } => "Sphere",
        ShapeEntry::Capsule { .. } => "Capsule",
        ShapeEntry::ConvexHull => "ConvexHull",
        ShapeEntry::Trimesh => "Trimesh",
    }
}

/// A shape named `name` with sizes of half a metre.
fn shape_named(name: &str) -> ShapeEntry {
    match name {
        "Cuboid" => ShapeEntry::Cuboid {
            half_extents: [0.5; 3],
        },
        "Sphere" => ShapeEntry::Sphere { radius: 0.5 },
        "Capsule" => ShapeEntry::Capsule {
            half_height: 0.5,
            radius: 0.25,
        },
        "ConvexHull" => ShapeEntry::ConvexHull,
        "Trimesh" => ShapeEntry::Trimesh,
        _ => ShapeEntry::Box,
    }
}

/// A body of kind `kind` with `shape` (a dynamic one keeps `mass` and `ccd`).
fn body_of(kind: &str, shape: ShapeEntry, mass: f32, ccd: bool) -> Option<BodyEntry> {
    Some(match kind {
        "Static" => BodyEntry::Static { shape },
        "Dynamic" => BodyEntry::Dynamic { shape, mass, ccd },
        "Kinematic" => BodyEntry::Kinematic { shape },
        "Sensor" => BodyEntry::Sensor { shape },
        _ => return None,
    })
}

/// The body widgets of `instances[index]`, whose body is `body`.
pub(super) fn show(ui: &mut egui::Ui, index: usize, body: Option<&BodyEntry>, p: &mut Pending) {
    let set = |p: &mut Pending, body| {
        p.edits.push(Edit::Instance {
            index,
            field: InstanceField::Body(body),
        })
    };
    let (shape, mass, ccd) = match body {
        Some(BodyEntry::Dynamic { shape, mass, ccd }) => (shape.clone(), *mass, *ccd),
        Some(
            BodyEntry::Static { shape }
            | BodyEntry::Kinematic { shape }
            | BodyEntry::Sensor { shape },
        ) => (shape.clone(), 1.0, false),
        None => (ShapeEntry::Box, 1.0, false),
    };
    let kind = kind_of(body);
    egui::ComboBox::from_label("body")
        .selected_text(kind)
        .show_ui(ui, |ui| {
            for k in KINDS {
                if ui.selectable_label(k == kind, k).clicked() && k != kind {
                    set(p, body_of(k, shape.clone(), mass, ccd));
                }
            }
        });
    if body.is_none() {
        return;
    }
    let name = shape_name(&shape);
    egui::ComboBox::from_label("shape")
        .selected_text(name)
        .show_ui(ui, |ui| {
            for s in SHAPES {
                if ui.selectable_label(s == name, s).clicked() && s != name {
                    set(p, body_of(kind, shape_named(s), mass, ccd));
                }
            }
        });
    let mut edited = shape.clone();
    let resized = match &mut edited {
        ShapeEntry::Cuboid { half_extents } => vec3(ui, "half extents (m)", half_extents, 0.01),
        ShapeEntry::Sphere { radius } => number(ui, "radius (m)", radius),
        ShapeEntry::Capsule {
            half_height,
            radius,
        } => number(ui, "half height (m)", half_height) | number(ui, "radius (m)", radius),
        _ => false,
    };
    if resized {
        set(p, body_of(kind, edited, mass, ccd));
    }
    if kind == "Dynamic" {
        let (mut m, mut c) = (mass, ccd);
        let weighed = number(ui, "mass (kg)", &mut m);
        let toggled = ui.checkbox(&mut c, "continuous collision (ccd)").changed();
        if weighed || toggled {
            set(p, body_of(kind, shape, m.max(1e-3), c));
        }
    }
}

/// A labelled drag value (not below zero); whether it changed.
fn number(ui: &mut egui::Ui, label: &str, v: &mut f32) -> bool {
    ui.horizontal(|ui| {
        ui.label(label);
        ui.add(egui::DragValue::new(v).speed(0.01).range(0.0..=1e6))
            .changed()
    })
    .inner
}
