//! The level's materials in a list of their own (the Materials window), and the typed fields of
//! one material, which the inspector also shows for an instance's override: kind, base colour
//! (linear RGB, a colour picker), emission (W·sr⁻¹·m⁻²) and two-sided emission, roughness,
//! metallic, IOR, and Beer–Lambert absorption (the colour left after a distance in metres).
//! A change edits the level material itself, so every model that uses it changes with it (the
//! runner re-spawns the level: `Touch::Level`). In a composed world the base file's materials
//! (`EditorState::base`) follow the part's, under the base's heading, edited as
//! `Edit::Base` and saved to the base file.
//!
//! Main thread, inside an egui pass. Must not: change the document (it only asks, `Pending`).

use crate::assets::{LevelMaterial, MaterialKind};
use crate::level::ItemRef;

use super::super::command::{Edit, MaterialField};
use super::super::state::EditorState;
use super::Pending;
use super::inspector::vec3;

/// Whose material a widget edits: the edited file's, or the base file's of a composed world.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(super) enum Owner {
    Level,
    Base,
}

impl Owner {
    /// The edit of field `field` of this owner's `materials[index]`.
    fn edit(self, index: usize, field: MaterialField) -> Edit {
        let edit = Edit::Material { index, field };
        match self {
            Owner::Level => edit,
            Owner::Base => Edit::Base(Box::new(edit)),
        }
    }
}

/// Every level material as a collapsible section with its fields (the one in focus is open),
/// then the base file's.
pub(super) fn show(ui: &mut egui::Ui, state: &EditorState, p: &mut Pending) {
    let level = &state.doc.level;
    let base = state.base().map(|b| &b.materials[..]).unwrap_or_default();
    if level.materials.is_empty() && base.is_empty() {
        ui.label("The level defines no materials.");
        return;
    }
    let focus = state.selection.item();
    let users = |name: &str| {
        (level.instances.iter())
            .filter(|i| i.material.as_deref() == Some(name))
            .count()
    };
    egui::ScrollArea::vertical()
        .id_salt("editor_materials")
        .max_height(360.0)
        .show(ui, |ui| {
            for (index, m) in level.materials.iter().enumerate() {
                let open = focus == Some(ItemRef::Material(index));
                egui::CollapsingHeader::new(format!("{}  ({} overrides)", m.name, users(&m.name)))
                    .id_salt(("editor_material", index))
                    .open(open.then_some(true))
                    .show(ui, |ui| fields(ui, Owner::Level, index, m, p));
            }
            if base.is_empty() {
                return;
            }
            let file = (state.base_path.as_deref())
                .and_then(|p| p.file_name())
                .map_or("the base file".into(), |n| n.to_string_lossy());
            ui.label(egui::RichText::new(format!("From {file} (saved there)")).strong());
            for (index, m) in base.iter().enumerate() {
                egui::CollapsingHeader::new(format!("{}  ({} overrides)", m.name, users(&m.name)))
                    .id_salt(("editor_base_material", index))
                    .show(ui, |ui| fields(ui, Owner::Base, index, m, p));
            }
        });
}

/// The typed fields of `owner`'s `materials[index]`.
pub(super) fn fields(
    ui: &mut egui::Ui,
    owner: Owner,
    index: usize,
    m: &LevelMaterial,
    p: &mut Pending,
) {
    let set = |p: &mut Pending, field| p.edits.push(owner.edit(index, field));
    let whose = if owner == Owner::Base {
        ", base file"
    } else {
        ""
    };
    ui.label(egui::RichText::new(format!("Material {:?} ({:?}{whose})", m.name, m.kind)).strong());
    egui::ComboBox::from_id_salt(("editor_material_kind", owner, index))
        .selected_text(format!("{:?}", m.kind))
        .show_ui(ui, |ui| {
            for kind in [
                MaterialKind::Diffuse,
                MaterialKind::Conductor,
                MaterialKind::Dielectric,
                MaterialKind::MetalRough,
            ] {
                let label = format!("{kind:?}");
                if ui.selectable_label(kind == m.kind, label).clicked() && kind != m.kind {
                    set(p, MaterialField::Kind(kind));
                }
            }
        });
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
    let mut two_sided = m.two_sided_emission;
    if ui.checkbox(&mut two_sided, "two-sided emission").changed() {
        set(p, MaterialField::TwoSidedEmission(two_sided));
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
    ui.horizontal(|ui| {
        let mut c = m.attenuation_color;
        ui.label("absorption: colour left");
        if ui.color_edit_button_rgb(&mut c).changed() {
            set(p, MaterialField::AttenuationColor(c));
        }
        let mut on = m.attenuation_distance.is_some();
        let mut d = m.attenuation_distance.unwrap_or(1.0);
        let toggled = ui.checkbox(&mut on, "after (m)").changed();
        let moved = on
            && ui
                .add(egui::DragValue::new(&mut d).speed(0.01).range(1e-3..=1e4))
                .changed();
        if toggled || moved {
            set(p, MaterialField::AttenuationDistance(on.then_some(d)));
        }
    });
}
