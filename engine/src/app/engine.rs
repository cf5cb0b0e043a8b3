//! [`Engine`]: one frame of the Brigade pipeline, headless. The window runner drives the same
//! frames.
//!
//! Owns: the world (hecs), its [`PhysicsWorld`] and [`LevelLogic`], the game side's [`Upkeep`] (and so the ray-query scene), the
//! [`Extractor`], the fixed-step clock and the [`RenderThread`]. A frame: run the game's fixed
//! steps (with queries on the previous frame's BVH), each followed by a physics step and the
//! level's logic (clips, lasers, trigger volumes, rules; their effects carried out here) →
//! physics interpolation → skinned meshes deformed → propagate transforms → extract → upkeep →
//! seal the commit → hand it off. The game rules of frame N+1 then run while the render thread
//! renders frame N. Main thread.
//! Must not: render (the render thread does) or block on anything but the hand-off.

use std::time::Instant;

use hecs::World;

use super::clock::FixedClock;
use super::work::FrameWork;
use crate::accel::Upkeep;
use crate::assets::{CameraDesc, RenderSettings, SkyDesc, SunDesc};
use crate::audio::{Audio, PlayOptions, sync_emitters};
use crate::commit::{Commit, Motion, PresentRequest};
use crate::ecs::propagate_transforms;
use crate::extract::Extractor;
use crate::query::Queries;
use crate::render::present::PresentTarget;
use crate::render::{RenderConfig, RenderError, RenderThread, Rendered};
use crate::sim::animation::{deform_skinned, tick_skinned};
use crate::sim::physics::PhysicsWorld;
use crate::sim::triggers::{Effect, LevelLogic};

/// Everything about the scene that is not an entity: sun, sky, render settings, and the view to
/// use when no entity carries a camera.
#[derive(Clone, Copy, Debug)]
pub struct Environment {
    pub sun: Option<SunDesc>,
    pub sky: SkyDesc,
    pub render: RenderSettings,
    pub default_camera: CameraDesc,
}

/// Errors of the runner.
#[derive(Debug, thiserror::Error)]
pub enum EngineError {
    #[error(transparent)]
    Render(#[from] RenderError),
}

/// What one call of [`Engine::frame`] did on the main thread.
#[derive(Clone, Copy, Debug, Default)]
pub struct FrameReport {
    pub frame: u64,
    pub steps: u32,
    /// Seconds in game rules (fixed steps) and transform propagation.
    pub update_seconds: f64,
    /// Seconds in extraction and upkeep (BVH refits/rebuilds, TLAS, lights).
    pub upkeep_seconds: f64,
    /// Seconds waiting for the render thread to take the commit.
    pub handoff_seconds: f64,
    pub commit_bytes: usize,
    /// Bytes of overlay (egui vertices, indices, texture updates) the commit carried.
    pub overlay_bytes: usize,
    /// What was computed: instances, BVH refits/rebuilds, TLAS builds, lights, bounces.
    pub work: FrameWork,
}

/// The engine's frame loop.
pub struct Engine {
    pub world: World,
    pub upkeep: Upkeep,
    pub environment: Environment,
    pub clock: FixedClock,
    /// Rigid bodies, characters, carrying, sensors: stepped after the game rules of every
    /// fixed step (an empty world costs next to nothing).
    pub physics: PhysicsWorld,
    /// The level's clips, trigger volumes, lasers and rules (empty until a level with a
    /// `gameplay` section is spawned), run after physics in every fixed step.
    pub logic: LevelLogic,
    /// Sounds, music and spatial emitters; listener at the camera. Headless engines record
    /// silently (`Audio::silent`); windowed ones open the sound device when there is one.
    pub audio: Audio,
    extractor: Extractor,
    render: RenderThread,
    frame: u64,
    camera: CameraDesc,
    cut: bool,
    capture_next: bool,
    present_next: Option<PresentRequest>,
}

impl Engine {
    /// Starts the render thread with `config`, headless.
    pub fn new(config: RenderConfig, environment: Environment) -> Result<Self, EngineError> {
        Ok(Self::with_render(
            RenderThread::spawn(config)?,
            environment,
            Audio::silent(),
        ))
    }

    /// Starts the render thread with `config`, presenting into `target`'s window (see
    /// [`Engine::present_next`]).
    pub fn new_windowed(
        config: RenderConfig,
        environment: Environment,
        target: PresentTarget,
    ) -> Result<Self, EngineError> {
        Ok(Self::with_render(
            RenderThread::spawn_windowed(config, target)?,
            environment,
            Audio::new(),
        ))
    }

    fn with_render(render: RenderThread, environment: Environment, audio: Audio) -> Self {
        Self {
            world: World::new(),
            upkeep: Upkeep::new(),
            camera: environment.default_camera,
            environment,
            clock: FixedClock::default(),
            physics: PhysicsWorld::new(),
            logic: LevelLogic::default(),
            audio,
            extractor: Extractor::new(),
            render,
            frame: 0,
            cut: true,
            capture_next: false,
            present_next: None,
        }
    }

    /// The view used while no entity carries a camera.
    pub fn set_default_camera(&mut self, camera: CameraDesc) {
        self.environment.default_camera = camera;
        self.camera = camera;
        self.cut = true;
    }

    /// Simulated seconds since the start (fixed steps taken × step length).
    pub fn time_seconds(&self) -> f64 {
        self.clock.steps as f64 * self.clock.step_seconds
    }

    /// Marks the next frame as a camera cut (the converged image restarts).
    pub fn cut(&mut self) {
        self.cut = true;
    }

    /// Asks the render thread to send the converged film back after the next frame.
    pub fn capture_next(&mut self) {
        self.capture_next = true;
    }

    /// How the next frame is to be shown in the window (the window runner sets it every
    /// frame). A headless render thread presents nothing but follows the surface size.
    pub fn present_next(&mut self, request: PresentRequest) {
        self.present_next = Some(request);
    }

    /// Runs one frame: `frame_seconds` of simulated time in fixed steps of game rules
    /// (`game(world, queries, step_seconds)`) each followed by a physics step, then physics
    /// interpolation, extraction, upkeep and the hand-off.
    pub fn frame(
        &mut self,
        frame_seconds: f64,
        mut game: impl FnMut(&mut World, Queries<'_>, f64),
    ) -> Result<FrameReport, EngineError> {
        let started = Instant::now();
        let steps = self.clock.advance(frame_seconds);
        for _ in 0..steps {
            game(
                &mut self.world,
                self.upkeep.queries(),
                self.clock.step_seconds,
            );
            self.physics.step(&mut self.world, self.clock.step_seconds);
            tick_skinned(&mut self.world, self.clock.step_seconds);
            let effects = self.logic.step(
                &mut self.world,
                &self.physics,
                self.upkeep.queries(),
                self.clock.step_seconds,
            );
            self.carry_out(effects);
            self.audio.tick(self.clock.step_seconds);
        }
        // Render between the last two physics steps (the clock's leftover fraction).
        self.physics
            .interpolate(&mut self.world, self.clock.alpha());
        deform_skinned(&mut self.world);
        propagate_transforms(&mut self.world);
        let update_seconds = started.elapsed().as_secs_f64();

        let started = Instant::now();
        let extracted = self.extractor.extract(&mut self.world);
        let objects = !extracted.changes.is_empty();
        self.upkeep.apply_changes(extracted.changes);
        if let Some(camera) = extracted.camera {
            self.camera = camera;
        }
        self.follow_with_audio();
        // Camera-relative rendering: keep render space's origin near the camera.
        self.upkeep
            .follow_camera(glam::Vec3::from(self.camera.position));
        let (writes, header, upkeep) = self.upkeep.finish_frame();
        let mut work = FrameWork::of(&self.world, &self.upkeep, &upkeep, &self.environment.render);
        work.awake_bodies = self.physics.awake_bodies() as u32;
        let upkeep_seconds = started.elapsed().as_secs_f64();

        let commit = Commit {
            frame: self.frame,
            writes,
            header,
            camera: self.camera,
            sun: self.environment.sun,
            sky: self.environment.sky,
            render: self.environment.render,
            motion: Motion {
                cut: std::mem::take(&mut self.cut),
                camera: if extracted.camera.is_some() {
                    extracted.camera_motion
                } else {
                    0.0
                },
                objects,
            },
            upkeep,
            capture: std::mem::take(&mut self.capture_next),
            update_seconds,
            present: self.present_next.take(),
        };
        let commit_bytes = commit.bytes();
        let overlay_bytes = commit
            .present
            .as_ref()
            .and_then(|p| p.overlay.as_ref())
            .map_or(0, |o| o.bytes());
        let started = Instant::now();
        self.render.submit(commit)?;
        let handoff_seconds = started.elapsed().as_secs_f64();
        let report = FrameReport {
            frame: self.frame,
            steps,
            update_seconds,
            upkeep_seconds,
            handoff_seconds,
            commit_bytes,
            overlay_bytes,
            work,
        };
        self.frame += 1;
        Ok(report)
    }

    /// Carries out what the level's rules asked for in a step.
    fn carry_out(&mut self, effects: Vec<Effect>) {
        for effect in effects {
            match effect {
                Effect::Lights { group, on } => self.upkeep.set_light_group(group, on),
                Effect::ToggleLights(group) => {
                    let on = self.upkeep.light_group_on(group);
                    self.upkeep.set_light_group(group, !on);
                }
                Effect::Sound { sound, at, volume } => {
                    let Some(planned) = self.logic.sounds().get(sound) else {
                        continue;
                    };
                    let at = at.and_then(|e| {
                        crate::sim::triggers::world_from_model(&self.world, e)
                            .map(|m| m.w_axis.truncate())
                    });
                    let options = PlayOptions {
                        volume,
                        looped: false,
                        at,
                    };
                    if let Err(e) = self.audio.play(&planned.sound, options) {
                        log::warn!("sound {:?}: {e}", planned.name);
                    }
                }
            }
        }
    }

    /// Puts the listener at the camera and moves spatial emitters with their entities.
    fn follow_with_audio(&mut self) {
        let c = &self.camera;
        let position = glam::Vec3::from(c.position);
        let forward = (glam::Vec3::from(c.look_at) - position).normalize_or_zero();
        let right = forward.cross(glam::Vec3::from(c.up)).normalize_or_zero();
        if forward != glam::Vec3::ZERO && right != glam::Vec3::ZERO {
            // The listener looks along its local −Z with +Y up (right-handed).
            let up = right.cross(forward);
            let basis = glam::Mat3::from_cols(right, up, -forward);
            self.audio
                .set_listener(position, glam::Quat::from_mat3(&basis).normalize());
        }
        sync_emitters(&mut self.audio, &mut self.world);
    }

    /// Render results that are ready.
    pub fn rendered(&self) -> Vec<Result<Rendered, RenderError>> {
        self.render.ready()
    }

    /// Waits for the next render result.
    pub fn wait_rendered(&self) -> Option<Result<Rendered, RenderError>> {
        self.render.wait()
    }

    /// Stops the render thread after it rendered everything submitted; returns those results.
    pub fn shutdown(self) -> Vec<Result<Rendered, RenderError>> {
        self.render.shutdown()
    }
}
