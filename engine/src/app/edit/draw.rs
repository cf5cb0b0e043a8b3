//! What the editor draws besides the `editor::ui` panels: the toolbar (tool, space, snapping,
//! save, the recovery offer, messages) and, under every window, the selection highlight (each
//! selected instance's bounds projected as a wire box, the primary one brighter), the box
//! select band, the gizmo and, while a move drags, the grid of its plane (`align.rs`). All of it is egui shapes over the picture: the path tracer never sees it.
//!
//! Main thread, inside the editor's egui pass. Must not: touch the world or the document
//! except through the toolbar's snapping settings and the mode's operations.

use glam::Vec2;

use super::camera::project;
use super::gizmo::{Gizmo, Space, Tool};
use super::mode::EditMode;

/// The twelve edges of a box whose corner `k` has bit 0, 1, 2 set for max x, y, z.
const EDGES: [(usize, usize); 12] = [
    (0, 1),
    (2, 3),
    (4, 5),
    (6, 7),
    (0, 2),
    (1, 3),
    (4, 6),
    (5, 7),
    (0, 4),
    (1, 5),
    (2, 6),
    (3, 7),
];

/// The highlight's colours: the primary selected instance, the others.
pub const PRIMARY_COLOUR: egui::Color32 = egui::Color32::from_rgb(255, 200, 40);
pub const OTHER_COLOUR: egui::Color32 = egui::Color32::from_rgb(255, 140, 30);
/// The editor's view keys, in the toolbar's tooltip.
const KEYS: &str = "F1: play from here · right drag: look, WASD QE fly · middle drag or \
                    Alt+left: orbit · wheel: dolly · F: frame · left drag: box select";
/// The box select band's fill (premultiplied, faint).
const BAND_FILL: egui::Color32 = egui::Color32::from_rgba_premultiplied(40, 32, 6, 40);

fn snap_row(ui: &mut egui::Ui, label: &str, step: &mut Option<f32>, default: f32, unit: &str) {
    ui.horizontal(|ui| {
        let mut on = step.is_some();
        if ui.checkbox(&mut on, label).changed() {
            *step = on.then_some(default);
        }
        if let Some(s) = step.as_mut() {
            ui.add(
                egui::DragValue::new(s)
                    .speed(0.01)
                    .range(0.001..=1000.0)
                    .suffix(unit),
            );
        }
    });
}

impl EditMode {
    /// The toolbar window; returns whether Save was clicked.
    pub(super) fn toolbar(&mut self, ctx: &egui::Context) -> bool {
        let mut save = false;
        let mut restore = false;
        let mut discard = false;
        // A toolbar without a title bar docked at the bottom centre, under the picture's
        // middle; the keys in the tooltip of its "Keys" label.
        egui::Window::new("Editor")
            .title_bar(false)
            .resizable(false)
            .anchor(egui::Align2::CENTER_BOTTOM, [0.0, -8.0])
            .show(ctx, |ui| {
                ui.horizontal(|ui| {
                    for (tool, label) in [
                        (Tool::Translate, "Move (W)"),
                        (Tool::Rotate, "Rotate (E)"),
                        (Tool::Scale, "Scale (R)"),
                    ] {
                        if ui
                            .selectable_label(self.gizmo.tool == tool, label)
                            .clicked()
                        {
                            self.gizmo.tool = tool;
                        }
                    }
                    ui.separator();
                    for (space, label) in [(Space::World, "world"), (Space::Local, "local (X)")] {
                        if ui
                            .selectable_label(self.gizmo.space == space, label)
                            .clicked()
                        {
                            self.gizmo.space = space;
                        }
                    }
                });
                ui.horizontal(|ui| {
                    ui.label("snap:");
                    let snap = &mut self.state.snap;
                    snap_row(ui, "grid", &mut snap.grid, 0.25, " m");
                    snap_row(ui, "angle", &mut snap.angle_deg, 15.0, "°");
                    snap_row(ui, "scale", &mut snap.scale, 0.1, "×");
                    ui.separator();
                    save = ui.button("Save (Ctrl+S)").clicked();
                    ui.label("Keys").on_hover_text(KEYS);
                });
                if self.state.dirty() {
                    ui.label("unsaved changes");
                }
                if let Some(info) = &self.recovery {
                    let name = info.path.file_name().unwrap_or(info.path.as_os_str());
                    ui.label(format!(
                        "Unsaved edits from an earlier session: {}",
                        name.to_string_lossy()
                    ));
                    ui.horizontal(|ui| {
                        restore = ui.button("Restore it").clicked();
                        discard = ui.button("Discard it").clicked();
                    });
                }
                for message in self.messages.iter().rev().take(2).rev() {
                    ui.label(egui::RichText::new(message).small());
                }
            });
        if restore {
            self.pending_restore = true;
        }
        if discard {
            self.discard_offer();
        }
        save
    }

    /// The selection highlight and the gizmo, under every window.
    pub(super) fn draw_overlay(&mut self, ctx: &egui::Context) {
        let Some(camera) = self.camera else {
            return;
        };
        let rect = ctx.content_rect();
        let size = Vec2::new(rect.width(), rect.height());
        let desc = camera.desc();
        let painter = ctx.layer_painter(egui::LayerId::new(
            egui::Order::Background,
            egui::Id::unique("editor_overlay"),
        ));
        self.draw_drag_grid(&painter, &desc, camera.forward(), size, rect.min);
        let level = &self.state.doc.level;
        let primary = self.state.selection.primary();
        let at = |v: Vec2| egui::pos2(rect.min.x + v.x, rect.min.y + v.y);
        for &index in self.state.selection.instances() {
            let Some(corners) = self.world.world_box(level, index) else {
                continue;
            };
            let px = corners.map(|c| project(&desc, size, c));
            let colour = if primary == Some(index) {
                PRIMARY_COLOUR
            } else {
                OTHER_COLOUR
            };
            let stroke = egui::Stroke::new(2.0, colour);
            for (a, b) in EDGES {
                if let (Some(a), Some(b)) = (px[a], px[b]) {
                    painter.line_segment([at(a), at(b)], stroke);
                }
            }
        }
        if let Some(band) = self.box_drag.filter(|b| b.is_box()) {
            let (lo, hi) = band.rect();
            let r = egui::Rect::from_min_max(at(lo), at(hi));
            painter.rect_filled(r, 0.0, BAND_FILL);
            painter.rect_stroke(
                r,
                0.0,
                egui::Stroke::new(1.0, PRIMARY_COLOUR),
                egui::StrokeKind::Inside,
            );
        }
        let handles = primary
            .and_then(|p| level.instances.get(p))
            .and_then(|entry| self.gizmo.handles(&desc, size, entry));
        if let Some(h) = handles {
            let pointer = ctx.input(|i| i.pointer.hover_pos());
            let hot = self
                .gizmo
                .dragging()
                .or_else(|| pointer.and_then(|p| Gizmo::hit(&h, Vec2::new(p.x, p.y))));
            self.gizmo.draw(&painter, &h, hot);
        }
    }
}
