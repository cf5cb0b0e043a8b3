//! The level editor in a running game or tool (issue 12, `docs/EDITOR.md`): F1 toggles
//! [`EditMode`] over the level being played. It builds on the window-free core in
//! `crate::editor` (documents, edits with undo, selection, picking, snapping, saves, recovery,
//! panels) and adds what needs the world and the view: keeping the world in step with the
//! document ([`EditWorld`]), the free editor camera ([`EditorCamera`]), the transform
//! [`Gizmo`], the selection highlight and the toolbar.
//!
//! [`EditHooks`] (what a game offers the editor, through `Game::editor`) and [`EditTarget`]
//! (the level it hands over) live in the runner (`app/runner/edit_target.rs`: the first-person
//! game, a layer below, implements them) and are re-exported here.
//!
//! One file per job: `world` (the world in step), `align` (measure, face snapping, the drag
//! grid),
//! `camera`, `gizmo`, `box_select` (the rubber band), `mode` (entering, leaving, one pass),
//! `play` (entering and leaving with the game's hooks: play from here),
//! `place` (the palette's pieces put where the view's ray hits), `recover` (the recovery
//! file), `view_input` (pointer and keys
//! over the picture), `draw` (toolbar, highlight). Main thread. Must not: render, or run the
//! game's hooks (the runner holds the game while editing); may use only `input`, `persist`,
//! `replay`, `runner`, `script` and `play` of `app` (the layers before it).

mod align;
mod box_select;
mod camera;
mod draw;
mod gizmo;
mod mode;
mod place;
mod play;
mod recover;
mod view_input;
mod world;

pub use crate::app::runner::{BuildWorld, CheckWorld, EditHooks, EditTarget};
pub use align::{FACE_SNAP_METRES, face_offset};
pub use box_select::{BoxDrag, MIN_BOX_POINTS, instances_in};
pub use camera::{EditorCamera, LOOK_RADIANS_PER_POINT, project};
pub use draw::{OTHER_COLOUR, PRIMARY_COLOUR};
pub use gizmo::{
    DEGREES_PER_POINT, GRAB_POINTS, Gizmo, Handles, POINTS_PER_SCALE, Space, Tool, degrees_of,
    rotation_of,
};
pub use mode::{EditFrame, EditMode};
pub use place::{PLACE_DISTANCE_METRES, palette_folder};
pub use recover::older_recovery_path;
pub use world::{Bounds, EditWorld, Followed};
