//! The outliner: every instance (by its name first, then its model; by model and index only
//! when it has no name: [`instance_label`]) with a search field, then the
//! light groups, trigger volumes, lasers, clips and rules. Clicking an instance selects it
//! (Shift adds, Ctrl toggles).
//!
//! Main thread, inside an egui pass. Must not: change the document (it only asks, `Pending`).

use std::collections::BTreeSet;

use crate::assets::InstanceEntry;

use super::super::state::EditorState;
use super::{Pending, mode_of};

/// The search field's id salt (`egui::Id::unique(SEARCH_ID)`; tests give it the keyboard).
pub const SEARCH_ID: &str = "editor_outliner_search";

pub(super) fn show(ui: &mut egui::Ui, state: &EditorState, p: &mut Pending) {
    let id = egui::Id::unique(SEARCH_ID);
    let mut search: String = ui.data_mut(|d| d.get_temp(id)).unwrap_or_default();
    ui.add(
        egui::TextEdit::singleline(&mut search)
            .id(id)
            .hint_text("search"),
    );
    ui.data_mut(|d| d.insert_temp(id, search.clone()));
    let needle = search.to_lowercase();
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
            let groups: BTreeSet<u32> = level
                .instances
                .iter()
                .filter_map(|i| i.light_group)
                .collect();
            section(
                ui,
                "Light groups",
                groups.iter().map(|g| format!("group {g}")),
                &needle,
            );
            section(
                ui,
                "Volumes",
                g.volumes
                    .iter()
                    .map(|v| format!("{} on {}", v.name, v.instance)),
                &needle,
            );
            section(
                ui,
                "Lasers",
                g.lasers
                    .iter()
                    .enumerate()
                    .map(|(i, l)| format!("laser {i} on {}", l.instance)),
                &needle,
            );
            section(
                ui,
                "Clips",
                g.animations.iter().map(|a| a.name.clone()),
                &needle,
            );
            section(ui, "Rules", g.rules.iter().map(|r| r.name.clone()), &needle);
        });
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

fn section(ui: &mut egui::Ui, title: &str, items: impl Iterator<Item = String>, needle: &str) {
    let items: Vec<String> = items
        .filter(|s| needle.is_empty() || s.to_lowercase().contains(needle))
        .collect();
    if items.is_empty() {
        return;
    }
    ui.label(egui::RichText::new(title).strong());
    for item in items {
        ui.label(item);
    }
}
