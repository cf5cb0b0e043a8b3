//! Gameplay widgets: each trigger volume's sensor instance, each laser's origin and
//! direction (metres and a direction in the laser instance's model space), and each rule's
//! volumes, which a menu rewires to another volume (`Edit::RewireRule`).
//!
//! Main thread, inside an egui pass. Must not: change the document (it only asks, `Pending`).

use crate::assets::ConditionEntry;

use super::super::command::{Edit, LaserField, VolumeField};
use super::super::state::EditorState;
use super::Pending;
use super::inspector::vec3;

pub(super) fn show(ui: &mut egui::Ui, state: &EditorState, p: &mut Pending) {
    let level = &state.doc.level;
    let g = &level.gameplay;
    let sensors: Vec<&str> = level
        .instances
        .iter()
        .filter_map(|i| i.name.as_deref())
        .collect();
    for (index, v) in g.volumes.iter().enumerate() {
        egui::ComboBox::from_id_salt(("editor_volume", index))
            .selected_text(format!("volume {}: {}", v.name, v.instance))
            .show_ui(ui, |ui| {
                for s in &sensors {
                    if ui.selectable_label(*s == v.instance, *s).clicked() && *s != v.instance {
                        p.edits.push(Edit::Volume {
                            index,
                            field: VolumeField::Instance(s.to_string()),
                        });
                    }
                }
            });
    }
    for (index, l) in g.lasers.iter().enumerate() {
        ui.label(format!("laser {index} on {}", l.instance));
        let (mut origin, mut direction) = (l.origin, l.direction);
        if vec3(ui, "origin (m)", &mut origin, 0.01) {
            p.edits.push(Edit::Laser {
                index,
                field: LaserField::Origin(origin),
            });
        }
        if vec3(ui, "direction", &mut direction, 0.01) {
            p.edits.push(Edit::Laser {
                index,
                field: LaserField::Direction(direction),
            });
        }
    }
    let volumes: Vec<&str> = g.volumes.iter().map(|v| v.name.as_str()).collect();
    for (index, rule) in g.rules.iter().enumerate() {
        let mut used = Vec::new();
        volumes_of(&rule.when, &mut used);
        used.dedup();
        for (k, from) in used.iter().enumerate() {
            egui::ComboBox::from_id_salt(("editor_rule", index, k))
                .selected_text(format!("rule {}: {from}", rule.name))
                .show_ui(ui, |ui| {
                    for to in &volumes {
                        if ui.selectable_label(to == from, *to).clicked() && to != from {
                            p.edits.push(Edit::RewireRule {
                                index,
                                from: from.to_string(),
                                to: to.to_string(),
                            });
                        }
                    }
                });
        }
    }
}

/// The volume names a condition uses, in order.
fn volumes_of<'a>(c: &'a ConditionEntry, out: &mut Vec<&'a str>) {
    match c {
        ConditionEntry::Occupied(v) | ConditionEntry::Entered(v) | ConditionEntry::Exited(v) => {
            out.push(v)
        }
        ConditionEntry::Occupants { volume, .. } | ConditionEntry::SunLit(volume) => {
            out.push(volume)
        }
        ConditionEntry::Event(_)
        | ConditionEntry::LightsOn(_)
        | ConditionEntry::Fired(_)
        | ConditionEntry::Counter { .. }
        | ConditionEntry::SunElevation { .. } => {}
        ConditionEntry::All(cs)
        | ConditionEntry::Any(cs)
        | ConditionEntry::AtLeast { of: cs, .. }
        | ConditionEntry::Sequence(cs) => cs.iter().for_each(|c| volumes_of(c, out)),
        ConditionEntry::Not(c) | ConditionEntry::Times { of: c, .. } => volumes_of(c, out),
    }
}
