//! [`EditMode`]: the editor over a running level (F1). Entering it spawns the level again from
//! the document (what was played is discarded: "edits made while playing are discarded on
//! return"), takes over the view with the [`EditorCamera`] and holds the game (the runner
//! pauses the engine; the path tracer keeps converging). Each egui pass it draws the panels
//! (`editor::ui`), the toolbar, the selection highlight and the gizmo, reads the view's
//! pointer and keys (`view_input.rs`), and brings the world up to date after every edit
//! ([`EditWorld::follow`]) and keeps the recovery file (`recover.rs`). Leaving gives the view back: the game plays the edited level
//! ("play from here").
//!
//! Main thread, inside the runner's egui pass. Must not: render, or run the game's hooks.

use glam::Vec3;
use hecs::Entity;

use std::path::PathBuf;

use super::box_select::BoxDrag;
use super::camera::EditorCamera;
use super::gizmo::Gizmo;
use super::world::{EditWorld, Followed};
use crate::app::runner::EditTarget;
use crate::app::runner::Engine;
use crate::app::runner::SpawnedLevel;
use crate::ecs::{CameraRig, Transform};
use crate::editor::{
    Document, DocumentError, Edit, EditError, EditorState, Picked, RecoveryInfo, SaveReport,
    Thumbnails, Touch, find_recovery,
};

/// Messages kept for the toolbar.
const MESSAGES: usize = 5;

/// What one pass of the editor did, for the runner.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct EditFrame {
    /// The level was spawned again: the game's handles are stale (`EditHooks::level_respawned`).
    pub respawned: bool,
    /// A save was written this pass.
    pub saved: bool,
}

/// The editor over a running level.
pub struct EditMode {
    pub state: EditorState,
    pub world: EditWorld,
    pub camera: Option<EditorCamera>,
    pub gizmo: Gizmo,
    /// The camera entity the editor drives and its transform before it took it.
    taken: Option<(Entity, Transform)>,
    /// A camera the editor spawned because the world had none.
    own_camera: Option<Entity>,
    active: bool,
    pub(super) messages: Vec<String>,
    /// A recovery file newer than the level, offered on opening.
    pub(super) recovery: Option<RecoveryInfo>,
    /// `History::state_id` the recovery file on disk holds (or that needs none).
    pub(super) recovered_state: u64,
    /// The last pick (instance under the click), for tools and tests.
    pub last_pick: Option<Picked>,
    /// The toolbar's Restore was clicked (carried out after the pass's drawing).
    pub(super) pending_restore: bool,
    /// The rubber band of a box select being dragged.
    pub(super) box_drag: Option<BoxDrag>,
    /// Whether recovery files are written (tools and tests that edit committed levels they
    /// must not write beside turn it off).
    pub(super) recovery_files: bool,
    /// Where the palette's thumbnails are cached, until the first pass makes them (`None`:
    /// none are made).
    thumbnail_cache: Option<PathBuf>,
}

impl EditMode {
    /// Opens `target`'s level file for editing over the world the game spawned (`spawned`).
    pub fn open(target: EditTarget, spawned: SpawnedLevel) -> Result<Self, DocumentError> {
        let mut state = EditorState::open(&target.path)?;
        let folder = super::place::palette_folder(&target.path);
        state.palette.files = crate::editor::model_files(target.root.path(), &folder);
        if let Some(base_path) = &target.base_path {
            state.set_base(base_path, Document::open(base_path)?);
        }
        let recovery = find_recovery(&target.path);
        Ok(Self {
            state,
            world: EditWorld::new(target, spawned),
            camera: None,
            gizmo: Gizmo::default(),
            taken: None,
            own_camera: None,
            active: false,
            messages: Vec::new(),
            recovery,
            recovered_state: 0,
            last_pick: None,
            pending_restore: false,
            box_drag: None,
            recovery_files: true,
            thumbnail_cache: Some(crate::editor::user_cache_dir()),
        })
    }

    /// The toolbar's last messages (saves, refusals, a document that does not load), oldest
    /// first.
    pub fn messages(&self) -> &[String] {
        &self.messages
    }

    /// The rubber band of a box select being dragged (points from the view's corner).
    pub fn box_drag(&self) -> Option<BoxDrag> {
        self.box_drag
    }

    /// Caches the palette's thumbnails in `cache` instead of the user's cache folder (`None`:
    /// draws none). Tests give a scratch folder.
    pub fn with_thumbnail_cache(mut self, cache: Option<PathBuf>) -> Self {
        self.thumbnail_cache = cache;
        self
    }

    /// Writes no recovery files from now on (for tools and tests over committed levels).
    pub fn without_recovery_files(mut self) -> Self {
        self.recovery_files = false;
        self
    }

    /// Whether edit mode is on.
    pub fn active(&self) -> bool {
        self.active
    }

    pub(super) fn say(&mut self, message: impl Into<String>) {
        let message = message.into();
        log::info!("editor: {message}");
        self.messages.push(message);
        if self.messages.len() > MESSAGES {
            self.messages.remove(0);
        }
    }

    /// Turns edit mode on: the level spawned again from the document, the view taken over.
    /// Returns what happened to the world (the runner tells the game when it was respawned).
    pub fn enter(&mut self, engine: &mut Engine) -> EditFrame {
        let mut frame = EditFrame::default();
        if self.active {
            return frame;
        }
        self.active = true;
        let doc = &self.state.doc;
        let base = doc.base.as_deref().map(|b| &b.level);
        match self.world.respawn_in(engine, &doc.level, base) {
            Ok(()) => frame.respawned = true,
            Err(e) => self.say(format!("the level does not load: {e}")),
        }
        self.take_camera(engine);
        frame
    }

    /// Turns edit mode off: the game's camera back where it was; the world stays as edited.
    /// A recovery file is written when there are unsaved changes.
    pub fn leave(&mut self, engine: &mut Engine) {
        if !self.active {
            return;
        }
        self.active = false;
        self.gizmo.end();
        self.box_drag = None;
        self.state.end_drag();
        if let Some((entity, transform)) = self.taken.take() {
            let _ = engine.world.insert_one(entity, transform);
        }
        if let Some(entity) = self.own_camera.take() {
            let _ = engine.world.despawn(entity);
        }
        self.keep_recovery();
        self.world.leave_lights(engine);
        engine.cut();
    }

    fn take_camera(&mut self, engine: &mut Engine) {
        let found = engine
            .world
            .query::<(Entity, &CameraRig, &Transform)>()
            .iter()
            .next()
            .map(|(e, rig, t)| (e, *rig, *t));
        let (entity, rig, transform) = match found {
            Some(found) => found,
            None => {
                let desc = engine.environment().default_camera;
                let (_, transform, rig) = crate::app::play::FlyCamera::from_view(&desc, 4.0);
                let entity = engine.world.spawn((transform, rig));
                self.own_camera = Some(entity);
                (entity, rig, transform)
            }
        };
        self.taken = Some((entity, transform));
        let camera = self.camera.get_or_insert_with(|| {
            EditorCamera::from_transform(&transform, rig, level_speed(&self.world, &self.state))
        });
        camera.rig = rig;
        let _ = engine.world.insert_one(entity, camera.transform());
    }

    /// The camera entity's transform follows the editor camera.
    pub(super) fn place_camera(&mut self, engine: &mut Engine) {
        if let (Some((entity, _)), Some(camera)) = (self.taken, self.camera) {
            let transform = camera.transform();
            let moved = engine
                .world
                .get::<&Transform>(entity)
                .map_or(true, |t| *t != transform);
            if moved {
                let _ = engine.world.insert_one(entity, transform);
            }
        }
    }

    /// One egui pass of the editor (nothing while it is off).
    pub fn ui(&mut self, ctx: &egui::Context, engine: &mut Engine) -> EditFrame {
        let mut frame = EditFrame::default();
        if !self.active {
            return frame;
        }
        self.state.bounds = self.selection_bounds();
        if let Some(cache) = self.thumbnail_cache.take() {
            let thumbs = Thumbnails::new(self.world.target.root.clone(), cache);
            self.state.thumbs = Some(std::sync::Arc::new(std::sync::Mutex::new(thumbs)));
        }
        let out = crate::editor::ui::panels(ctx, &mut self.state);
        for e in &out.errors {
            self.say(e.clone());
        }
        let failed = (self.state.thumbs.as_ref())
            .and_then(|t| t.lock().ok().map(|mut t| std::mem::take(&mut t.messages)));
        for message in failed.unwrap_or_default() {
            self.say(message);
        }
        let mut touched = out.touched;
        if let Some(item) = &out.place {
            touched.extend(self.place(ctx, engine, item, None));
        }
        let mut save = out.save;
        save |= self.toolbar(ctx);
        touched.extend(self.view_input(ctx, engine));
        self.place_camera(engine);
        frame.respawned = self.follow(engine, touched);
        if std::mem::take(&mut self.pending_restore) {
            frame.respawned |= self.restore(engine);
        }
        self.draw_overlay(ctx);
        if save {
            frame.saved = self.save();
        }
        self.keep_recovery();
        frame
    }

    /// Applies `edit` as a panel's typed field does (one command) and brings the world up to
    /// date.
    pub fn apply(&mut self, engine: &mut Engine, edit: Edit) -> Result<EditFrame, EditError> {
        let touch = self.state.apply(edit)?;
        let respawned = self.follow(engine, vec![touch]);
        self.keep_recovery();
        Ok(EditFrame {
            respawned,
            saved: false,
        })
    }

    /// Undoes the last command and brings the world up to date (`false`: nothing to undo).
    pub fn undo(&mut self, engine: &mut Engine) -> Result<bool, EditError> {
        let Some(touch) = self.state.undo()? else {
            return Ok(false);
        };
        self.follow(engine, vec![touch]);
        self.keep_recovery();
        Ok(true)
    }

    /// Redoes the last undone command and brings the world up to date.
    pub fn redo(&mut self, engine: &mut Engine) -> Result<bool, EditError> {
        let Some(touch) = self.state.redo()? else {
            return Ok(false);
        };
        self.follow(engine, vec![touch]);
        self.keep_recovery();
        Ok(true)
    }

    /// Brings the world up to date after `touched` (one respawn at most per pass).
    pub(super) fn follow(&mut self, engine: &mut Engine, touched: Vec<Touch>) -> bool {
        let mut moved = Vec::new();
        let mut level = false;
        for touch in touched {
            match touch {
                Touch::Transforms(indices) => moved.extend(indices),
                Touch::Level => level = true,
            }
        }
        moved.sort_unstable();
        moved.dedup();
        let touch = if level {
            Touch::Level
        } else if moved.is_empty() {
            return false;
        } else {
            Touch::Transforms(moved)
        };
        let doc = &self.state.doc;
        let base = doc.base.as_deref().map(|b| &b.level);
        match self.world.follow_in(engine, &doc.level, base, &touch) {
            Ok(Followed::Respawned) => true,
            Ok(Followed::Moved(_)) => false,
            Err(e) => {
                self.say(format!("the world keeps its last good state: {e}"));
                false
            }
        }
    }

    /// Saves through the target's asset root (a part of a composed world with its base: each
    /// changed file to itself); says which files were written.
    pub fn save(&mut self) -> bool {
        let root = self.world.target.root.clone();
        let saved = match self.world.target.check.clone() {
            Some(check) => {
                let doc = &self.state.doc;
                let problems = check(&doc.level, doc.base.as_deref().map(|b| &b.level));
                self.state.save_world(problems)
            }
            None => self.state.save(Some(&root)).map(|report| vec![report]),
        };
        match saved {
            Ok(reports) => {
                let files: Vec<String> = reports.iter().map(|r| written(r, root.path())).collect();
                self.say(format!("saved {}", files.join("; ")));
                true
            }
            Err(e) => {
                self.say(format!("not saved: {e}"));
                false
            }
        }
    }

    /// Centre and radius (metres) of the selected instances' bounds, or of the whole level
    /// when nothing is selected.
    pub fn focus_sphere(&self) -> Option<(Vec3, f32)> {
        let level = &self.state.doc.level;
        let selected = self.state.selection.instances();
        let indices: Vec<usize> = if selected.is_empty() {
            (0..level.instances.len()).collect()
        } else {
            selected.to_vec()
        };
        let (mut lo, mut hi) = (Vec3::INFINITY, Vec3::NEG_INFINITY);
        for i in indices {
            for p in self.world.world_box(level, i).into_iter().flatten() {
                lo = lo.min(p);
                hi = hi.max(p);
            }
        }
        (lo.x <= hi.x).then(|| ((lo + hi) * 0.5, (hi - lo).length() * 0.5))
    }
}

/// What the status line says of one file a save wrote.
/// The status line's words for one written file: its path under the asset root `root` (in
/// full when outside it), its size and how much of it changed.
fn written(report: &SaveReport, root: &std::path::Path) -> String {
    let path = report.path.strip_prefix(root).unwrap_or(&report.path);
    let how = match &report.rewritten {
        None => "only the edited items changed".to_string(),
        Some(why) => format!("the whole file rewritten: {why}"),
    };
    format!("{} ({} bytes, {how})", path.display(), report.bytes)
}

/// A fly speed for the level: its size crossed in about ten seconds.
fn level_speed(world: &EditWorld, state: &EditorState) -> f32 {
    let level = &state.doc.level;
    let (mut lo, mut hi) = (Vec3::INFINITY, Vec3::NEG_INFINITY);
    for i in 0..level.instances.len() {
        for p in world.world_box(level, i).into_iter().flatten() {
            lo = lo.min(p);
            hi = hi.max(p);
        }
    }
    if lo.x <= hi.x {
        ((hi - lo).length() / 10.0).clamp(0.5, 50.0)
    } else {
        4.0
    }
}
