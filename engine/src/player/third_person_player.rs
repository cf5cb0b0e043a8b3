//! [`ThirdPersonPlayer`]: a level character played in third person — the controller
//! (`third_person`), the follow camera (`follow_camera`) and what the character can use.
//!
//! Each fixed step it turns the follow camera by the look input, moves the character relative
//! to the camera, places its camera entity, and finds the usable the character faces: the
//! nearest instance with a `Usable` whose origin is within [`ThirdPersonPlayer::reach_m`] of the
//! character's centre (horizontally) and in front of it (within 70° of its heading or of the
//! camera's view). A `use` press uses it. Usables are found by their place, not by a ray, so a
//! lever seen past the character's own shoulder is usable as soon as the character stands at it.
//! A use press with no usable in front lifts the light body in front, or puts the held one down;
//! the primary action throws it (`third_person_hands`). The character plays its model's
//! `pick_up` clip as it lifts or puts down (on the whole body while it stands, on the upper
//! body while it walks), its `push` clip while it leans into a body, and the
//! push clip's upper body over its walk while it carries (`sim::animation::upper_body`).
//!
//! Main thread, in the game's fixed step, before physics. Must not: read devices (its input is
//! a `PlayerInput`), move the body itself (the physics controller does), or know the runner.
//! Units: metres, seconds, radians; yaw 0 looks along −Z, positive turns right.

use glam::Vec3;
use hecs::{Entity, World};

use super::follow_camera::{CameraPose, FollowCamera};
use super::input::PlayerInput;
use super::third_person::ThirdPersonController;
use super::third_person_hands::{Hands, HandsAct};
use crate::ecs::{CameraRig, Transform};
use crate::extract::RenderCamera;
use crate::sim::animation::{
    ActionKind, ActionRequest, AnimResult, CharacterAnimation, SkinnedAnimator, heading_direction,
    request_action, request_upper_body,
};
use crate::sim::physics::{CharacterState, PhysicsWorld};
use crate::sim::triggers::Usable;

/// The clip whose upper body the character holds a carried body with.
pub const CARRY_CLIP: &str = "push";

/// Cosine of the widest angle between the character's heading (or the camera's view) and a
/// usable it can use (70°).
const FACING_COS: f32 = 0.342;

/// What one step of the player did.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ThirdPersonStep {
    /// The event of the usable used this step (for `Commands::send_event`).
    pub used: Option<String>,
    /// The camera's pose after the step.
    pub camera: Option<CameraPose>,
    /// What the hands were asked to do.
    pub hands: HandsAct,
    /// The character leans into a dynamic body (it walked into one from the side in the last
    /// physics step) and plays its push clip.
    pub pushing: bool,
}

/// A level character driven in third person.
#[derive(Clone, Debug)]
pub struct ThirdPersonPlayer {
    /// The character's capsule (`CharacterInput`, `CharacterAnimation`).
    pub body: Entity,
    /// Its drawn model (skipped by the camera's probes).
    pub visual: Entity,
    /// The entity the renderer looks through (`Transform`, `CameraRig`).
    pub camera: Entity,
    pub follow: FollowCamera,
    pub controller: ThirdPersonController,
    /// How far from the character's centre (horizontally) a usable's origin may be, metres.
    pub reach_m: f32,
    /// What it lifts and carries.
    pub hands: Hands,
    focus: Option<(Entity, Usable)>,
    pushing: bool,
}

impl ThirdPersonPlayer {
    /// Plays the character `body` (drawn by `visual`) in third person: spawns the camera
    /// entity and turns the follow camera to look the way `view` looks (a level's camera).
    pub fn spawn(world: &mut World, body: Entity, visual: Entity, view: &RenderCamera) -> Self {
        let ahead = view.forward();
        let mut follow = FollowCamera::default();
        if ahead.x != 0.0 || ahead.z != 0.0 {
            follow.yaw_rad = ahead.x.atan2(-ahead.z).rem_euclid(std::f32::consts::TAU);
        }
        let rig = CameraRig {
            vertical_fov: view.vertical_fov_radians(),
            ..CameraRig::default()
        };
        let camera = world.spawn((Transform::IDENTITY, rig));
        let player = Self {
            body,
            visual,
            camera,
            follow,
            controller: ThirdPersonController::default(),
            reach_m: 1.8,
            hands: Hands::default(),
            focus: None,
            pushing: false,
        };
        // Place the camera behind the character before the first step.
        let centre = player.centre(world, None);
        let rotation = player.follow.rotation();
        let pivot = centre + Vec3::Y * player.follow.pivot_height_m;
        if let Ok(mut t) = world.get::<&mut Transform>(camera) {
            t.translation = pivot + rotation * Vec3::Z * player.follow.current_m;
            t.rotation = rotation;
        }
        player
    }

    /// The capsule's centre, metres: the simulated pose when `physics` knows the body, else
    /// its `Transform`.
    pub fn centre(&self, world: &World, physics: Option<&PhysicsWorld>) -> Vec3 {
        physics
            .and_then(|p| p.pose(self.body))
            .map(|(position, _)| position)
            .or_else(|| {
                world
                    .get::<&Transform>(self.body)
                    .ok()
                    .map(|t| t.translation)
            })
            .unwrap_or(Vec3::ZERO)
    }

    /// The character's heading, radians (yaw 0 faces −Z).
    pub fn heading(&self, world: &World) -> f32 {
        world
            .get::<&CharacterAnimation>(self.body)
            .map_or(0.0, |a| a.heading_rad)
    }

    /// Asks the character to play its model's clip `clip` (`"push"`, `"pick_up"`,
    /// `"celebrate"`) as `kind` — from the game's fixed step, before or after
    /// [`ThirdPersonPlayer::step`]: a [`ActionKind::Once`] once, then the character returns
    /// to its locomotion; a [`ActionKind::Held`] every step it should go on. A clip the model
    /// lacks is an error naming the model's file ([`request_action`]).
    pub fn request_action(
        &self,
        world: &mut World,
        clip: &str,
        kind: ActionKind,
    ) -> AnimResult<()> {
        request_action(world, self.body, clip, kind).map(|_| ())
    }

    /// The usable the character faces (its entity and prompt), as of the last step.
    pub fn focus(&self) -> Option<&(Entity, Usable)> {
        self.focus.as_ref()
    }

    /// Whether it leaned into a dynamic body at its last step (and played its push clip).
    pub fn pushing(&self) -> bool {
        self.pushing
    }

    /// The body it carries now.
    pub fn held(&self, world: &World) -> Option<Entity> {
        self.hands.held(world)
    }

    /// The level was spawned again (the editor): play `body` drawn by `visual`; whatever the
    /// hands held is gone with the old entities.
    pub fn respawned(&mut self, body: Entity, visual: Entity) {
        self.body = body;
        self.visual = visual;
        self.hands.forget();
        self.focus = None;
    }

    /// One fixed step of `dt_seconds`: camera, move, focus, use.
    pub fn step(
        &mut self,
        world: &mut World,
        physics: &PhysicsWorld,
        queries: &crate::query::Queries<'_>,
        input: &PlayerInput,
        dt_seconds: f32,
    ) -> ThirdPersonStep {
        let centre = self.centre(world, Some(physics));
        let pose = self
            .follow
            .update(input.look, centre, queries, &[self.visual], dt_seconds);
        self.controller
            .drive(world, self.body, input, self.follow.yaw_rad, dt_seconds);
        if let Ok(mut t) = world.get::<&mut Transform>(self.camera) {
            t.translation = pose.position;
            t.rotation = pose.rotation;
        }
        let facing = [
            heading_direction(self.heading(world)),
            heading_direction(self.follow.yaw_rad),
        ];
        self.focus = nearest_usable(world, centre, &facing, self.reach_m);
        let used = match (&self.focus, input.use_pressed) {
            (Some((_, usable)), true) => Some(usable.event.clone()),
            _ => None,
        };
        let heading = self.heading(world);
        let hands = self.hands.step(
            world,
            physics,
            self.body,
            centre,
            heading,
            &facing,
            self.reach_m,
            input.use_pressed && used.is_none(),
            input.primary_pressed,
        );
        // A model without the clip just goes on walking. The lift holds the whole body while
        // the character stands, and only its arms once it walks (`sim::animation::action`).
        if matches!(hands, HandsAct::Take(_) | HandsAct::PutDown) {
            let _ = request_yielding_action(world, self.body, "pick_up");
        }
        // Carrying: the arms hold the body out in front (the push clip's upper body) while
        // the legs walk.
        let carrying = match hands {
            HandsAct::Take(_) => true,
            HandsAct::PutDown | HandsAct::Throw => false,
            HandsAct::Nothing => self.hands.carrying(),
        };
        if carrying {
            let _ = request_upper_body(world, self.body, CARRY_CLIP);
        }
        self.pushing = world
            .get::<&CharacterState>(self.body)
            .is_ok_and(|s| s.pushing);
        if self.pushing {
            let _ = self.request_action(world, "push", ActionKind::Held);
        }
        ThirdPersonStep {
            used,
            camera: Some(pose),
            hands,
            pushing: self.pushing,
        }
    }
}

/// Asks the character `body` for its model's one-shot `clip`, its legs given back to
/// locomotion while it moves ([`ActionRequest::yielding_legs`]); whether it is a character.
fn request_yielding_action(world: &mut World, body: Entity, clip: &str) -> AnimResult<bool> {
    let Ok(mut anim) = world.get::<&mut CharacterAnimation>(body) else {
        return Ok(false);
    };
    let Ok(animator) = world.get::<&SkinnedAnimator>(anim.visual) else {
        return Ok(false);
    };
    let index = animator.model.find_clip(clip)?;
    anim.request_action(ActionRequest::new(index, ActionKind::Once).yielding_legs());
    Ok(true)
}

/// The usable whose origin is nearest `centre` within `reach` metres horizontally and within
/// 70° of one of the `facing` directions (unit, horizontal).
pub fn nearest_usable(
    world: &World,
    centre: Vec3,
    facing: &[Vec3],
    reach: f32,
) -> Option<(Entity, Usable)> {
    let mut best: Option<(f32, Entity, Usable)> = None;
    for (entity, usable, transform) in world.query::<(Entity, &Usable, &Transform)>().iter() {
        let mut to = transform.translation - centre;
        to.y = 0.0;
        let distance = to.length();
        if !distance.is_finite() || distance > reach {
            continue;
        }
        let ahead = distance < 0.3 || facing.iter().any(|f| to.dot(*f) >= FACING_COS * distance);
        if ahead && best.as_ref().is_none_or(|b| distance < b.0) {
            best = Some((distance, entity, usable.clone()));
        }
    }
    best.map(|(_, e, u)| (e, u))
}
