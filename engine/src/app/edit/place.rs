//! Placing the palette's pieces in the view: the point a piece goes to is where the pick ray
//! through the view's centre (a click in the palette) or through the pointer (P over the view)
//! first hits a level instance — the new instance's origin on that surface — else
//! [`PLACE_DISTANCE_METRES`] in front of the camera along that ray. The piece is placed by one
//! command (`editor::place_edit`: undo takes it away, with the model entry a file needed), and
//! the new instance becomes the selection. Also the palette's files, found when the editor opens
//! ([`palette_folder`]).
//!
//! Main thread, inside the editor's egui pass. Must not: edit the document except through
//! `EditorState::apply`, or touch the world (the mode follows the returned touch).

use std::path::{Path, PathBuf};

use glam::Vec2;

use super::mode::EditMode;
use crate::app::runner::Engine;
use crate::editor::{PaletteItem, SelectMode, Touch, pick, pixel_ray, place_edit};

/// How far in front of the camera a piece goes when the pick ray hits nothing, metres.
pub const PLACE_DISTANCE_METRES: f32 = 4.0;

/// The folder whose model files the palette offers for the level file at `level`: the
/// level's own folder, or the folder above it when that is named `levels` (a game's levels
/// beside its kit: `assets/reflect/levels/chamber_1.ron` offers `assets/reflect/**`).
pub fn palette_folder(level: &Path) -> PathBuf {
    let folder = level.parent().unwrap_or(Path::new("."));
    match folder.parent() {
        Some(up) if folder.file_name().is_some_and(|n| n == "levels") => up.to_path_buf(),
        _ => folder.to_path_buf(),
    }
}

impl EditMode {
    /// Places `item` where the ray through `at` (points from the view's top-left corner; the
    /// view's centre when `None`) meets the level; the new instance is selected. `None` when
    /// the editor has no camera yet or the edit was refused (said in the toolbar).
    pub(super) fn place(
        &mut self,
        ctx: &egui::Context,
        engine: &Engine,
        item: &PaletteItem,
        at: Option<Vec2>,
    ) -> Option<Touch> {
        let camera = self.camera?.desc();
        let rect = ctx.content_rect();
        let size = Vec2::new(rect.width(), rect.height());
        let p = at.unwrap_or(size * 0.5);
        let ray = pixel_ray(&camera, size.x as u32, size.y as u32, p.x, p.y);
        let entities = self.world.entities(&self.state.doc.level);
        let point = match pick(&engine.queries(), entities, &ray) {
            Some(hit) => hit.position,
            None => ray.origin + ray.direction.normalize_or_zero() * PLACE_DISTANCE_METRES,
        };
        let edit = place_edit(&self.state.doc.level, item, point, &self.state.snap);
        match self.state.apply(edit) {
            Ok(touch) => {
                let index = self.state.doc.level.instances.len().checked_sub(1)?;
                self.state.selection.click(Some(index), SelectMode::Replace);
                let t = self.state.doc.level.instances[index].transform.translation;
                self.say(format!(
                    "placed {item:?} at ({:.2}, {:.2}, {:.2}) m",
                    t[0], t[1], t[2]
                ));
                Some(touch)
            }
            Err(e) => {
                self.say(format!("not placed: {e}"));
                None
            }
        }
    }
}
