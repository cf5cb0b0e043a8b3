//! The world and the query scene a fixed step sees: as the previous step left them, posed with
//! no interpolation, whatever the frame rate. A frame of one step gets that from the frame's own
//! pose and upkeep (the clock leaves no fraction of a step); a frame of several steps (a slow
//! frame rate) or one that ends between steps (posed part-way to the next step) settles them
//! again before each step that needs it, so a replay, or the same live input, does the same at
//! 10 fps as at 60 fps. Only with `Engine::settle_every_step` (the first- and third-person
//! games turn it on): each settle is an upkeep (deforming meshes refitted, the TLAS rebuilt), which scripted
//! runs and captures, whose steps query nothing, do not pay.
//!
//! Owns: [`Engine::settle_step_scene`] and [`Engine::update_scene`] (typed scene changes into
//! the flattened scene, the camera, the listener, the render-space origin, and the motion
//! summed for the next commit); [`Engine::camera_position`] (where the camera those left is). Main thread, inside `Engine::frame`.
//! Must not: seal or hand off commits (the scene writes stay pending for the frame's commit),
//! or run game hooks.

use super::engine::Engine;
use crate::audio::sync_emitters;

impl Engine {
    /// Where the camera the last frame rendered from stands (metres, world space): the one an
    /// entity carries, else the default camera. The render areas sample from here.
    pub fn camera_position(&self) -> glam::Vec3 {
        self.camera.position()
    }

    /// Makes the world's transforms and the query scene what fixed step `index` needs: posed
    /// as of the end of the step before (physics not interpolated, level waves at `index`
    /// steps of simulated time), the changes in the flattened scene and its TLAS rebuilt. The
    /// writes join the next commit's.
    pub(in crate::app) fn settle_step_scene(&mut self, index: u64) {
        self.pose(0.0, index as f64 * self.clock.step_seconds);
        self.update_scene();
        self.upkeep.settle_queries();
        self.step_scene_current = true;
    }

    /// Typed scene changes into the flattened scene; the camera, the listener and the emitters
    /// follow their entities, render space's origin stays near the camera, and the motion
    /// since the last commit adds up (metres plus radians of camera motion; whether objects
    /// changed).
    pub(in crate::app) fn update_scene(&mut self) {
        let extracted = {
            puffin::profile_scope!("extract");
            self.extractor.extract(&mut self.world)
        };
        self.motion.objects |= !extracted.changes.is_empty();
        {
            puffin::profile_scope!("instances and BLAS");
            self.upkeep.apply_changes(extracted.changes);
        }
        if let Some(camera) = extracted.camera {
            self.camera = camera;
            self.motion.camera += extracted.camera_motion;
        }
        self.follow_with_audio();
        // Camera-relative rendering: keep render space's origin near the camera.
        self.upkeep.follow_camera(self.camera.position());
        // Light groups out of sight of the camera's render area leave the light table.
        self.upkeep.sample_from(self.camera.position());
    }

    /// Puts the listener at the camera (its basis as built by the extractor; a stand-in
    /// basis leaves the listener turned as it was) and moves spatial emitters with their
    /// entities.
    fn follow_with_audio(&mut self) {
        if !self.camera.is_fallback() {
            self.audio
                .set_listener(self.camera.position(), self.camera.orientation());
        }
        sync_emitters(&mut self.audio, &mut self.world);
    }
}
