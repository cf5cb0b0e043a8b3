//! The outliner: every instance (by its name first, then its model; by model and index only
//! when it has no name: [`instance_label`]) with a search field, then the
//! materials, light groups, trigger volumes, lasers, clips and rules; in a composed world the
//! base file's materials after them, under the base file's name (`Materials (common.ron)`).
//! Clicking an instance selects it (Shift adds, Ctrl toggles); clicking a light group selects
//! its instances; clicking any other item puts it in focus (`Selection::item`, a base
//! material `Selection::base_item`), and the inspector shows it.
//!
//! Main thread, inside an egui pass. Must not: change the document (it only asks, `Pending`).

use std::collections::BTreeSet;

use crate::assets::InstanceEntry;
use crate::level::ItemRef;

use super::super::state::EditorState;
use super::{Pending, mode_of};

/// The search field's id salt (`egui::Id::unique(SEARCH_ID)`; tests give it the keyboard).
pub const SEARCH_ID: &str = "editor_outliner_search";

pub(super) fn show(ui: &mut egui::Ui, state: &EditorState, p: &mut Pending) {
    let needle = super::search_field(ui, SEARCH_ID, "search");
    let level = &state.doc.level;
    let modifiers = ui.input(|i| i.modifiers);
    egui::ScrollArea::vertical()
        .auto_shrink([false, false])
        .show(ui, |ui| {
            ui.label(egui::RichText::new("Instances").strong());
            for (i, entry) in level.instances.iter().enumerate() {
                let label = instance_label(i, entry);
                if !needle.is_empty() && !label.to_lowercase().contains(&needle) {
                    continue;
                }
                if ui
                    .selectable_label(state.selection.contains(i), label)
                    .clicked()
                {
                    p.select = Some((Some(i), mode_of(modifiers)));
                }
            }
            let g = &level.gameplay;
            let focus = state.selection.item();
            let mut section = |ui: &mut egui::Ui, title: &str, items: Vec<(String, ItemRef)>| {
                let items: Vec<_> = (items.into_iter())
                    .filter(|(s, _)| needle.is_empty() || s.to_lowercase().contains(&needle))
                    .collect();
                if items.is_empty() {
                    return;
                }
                ui.label(egui::RichText::new(title).strong());
                for (label, item) in items {
                    if ui.selectable_label(focus == Some(item), label).clicked() {
                        p.focus = Some(item);
                    }
                }
            };
            let listed = |names: Vec<String>, item: fn(usize) -> ItemRef| {
                (names.into_iter().enumerate())
                    .map(|(i, n)| (n, item(i)))
                    .collect::<Vec<_>>()
            };
            let names = level.materials.iter().map(|m| m.name.clone()).collect();
            section(ui, "Materials", listed(names, ItemRef::Material));
            let names = g
                .volumes
                .iter()
                .map(|v| format!("{} on {}", v.name, v.instance));
            section(ui, "Volumes", listed(names.collect(), ItemRef::Volume));
            let names =
                (g.lasers.iter().enumerate()).map(|(i, l)| format!("laser {i} on {}", l.instance));
            section(ui, "Lasers", listed(names.collect(), ItemRef::Laser));
            let names = g.animations.iter().map(|a| a.name.clone()).collect();
            section(ui, "Clips", listed(names, ItemRef::Clip));
            let names = g.rules.iter().map(|r| r.name.clone()).collect();
            section(ui, "Rules", listed(names, ItemRef::Rule));
            base_materials(ui, state, &needle, p);
            let groups: BTreeSet<u32> = level
                .instances
                .iter()
                .filter_map(|i| i.light_group)
                .collect();
            if !groups.is_empty() {
                ui.label(egui::RichText::new("Light groups").strong());
            }
            for group in groups {
                if ui
                    .selectable_label(false, format!("group {group}"))
                    .clicked()
                {
                    let members = (level.instances.iter().enumerate())
                        .filter(|(_, e)| e.light_group == Some(group))
                        .map(|(i, _)| i);
                    p.select_set = Some(members.collect());
                }
            }
        });
}

/// The base file's materials (a composed world's `common.ron`), each a click from focus.
fn base_materials(ui: &mut egui::Ui, state: &EditorState, needle: &str, p: &mut Pending) {
    let Some(base) = state.base() else {
        return;
    };
    let items: Vec<(usize, &str)> = (base.materials.iter().enumerate())
        .map(|(i, m)| (i, m.name.as_str()))
        .filter(|(_, n)| needle.is_empty() || n.to_lowercase().contains(needle))
        .collect();
    if items.is_empty() {
        return;
    }
    let file = (state.base_path.as_deref())
        .and_then(|path| path.file_name())
        .map_or("base file".into(), |n| n.to_string_lossy());
    ui.label(egui::RichText::new(format!("Materials ({file})")).strong());
    let focus = state.selection.base_item();
    for (i, name) in items {
        let item = ItemRef::Material(i);
        if ui.selectable_label(focus == Some(item), name).clicked() {
            p.focus_base = Some(item);
        }
    }
}

/// How the outliner and the inspector name `instances[index]`: its name, then its model
/// (`door_1  (door)`); only an instance without a name is known by its model and index
/// (`wall_8x4 #12`).
pub fn instance_label(index: usize, entry: &InstanceEntry) -> String {
    match &entry.name {
        Some(name) => format!("{name}  ({})", entry.model),
        None => format!("{} #{index}", entry.model),
    }
}
