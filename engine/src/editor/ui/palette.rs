//! The palette: every model the level can place — its own models (files, grids, boxes,
//! terrains, cities: `editor::model_names`), then the model files of its asset folder it does
//! not list yet (`EditorState::palette`, found when the editor opens), and in a composed
//! world the base file's models (`name (base)`) — with a search field.
//! Clicking a piece asks the runner to place it in front of the camera, where the view's
//! centre ray hits (`PanelOutput::place`), and makes it the current piece, which P places
//! under the pointer over the view (`app::edit`). Each piece made from a model file has its
//! thumbnail beside its name (`editor::thumbs`, rendered off the main thread and cached; a grey
//! square while it renders, a crossed one with the error on hover when the model does not
//! load); engine-made models (boxes, grids) have an empty square.
//!
//! Main thread, inside an egui pass. Must not: change the document (it only asks, `Pending`).

use super::super::place::{PaletteItem, model_names};
use super::super::state::EditorState;
use super::super::thumbs::Shown;
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
            let mut thumbs = (state.thumbs.as_ref()).and_then(|t| t.lock().ok());
            if let Some(t) = thumbs.as_mut() {
                t.poll(ui.ctx());
            }
            for (label, item) in own.chain(files) {
                if !needle.is_empty() && !label.to_lowercase().contains(&needle) {
                    continue;
                }
                let shown = (thumbs.as_mut())
                    .zip(model_file(state, &item))
                    .map(|(t, file)| t.shown(&file));
                let current = state.palette.current.as_ref() == Some(&item);
                ui.horizontal(|ui| {
                    thumbnail(ui, shown);
                    if ui.selectable_label(current, label).clicked() {
                        p.place = Some(item);
                    }
                });
            }
        });
}

/// Points a thumbnail takes in the list.
const THUMB_POINTS: f32 = 32.0;

/// The model file (relative to the asset root) `item` is made from, if any.
fn model_file(state: &EditorState, item: &PaletteItem) -> Option<String> {
    match item {
        PaletteItem::File(f) => Some(f.clone()),
        PaletteItem::Model(name) => (state.doc.level.models.iter())
            .chain(state.base().into_iter().flat_map(|b| b.models.iter()))
            .find(|m| &m.name == name)
            .map(|m| m.path.clone()),
    }
}

/// Draws `shown` in a square (an empty one for `None`).
fn thumbnail(ui: &mut egui::Ui, shown: Option<Shown>) {
    let size = egui::vec2(THUMB_POINTS, THUMB_POINTS);
    if let Some(Shown::Ready(texture)) = &shown {
        ui.add(egui::Image::new((texture.id(), size)));
        return;
    }
    let (rect, response) = ui.allocate_exact_size(size, egui::Sense::hover());
    let painter = ui.painter();
    painter.rect_filled(rect, 3.0, egui::Color32::from_gray(40));
    if let Some(Shown::Failed(why)) = shown {
        let stroke = egui::Stroke::new(1.5, egui::Color32::from_rgb(200, 80, 70));
        painter.line_segment([rect.left_top(), rect.right_bottom()], stroke);
        painter.line_segment([rect.right_top(), rect.left_bottom()], stroke);
        response.on_hover_text(format!("no thumbnail: {why}"));
    }
}
