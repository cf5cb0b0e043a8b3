//! [`FirstPersonPlayer`]: walking, looking, using and carrying in first person.
//!
//! Owns: the player's yaw and pitch, its two entities — a character (capsule, kinematic
//! controller: `sim::physics::character`) and a camera whose `Transform` is the eye (with a
//! `CameraRig` the renderer follows and a `Carrier` that holds bodies in front of it) — and
//! turning one [`PlayerInput`] per fixed step into the character's input, the eye's pose, the
//! focus under the crosshair and carrying requests.
//!
//! Mapping (the standard actions, `app::player_input`): move axes walk in the view's frame
//! (yaw only, so looking down does not slow walking); `use` uses the focused usable (its
//! event is returned for the game to send to the rules), picks up the focused dynamic body,
//! or drops the held one — pressed at a usable or a body beyond reach (within
//! [`TOO_FAR_FACTOR`] times it) it does nothing and says so (`PlayerStep::too_far`, for the
//! HUD); `primary` throws the held body along the view; `secondary` drops it.
//!
//! Conventions: right-handed, +Y up, metres, seconds, radians; yaw about +Y, 0 looking along
//! −Z, positive turning left; pitch positive up, clamped to ±`max_pitch`; no roll. The eye
//! follows the body's simulated pose as of the last physics step (it lags the body by one
//! fixed step, 1/60 s). What is under the crosshair comes from ray queries on the scene as the
//! previous fixed step left it, at any frame rate (`app/runner/step_scene.rs`).
//! Main thread, fixed step, before physics. Must not: read devices or send events itself.

use glam::{EulerRot, Quat, Vec2, Vec3};
use hecs::{Entity, World};

use super::input::PlayerInput;
use super::interact::{Focus, FocusKind, focus};
use crate::ecs::{CameraRig, Transform};
use crate::extract::RenderCamera;
use crate::query::Queries;
use crate::sim::physics::{
    Carrier, CarryRequest, CharacterController, CharacterInput, PhysicsWorld, Placement,
    ShapeError, character_bundle,
};

/// How far past `reach` a use press still finds what it was aimed at, to tell the player it
/// is too far (a multiple of `FirstPersonConfig::reach`).
pub const TOO_FAR_FACTOR: f32 = 3.0;

/// How a first-person player is built and moves.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FirstPersonConfig {
    /// Capsule height, feet to head, metres.
    pub height: f32,
    /// Capsule radius, metres.
    pub radius: f32,
    /// Eye above the feet, metres.
    pub eye_height: f32,
    /// Largest pitch up or down, radians.
    pub max_pitch: f32,
    /// Longest use and pick ray, metres.
    pub reach: f32,
    /// Where a held body floats, metres along the view.
    pub hold_distance: f32,
    /// How far a held body floats to the right (+x) and up (+y) of the view's centre,
    /// metres: low and to the side, so the crosshair and the way ahead stay in sight.
    pub hold_offset: Vec2,
    /// Lowest pitch the hold point follows, radians (looking at one's feet does not pull the
    /// body into them).
    pub hold_pitch_min: f32,
    /// A drop places the held body on the surface under the crosshair within this many
    /// metres (`sim::physics::Placement`); farther, it falls from where it is held.
    pub place_reach: f32,
    /// Speed a throw gives the held body, m/s.
    pub throw_speed: f32,
    /// Vertical field of view, radians.
    pub vertical_fov: f32,
    pub controller: CharacterController,
}

impl Default for FirstPersonConfig {
    fn default() -> Self {
        Self {
            height: 1.8,
            radius: 0.3,
            eye_height: 1.65,
            max_pitch: 89f32.to_radians(),
            reach: 2.5,
            hold_distance: 1.3,
            hold_offset: Vec2::new(0.4, -0.35),
            hold_pitch_min: -40f32.to_radians(),
            place_reach: 3.5,
            throw_speed: 6.0,
            vertical_fov: 70f32.to_radians(),
            controller: CharacterController::default(),
        }
    }
}

/// What a step of the player did that the game carries out.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PlayerStep {
    /// The event of the usable the player used this step (for `Commands::send_event`).
    pub used: Option<String>,
    /// `use` was pressed at a usable or a body that is out of reach (nothing was done).
    pub too_far: bool,
}

/// A first-person player in a world.
#[derive(Clone, Debug)]
pub struct FirstPersonPlayer {
    /// The character entity (capsule centre at its `Transform`).
    pub body: Entity,
    /// The eye: `Transform`, `CameraRig`, `Carrier`.
    pub camera: Entity,
    /// Radians, see the module doc.
    pub yaw: f32,
    /// Radians, positive up.
    pub pitch: f32,
    pub config: FirstPersonConfig,
    focus: Option<Focus>,
    /// Where the held body would land if dropped now, and the eye it was seen from (as of
    /// the last step).
    drop_preview: Option<(Placement, Vec3)>,
    /// Whether it held a body at its last step (for prompts; the world says it exactly).
    carrying: bool,
}

impl FirstPersonPlayer {
    /// Spawns a player standing with its feet at `feet`, looking along `yaw` (level).
    pub fn spawn(
        world: &mut World,
        feet: Vec3,
        yaw: f32,
        config: FirstPersonConfig,
    ) -> Result<Self, ShapeError> {
        let centre = feet + Vec3::Y * (config.height * 0.5 + config.controller.skin);
        let body = world.spawn(character_bundle(
            centre,
            config.height,
            config.radius,
            config.controller,
        )?);
        let mut player = Self {
            body,
            camera: body,
            yaw,
            pitch: 0.0,
            config,
            focus: None,
            drop_preview: None,
            carrying: false,
        };
        let eye = Transform {
            translation: centre + player.eye_offset(),
            rotation: player.rotation(),
            scale: Vec3::ONE,
        };
        let rig = CameraRig {
            vertical_fov: config.vertical_fov,
            aperture_radius: 0.0,
            focus_distance: 2.0,
        };
        let carrier = Carrier {
            hold_distance: config.hold_distance,
            hold_offset: config.hold_offset,
            hold_pitch_min: config.hold_pitch_min,
            place_reach: config.place_reach,
            reach: config.reach,
            ignore: Some(body),
            ..Carrier::default()
        };
        player.camera = world.spawn((eye, rig, carrier));
        Ok(player)
    }

    /// Spawns a player whose eye is where `camera` (a level's camera) is, facing its view
    /// direction horizontally (yaw about +Y, radians, 0 looking along −Z); yaw 0 when the view
    /// has no horizontal part or no direction at all.
    pub fn at_view(
        world: &mut World,
        camera: &RenderCamera,
        config: FirstPersonConfig,
    ) -> Result<Self, ShapeError> {
        let eye = camera.position();
        let ahead = camera.forward();
        let yaw = if camera.forward_is_fallback() || (ahead.x == 0.0 && ahead.z == 0.0) {
            0.0
        } else {
            (-ahead.x).atan2(-ahead.z)
        };
        Self::spawn(world, eye - Vec3::Y * config.eye_height, yaw, config)
    }

    /// Moves the player to stand with its feet at `feet` (metres), looking along `yaw` and
    /// `pitch` (radians, as the fields): the body teleported (`PhysicsWorld::set_pose`) and
    /// the eye placed at once. Anything carried is dropped. ("Play from here": the editor's
    /// camera becomes the player's view.)
    pub fn stand_at(
        &mut self,
        world: &mut World,
        physics: &mut PhysicsWorld,
        feet: Vec3,
        yaw: f32,
        pitch: f32,
    ) {
        if let Ok(mut c) = world.get::<&mut Carrier>(self.camera)
            && c.held.is_some()
        {
            c.request = Some(CarryRequest::Drop);
        }
        let centre = feet + Vec3::Y * (self.config.height * 0.5 + self.config.controller.skin);
        physics.set_pose(self.body, centre, Quat::IDENTITY);
        if let Ok(mut t) = world.get::<&mut Transform>(self.body) {
            t.translation = centre;
        }
        self.yaw = yaw;
        self.pitch = pitch.clamp(-self.config.max_pitch, self.config.max_pitch);
        let eye = Transform {
            translation: centre + self.eye_offset(),
            rotation: self.rotation(),
            scale: Vec3::ONE,
        };
        let _ = world.insert_one(self.camera, eye);
    }

    /// The eye's rotation (yaw, then pitch; no roll).
    pub fn rotation(&self) -> Quat {
        Quat::from_euler(EulerRot::YXZ, self.yaw, self.pitch, 0.0)
    }

    /// Unit view direction.
    pub fn view(&self) -> Vec3 {
        self.rotation() * Vec3::NEG_Z
    }

    /// From the capsule's centre to the eye, metres.
    fn eye_offset(&self) -> Vec3 {
        Vec3::Y * (self.config.eye_height - self.config.height * 0.5)
    }

    /// The body's capsule centre (metres), as of the last physics step.
    pub fn position(&self, world: &World) -> Vec3 {
        world
            .get::<&Transform>(self.body)
            .map_or(Vec3::ZERO, |t| t.translation)
    }

    /// The feet (bottom of the capsule less the controller's gap), metres.
    pub fn feet(&self, world: &World) -> Vec3 {
        self.position(world) - Vec3::Y * (self.config.height * 0.5 + self.config.controller.skin)
    }

    /// The eye, metres.
    pub fn eye(&self, world: &World) -> Vec3 {
        self.position(world) + self.eye_offset()
    }

    /// The body being carried, if any.
    pub fn held(&self, world: &World) -> Option<Entity> {
        world.get::<&Carrier>(self.camera).ok().and_then(|c| c.held)
    }

    /// Where the held body would land if dropped now (as of the last step), for a preview.
    pub fn drop_preview(&self) -> Option<&Placement> {
        self.drop_preview.as_ref().map(|(p, _)| p)
    }

    /// The drop preview's outline in view-plane units for the HUD ([`super::drop_outline`]),
    /// seen from the last step's eye; empty when nothing would be placed.
    pub fn drop_outline(&self) -> Vec<[[f32; 2]; 2]> {
        self.drop_preview
            .as_ref()
            .map_or_else(Vec::new, |(placement, eye)| {
                super::drop_outline(placement, *eye, self.rotation(), self.config.vertical_fov)
            })
    }

    /// What was under the crosshair at the last step.
    pub fn focus(&self) -> Option<&Focus> {
        self.focus.as_ref()
    }

    /// Whether it held a body at its last step (what [`FirstPersonPlayer::held`] said then):
    /// for a HUD, which has no world to ask.
    pub fn carrying(&self) -> bool {
        self.carrying
    }

    /// The prompt of the usable under the crosshair, for the HUD.
    pub fn prompt(&self) -> Option<&str> {
        match &self.focus.as_ref()?.kind {
            FocusKind::Usable(u) => Some(&u.prompt),
            _ => None,
        }
    }

    /// One fixed step: turn by `input.look`, set the character's walk, place the eye, find
    /// the focus and act on `use`, `primary` and `secondary`.
    pub fn step(
        &mut self,
        world: &mut World,
        physics: &PhysicsWorld,
        queries: &Queries<'_>,
        input: &PlayerInput,
    ) -> PlayerStep {
        let look = if input.look.is_finite() {
            input.look
        } else {
            Vec2::ZERO
        };
        self.yaw = (self.yaw + look.x).rem_euclid(std::f32::consts::TAU);
        let limit = self.config.max_pitch;
        self.pitch = (self.pitch + look.y).clamp(-limit, limit);

        let facing = Quat::from_rotation_y(self.yaw);
        let mut axes = if input.move_axes.is_finite() {
            input.move_axes
        } else {
            Vec2::ZERO
        };
        if axes.length_squared() > 1.0 {
            axes = axes.normalize();
        }
        let walk = facing * Vec3::X * axes.x + facing * Vec3::NEG_Z * axes.y;
        if let Ok(mut c) = world.get::<&mut CharacterInput>(self.body) {
            *c = CharacterInput {
                move_direction: walk,
                run: input.run,
                jump: input.jump,
            };
        }

        // The body's simulated pose, not its `Transform` (which the frame may have posed
        // between two steps): the same steps give the same eye at any frame rate.
        let centre = physics
            .pose(self.body)
            .map_or_else(|| self.position(world), |(t, _)| t);
        let eye = centre + self.eye_offset();
        let rotation = self.rotation();
        if let Ok(mut t) = world.get::<&mut Transform>(self.camera) {
            t.translation = eye;
            t.rotation = rotation;
        }
        self.focus = focus(world, queries, eye, self.view(), self.config.reach);
        self.drop_preview = physics.placement(world, self.camera).map(|p| (p, eye));

        let held = self.held(world);
        self.carrying = held.is_some();
        let mut out = PlayerStep::default();
        let request = if input.primary_pressed && held.is_some() {
            Some(CarryRequest::Throw {
                speed: self.config.throw_speed,
            })
        } else if (input.use_pressed || input.secondary_pressed) && held.is_some() {
            Some(CarryRequest::Drop)
        } else if input.use_pressed {
            match self.focus.as_ref().map(|f| &f.kind) {
                Some(FocusKind::Usable(u)) => {
                    out.used = Some(u.event.clone());
                    None
                }
                Some(FocusKind::Body) => Some(CarryRequest::Pick),
                Some(FocusKind::Surface) => None,
                None => {
                    out.too_far = self.out_of_reach(world, queries, eye);
                    None
                }
            }
        } else {
            None
        };
        if let Some(request) = request
            && let Ok(mut c) = world.get::<&mut Carrier>(self.camera)
        {
            c.request = Some(request);
        }
        out
    }

    /// Whether the first thing along the view past reach (within [`TOO_FAR_FACTOR`] times
    /// it) is a usable or a body: what a use press was aimed at but could not reach.
    fn out_of_reach(&self, world: &World, queries: &Queries<'_>, eye: Vec3) -> bool {
        let far = self.config.reach * TOO_FAR_FACTOR;
        focus(world, queries, eye, self.view(), far)
            .is_some_and(|f| matches!(f.kind, FocusKind::Usable(_) | FocusKind::Body))
    }
}
