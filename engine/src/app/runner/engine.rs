//! [`Engine`]: the engine a game runs on, headless or in a window, and its public surface: the
//! world, level spawning, light groups, physics, the level's logic, audio, ray queries, input,
//! the clock and the environment. One frame of the Brigade pipeline is [`Engine::frame`]
//! (`frame.rs`, phase by phase as `phase.rs` lists them).
//!
//! Owns: the world (hecs), its [`PhysicsWorld`] and [`LevelLogic`], the game side's [`Upkeep`]
//! (and so the ray-query scene), the [`Extractor`], the fixed-step clock, the actions' state
//! and the [`RenderThread`]. Games see them only through these methods: the upkeep, the
//! extractor and the render thread stay private. Main thread.
//! Must not: render (the render thread does) or block on anything but the hand-off.

use hecs::World;

use super::clock::FixedClock;
use super::commands::Commands;
use super::commands::ProgressEvent;
use super::environment::Environment;
use crate::accel::Upkeep;
use crate::app::input::ActionFrame;
use crate::app::input::ActionSet;
use crate::app::input::{InputMap, InputState};
use crate::app::persist::Settings;
use crate::app::replay::ReplayError;
use crate::app::replay::StepInput;
use crate::assets::{CameraDesc, Model};
use crate::audio::Audio;
use crate::commit::{Motion, PresentRequest};
use crate::ecs::ModelHandle;
use crate::extract::{Extractor, RenderCamera};
use crate::query::Queries;
use crate::render::present::PresentTarget;
use crate::render::{RenderConfig, RenderError, RenderThread, Rendered};
use crate::scene::RenderScene;
use crate::sim::physics::PhysicsWorld;
use crate::sim::triggers::LevelLogic;

/// Errors of the runner.
#[derive(Debug, thiserror::Error)]
pub enum EngineError {
    #[error(transparent)]
    Render(#[from] RenderError),
}

/// The engine's frame loop.
pub struct Engine {
    pub(in crate::app) world: World,
    pub(in crate::app) upkeep: Upkeep,
    pub(in crate::app) environment: Environment,
    pub(in crate::app) clock: FixedClock,
    /// Rigid bodies, characters, carrying, sensors: stepped after the game rules of every
    /// fixed step (an empty world costs next to nothing).
    pub(in crate::app) physics: PhysicsWorld,
    /// The level's clips, trigger volumes, lasers and rules (empty until a level with a
    /// `gameplay` section is spawned), run after physics in every fixed step.
    pub(in crate::app) logic: LevelLogic,
    /// Sounds, music and spatial emitters; listener at the camera. Headless engines record
    /// silently (`Audio::silent`); windowed ones open the sound device when there is one.
    pub(in crate::app) audio: Audio,
    /// Devices' state, fed by the runner (window events), read by the frame hook and menus.
    pub(in crate::app) input: InputState,
    /// The game's named actions: what each fixed step's [`ActionFrame`] holds.
    pub(in crate::app) actions: ActionSet,
    /// Where each fixed step's actions come from: the devices, recorded or not, or a replay.
    pub(in crate::app) step_input: StepInput,
    /// This step's actions (what the game's step hooks read).
    pub(in crate::app) step_actions: ActionFrame,
    /// Set when a replay has played its last step; later steps get no input.
    pub(in crate::app) replay_done: bool,
    /// What the game's hooks asked for, carried out after each hook.
    pub(in crate::app) commands: Commands,
    pub(in crate::app) extractor: Extractor,
    pub(in crate::app) render: RenderThread,
    pub(in crate::app) frame: u64,
    pub(in crate::app) camera: RenderCamera,
    pub(in crate::app) cut: bool,
    pub(in crate::app) capture_next: bool,
    pub(in crate::app) present_next: Option<PresentRequest>,
    /// Held by the shell (menus): no game hooks, no fixed steps; rendering goes on.
    pub(in crate::app) paused: bool,
    /// The player's settings as last applied (player code reads sensitivity and invert-Y).
    pub(in crate::app) settings: Settings,
    /// The settings the fixed steps read: the player's, with the look fixed by a recording
    /// or a replay (`StepInput::fixed_look`) while there is one.
    pub(in crate::app) step_settings: Settings,
    /// Checkpoints and level ends for the shell to save.
    pub(in crate::app) progress_events: Vec<ProgressEvent>,
    /// The world's transforms and the query scene are what the next fixed step needs: posed
    /// with no interpolation after the last step (see `app/step_scene.rs`). True at the start:
    /// the first step sees the scene as it is (at every frame rate alike), and the first frame
    /// does no upkeep twice.
    pub(in crate::app) step_scene_current: bool,
    /// Whether frames of several steps settle the world and the query scene before each extra
    /// step (`app/step_scene.rs`; [`Engine::settle_every_step`]).
    pub(in crate::app) settle_steps: bool,
    /// The laser beams' models registered so far, by their radiance's bits (`level.rs`): a
    /// level spawned again (the editor's F1, a restart) reuses them instead of growing the
    /// scene by one model per laser each time.
    pub(in crate::app) beam_models: std::collections::HashMap<[u32; 3], crate::ecs::ModelHandle>,
    /// What moved since the last commit (the cut is `cut`'s).
    pub(in crate::app) motion: Motion,
    /// The sun and sky the last commit carried (for `Motion::lighting`; `time_of_day.rs`).
    pub(in crate::app) committed_light:
        Option<(Option<crate::assets::SunDesc>, crate::assets::SkyDesc)>,
    /// The main thread's own sky tables, for the exposure (`sky_exposure.rs`).
    pub(in crate::app) sky_meter: super::sky_exposure::SkyMeter,
}

impl Engine {
    /// Starts the render thread with `config`, headless.
    pub fn new(config: RenderConfig, environment: Environment) -> Result<Self, EngineError> {
        let sky = config.sky_rebuild;
        Ok(Self::with_render(
            RenderThread::spawn(config)?,
            environment,
            Audio::silent(),
            sky,
        ))
    }

    /// Starts the render thread headless on the tracer `open` makes (`config.tracer` is
    /// ignored): for tests that need a tracer of their own, such as one whose GPU device is
    /// lost part-way (`RenderThread::spawn_with_tracer`).
    pub fn with_tracer(
        config: RenderConfig,
        environment: Environment,
        open: crate::render::OpenTracer,
    ) -> Result<Self, EngineError> {
        let sky = config.sky_rebuild;
        Ok(Self::with_render(
            RenderThread::spawn_with_tracer(config, open)?,
            environment,
            Audio::silent(),
            sky,
        ))
    }

    /// Starts the render thread with `config`, presenting into `target`'s window (see
    /// [`Engine::present_next`]).
    pub fn new_windowed(
        config: RenderConfig,
        environment: Environment,
        target: PresentTarget,
    ) -> Result<Self, EngineError> {
        let sky = config.sky_rebuild;
        Ok(Self::with_render(
            RenderThread::spawn_windowed(config, target)?,
            environment,
            Audio::new(),
            sky,
        ))
    }

    fn with_render(
        render: RenderThread,
        environment: Environment,
        audio: Audio,
        sky_rebuild: crate::scene::SkyRebuild,
    ) -> Self {
        Self {
            world: World::new(),
            upkeep: Upkeep::new(),
            camera: RenderCamera::from_desc(&environment.default_camera),
            environment,
            clock: FixedClock::default(),
            physics: PhysicsWorld::new(),
            logic: LevelLogic::default(),
            audio,
            input: InputState::default(),
            step_actions: ActionFrame::empty(&ActionSet::standard()),
            actions: ActionSet::standard(),
            step_input: StepInput::Live,
            replay_done: false,
            commands: Commands::default(),
            extractor: Extractor::new(),
            render,
            frame: 0,
            cut: true,
            capture_next: false,
            present_next: None,
            paused: false,
            settings: Settings::default(),
            step_settings: Settings::default(),
            progress_events: Vec::new(),
            step_scene_current: true,
            settle_steps: false,
            beam_models: std::collections::HashMap::new(),
            motion: Motion::default(),
            committed_light: None,
            sky_meter: super::sky_exposure::SkyMeter::new(sky_rebuild),
        }
    }

    /// The view used while no entity carries a camera.
    pub fn set_default_camera(&mut self, camera: CameraDesc) {
        self.environment.default_camera = camera;
        self.camera = RenderCamera::from_desc(&camera);
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

    /// The world: entities and their components.
    pub fn world(&self) -> &World {
        &self.world
    }

    /// The world, to spawn and change entities.
    pub fn world_mut(&mut self) -> &mut World {
        &mut self.world
    }

    /// Registers `model` (its meshes get BLAS slots); entities with a `Renderable` of the
    /// returned handle place it.
    pub fn add_model(&mut self, model: &Model) -> ModelHandle {
        self.upkeep.add_model(model)
    }

    /// Switches light group `group` on or off (a switched-off group leaves the light
    /// distribution from the next commit on).
    pub fn set_light_group(&mut self, group: u32, on: bool) {
        self.upkeep.set_light_group(group, on);
    }

    /// Whether light group `group` is on (groups start on).
    pub fn light_group_on(&self, group: u32) -> bool {
        self.upkeep.light_group_on(group)
    }

    /// From now on, every fixed step sees the world posed and the query scene as the previous
    /// step left them, however many steps a frame runs: the same input gives the same outcome
    /// at 10 fps as at 60 fps (`app/step_scene.rs`). It costs an upkeep (extraction, changed
    /// BLAS refits, a TLAS build) per extra step of a frame, so only games whose rules query the
    /// scene or read positions in their steps turn it on (the first-person game does); scripted
    /// runs and captures keep one upkeep a frame.
    pub fn settle_every_step(&mut self, on: bool) {
        self.settle_steps = on;
    }

    /// Ray queries on the flattened scene as of the last sealed commit (or, inside a frame's
    /// fixed steps, as the previous step left it).
    pub fn queries(&self) -> Queries<'_> {
        self.upkeep.queries()
    }

    /// The flattened scene as of the last sealed commit (read only: tools and tests).
    pub fn scene(&self) -> &RenderScene {
        self.upkeep.scene()
    }

    /// Rigid bodies, characters, carrying and sensors.
    pub fn physics(&self) -> &PhysicsWorld {
        &self.physics
    }

    /// Physics, to add characters, pick up bodies or apply impulses.
    pub fn physics_mut(&mut self) -> &mut PhysicsWorld {
        &mut self.physics
    }

    /// The level's running gameplay (outcome, last step's events, clips).
    pub fn logic(&self) -> &LevelLogic {
        &self.logic
    }

    /// The level's gameplay, to send events to its rules.
    pub fn logic_mut(&mut self) -> &mut LevelLogic {
        &mut self.logic
    }

    /// Sounds, music and their volumes.
    pub fn audio(&self) -> &Audio {
        &self.audio
    }

    /// Audio, to play sounds and set volumes.
    pub fn audio_mut(&mut self) -> &mut Audio {
        &mut self.audio
    }

    /// Replaces the sound output (the sounds playing on the old one stop): for example an
    /// `Audio::with_output` on a test device that can fail.
    pub fn set_audio(&mut self, audio: Audio) {
        self.audio = audio;
    }

    /// The actions' state that the game's hooks read.
    pub fn input(&self) -> &InputState {
        &self.input
    }

    /// The actions' state, for the runner to feed (window events, a replay).
    pub fn input_mut(&mut self) -> &mut InputState {
        &mut self.input
    }

    /// The game's named actions (`ActionSet::standard` until [`Engine::set_actions`]).
    pub fn actions(&self) -> &ActionSet {
        &self.actions
    }

    /// Sets the game's named actions; the devices' bindings come from its default map (see
    /// `Settings::input_map` for the player's own).
    pub fn set_actions(&mut self, actions: ActionSet) {
        self.input = InputState::new(&actions.default_map());
        self.step_actions = ActionFrame::empty(&actions);
        self.actions = actions;
    }

    /// Where the fixed steps' actions come from from now on: the devices ([`StepInput::Live`]),
    /// the devices recorded, or a replay (which then alone drives the game's steps, so a run
    /// repeats exactly, whatever the frame rate or the tracer).
    /// A recording is stamped with the player's look settings as they are now, and the steps
    /// keep them (and a replay's recorded ones) until the source changes: a run turns the same
    /// whatever settings the player has when it is replayed.
    pub fn set_step_input(&mut self, mut source: StepInput) {
        source.stamp_look(crate::app::replay::RecordedLook {
            mouse_sensitivity: self.settings.mouse_sensitivity,
            invert_y: self.settings.invert_y,
        });
        self.replay_done = false;
        self.step_input = source;
        self.refresh_step_settings();
    }

    fn refresh_step_settings(&mut self) {
        let mut step = self.settings.clone();
        if let Some(look) = self.step_input.fixed_look() {
            step.mouse_sensitivity = look.mouse_sensitivity;
            step.invert_y = look.invert_y;
        }
        self.step_settings = step;
    }

    /// Whether a replay has played its last step.
    pub fn replay_finished(&self) -> bool {
        self.replay_done
    }

    /// Writes the recording, when recording (atomically; every step so far).
    pub fn finish_recording(&self) -> Result<(), ReplayError> {
        self.step_input.finish()
    }

    /// Holds the game (`true`): frames still render and converge, but the game's `frame` and
    /// `fixed_step` hooks, physics and the level's logic do not run and game time stands
    /// still; effect sounds are held (`Audio::set_effects_paused`), music plays on. The shell
    /// holds it outside the Playing screen.
    pub fn set_paused(&mut self, paused: bool) {
        self.paused = paused;
        // Laser hums and footsteps stop with the game; the music plays on.
        self.audio.set_effects_paused(paused);
    }

    /// Whether the game is held ([`Engine::set_paused`]).
    pub fn paused(&self) -> bool {
        self.paused
    }

    /// The player's settings as last applied: mouse sensitivity and invert-Y for player
    /// controllers (`Settings::look_y_sign`), the volumes, the picture settings.
    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    /// Applies the player's settings: keeps them for [`Engine::settings`] and sets the audio
    /// buses (master, effects, music). Bindings go in with [`Engine::set_input_map`]; the
    /// window and the render thread's scaling are the runner's (the shell does both).
    pub fn set_settings(&mut self, settings: Settings) {
        use crate::audio::Bus;
        self.audio.set_volume(Bus::Master, settings.master_volume);
        self.audio.set_volume(Bus::Effects, settings.effects_volume);
        self.audio.set_volume(Bus::Music, settings.music_volume);
        self.settings = settings;
        self.refresh_step_settings();
    }

    /// Binds the devices by `map` from now on (held keys are let go).
    pub fn set_input_map(&mut self, map: &InputMap) {
        self.input = InputState::new(map);
    }

    /// Checkpoints and level ends reported since the last call (`Commands::checkpoint`,
    /// `Commands::end_level`, a `Win`/`Lose` rule), oldest first.
    pub fn take_progress_events(&mut self) -> Vec<ProgressEvent> {
        std::mem::take(&mut self.progress_events)
    }

    /// The fixed-step clock (step length, steps taken).
    pub fn clock(&self) -> &FixedClock {
        &self.clock
    }

    /// The clock, to change the step length before the first frame.
    pub fn clock_mut(&mut self) -> &mut FixedClock {
        &mut self.clock
    }

    /// Sun, sky, render settings and the default view.
    pub fn environment(&self) -> &Environment {
        &self.environment
    }

    /// The environment, to change the sun, sky or render settings (from the next commit on).
    pub fn environment_mut(&mut self) -> &mut Environment {
        &mut self.environment
    }

    /// Frames sealed so far.
    pub fn frames(&self) -> u64 {
        self.frame
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
