//! Gameplay widgets, one function per kind of item: a trigger volume (its sensor instance and
//! what it detects), a laser (every field: instance, origin in metres and direction in the
//! instance's model space, most reflections, length in metres), a rule (its volumes, which a
//! menu rewires to another volume: `Edit::RewireRule`) and the light groups (which start
//! switched off). [`show`] lists them all (the inspector's Gameplay section); `items` shows the
//! one in focus.
//!
//! Main thread, inside an egui pass. Must not: change the document (it only asks, `Pending`).

use std::collections::BTreeSet;

use crate::assets::{ConditionEntry, Detect};

use super::super::command::{Edit, LaserField, ListEdit, VolumeField};
use super::super::state::EditorState;
use super::Pending;
use super::inspector::vec3;

pub(super) fn show(ui: &mut egui::Ui, state: &EditorState, p: &mut Pending) {
    let g = &state.doc.level.gameplay;
    for (index, v) in g.volumes.iter().enumerate() {
        egui::CollapsingHeader::new(format!("volume {}", v.name))
            .id_salt(("editor_volume_section", index))
            .show(ui, |ui| volume(ui, state, index, p));
    }
    for (index, l) in g.lasers.iter().enumerate() {
        egui::CollapsingHeader::new(format!("laser {index} on {}", l.instance))
            .id_salt(("editor_laser_section", index))
            .show(ui, |ui| laser(ui, state, index, p));
    }
    for (index, r) in g.rules.iter().enumerate() {
        egui::CollapsingHeader::new(format!("rule {}", r.name))
            .id_salt(("editor_rule_section", index))
            .show(ui, |ui| rule(ui, state, index, p));
    }
    egui::CollapsingHeader::new("light groups")
        .id_salt("editor_light_groups")
        .show(ui, |ui| light_groups(ui, state, p));
}

/// The names of the level's named instances, for the pickers.
fn named_instances(state: &EditorState) -> Vec<&str> {
    (state.doc.level.instances.iter())
        .filter_map(|i| i.name.as_deref())
        .collect()
}

/// A combo box choosing one of `names`; the name chosen when it differs from `current`.
fn pick_name(
    ui: &mut egui::Ui,
    id: impl std::hash::Hash + std::fmt::Debug,
    current: &str,
    names: &[&str],
) -> Option<String> {
    let mut chosen = None;
    egui::ComboBox::from_id_salt(id)
        .selected_text(current)
        .show_ui(ui, |ui| {
            for n in names {
                if ui.selectable_label(*n == current, *n).clicked() && *n != current {
                    chosen = Some(n.to_string());
                }
            }
        });
    chosen
}

/// `gameplay.volumes[index]`: its sensor instance and what it detects.
pub(super) fn volume(ui: &mut egui::Ui, state: &EditorState, index: usize, p: &mut Pending) {
    let Some(v) = state.doc.level.gameplay.volumes.get(index) else {
        return;
    };
    let set = |p: &mut Pending, field| p.edits.push(Edit::Volume { index, field });
    ui.label(egui::RichText::new(format!("Volume {:?}", v.name)).strong());
    ui.horizontal(|ui| {
        ui.label("sensor instance");
        let names = named_instances(state);
        if let Some(n) = pick_name(ui, ("editor_volume", index), &v.instance, &names) {
            set(p, VolumeField::Instance(n));
        }
    });
    ui.horizontal(|ui| {
        ui.label("detects");
        for d in [Detect::Player, Detect::Bodies, Detect::Lasers] {
            let mut on = v.detects.contains(&d);
            if ui.checkbox(&mut on, format!("{d:?}")).changed() {
                let mut detects: Vec<Detect> =
                    v.detects.iter().copied().filter(|k| *k != d).collect();
                if on {
                    detects.push(d);
                    detects.sort();
                }
                set(p, VolumeField::Detects(detects));
            }
        }
    });
}

/// `gameplay.lasers[index]`: every field.
pub(super) fn laser(ui: &mut egui::Ui, state: &EditorState, index: usize, p: &mut Pending) {
    let Some(l) = state.doc.level.gameplay.lasers.get(index) else {
        return;
    };
    let set = |p: &mut Pending, field| p.edits.push(Edit::Laser { index, field });
    ui.label(egui::RichText::new(format!("Laser {index}")).strong());
    ui.horizontal(|ui| {
        ui.label("instance");
        let names = named_instances(state);
        if let Some(n) = pick_name(ui, ("editor_laser", index), &l.instance, &names) {
            set(p, LaserField::Instance(n));
        }
    });
    let (mut origin, mut direction) = (l.origin, l.direction);
    if vec3(ui, "origin (m)", &mut origin, 0.01) {
        set(p, LaserField::Origin(origin));
    }
    if vec3(ui, "direction", &mut direction, 0.01) {
        set(p, LaserField::Direction(direction));
    }
    let mut reflections = l.max_reflections;
    let mut length = l.max_length;
    ui.horizontal(|ui| {
        ui.label("max reflections");
        if ui
            .add(egui::DragValue::new(&mut reflections).range(0..=64))
            .changed()
        {
            set(p, LaserField::MaxReflections(reflections));
        }
        ui.label("max length (m)");
        if ui
            .add(
                egui::DragValue::new(&mut length)
                    .speed(0.1)
                    .range(0.0..=1e4),
            )
            .changed()
        {
            set(p, LaserField::MaxLength(length));
        }
    });
}

/// `gameplay.rules[index]`: its condition, and a menu per volume it uses to rewire it.
pub(super) fn rule(ui: &mut egui::Ui, state: &EditorState, index: usize, p: &mut Pending) {
    let g = &state.doc.level.gameplay;
    let Some(rule) = g.rules.get(index) else {
        return;
    };
    ui.label(egui::RichText::new(format!("Rule {:?}", rule.name)).strong());
    ui.label(format!("when {:?}", rule.when));
    let volumes: Vec<&str> = g.volumes.iter().map(|v| v.name.as_str()).collect();
    let mut used = Vec::new();
    volumes_of(&rule.when, &mut used);
    used.dedup();
    for (k, from) in used.iter().enumerate() {
        ui.horizontal(|ui| {
            ui.label(format!("volume {from} →"));
            if let Some(to) = pick_name(ui, ("editor_rule", index, k), from, &volumes) {
                p.edits.push(Edit::RewireRule {
                    index,
                    from: from.to_string(),
                    to,
                });
            }
        });
    }
}

/// Every light group the instances use: its instances and whether it starts switched off.
pub(super) fn light_groups(ui: &mut egui::Ui, state: &EditorState, p: &mut Pending) {
    let level = &state.doc.level;
    let groups: BTreeSet<u32> = level
        .instances
        .iter()
        .filter_map(|i| i.light_group)
        .collect();
    if groups.is_empty() {
        ui.label("No instance is in a light group.");
    }
    let off = &level.gameplay.lights_off;
    for group in groups {
        let members = level
            .instances
            .iter()
            .filter(|i| i.light_group == Some(group))
            .count();
        let label = format!("group {group} ({members} instances) starts off");
        starts_off(ui, off, group, &label, p);
    }
}

/// A check box for whether light `group` starts switched off (`off`: the level's list).
pub(super) fn starts_off(ui: &mut egui::Ui, off: &[u32], group: u32, label: &str, p: &mut Pending) {
    let mut is_off = off.contains(&group);
    if ui.checkbox(&mut is_off, label).changed() {
        let mut list: Vec<u32> = off.iter().copied().filter(|g| *g != group).collect();
        if is_off {
            list.push(group);
            list.sort_unstable();
        }
        p.edits.push(Edit::List(ListEdit::LightsOff(list)));
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
