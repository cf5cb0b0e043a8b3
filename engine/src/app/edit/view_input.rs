//! The editor's view: what the pointer and keys do over the picture (outside the panels).
//! - Right button held: look with the mouse, fly with W/A/S/D, Q/E (down, up), Shift faster.
//! - Middle button, or Alt with the left: orbit about the pivot. Wheel: dolly.
//! - Left click: pick the instance under the pointer (`editor::pick`, a ray query on the last
//!   commit) — Shift adds, Ctrl toggles, the sky clears.
//! - Left drag on a gizmo handle: move, rotate or scale the selection (one command; a move
//!   along a world axis snaps to other instances' faces, `align.rs`); elsewhere:
//!   box select (`box_select.rs`), with the same Shift and Ctrl.
//! - Keys, unless a text field has the keyboard or the right button flies: W, E, R pick the
//!   tool, X switches world/local, F frames the selection, P places the palette's current
//!   piece under the pointer (`place.rs`).
//!
//! Main thread, inside the editor's egui pass. Must not: touch the world except the camera's
//! pose (edits go through `EditorState`; the mode follows their touches).

use glam::{Vec2, Vec3};

use super::box_select::{BoxDrag, instances_in};
use super::gizmo::{Gizmo, Space, Tool};
use super::mode::EditMode;
use crate::app::runner::Engine;
use crate::assets::CameraDesc;
use crate::editor::{Touch, pick, pixel_ray};

/// Points of wheel scrolling that make one dolly step.
const POINTS_PER_DOLLY_STEP: f32 = 50.0;

fn v2(p: egui::Pos2) -> Vec2 {
    Vec2::new(p.x, p.y)
}

impl EditMode {
    /// Reads the view's input for this pass; returns the touches of the edits it applied.
    pub(super) fn view_input(&mut self, ctx: &egui::Context, engine: &mut Engine) -> Vec<Touch> {
        let mut touched = Vec::new();
        let rect = ctx.content_rect();
        let size = Vec2::new(rect.width(), rect.height());
        let response = egui::Area::new(egui::Id::unique("editor_view"))
            .order(egui::Order::Background)
            .fixed_pos(rect.min)
            .show(ctx, |ui| {
                ui.interact(
                    rect,
                    egui::Id::unique("editor_view_input"),
                    egui::Sense::click_and_drag(),
                )
            })
            .inner;
        let Some(mut camera) = self.camera else {
            return touched;
        };
        let (dt, modifiers, scroll, press_origin, primary_down) = ctx.input(|i| {
            (
                i.stable_dt,
                i.modifiers,
                i.smooth_scroll_delta.y,
                i.pointer.press_origin(),
                i.pointer.primary_down(),
            )
        });
        let delta = v2(response.drag_delta().to_pos2());
        let flying = response.dragged_by(egui::PointerButton::Secondary);
        if flying {
            camera.look(delta);
            let key = |k| ctx.input(|i| i.key_down(k));
            let axis =
                |plus, minus| f32::from(u8::from(key(plus))) - f32::from(u8::from(key(minus)));
            let direction = Vec3::new(
                axis(egui::Key::D, egui::Key::A),
                axis(egui::Key::E, egui::Key::Q),
                axis(egui::Key::S, egui::Key::W),
            );
            camera.fly(direction, dt, modifiers.shift);
        }
        let orbiting = response.dragged_by(egui::PointerButton::Middle)
            || (modifiers.alt && response.dragged_by(egui::PointerButton::Primary));
        if orbiting {
            camera.orbit(delta);
        }
        if response.hovered() && scroll != 0.0 {
            camera.dolly(scroll / POINTS_PER_DOLLY_STEP);
        }
        if !flying && !ctx.egui_wants_keyboard_input() {
            self.tool_keys(ctx, &mut camera);
        }
        self.camera = Some(camera);
        let place_key = !flying
            && !ctx.egui_wants_keyboard_input()
            && ctx.input_mut(|i| i.consume_key(egui::Modifiers::NONE, egui::Key::P));
        if place_key
            && let Some(p) = response.hover_pos()
            && let Some(item) = self.state.palette.current.clone()
        {
            touched.extend(self.place(ctx, engine, &item, Some(v2(p))));
        }
        let desc = camera.desc();
        let level = &self.state.doc.level;
        let handles = self
            .state
            .selection
            .primary()
            .and_then(|p| level.instances.get(p))
            .and_then(|entry| self.gizmo.handles(&desc, size, entry));
        let pointer = response
            .interact_pointer_pos()
            .or(response.hover_pos())
            .map(v2);
        let ray_at = |p: Vec2| pixel_ray(&desc, size.x as u32, size.y as u32, p.x, p.y);
        // Gizmo drags.
        if self.gizmo.dragging().is_none()
            && !modifiers.alt
            && response.drag_started_by(egui::PointerButton::Primary)
            && let (Some(h), Some(origin)) = (handles, press_origin)
            && let Some(axis) = Gizmo::hit(&h, v2(origin))
        {
            let selected = self
                .state
                .selection
                .instances()
                .iter()
                .filter_map(|&i| level.instances.get(i).map(|e| (i, e.transform)))
                .collect();
            self.gizmo
                .begin(axis, &h, selected, v2(origin), &ray_at(v2(origin)));
            self.state.begin_drag();
        }
        if self.gizmo.dragging().is_some() {
            if !primary_down {
                // Released: the last motion's edit is the drag's command.
                self.gizmo.end();
                self.state.end_drag();
            } else if let Some(p) = pointer
                && let Some(edit) = self.gizmo.drag_edit(p, &ray_at(p), &self.state.snap)
            {
                let edit = match self.gizmo.drag_line() {
                    Some((dir, _)) => self.align_to_faces(edit, dir),
                    None => edit,
                };
                match self.state.apply(edit) {
                    Ok(touch) => touched.push(touch),
                    Err(e) => self.say(e.to_string()),
                }
            }
        }
        // Box select: a left drag the gizmo did not take.
        if self.gizmo.dragging().is_none()
            && self.box_drag.is_none()
            && !modifiers.alt
            && response.drag_started_by(egui::PointerButton::Primary)
            && let Some(origin) = press_origin
        {
            let start = v2(origin);
            self.box_drag = Some(BoxDrag { start, end: start });
        }
        if let Some(mut band) = self.box_drag {
            if let Some(p) = pointer {
                band.end = p;
            }
            if primary_down {
                self.box_drag = Some(band);
            } else {
                self.box_drag = None;
                if band.is_box() {
                    self.select_box(&desc, size, band, modifiers);
                }
            }
        }
        // Picking.
        let on_handle = handles
            .zip(pointer)
            .is_some_and(|(h, p)| Gizmo::hit(&h, p).is_some());
        if response.clicked()
            && !on_handle
            && let Some(p) = pointer
        {
            let entities = self.world.entities(&self.state.doc.level);
            let picked = pick(&engine.queries(), entities, &ray_at(p));
            self.last_pick = picked;
            let mode = crate::editor::ui::mode_of(modifiers);
            self.state.selection.click(picked.map(|p| p.instance), mode);
        }
        touched
    }

    /// Selects what `band` holds (see `box_select`), as `modifiers` say.
    pub(super) fn select_box(
        &mut self,
        camera: &CameraDesc,
        size: Vec2,
        band: BoxDrag,
        modifiers: egui::Modifiers,
    ) {
        let level = &self.state.doc.level;
        let boxes = (0..level.instances.len())
            .filter_map(|i| self.world.world_box(level, i).map(|corners| (i, corners)));
        let inside = instances_in(camera, size, band.rect(), boxes);
        let mode = crate::editor::ui::mode_of(modifiers);
        self.state.selection.boxed(&inside, mode);
    }

    fn tool_keys(&mut self, ctx: &egui::Context, camera: &mut super::camera::EditorCamera) {
        use egui::{Key, Modifiers};
        let (w, e, r, x, f) = ctx.input_mut(|i| {
            (
                i.consume_key(Modifiers::NONE, Key::W),
                i.consume_key(Modifiers::NONE, Key::E),
                i.consume_key(Modifiers::NONE, Key::R),
                i.consume_key(Modifiers::NONE, Key::X),
                i.consume_key(Modifiers::NONE, Key::F),
            )
        });
        if self.gizmo.dragging().is_none() {
            if w {
                self.gizmo.tool = Tool::Translate;
            }
            if e {
                self.gizmo.tool = Tool::Rotate;
            }
            if r {
                self.gizmo.tool = Tool::Scale;
            }
            if x {
                self.gizmo.space = match self.gizmo.space {
                    Space::World => Space::Local,
                    Space::Local => Space::World,
                };
            }
        }
        if f && let Some((centre, radius)) = self.focus_sphere() {
            camera.frame(centre, radius);
        }
    }
}
