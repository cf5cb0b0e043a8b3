//! The editor's first egui panels: an outliner of the level's instances and gameplay items
//! (with search), an inspector with typed fields for the primary selected instance and its
//! material, gameplay widgets (volumes' instances, lasers' origin and direction, rewiring a
//! rule from one volume to another), the history with undo and redo, and the problems of the
//! last refused save; plus the editor's keys (Ctrl+Z, Ctrl+Shift+Z or Ctrl+Y, Ctrl+D,
//! Delete, Ctrl+S), which are ignored while a text field has the keyboard.
//!
//! [`panels`] is called once per egui pass by `app::edit::EditMode`. Widgets only
//! collect `Pending` edits; they are applied through [`EditorState`] after the pass draws, so
//! every change is a command. A change made while the primary pointer button is held (a
//! `DragValue` drag, a slider, a colour picker) belongs to one drag: one command.
//! Main thread. Must not: touch the world or the renderer (the runner follows the returned
//! [`Touch`]es) or save by itself (Ctrl+S is reported in [`PanelOutput::save`]).

mod gameplay;
mod inspector;
pub mod outliner;

use super::check::instance_to_select;
use super::command::{Edit, Touch};
pub use super::selection::SelectMode;
use super::state::EditorState;

/// What the panels did this pass, for the runner.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PanelOutput {
    /// What of the world the applied edits, undos and redos changed, in order.
    pub touched: Vec<Touch>,
    /// Edits that could not be applied (the document is unchanged), as messages.
    pub errors: Vec<String>,
    /// Ctrl+S was pressed: the runner saves (`EditorState::save`) with its asset root.
    pub save: bool,
}

/// What the widgets asked for during a pass.
#[derive(Default)]
pub(super) struct Pending {
    pub edits: Vec<Edit>,
    pub select: Option<(Option<usize>, SelectMode)>,
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
    egui::Window::new("Inspector")
        .default_pos([right - INSPECTOR_WIDTH - 16.0, top])
        .default_width(INSPECTOR_WIDTH)
        .show(ctx, |ui| {
            inspector::show(ui, state, &mut pending);
            ui.collapsing("Gameplay", |ui| gameplay::show(ui, state, &mut pending));
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
        if clicked && let Some(i) = instance_to_select(problem, &state.doc.level) {
            p.select = Some((Some(i), SelectMode::Replace));
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
