//! The inspector: headed by the primary selected instance's name (its model and index only
//! when it has no name, `outliner::instance_label`) and the selection's bounds in metres
//! (`EditorState::bounds`, world axes, from the runner), typed fields for it — transform
//! (translation in metres, rotation in degrees, scale, snapped when snapping is on), model,
//! material override, dynamic flag, light group, body (`bodies`) — and the fields of its
//! override material (`materials`). When the outliner or the problems panel put another item
//! in focus (`Selection::item`: a material, volume, laser, clip or rule), the inspector shows
//! that item's widgets instead. In a composed world the base file's models and materials are
//! offered too (`EditorState::base`); a base material's fields (an instance's, or the one the
//! outliner put in focus, `Selection::base_item`) edit the base file's material (`Edit::Base`,
//! saved to the base file).
//!
//! Main thread, inside an egui pass. Must not: change the document (it only asks, `Pending`).

use crate::assets::{InstanceEntry, TransformDesc};
use crate::level::ItemRef;

use super::super::command::{Edit, InstanceField};
use super::super::place::model_names;
use super::super::state::EditorState;
use super::materials::Owner;
use super::outliner::instance_label;
use super::{Pending, bodies, clips, gameplay, materials};

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
    if let Some(item) = state.selection.item()
        && focused(ui, state, item, p)
    {
        return;
    }
    if let Some(ItemRef::Material(i)) = state.selection.base_item()
        && let Some(m) = state.base().and_then(|b| b.materials.get(i))
    {
        materials::fields(ui, Owner::Base, i, m, p);
        return;
    }
    let Some(index) = state.selection.primary() else {
        ui.label("Nothing selected: click an instance in the view or the outliner.");
        return;
    };
    let Some(entry) = level.instances.get(index) else {
        return;
    };
    ui.label(egui::RichText::new(instance_label(index, entry)).strong());
    if let Some((lo, hi)) = state.bounds {
        let d = hi - lo;
        ui.label(format!(
            "bounds (m): {:.2} × {:.2} × {:.2}  (x {:.2}…{:.2}, y {:.2}…{:.2}, z {:.2}…{:.2})",
            d.x, d.y, d.z, lo.x, hi.x, lo.y, hi.y, lo.z, hi.z
        ));
    }
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
        materials::fields(ui, Owner::Level, m, &level.materials[m], p);
    } else if let Some(name) = entry.material.as_deref()
        && let Some(base) = state.base()
        && let Some(m) = base.materials.iter().position(|m| m.name == name)
    {
        ui.separator();
        materials::fields(ui, Owner::Base, m, &base.materials[m], p);
    }
}

/// The widgets of the item in focus; `false` for a kind the inspector has none for.
fn focused(ui: &mut egui::Ui, state: &EditorState, item: ItemRef, p: &mut Pending) -> bool {
    let level = &state.doc.level;
    match item {
        ItemRef::Material(i) => match level.materials.get(i) {
            Some(m) => materials::fields(ui, Owner::Level, i, m, p),
            None => return false,
        },
        ItemRef::Volume(i) => gameplay::volume(ui, state, i, p),
        ItemRef::Laser(i) => gameplay::laser(ui, state, i, p),
        ItemRef::Rule(i) => gameplay::rule(ui, state, i, p),
        ItemRef::Clip(i) => clips::show(ui, state, i, p),
        ItemRef::LightsOff(_) => gameplay::light_groups(ui, state, p),
        _ => return false,
    }
    true
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
    let base = state.base();
    let mut models = model_names(level);
    models.extend(base.iter().flat_map(|b| model_names(b)));
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
            for m in level
                .materials
                .iter()
                .chain(base.iter().flat_map(|b| &b.materials))
            {
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
        if let Some(group) = e.light_group {
            gameplay::starts_off(ui, &level.gameplay.lights_off, group, "starts off", p);
        }
    });
    bodies::show(ui, index, e.body.as_ref(), p);
}
