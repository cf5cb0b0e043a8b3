//! [`ReflectGame`]: Reflect's rules over the engine's first-person game — the world of
//! chambers, the mirror gun, lasers that send the player back, which chamber the player is in
//! (finishing the one behind them), the HUD, the chamber select and the ending's summary.
//!
//! The gun's arming and firing and the carried cube's turn are in `gun.rs`; the messages,
//! flash and sounds of puzzle events in `feedback.rs`; the shell's hooks (chamber select,
//! starting a chamber, the HUD, the ending's summary) in `hud.rs`; the editor's hooks here.
//!
//! Main thread, inside the engine's hooks (`candela::app::Game`). Must not: read devices (the
//! step's actions come from the devices or a replay alike) or reach into the renderer.

use candela::app::edit::{EditHooks, EditTarget};
use candela::app::shell::ShellHooks;
use candela::app::{FirstPersonGame, Game, LevelEvent, SetupError, SpawnedLevel, Step};
use candela::sim::triggers::{Outcome, Phase};
use hecs::Entity;

use crate::hazard::{beam_crosses, send_back};
use crate::mirror_gun::{GunShot, MirrorGun};
use crate::world::ReflectWorld;

pub mod feedback;
mod gun;
mod hud;
use feedback::Feedback;
use gun::turn_held_cube;

/// Events the level's rules hear from the game (declared in the base level's `events`), for
/// sounds: a mirror made, a mirror reverted, a refused shot, the player sent back.
pub const EVENTS: [&str; 5] = [
    "mirror_on",
    "mirror_off",
    "mirror_refused",
    "zapped",
    "footstep",
];

/// Metres walked between two footsteps.
const STRIDE: f32 = 0.75;

/// Something that happened, for tools, tests and the bot.
#[derive(Clone, Debug, PartialEq)]
pub enum ReflectEvent {
    /// The player entered chamber `index`.
    Entered(usize),
    /// Chamber `index` is finished (the player went on to the next, or reached the ending).
    Finished(usize),
    /// A mirror gun shot (not `Nothing`).
    Shot(GunShot),
    /// A laser crossed the player in chamber `index`.
    SentBack(usize),
    /// A level rule's condition rose or fell.
    Rule { name: String, rising: bool },
    /// The ending was reached.
    Ending,
}

/// Reflect.
pub struct ReflectGame {
    world: ReflectWorld,
    inner: FirstPersonGame,
    gun: MirrorGun,
    /// Chamber to put the player in at the next step.
    pending_start: Option<usize>,
    current: Option<usize>,
    /// Fixed steps played since the start (the ending's time).
    steps: u64,
    step_seconds: f64,
    ended_at: Option<u64>,
    sent_back: u32,
    aimed: Option<Entity>,
    log: Vec<(u64, ReflectEvent)>,
    /// Feet at the last step and metres walked since the last footstep.
    stride: (Option<glam::Vec3>, f32),
    /// A view to put the player's eye at once started (screenshots): eye, yaw, pitch.
    pending_view: Option<(glam::Vec3, f32, f32)>,
    /// The HUD's messages and flash for puzzle events.
    feedback: Feedback,
    /// The last fixed step run (the HUD's messages fade by it).
    now: u64,
}

impl ReflectGame {
    /// Reflect over the loaded `world`, starting in chamber `start` (an index).
    pub fn new(world: ReflectWorld, start: usize) -> Self {
        let inner = FirstPersonGame::of_level(&world.game_path, world.playable.clone());
        let feedback = Feedback::new(&inner.level().gameplay);
        Self {
            world,
            inner,
            gun: MirrorGun::default(),
            pending_start: Some(start),
            current: None,
            steps: 0,
            step_seconds: 1.0 / 60.0,
            ended_at: None,
            sent_back: 0,
            aimed: None,
            log: Vec::new(),
            stride: (None, 0.0),
            pending_view: None,
            feedback,
            now: 0,
        }
    }

    /// Puts the player's eye at `camera` (its eye, world metres, and its view direction as
    /// yaw about +Y and pitch, radians) at the first step, after the chamber's start: a
    /// chamber's preview view. A view with no direction of its own (`look_at` at the eye)
    /// reads as yaw −π, pitch 0, as it always has.
    pub fn start_at_view(&mut self, camera: &candela::extract::RenderCamera) {
        let eye = camera.position();
        let d = if camera.forward_is_fallback() {
            glam::Vec3::ZERO
        } else {
            camera.forward()
        };
        let yaw = (-d.x).atan2(-d.z);
        let pitch = d.y.atan2(d.with_y(0.0).length());
        self.pending_view = Some((eye, yaw, pitch));
    }

    /// The first-person game underneath (the player, the spawned level, its log).
    pub fn inner(&self) -> &FirstPersonGame {
        &self.inner
    }

    /// Mutable access, for the runner (replays, the shell's HUD).
    pub fn inner_mut(&mut self) -> &mut FirstPersonGame {
        &mut self.inner
    }

    pub fn world(&self) -> &ReflectWorld {
        &self.world
    }

    pub fn gun(&self) -> &MirrorGun {
        &self.gun
    }

    /// What happened so far, with the step index.
    pub fn log(&self) -> &[(u64, ReflectEvent)] {
        &self.log
    }

    /// The chamber the player is in.
    pub fn current(&self) -> Option<usize> {
        self.current
    }

    /// Chambers finished, in the order they were.
    pub fn finished(&self) -> Vec<usize> {
        self.log
            .iter()
            .filter_map(|(_, e)| match e {
                ReflectEvent::Finished(i) => Some(*i),
                _ => None,
            })
            .collect()
    }

    /// Whether the ending was reached.
    pub fn ended(&self) -> bool {
        self.ended_at.is_some()
    }

    /// Seconds of play until the ending (or until now).
    pub fn play_seconds(&self) -> f64 {
        self.ended_at.unwrap_or(self.steps) as f64 * self.step_seconds
    }

    /// Times a laser sent the player back.
    pub fn sent_back(&self) -> u32 {
        self.sent_back
    }

    fn note(&mut self, step: u64, event: ReflectEvent) {
        self.log.push((step, event));
    }

    /// Which chamber holds the player's feet, and what changes when it is a new one.
    fn track_chamber(&mut self, step: &mut Step<'_>) {
        let Some(player) = self.inner.player() else {
            return;
        };
        let feet = player.feet(step.world);
        let Some(k) = self.world.chambers.iter().position(|c| c.contains(feet)) else {
            return;
        };
        if self.current == Some(k) {
            return;
        }
        if let Some(c) = self.current
            && k == c + 1
        {
            step.commands
                .finish_level(self.world.chambers[c].id.clone());
            self.note(step.index, ReflectEvent::Finished(c));
            self.feedback.finished(step.index, c, step.commands);
        }
        self.current = Some(k);
        step.commands.checkpoint(self.world.chambers[k].id.clone());
        self.note(step.index, ReflectEvent::Entered(k));
    }

    /// A footstep sound every [`STRIDE`] metres walked (a jump of more than a metre in a step is
    /// a teleport, not a walk).
    fn footsteps(&mut self, step: &mut Step<'_>) {
        let Some(player) = self.inner.player() else {
            return;
        };
        let feet = player.feet(step.world);
        let (last, walked) = &mut self.stride;
        if let Some(last) = *last {
            let d = (feet - last).with_y(0.0).length();
            if d < 1.0 {
                *walked += d;
            }
        }
        *last = Some(feet);
        if *walked >= STRIDE {
            *walked = 0.0;
            step.commands.send_event("footstep");
        }
    }
}

impl Game for ReflectGame {
    fn setup(&mut self, engine: &mut candela::app::Engine) -> Result<(), SetupError> {
        self.inner.setup(engine)?;
        self.step_seconds = engine.clock().step_seconds;
        self.arm_gun(engine);
        Ok(())
    }

    fn fixed_step(&mut self, step: &mut Step<'_>) {
        self.now = step.index;
        self.feedback.expire(step.index);
        if let Some(k) = self.pending_start.take()
            && let Some(player) = self.inner.player_mut()
        {
            let c = &self.world.chambers[k];
            send_back(step.world, step.physics, player, c.start, c.yaw);
            step.commands.cut();
            self.current = None;
        }
        if let Some((eye, yaw, pitch)) = self.pending_view.take()
            && let Some(player) = self.inner.player_mut()
        {
            let feet = eye - glam::Vec3::Y * player.config.eye_height;
            send_back(step.world, step.physics, player, feet, yaw);
            player.pitch = pitch;
        }
        let held_before = self
            .inner
            .player()
            .is_some_and(|p| p.held(step.world).is_some());
        self.inner.fixed_step(step);
        if self.inner.too_far_at() == Some(step.index) {
            step.commands.play_sound("buzz", 0.25);
        }
        turn_held_cube(step, &self.inner);
        self.mirror_gun(step, held_before);
        self.footsteps(step);
        self.track_chamber(step);
        if let (Some(k), Some(player)) = (self.current, self.inner.player())
            && beam_crosses(step.world, step.physics, player)
        {
            let c = &self.world.chambers[k];
            let (start, yaw) = (c.start, c.yaw);
            if let Some(player) = self.inner.player_mut() {
                send_back(step.world, step.physics, player, start, yaw);
            }
            self.sent_back += 1;
            step.commands.send_event("zapped");
            step.commands.cut();
            self.note(step.index, ReflectEvent::SentBack(k));
            self.feedback.sent_back(step.index, step.commands);
        }
        if self.ended_at.is_none() {
            self.steps += 1;
        }
    }

    fn level_event(&mut self, step: &mut Step<'_>, event: &LevelEvent) {
        self.inner.level_event(step, event);
        match event {
            LevelEvent::Rule { name, firing } => {
                let rule = ReflectEvent::Rule {
                    name: name.clone(),
                    rising: firing.rising,
                };
                self.note(step.index, rule);
                let current = self.current;
                self.feedback
                    .rule(step.index, name, firing.rising, current, step.commands);
            }
            LevelEvent::Volume { name, event } if event.phase != Phase::Stay => {
                self.feedback.volume(step.index, name, event, step.commands);
            }
            LevelEvent::Ended(Outcome::Won(_)) if self.ended_at.is_none() => {
                self.ended_at = Some(self.steps);
                if let Some(c) = self.current {
                    step.commands
                        .finish_level(self.world.chambers[c].id.clone());
                    self.note(step.index, ReflectEvent::Finished(c));
                    self.feedback.finished(step.index, c, step.commands);
                }
                self.note(step.index, ReflectEvent::Ending);
            }
            _ => {}
        }
    }

    fn has_ui(&self) -> bool {
        self.inner.has_ui()
    }

    fn ui(&mut self, ctx: &egui::Context) {
        self.inner.ui(ctx);
    }

    fn shell(&mut self) -> Option<&mut dyn ShellHooks> {
        Some(self)
    }

    fn editor(&mut self) -> Option<&mut dyn EditHooks> {
        Some(self)
    }
}

impl EditHooks for ReflectGame {
    /// F1 edits the chamber the player is in (or starts in): a part of the composed world.
    fn edit_target(&self) -> Option<(EditTarget, SpawnedLevel)> {
        let chamber = self.current.or(self.pending_start).unwrap_or(0);
        let files = &self.world.files;
        let target =
            EditTarget::composed_part(&files[0], &files[1..], chamber, self.world.root.clone());
        match target {
            Ok(target) => Some((target, self.inner.spawned().clone())),
            Err(e) => {
                log::error!("the editor cannot open chamber {chamber}: {e}");
                None
            }
        }
    }

    fn level_respawned(&mut self, engine: &mut candela::app::Engine, spawned: &SpawnedLevel) {
        self.inner.set_spawned(spawned.clone());
        self.aimed = None;
        self.feedback.respawned();
        self.arm_gun(engine);
    }

    /// Play from here: the player on the floor below the editor camera (the chamber it stands
    /// in is found at the next step); a start still pending is dropped.
    fn play_from(
        &mut self,
        engine: &mut candela::app::Engine,
        eye: glam::Vec3,
        forward: glam::Vec3,
    ) {
        self.pending_start = None;
        self.pending_view = None;
        self.inner.play_from_view(engine, eye, forward);
    }
}
