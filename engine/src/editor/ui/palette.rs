//! The palette: every model the level can place — its own models (files, grids, boxes,
//! terrains, cities: `editor::model_names`), then the model files of its asset folder it does
//! not list yet (`EditorState::palette`, found when the editor opens), and in a composed
//! world the base file's models (`name (base)`) — with a search field.
//! Clicking a piece asks the runner to place it in front of the camera, where the view's
//! centre ray hits (`PanelOutput::place`), and makes it the current piece, which P places
//! under the pointer over the view (`app::edit`). Pieces are listed by name; thumbnails are
//! not drawn yet.
//!
//! Main thread, inside an egui pass. Must not: change the document (it only asks, `Pending`).

use super::super::place::{PaletteItem, model_names};
use super::super::state::EditorState;
use super::Pending;

/// The search field's id salt (`egui::Id::unique(SEARCH_ID)`).
pub const SEARCH_ID: &str = "editor_palette_search";

pub(super) fn show(ui: &mut egui::Ui, state: &EditorState, p: &mut Pending) {
    let needle = super::search_field(ui, SEARCH_ID, "search pieces");
    let level = &state.doc.level;
    let listed: Vec<&str> = (level.models.iter())
        .chain(state.base().into_iter().flat_map(|b| b.models.iter()))
        .map(|m| m.path.as_str())
        .collect();
    let own = model_names(level)
        .into_iter()
        .map(|name| (name.to_string(), PaletteItem::Model(name.to_string())));
    let base = (state.base().into_iter())
        .flat_map(model_names)
        .map(|name| {
            (
                format!("{name} (base)"),
                PaletteItem::Model(name.to_string()),
            )
        });
    let own = own.chain(base);
    let files = (state.palette.files.iter())
        .filter(|f| !listed.contains(&f.as_str()))
        .map(|f| (format!("{f} (file)"), PaletteItem::File(f.clone())));
    ui.label("Click: place in front of the camera. P over the view: under the pointer.");
    egui::ScrollArea::vertical()
        .id_salt("editor_palette_list")
        .max_height(220.0)
        .auto_shrink([false, true])
        .show(ui, |ui| {
            for (label, item) in own.chain(files) {
                if !needle.is_empty() && !label.to_lowercase().contains(&needle) {
                    continue;
                }
                let current = state.palette.current.as_ref() == Some(&item);
                if ui.selectable_label(current, label).clicked() {
                    p.place = Some(item);
                }
            }
        });
}
