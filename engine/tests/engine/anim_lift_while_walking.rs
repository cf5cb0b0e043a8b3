//! A lift (`pick_up`, asked for as a one-shot that yields its legs:
//! `ActionRequest::yielding_legs`) on the generated hero (`assets/common/hero/hero.glb`), with
//! the action slot, the upper-body slot and an idle/walk machine as `animate_characters` runs
//! them: standing, it holds the whole body; as soon as the hero walks, the legs crossfade into
//! the walk while the arms finish the lift from where they were (no jump); asked for while
//! walking, it plays on the arms only from the start; after it ends, its layer fades out and a
//! held clip asked for meanwhile (the carry) fades in. Before this, the one-shot held the whole
//! body for its 1.4 s and the hero slid along crouched.

use candela::sim::animation::{
    ActionKind, ActionRequest, ActionSlot, AnimState, AnimatedModel, AnimationPlayer, Locomotion,
    Pose, StateMachine, UPPER_FADE_SECONDS, UpperBodySlot, YIELD_SPEED_MPS,
};

use super::anim_actions::hero;

const DT: f64 = 1.0 / 60.0;
const WALK_MPS: f32 = 2.0;

/// `anim_actions`' locomotion state at a fixed rate of 1 (the legs then follow the walk clip
/// exactly, which the tests compare against).
fn state(name: &str, clip: usize, speeds: (f32, f32)) -> AnimState {
    AnimState {
        min_rate: 1.0,
        max_rate: 1.0,
        ..super::anim_actions::state(name, clip, speeds)
    }
}

/// The hero's idle and walk, its action and upper-body slots and its player.
struct Rig {
    model: AnimatedModel,
    machine: StateMachine,
    action: ActionSlot,
    upper: UpperBodySlot,
    player: AnimationPlayer,
}

impl Rig {
    fn new() -> anyhow::Result<Self> {
        let model = hero()?;
        let machine = StateMachine::new(
            vec![
                state("idle", model.find_clip("idle")?, (0.0, 0.3)),
                state("walk", model.find_clip("walk")?, (0.3, f32::INFINITY)),
            ],
            0.2,
        )?;
        Ok(Self {
            model,
            machine,
            action: ActionSlot::default(),
            upper: UpperBodySlot::default(),
            player: AnimationPlayer::new(),
        })
    }

    /// One step at `speed_mps`, in `animate_characters`' order.
    fn step(&mut self, speed_mps: f32) {
        let m = Locomotion {
            horizontal_speed_mps: speed_mps,
            vertical_speed_mps: 0.0,
            grounded: true,
        };
        self.upper.update(&mut self.player, DT);
        self.action.update_layered(
            &mut self.machine,
            &mut self.player,
            &m,
            DT,
            Some((&self.model, &mut self.upper)),
        );
        self.player.tick(&self.model.clips, DT);
    }

    fn lift(&mut self) -> anyhow::Result<usize> {
        let clip = self.model.find_clip("pick_up")?;
        self.action
            .request(ActionRequest::new(clip, ActionKind::Once).yielding_legs());
        Ok(clip)
    }

    fn pose(&self) -> Pose {
        self.player.pose(&self.model.clips, &self.model.rest_pose())
    }

    /// Radians between joint `name`'s rotation in `a` and in `b`.
    fn apart(&self, a: &Pose, b: &Pose, name: &str) -> anyhow::Result<f32> {
        let j = self.model.find_joint(name)?;
        Ok(a.rotation[j]
            .normalize()
            .angle_between(b.rotation[j].normalize()))
    }
}

const LEGS: [&str; 6] = [
    "upper_leg_l",
    "lower_leg_l",
    "foot_l",
    "upper_leg_r",
    "lower_leg_r",
    "foot_r",
];
const ARMS: [&str; 4] = ["upper_arm_l", "lower_arm_l", "upper_arm_r", "chest"];

/// The legs follow the walk clip at the player's playhead and the arms the lift at the
/// layer's, within `tolerance` radians (`angle_between` of f32 unit quaternions reads equal
/// ones as up to 7e-4 rad apart: acos near 1).
fn legs_walk_arms_lift(rig: &Rig, tolerance: f32) -> anyhow::Result<()> {
    let walk = rig.model.find_clip("walk")?;
    let lift = rig.model.find_clip("pick_up")?;
    let pose = rig.pose();
    let now = rig
        .player
        .current()
        .ok_or_else(|| anyhow::anyhow!("nothing plays"))?;
    anyhow::ensure!(now.clip == walk, "the legs play clip {}", now.clip);
    let walking = rig.model.pose_at(walk, now.time_seconds);
    let layer = rig
        .player
        .layer()
        .ok_or_else(|| anyhow::anyhow!("no layer"))?;
    anyhow::ensure!(layer.playback.clip == lift && layer.weight == 1.0);
    let lifting = rig.model.pose_at(lift, layer.playback.time_seconds);
    for name in LEGS {
        let d = rig.apart(&pose, &walking, name)?;
        anyhow::ensure!(d < tolerance, "{name} is {d} rad from the walk");
    }
    for name in ARMS {
        let d = rig.apart(&pose, &lifting, name)?;
        anyhow::ensure!(d < tolerance, "{name} is {d} rad from the lift");
    }
    Ok(())
}

#[test]
fn a_lift_gives_the_legs_back_to_the_walk_as_soon_as_the_hero_moves() -> anyhow::Result<()> {
    let mut rig = Rig::new()?;
    for _ in 0..30 {
        rig.step(0.0);
    }
    let lift = rig.lift()?;
    // Standing: the whole body lifts (crouched legs).
    for _ in 0..30 {
        rig.step(0.0);
    }
    assert_eq!(rig.action.playing().map(|a| a.clip), Some(lift));
    let crouched = rig.pose();
    let lifting = rig
        .model
        .pose_at(lift, rig.player.current().map_or(0.0, |p| p.time_seconds));
    assert!(
        rig.apart(&crouched, &lifting, "upper_leg_l")? < 2e-3,
        "standing: legs lift too"
    );
    // Sets off: one step hands the lift to the upper body, the arms do not jump.
    rig.step(WALK_MPS);
    assert_eq!(rig.action.playing(), None, "the legs are the walk's again");
    assert!(rig.upper.playing_once() && rig.upper.playing() == Some(lift));
    let handed = rig.pose();
    for name in ARMS {
        let d = rig.apart(&crouched, &handed, name)?;
        assert!(d < 0.1, "{name} jumped {d} rad at the hand-over");
    }
    // After the legs' crossfade (0.2 s), legs walk and arms lift, until the lift ends.
    for _ in 0..15 {
        rig.step(WALK_MPS);
    }
    assert_eq!(rig.machine.current().map(|s| s.name.as_str()), Some("walk"));
    assert!(
        rig.apart(&rig.pose(), &crouched, "upper_leg_l")? > 0.3,
        "the legs no longer crouch"
    );
    while rig.player.layer().is_some_and(|l| !l.playback.finished) {
        legs_walk_arms_lift(&rig, 2e-3)?;
        rig.step(WALK_MPS);
    }
    // Then the layer fades out, and the carry asked for meanwhile fades in.
    let push = rig.model.find_clip("push")?;
    let fade_steps = (UPPER_FADE_SECONDS / DT).ceil() as usize;
    for _ in 0..fade_steps + 2 {
        rig.upper.request(&rig.model, push)?;
        rig.step(WALK_MPS);
    }
    assert!(!rig.upper.playing_once());
    assert_eq!(
        rig.upper.playing(),
        Some(push),
        "the carry follows the lift"
    );
    Ok(())
}

#[test]
fn a_lift_asked_for_while_walking_plays_on_the_arms_only() -> anyhow::Result<()> {
    let mut rig = Rig::new()?;
    for _ in 0..40 {
        rig.step(WALK_MPS);
    }
    assert!(WALK_MPS > YIELD_SPEED_MPS);
    let lift = rig.lift()?;
    rig.step(WALK_MPS);
    assert_eq!(rig.action.playing(), None, "no whole-body action");
    assert_eq!(rig.upper.playing(), Some(lift));
    let fade_steps = (UPPER_FADE_SECONDS / DT).ceil() as usize;
    for _ in 0..=fade_steps {
        rig.step(WALK_MPS);
    }
    legs_walk_arms_lift(&rig, 2e-3)?;
    let duration = rig.model.clips[lift].duration_seconds;
    for _ in 0..((duration / DT) as usize + 2 * fade_steps) {
        rig.step(WALK_MPS);
    }
    assert_eq!(rig.upper.playing(), None, "the lift ended and faded out");
    assert!(rig.player.layer().is_none());
    Ok(())
}
