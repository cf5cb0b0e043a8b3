//! The level editor's core (issue 12), the part that needs no window: a level document (the
//! `Level` RON plus the comments of its file), edit commands with undo and redo on one history,
//! the selection and picking it by a ray from the camera, snapping, placing new pieces (the
//! palette's command), saving atomically with a backup after checking every reference, and
//! recovery files.
//!
//! Main thread. It edits the level description; the runner brings the world up to date
//! (re-spawn, or [`Edit::touches`] for targeted transform updates). Must not: touch the
//! renderer, the render thread or the GPU; it reads the scene only through `query`.
//! The egui panels in `ui` (outliner, palette, inspector, materials, history, problems, keys). The editor in the
//! running game (F1, camera, gizmos, highlight, the world in step) is `app::edit`, above this
//! layer. See `docs/EDITOR.md`.

mod check;
mod command;
mod comment_scan;
mod comments;
mod document;
mod fields;
mod history;
mod layout;
mod list_edit;
mod pick;
mod place;
mod recovery;
mod ron_tree;
mod save;
mod save_diff;
mod save_world;
mod selection;
mod snap;
mod splice;
mod state;
mod thumbs;
pub mod ui;
mod write;

pub use crate::level::ItemRef;
pub use check::{Problem, check_level, check_references, instance_to_select};
pub use command::{
    Edit, EditError, InstanceField, LaserField, ListEdit, MaterialField, MergeKey, Shift, Touch,
    VolumeField,
};
pub use comments::{Anchored, Comments};
pub use document::{Document, DocumentError};
pub use history::{History, HistoryEntry};
pub use pick::{Picked, ViewBasis, pick, pixel_ray};
pub use place::{Palette, PaletteItem, model_files, model_names, place_edit};
pub use recovery::{
    RecoveryInfo, base_recovery_path, discard_recovery, find_recovery, recovery_path,
    restore_recovery, write_recovery,
};
pub use save::{SaveError, SaveReport, backup_path, save_document, write_document};
pub use selection::{SelectMode, Selection};
pub use snap::{Snap, snap_angle_deg, snap_scale, snap_value};
pub use state::EditorState;
pub use thumbs::{
    Shown, Source, THUMB_PIXELS, THUMB_SPP, ThumbError, Thumbnails, content_hash, render_thumbnail,
    user_cache_dir,
};
pub use write::render_document;
