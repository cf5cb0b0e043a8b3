//! The inspector: headed by the primary selected instance's name (its model and index only
//! when it has no name, `outliner::instance_label`), typed fields for it — transform
//! (translation in metres, rotation in degrees, scale, snapped when snapping is on), model,
//! material override, dynamic flag, light group — and the fields of its override material
//! (base colour, emission, roughness, metallic, IOR). Bodies are shown, not yet edited.
//!
//! Main thread, inside an egui pass. Must not: change the document (it only asks, `Pending`).

use crate::assets::{InstanceEntry, LevelMaterial, TransformDesc};

use super::super::command::{Edit, InstanceField, MaterialField};
use super::super::state::EditorState;
use super::Pending;
use super::outliner::instance_label;

/// Three drag values in a row; whether any changed.
pub(super) fn vec3(ui: &mut egui::Ui, label: &str, v: &mut [f32; 3], speed: f64) -> bool {
    let mut changed = false;
    ui.horizontal(|ui| {
        ui.label(label);
        for c in v.iter_mut() {
            changed |= ui.add(egui::DragValue::new(c).speed(speed)).changed();
        }
    });
    changed
}

pub(super) fn show(ui: &mut egui::Ui, state: &EditorState, p: &mut Pending) {
    let level = &state.doc.level;
    let Some(index) = state.selection.primary() else {
        ui.label("Nothing selected: click an instance in the view or the outliner.");
        return;
    };
    let Some(entry) = level.instances.get(index) else {
        return;
    };
    ui.label(egui::RichText::new(instance_label(index, entry)).strong());
    let mut t: TransformDesc = entry.transform;
    let moved = vec3(ui, "translation (m)", &mut t.translation, 0.01)
        | vec3(ui, "rotation (°)", &mut t.rotation_deg, 0.5)
        | vec3(ui, "scale", &mut t.scale, 0.01);
    if moved {
        p.edits.push(Edit::Instance {
            index,
            field: InstanceField::Transform(state.snap.transform(t)),
        });
    }
    fields(ui, state, index, entry, p);
    if let Some(m) = entry
        .material
        .as_deref()
        .and_then(|name| level.materials.iter().position(|m| m.name == name))
    {
        ui.separator();
        material(ui, m, &level.materials[m], p);
    }
}

fn fields(
    ui: &mut egui::Ui,
    state: &EditorState,
    index: usize,
    e: &InstanceEntry,
    p: &mut Pending,
) {
    let level = &state.doc.level;
    let set = |p: &mut Pending, field| p.edits.push(Edit::Instance { index, field });
    let models: Vec<&str> = level
        .models
        .iter()
        .map(|m| m.name.as_str())
        .chain(level.grids.iter().map(|g| g.name.as_str()))
        .chain(level.boxes.iter().map(|b| b.name.as_str()))
        .chain(level.terrains.iter().map(|t| t.name.as_str()))
        .chain(level.cities.iter().map(|c| c.name.as_str()))
        .collect();
    egui::ComboBox::from_label("model")
        .selected_text(e.model.as_str())
        .show_ui(ui, |ui| {
            for m in &models {
                if ui.selectable_label(*m == e.model, *m).clicked() && *m != e.model {
                    set(p, InstanceField::Model(m.to_string()));
                }
            }
        });
    let current = e.material.as_deref().unwrap_or("(the model's own)");
    egui::ComboBox::from_label("material")
        .selected_text(current)
        .show_ui(ui, |ui| {
            if ui
                .selectable_label(e.material.is_none(), "(the model's own)")
                .clicked()
            {
                set(p, InstanceField::Material(None));
            }
            for m in &level.materials {
                let chosen = e.material.as_deref() == Some(m.name.as_str());
                if ui.selectable_label(chosen, m.name.as_str()).clicked() && !chosen {
                    set(p, InstanceField::Material(Some(m.name.clone())));
                }
            }
        });
    let mut dynamic = e.dynamic;
    if ui.checkbox(&mut dynamic, "dynamic").changed() {
        set(p, InstanceField::Dynamic(dynamic));
    }
    ui.horizontal(|ui| {
        let mut lit = e.light_group.is_some();
        let mut group = e.light_group.unwrap_or(0);
        let toggled = ui.checkbox(&mut lit, "light group").changed();
        let moved = lit && ui.add(egui::DragValue::new(&mut group)).changed();
        if toggled || moved {
            set(p, InstanceField::LightGroup(lit.then_some(group)));
        }
    });
    let body = match &e.body {
        Some(b) => format!("{b:?}"),
        None => "none".into(),
    };
    ui.label(format!("body: {body}"));
}

fn material(ui: &mut egui::Ui, index: usize, m: &LevelMaterial, p: &mut Pending) {
    let set = |p: &mut Pending, field| p.edits.push(Edit::Material { index, field });
    ui.label(egui::RichText::new(format!("Material {:?} ({:?})", m.name, m.kind)).strong());
    ui.horizontal(|ui| {
        let mut c = m.base_color;
        ui.label("base colour");
        if ui.color_edit_button_rgb(&mut c).changed() {
            set(p, MaterialField::BaseColor(c));
        }
    });
    let mut emission = m.emission;
    if vec3(ui, "emission (W·sr⁻¹·m⁻²)", &mut emission, 0.05) {
        set(p, MaterialField::Emission(emission.map(|v| v.max(0.0))));
    }
    let mut slider =
        |ui: &mut egui::Ui, label: &str, v: f32, range, field: fn(f32) -> MaterialField| {
            let mut v = v;
            if ui
                .add(egui::Slider::new(&mut v, range).text(label))
                .changed()
            {
                set(p, field(v));
            }
        };
    slider(
        ui,
        "roughness",
        m.roughness,
        0.0..=1.0,
        MaterialField::Roughness,
    );
    slider(
        ui,
        "metallic",
        m.metallic,
        0.0..=1.0,
        MaterialField::Metallic,
    );
    slider(ui, "IOR", m.ior, 1.0..=3.0, MaterialField::Ior);
}
