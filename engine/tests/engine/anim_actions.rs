//! The explorer's actions on the generated hero (`assets/common/hero/hero.glb`): a one-shot
//! (`pick_up`, `celebrate`) plays its clip and then the character is back in the state its
//! locomotion calls for; a held action (`push`) plays while it is asked for every step and
//! stops the first step it is not; the joint lookup finds `hand_r` and names the joint and the
//! file when a joint is missing; two runs of the courtyard replay that ask for actions have the
//! same state hash at every frame, and a different one from a run without actions (the
//! animation is part of the hash).

use std::path::{Path, PathBuf};

use candela::app::{Engine, Game, SetupError, Step, StepInput, ThirdPersonGame};
use candela::assets::AssetRoot;
use candela::level::load_level;
use candela::render::RenderConfig;
use candela::sim::animation::{
    ActionKind, ActionRequest, ActionSlot, AnimState, AnimatedModel, AnimationPlayer, Contact,
    Locomotion, PlayMode, StateCondition, StateMachine, load_animation_file,
};

const DT: f64 = 1.0 / 60.0;

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

pub(crate) fn hero() -> anyhow::Result<AnimatedModel> {
    Ok(load_animation_file(
        &repo().join("assets/common/hero/hero.glb"),
    )?)
}

pub(crate) fn state(name: &str, clip: usize, speeds: (f32, f32)) -> AnimState {
    AnimState {
        name: name.into(),
        clip,
        mode: PlayMode::Loop,
        when: StateCondition {
            contact: Contact::Grounded,
            min_speed_mps: speeds.0,
            max_speed_mps: speeds.1,
        },
        reference_speed_mps: None,
        min_rate: 0.5,
        max_rate: 2.0,
        fade_in_seconds: 0.2,
        blend: None,
    }
}

/// The hero's idle and walk as a two-state machine, its slot and player, standing still.
struct Rig {
    model: AnimatedModel,
    machine: StateMachine,
    slot: ActionSlot,
    player: AnimationPlayer,
}

impl Rig {
    fn new() -> anyhow::Result<Self> {
        let model = hero()?;
        let idle = model.find_clip("idle")?;
        let walk = model.find_clip("walk")?;
        let machine = StateMachine::new(
            vec![
                state("idle", idle, (0.0, 0.3)),
                state("walk", walk, (0.3, f32::INFINITY)),
            ],
            0.2,
        )?;
        Ok(Self {
            model,
            machine,
            slot: ActionSlot::default(),
            player: AnimationPlayer::new(),
        })
    }

    fn step(&mut self, speed_mps: f32) {
        let m = Locomotion {
            horizontal_speed_mps: speed_mps,
            vertical_speed_mps: 0.0,
            grounded: true,
        };
        self.slot
            .update(&mut self.machine, &mut self.player, &m, DT);
        self.player.tick(&self.model.clips, DT);
    }

    fn playing_clip(&self) -> Option<&str> {
        let clip = self.player.current()?.clip;
        Some(self.model.clips[clip].name.as_str())
    }
}

#[test]
fn a_one_shot_plays_once_then_the_character_returns_to_locomotion() -> anyhow::Result<()> {
    for (name, speed) in [("pick_up", 0.0), ("celebrate", 1.0)] {
        let mut rig = Rig::new()?;
        let clip = rig.model.find_clip(name)?;
        let duration = rig.model.clips[clip].duration_seconds;
        let locomotion = if speed > 0.0 { "walk" } else { "idle" };
        for _ in 0..30 {
            rig.step(speed);
        }
        assert_eq!(rig.playing_clip(), Some(locomotion));
        rig.slot.request(ActionRequest::new(clip, ActionKind::Once));
        let steps = (duration / DT).round() as usize;
        for i in 0..steps {
            rig.step(speed);
            assert_eq!(
                rig.playing_clip(),
                Some(name),
                "{name}: step {i} of {steps}"
            );
            assert_eq!(rig.slot.playing().map(|a| a.clip), Some(clip));
        }
        // The clip's last step finished it: the next hands the player back.
        for _ in 0..2 {
            rig.step(speed);
        }
        assert_eq!(rig.slot.playing(), None, "{name} ended after {duration} s");
        assert_eq!(rig.playing_clip(), Some(locomotion), "back from {name}");
        assert_eq!(
            rig.machine.current().map(|s| s.name.as_str()),
            Some(locomotion)
        );
        // Crossfading back from the one-shot's end, not cutting.
        assert!(rig.player.fading_out().is_some_and(|p| p.clip == clip));
    }
    Ok(())
}

#[test]
fn a_held_push_plays_while_asked_for_and_stops_the_step_after() -> anyhow::Result<()> {
    let mut rig = Rig::new()?;
    let push = rig.model.find_clip("push")?;
    let duration = rig.model.clips[push].duration_seconds;
    rig.step(1.0);
    // Three cycles and a half: the clip loops while it is held.
    let steps = (3.5 * duration / DT).round() as usize;
    let mut wrapped = false;
    let mut last = 0.0;
    for i in 0..steps {
        rig.slot.request(ActionRequest::new(push, ActionKind::Held));
        rig.step(1.0);
        assert_eq!(rig.playing_clip(), Some("push"), "step {i}");
        let t = rig.player.current().map_or(0.0, |p| p.time_seconds);
        wrapped |= t < last;
        last = t;
    }
    assert!(wrapped, "the push loops");
    assert!(rig.slot.seconds() > 3.0 * duration);
    rig.step(1.0);
    assert_eq!(rig.slot.playing(), None, "not asked for: stopped");
    assert_eq!(rig.playing_clip(), Some("walk"));
    Ok(())
}

#[test]
fn the_joint_lookup_finds_hand_r_and_names_a_missing_joint_and_the_file() -> anyhow::Result<()> {
    let model = hero()?;
    let hand = model.find_joint("hand_r")?;
    assert_eq!(model.nodes.nodes[hand].name.as_deref(), Some("hand_r"));
    assert!(model.skins[0].joints.contains(&hand));
    let error = model
        .find_joint("torch_socket")
        .err()
        .ok_or_else(|| anyhow::anyhow!("a missing joint is refused"))?
        .to_string();
    assert!(error.contains("\"torch_socket\""), "{error}");
    assert!(error.contains("hero.glb"), "{error}");
    assert!(error.contains("hand_r"), "lists the joints: {error}");
    Ok(())
}

/// The courtyard game, asking for a pick-up at step 20, a push held over steps 60–119 and a
/// celebration at step 150 when `actions`.
struct Acting {
    inner: ThirdPersonGame,
    actions: bool,
    seen: Vec<String>,
}

impl Game for Acting {
    fn setup(&mut self, engine: &mut Engine) -> Result<(), SetupError> {
        self.inner.setup(engine)
    }

    fn fixed_step(&mut self, step: &mut Step<'_>) {
        self.inner.fixed_step(step);
        let Some(player) = self.inner.player() else {
            return;
        };
        let ask = match step.index {
            20 => Some(("pick_up", ActionKind::Once)),
            60..120 => Some(("push", ActionKind::Held)),
            150 => Some(("celebrate", ActionKind::Once)),
            _ => None,
        };
        if let (true, Some((clip, kind))) = (self.actions, ask) {
            let asked = player.request_action(step.world, clip, kind);
            self.seen
                .push(format!("{}: {clip} {:?}", step.index, asked.is_ok()));
        }
    }
}

fn hashes(actions: bool) -> anyhow::Result<(Vec<u64>, Vec<String>)> {
    let folder = repo().join("assets/test_scenes/platform");
    let level = folder.join("third_person.ron");
    let root = AssetRoot::new(repo().join("assets"))?;
    let mut inner = ThirdPersonGame::of_level(&level, load_level(&level, &root)?);
    inner.set_replay_names("candela-third-person", "platform/third_person");
    let replay = inner.open_replay(&folder.join("third_person.replay"))?;
    inner.start_with(StepInput::Replay(replay));
    let mut engine = Engine::new(RenderConfig::cpu(8, 8), inner.environment())?;
    let mut game = Acting {
        inner,
        actions,
        seen: Vec::new(),
    };
    game.setup(&mut engine)
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    let mut out = Vec::new();
    for _ in 0..200 {
        engine.frame(DT, &mut game)?;
        let _ = engine.rendered();
        out.push(engine.state_hash());
    }
    let _ = engine.shutdown();
    Ok((out, game.seen))
}

#[test]
fn two_runs_that_ask_for_actions_have_the_same_state_hash() -> anyhow::Result<()> {
    let (a, seen) = hashes(true)?;
    let (b, _) = hashes(true)?;
    let (plain, _) = hashes(false)?;
    assert_eq!(seen.len(), 62, "{seen:?}");
    assert!(seen.iter().all(|s| s.ends_with("true")), "{seen:?}");
    assert_eq!(a, b, "same steps, same hashes");
    assert_eq!(a[..20], plain[..20], "no action asked for yet");
    assert_ne!(a[20..], plain[20..], "the actions are in the hash");
    Ok(())
}
