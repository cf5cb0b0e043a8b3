//! The editor's egui panels: an outliner of every item of the level (with search), a palette
//! of pieces to place, an inspector with typed fields for the primary selected instance (its
//! transform, model, material, body, …) or for the item in focus (a material, volume, laser,
//! clip or rule), the level's materials, gameplay widgets, the history with undo and redo, and
//! the problems of the last refused save (a click selects the item a problem names); plus the
//! editor's keys (Ctrl+Z, Ctrl+Shift+Z or Ctrl+Y, Ctrl+D, Delete, Ctrl+S), which are ignored
//! while a text field has the keyboard.
//!
//! [`panels`] is called once per egui pass by `app::edit::EditMode`. Widgets only
//! collect `Pending` edits; they are applied through [`EditorState`] after the pass draws, so
//! every change is a command. A change made while the primary pointer button is held (a
//! `DragValue` drag, a slider, a colour picker) belongs to one drag: one command.
//! Main thread. Must not: touch the world or the renderer (the runner follows the returned
//! [`Touch`]es), save by itself (Ctrl+S is reported in [`PanelOutput::save`]) or pick (a
//! piece to place is reported in [`PanelOutput::place`]).

mod bodies;
pub mod clips;
mod gameplay;
mod inspector;
mod materials;
pub mod outliner;
pub mod palette;

use super::check::instance_to_select;
use super::command::{Edit, Touch};
use super::place::PaletteItem;
pub use super::selection::SelectMode;
use super::state::EditorState;
use crate::level::ItemRef;

/// What the panels did this pass, for the runner.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PanelOutput {
    /// What of the world the applied edits, undos and redos changed, in order.
    pub touched: Vec<Touch>,
    /// Edits that could not be applied (the document is unchanged), as messages.
    pub errors: Vec<String>,
    /// Ctrl+S was pressed: the runner saves (`EditorState::save`) with its asset root.
    pub save: bool,
    /// A palette piece was clicked: the runner places it in front of the camera
    /// (`editor::place_edit`, one command). It is also the palette's current piece now.
    pub place: Option<PaletteItem>,
}

/// What the widgets asked for during a pass.
#[derive(Default)]
pub(super) struct Pending {
    pub edits: Vec<Edit>,
    pub select: Option<(Option<usize>, SelectMode)>,
    /// Select exactly these instances (a light group's).
    pub select_set: Option<Vec<usize>>,
    /// Put this item in focus (after any selection of this pass).
    pub focus: Option<ItemRef>,
    /// Put this item of the base file (a composed world's `common.ron`) in focus.
    pub focus_base: Option<ItemRef>,
    pub place: Option<PaletteItem>,
    pub undo: bool,
    pub redo: bool,
}

/// How a click changes the selection, from the held modifiers (Shift adds, Ctrl toggles).
pub fn mode_of(modifiers: egui::Modifiers) -> SelectMode {
    if modifiers.command || modifiers.ctrl {
        SelectMode::Toggle
    } else if modifiers.shift {
        SelectMode::Add
    } else {
        SelectMode::Replace
    }
}

/// The inspector's width, points.
const INSPECTOR_WIDTH: f32 = 420.0;

/// Draws the editor's panels over `ctx` for `state` and applies what they and the keys asked.
pub fn panels(ctx: &egui::Context, state: &mut EditorState) -> PanelOutput {
    let mut pending = Pending::default();
    let mut out = PanelOutput::default();
    keys(ctx, state, &mut pending, &mut out);
    // Outliner top left, inspector top right (both can be moved), history bottom left and
    // problems bottom right (docked), the toolbar bottom centre: the picture's middle free.
    let view = ctx.content_rect();
    let (left, right) = (view.min.x + 8.0, view.max.x - 8.0);
    let top = view.min.y + 8.0;
    egui::Window::new("Outliner")
        .default_pos([left, top])
        .default_width(260.0)
        // Down to the history window, docked under it.
        .default_height((view.height() - 260.0).max(160.0))
        .show(ctx, |ui| outliner::show(ui, state, &mut pending));
    egui::Window::new("Palette")
        .default_pos([left + 280.0, top])
        .default_width(220.0)
        .default_open(true)
        .show(ctx, |ui| palette::show(ui, state, &mut pending));
    egui::Window::new("Materials")
        .default_pos([right - INSPECTOR_WIDTH - 16.0, view.center().y])
        .default_width(INSPECTOR_WIDTH)
        .default_open(false)
        .show(ctx, |ui| materials::show(ui, state, &mut pending));
    egui::Window::new("Inspector")
        .default_pos([right - INSPECTOR_WIDTH - 16.0, top])
        .default_width(INSPECTOR_WIDTH)
        .show(ctx, |ui| {
            // Long items (a clip's keys, the gameplay lists) scroll inside the window.
            egui::ScrollArea::vertical()
                .id_salt("editor_inspector_scroll")
                .max_height((view.height() - 120.0).max(200.0))
                .show(ui, |ui| {
                    inspector::show(ui, state, &mut pending);
                    ui.collapsing("Gameplay", |ui| gameplay::show(ui, state, &mut pending));
                });
        });
    egui::Window::new("History")
        .anchor(egui::Align2::LEFT_BOTTOM, [8.0, -8.0])
        .default_width(260.0)
        .show(ctx, |ui| history(ui, state, &mut pending));
    if !state.problems.is_empty() {
        egui::Window::new("Problems")
            .anchor(egui::Align2::RIGHT_BOTTOM, [-8.0, -8.0])
            .show(ctx, |ui| problems(ui, state, &mut pending));
    }
    apply(ctx, state, pending, &mut out);
    out
}

/// The editor's keys, unless a text field has the keyboard.
fn keys(ctx: &egui::Context, state: &EditorState, p: &mut Pending, out: &mut PanelOutput) {
    if ctx.egui_wants_keyboard_input() {
        return;
    }
    use egui::{Key, Modifiers};
    let shift_command = Modifiers::COMMAND | Modifiers::SHIFT;
    ctx.input_mut(|i| {
        if i.consume_key(shift_command, Key::Z) || i.consume_key(Modifiers::COMMAND, Key::Y) {
            p.redo = true;
        } else if i.consume_key(Modifiers::COMMAND, Key::Z) {
            p.undo = true;
        }
        if i.consume_key(Modifiers::COMMAND, Key::S) {
            out.save = true;
        }
        let selected = state.selection.instances();
        if i.consume_key(Modifiers::COMMAND, Key::D) {
            let mut indices = selected.to_vec();
            indices.sort_unstable_by(|a, b| b.cmp(a));
            p.edits.push(Edit::Batch(
                indices
                    .into_iter()
                    .map(|index| Edit::DuplicateInstance { index })
                    .collect(),
            ));
        }
        if i.consume_key(Modifiers::NONE, Key::Delete) {
            let mut indices = selected.to_vec();
            indices.sort_unstable_by(|a, b| b.cmp(a));
            p.edits.push(Edit::Batch(
                indices
                    .into_iter()
                    .map(|index| Edit::DeleteInstance { index })
                    .collect(),
            ));
        }
    });
}

fn history(ui: &mut egui::Ui, state: &EditorState, p: &mut Pending) {
    ui.horizontal(|ui| {
        if ui
            .add_enabled(state.history.can_undo(), egui::Button::new("Undo"))
            .clicked()
        {
            p.undo = true;
        }
        if ui
            .add_enabled(state.history.can_redo(), egui::Button::new("Redo"))
            .clicked()
        {
            p.redo = true;
        }
        if state.dirty() {
            ui.label("unsaved changes");
        }
    });
    egui::ScrollArea::vertical()
        .max_height(160.0)
        .show(ui, |ui| {
            for entry in state.history.entries() {
                let text = egui::RichText::new(entry.description);
                ui.label(if entry.done { text } else { text.weak() });
            }
        });
}

fn problems(ui: &mut egui::Ui, state: &EditorState, p: &mut Pending) {
    ui.label("The level was not saved:");
    for problem in &state.problems {
        let clicked = ui.selectable_label(false, problem.to_string()).clicked();
        if !clicked {
            continue;
        }
        // The instance it is in or sits on, if any; any other item goes in focus too.
        let instance = instance_to_select(problem, &state.doc.level);
        p.select = Some((instance, SelectMode::Replace));
        if !matches!(problem.item, ItemRef::Instance(_) | ItemRef::Level) {
            p.focus = Some(problem.item);
        }
    }
}

/// Applies the pass's requests in order: selection, undo/redo, then the edits (one drag while
/// the primary pointer button is held).
fn apply(ctx: &egui::Context, state: &mut EditorState, p: Pending, out: &mut PanelOutput) {
    let held = ctx.input(|i| i.pointer.primary_down());
    if state.history.dragging() && !held {
        state.end_drag();
    }
    if let Some((instance, mode)) = p.select {
        state.selection.click(instance, mode);
    }
    if let Some(instances) = p.select_set {
        state.selection.set(instances);
        state.selection.focus(None);
    }
    if let Some(item) = p.focus {
        state.selection.focus(Some(item));
    }
    if let Some(item) = p.focus_base {
        state.selection.focus_base(item);
    }
    if let Some(item) = p.place {
        state.palette.current = Some(item.clone());
        out.place = Some(item);
    }
    let mut results = Vec::new();
    if p.undo {
        results.push(
            state
                .undo()
                .map(|t| t.unwrap_or(Touch::Transforms(Vec::new()))),
        );
    }
    if p.redo {
        results.push(
            state
                .redo()
                .map(|t| t.unwrap_or(Touch::Transforms(Vec::new()))),
        );
    }
    if !p.edits.is_empty() && held && !state.history.dragging() {
        state.begin_drag();
    }
    for edit in p.edits {
        results.push(state.apply(edit));
    }
    for result in results {
        match result {
            Ok(Touch::Transforms(t)) if t.is_empty() => {}
            Ok(touch) => out.touched.push(touch),
            Err(e) => out.errors.push(e.to_string()),
        }
    }
}

/// A one-line search field whose text egui keeps under `egui::Id::unique(id_salt)` between
/// passes; returns the text lower-cased, to match labels against (empty: everything matches).
fn search_field(ui: &mut egui::Ui, id_salt: &str, hint: &str) -> String {
    let id = egui::Id::unique(id_salt);
    let mut search: String = ui.data_mut(|d| d.get_temp(id)).unwrap_or_default();
    ui.add(
        egui::TextEdit::singleline(&mut search)
            .id(id)
            .hint_text(hint),
    );
    ui.data_mut(|d| d.insert_temp(id, search.clone()));
    search.to_lowercase()
}
