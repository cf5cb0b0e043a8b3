//! The edit → play loop with the game's hooks, as the window runner drives it (F1): entering
//! edit mode spawns the level again from the document, so every play-time change is discarded,
//! and the game hears of the new entities (`EditHooks::level_respawned`); the document and its
//! undo history stay as they were. Leaving it is "play from here": the game gets the view back
//! and starts at the editor camera (`EditHooks::play_from`: a first-person player on the floor
//! below it), playing the edited level, saved or not.
//!
//! Main thread, between frames. Must not: render, or step the game.

use super::mode::{EditFrame, EditMode};
use crate::app::runner::{EditHooks, Engine};

impl EditMode {
    /// Turns edit mode on ([`EditMode::enter`]) and tells `hooks` when the level was spawned
    /// again.
    pub fn enter_with(
        &mut self,
        engine: &mut Engine,
        hooks: Option<&mut dyn EditHooks>,
    ) -> EditFrame {
        let frame = self.enter(engine);
        if frame.respawned
            && let Some(hooks) = hooks
        {
            hooks.level_respawned(engine, self.world.spawned());
        }
        frame
    }

    /// Turns edit mode off ([`EditMode::leave`]) and starts the game where the editor camera
    /// is (`EditHooks::play_from`). Nothing when edit mode is off.
    pub fn play_from_here(&mut self, engine: &mut Engine, hooks: Option<&mut dyn EditHooks>) {
        if !self.active() {
            return;
        }
        let camera = self.camera;
        self.leave(engine);
        if let (Some(camera), Some(hooks)) = (camera, hooks) {
            hooks.play_from(engine, camera.position, camera.forward());
        }
    }
}
