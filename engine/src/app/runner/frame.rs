//! [`Engine::frame`]: one frame of the Brigade pipeline on the main thread, one function per
//! [`Phase`] (`phase.rs` lists them and says what each does).
//!
//! Profiling (F5, `app/window/profile_frames.rs`): puffin scopes per [`Phase`] and system.
//!
//! Owns: the order of the engine's work in a frame, carrying out the game's [`Commands`] and
//! the level logic's effects, and delivering [`LevelEvent`]s to the game. Main thread.
//! Must not: render (the render thread does) or block on anything but the hand-off.

use std::time::Instant;

use super::commands::Command;
use super::commands::ProgressEvent;
use super::engine::{Engine, EngineError};
use super::game::{FrameInput, Game, LevelEvent, Step};
use super::phase::{FrameReport, Phase, PhaseTimes};
use super::waves::waves_system;
use super::work::FrameWork;
use crate::accel::UpkeepStats;
use crate::app::input::ActionFrame;
use crate::audio::PlayOptions;
use crate::commit::{Commit, Motion};
use crate::ecs::propagate_transforms;
use crate::scene::{SceneHeader, SceneWrite};
use crate::sim::animation::{animate_characters, deform_skinned, tick_skinned};
use crate::sim::triggers::Effect;
use crate::sim::water::water_system;

/// What the upkeep phase leaves for sealing.
struct Prepared {
    writes: Vec<SceneWrite>,
    header: SceneHeader,
    stats: UpkeepStats,
    work: FrameWork,
    motion: Motion,
}

/// Times consecutive phases.
struct PhaseTimer {
    times: PhaseTimes,
    lap: Instant,
}

impl PhaseTimer {
    fn start() -> Self {
        Self {
            times: PhaseTimes::default(),
            lap: Instant::now(),
        }
    }

    /// Ends `phase`: the time since the previous lap is its.
    fn lap(&mut self, phase: Phase) {
        let now = Instant::now();
        self.times.add(phase, (now - self.lap).as_secs_f64());
        self.lap = now;
    }
}

impl Engine {
    /// Runs one frame of `frame_seconds` wall-clock time: the game's frame hook, the fixed
    /// steps that time holds (each with the game's rules, physics, animation, the level's
    /// logic and its events), posing the world, the scene upkeep, sealing the commit and
    /// handing it to the render thread.
    pub fn frame<G: Game + ?Sized>(
        &mut self,
        frame_seconds: f64,
        game: &mut G,
    ) -> Result<FrameReport, EngineError> {
        if puffin::are_scopes_on() {
            puffin::GlobalProfiler::lock().new_frame();
        }
        puffin::profile_scope!("frame");
        let mut timer = PhaseTimer::start();
        let steps = if self.paused {
            // Held by the shell: no game hooks, no game time; presses made meanwhile are not
            // the game's when it resumes.
            self.input.end_step();
            0
        } else {
            self.input_phase(game, frame_seconds);
            timer.lap(Phase::Input);
            self.fixed_steps(game, frame_seconds)
        };
        timer.lap(Phase::Steps);
        self.pose(self.clock.alpha(), self.time_seconds());
        timer.lap(Phase::Pose);
        let prepared = self.upkeep_scene();
        // Posed with no interpolation, the world and the query scene are what the next step
        // needs (see `app/step_scene.rs`).
        self.step_scene_current = self.clock.alpha() == 0.0;
        timer.lap(Phase::Upkeep);
        let (upkeep, work) = (prepared.stats, prepared.work);
        let commit = self.seal(prepared);
        let commit_bytes = commit.bytes();
        let overlay_bytes = commit
            .present
            .as_ref()
            .and_then(|p| p.overlay.as_ref())
            .map_or(0, |o| o.bytes());
        timer.lap(Phase::Seal);
        {
            puffin::profile_scope!(Phase::HandOff.name());
            self.render.submit(commit)?;
        }
        timer.lap(Phase::HandOff);
        self.input.end_frame();
        let report = FrameReport {
            frame: self.frame,
            steps,
            phases: timer.times,
            commit_bytes,
            overlay_bytes,
            upkeep,
            work,
        };
        self.frame += 1;
        Ok(report)
    }

    /// [`Phase::Input`]: the game's per-frame hook.
    fn input_phase<G: Game + ?Sized>(&mut self, game: &mut G, frame_seconds: f64) {
        puffin::profile_scope!(Phase::Input.name());
        game.frame(&mut FrameInput {
            world: &mut self.world,
            input: &self.input,
            frame_seconds,
            commands: &mut self.commands,
        });
        self.carry_out_commands();
    }

    /// [`Phase::Steps`]: as many fixed steps as `frame_seconds` holds; with
    /// [`Engine::settle_every_step`], each on the world and the query scene as the previous step
    /// left them, however many steps the frame runs (`app/step_scene.rs`).
    fn fixed_steps<G: Game + ?Sized>(&mut self, game: &mut G, frame_seconds: f64) -> u32 {
        puffin::profile_scope!(Phase::Steps.name());
        let steps = self.clock.advance(frame_seconds);
        let first = self.clock.steps - u64::from(steps);
        for index in first..self.clock.steps {
            if self.settle_steps && !self.step_scene_current {
                puffin::profile_scope!("settle step scene");
                self.settle_step_scene(index);
            }
            self.fixed_step(game, index);
            self.step_scene_current = false;
        }
        steps
    }

    /// One fixed step: game rules → physics → water ripples → characters' animation states →
    /// skinned animation players → level logic and its effects → level events to the game →
    /// the day flows (`time_of_day.rs`) → audio.
    fn fixed_step<G: Game + ?Sized>(&mut self, game: &mut G, index: u64) {
        let dt = self.clock.step_seconds;
        self.step_actions = self.next_actions();
        {
            puffin::profile_scope!("game rules");
            game.fixed_step(&mut self.step_view(index));
            self.carry_out_commands();
        }
        {
            puffin::profile_scope!("physics step");
            self.physics.step(&mut self.world, dt);
            water_system(&mut self.world, dt);
        }
        {
            puffin::profile_scope!("animation");
            animate_characters(&mut self.world, dt);
            tick_skinned(&mut self.world, dt);
        }
        let level_logic = puffin::profile_scope_custom!("level logic");
        let ended_before = self.logic.outcome().is_some();
        let lights_off = self.upkeep.light_groups_off();
        let sun = self.sun_for_rules();
        let sun_elevation = self.sun_elevation_for_rules();
        let effects = self.logic.step(
            &mut self.world,
            &self.physics,
            self.upkeep.queries(),
            &lights_off,
            sun,
            sun_elevation,
            dt,
        );
        self.carry_out(effects);
        let events = self.level_events(ended_before);
        for event in &events {
            if let LevelEvent::Ended(outcome) = event {
                self.progress_events
                    .push(ProgressEvent::Ended(outcome.clone()));
            }
        }
        if !events.is_empty() {
            let mut step = self.step_view(index);
            for event in &events {
                game.level_event(&mut step, event);
            }
            self.carry_out_commands();
        }
        self.flow_time(dt);
        drop(level_logic);
        puffin::profile_scope!("audio");
        self.audio.tick(dt);
    }

    /// What the game's step hooks get for step `index`.
    fn step_view(&mut self, index: u64) -> Step<'_> {
        let sky = self.sky_now();
        Step {
            world: &mut self.world,
            queries: self.upkeep.queries(),
            physics: &mut self.physics,
            actions: &self.step_actions,
            action_set: &self.actions,
            index,
            step_seconds: self.clock.step_seconds,
            commands: &mut self.commands,
            settings: &self.step_settings,
            sky,
        }
    }

    /// This step's actions from the step input (which also ends the step in the devices'
    /// state); after a replay's last step, or on a recording error (logged), no input.
    fn next_actions(&mut self) -> ActionFrame {
        if self.replay_done {
            self.input.end_step();
            return ActionFrame::empty(&self.actions);
        }
        match self.step_input.next_step(&mut self.input, &self.actions) {
            Ok(Some(frame)) => frame,
            Ok(None) => {
                self.replay_done = true;
                ActionFrame::empty(&self.actions)
            }
            Err(e) => {
                log::error!("input recording: {e}");
                ActionFrame::empty(&self.actions)
            }
        }
    }

    /// [`Phase::Pose`]: the world as it is to be rendered — physics interpolated between the
    /// last two steps by `alpha` (the clock's leftover fraction of a step, 0 to 1), level waves
    /// at `seconds` of simulated time, skinned meshes deformed, transforms propagated.
    pub(in crate::app) fn pose(&mut self, alpha: f64, seconds: f64) {
        puffin::profile_scope!(Phase::Pose.name());
        self.physics.interpolate(&mut self.world, alpha);
        waves_system(&mut self.world, seconds);
        {
            puffin::profile_scope!("skinned deform");
            deform_skinned(&mut self.world);
        }
        puffin::profile_scope!("transforms");
        propagate_transforms(&mut self.world);
    }

    /// [`Phase::Upkeep`]: typed scene changes into the flattened scene (instance rows, BLAS
    /// refits and rebuilds, TLAS, light table), the render-space origin near the camera, and
    /// the listener and emitters following their entities.
    fn upkeep_scene(&mut self) -> Prepared {
        puffin::profile_scope!(Phase::Upkeep.name());
        self.update_scene();
        let (writes, header, stats) = self.upkeep.finish_frame();
        let mut work = FrameWork::of(&self.world, &self.upkeep, &stats, &self.environment.render);
        work.awake_bodies = self.physics.awake_bodies() as u32;
        let motion = Motion {
            cut: std::mem::take(&mut self.cut),
            lighting: self.take_lighting_change(),
            ..std::mem::take(&mut self.motion)
        };
        Prepared {
            writes,
            header,
            stats,
            work,
            motion,
        }
    }

    /// [`Phase::Seal`]: the frame's commit.
    fn seal(&mut self, prepared: Prepared) -> Commit {
        puffin::profile_scope!(Phase::Seal.name());
        Commit {
            frame: self.frame,
            writes: prepared.writes,
            header: prepared.header,
            camera: self.camera,
            sun: self.environment.sun,
            sky: self.environment.sky,
            render: self.environment.render,
            motion: prepared.motion,
            capture: std::mem::take(&mut self.capture_next),
            present: self.present_next.take(),
        }
    }

    /// Carries out what the game's hooks queued.
    fn carry_out_commands(&mut self) {
        let commands: Vec<Command> = self.commands.drain().collect();
        for command in commands {
            match command {
                Command::Lights { group, on } => self.upkeep.set_light_group(group, on),
                Command::Cut => self.cut = true,
                Command::Event(name) => self.logic.send_event(name),
                Command::Checkpoint(name) => {
                    self.progress_events.push(ProgressEvent::Checkpoint(name));
                }
                Command::EndLevel(outcome) => {
                    self.progress_events.push(ProgressEvent::Ended(outcome));
                }
                Command::Finished(level) => {
                    self.progress_events.push(ProgressEvent::Finished(level));
                }
                Command::Sound { name, volume } => self.play_named(&name, volume),
                Command::Loop { name, volume } => self.loop_named(&name, volume),
                Command::Time(change) => {
                    if let Err(e) = self.change_time(change) {
                        log::warn!("{change:?}: {e}; the time of day is unchanged");
                    }
                }
            }
        }
    }

    /// What the level's logic reported in the step that just ran, for the game.
    fn level_events(&self, ended_before: bool) -> Vec<LevelEvent> {
        let log = self.logic.last_step();
        let mut events = Vec::new();
        for firing in &log.firings {
            let name = self.logic.rule_name(firing.rule).unwrap_or_default();
            events.push(LevelEvent::Rule {
                name: name.to_string(),
                firing: firing.clone(),
            });
        }
        for event in &log.volume_events {
            let name = self.logic.volume_name(event.volume).unwrap_or_default();
            events.push(LevelEvent::Volume {
                name: name.to_string(),
                event: event.clone(),
            });
        }
        events.extend(log.clip_events.iter().cloned().map(LevelEvent::Clip));
        if !ended_before && let Some(outcome) = self.logic.outcome() {
            events.push(LevelEvent::Ended(outcome.clone()));
        }
        events
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
                Effect::Break(index) => {
                    self.physics.break_now(&mut self.world, index);
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

    /// Plays the level's sound `name` once, not placed (a game's [`Command::Sound`]).
    fn play_named(&mut self, name: &str, volume: f32) {
        let Some(planned) = self.logic.sounds().iter().find(|s| s.name == name) else {
            log::warn!("a game asked for sound {name:?}, which the level does not have");
            return;
        };
        let options = PlayOptions {
            volume,
            looped: false,
            at: None,
        };
        if let Err(e) = self.audio.play(&planned.sound, options) {
            log::warn!("sound {name:?}: {e}");
        }
    }

    /// Keeps the level's sound `name` looping at `volume`, not placed (a game's
    /// [`Command::Loop`]).
    fn loop_named(&mut self, name: &str, volume: f32) {
        let Some(planned) = self.logic.sounds().iter().find(|s| s.name == name) else {
            log::warn!("a game asked for loop {name:?}, which the level does not have");
            return;
        };
        if let Err(e) = self.audio.set_loop_volume(&planned.sound, volume) {
            log::warn!("loop {name:?}: {e}");
        }
    }
}
