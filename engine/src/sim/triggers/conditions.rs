//! Evaluating a rule's condition in one fixed step, and the memory its nodes keep across steps.
//!
//! Owns: [`Facts`] (what a step's conditions read: volumes, events, light groups), the rule
//! book's memory as conditions read it ([`Memory`]: which rules have fired, the counters),
//! and [`NodeState`], the state of the condition nodes that remember (`Times` counts rising
//! edges, `Sequence` tracks its steps), kept per rule in pre-order. Every sub-condition is
//! evaluated every step (no short-circuit), so a remembering node never misses an edge.
//! Main thread, fixed step. Must not: change the memory (the rule book does, as rules fire).

use super::plan::Condition;
use super::volumes::VolumeFacts;

/// What the conditions read in one step.
#[derive(Clone, Copy, Debug)]
pub struct Facts<'a> {
    /// Per volume, in level order.
    pub volumes: &'a [VolumeFacts],
    /// Names of the clip events fired in this step.
    pub events: &'a [String],
    /// Light groups switched off now (any order).
    pub lights_off: &'a [u32],
    /// Per volume: its centre sees the sun (computed only for volumes a `SunLit` condition
    /// reads; `false` for the others and without a sun).
    pub sun_lit: &'a [bool],
    /// The sun's elevation above the horizon, degrees (`None`: the level has no sun).
    pub sun_elevation_deg: Option<f32>,
}

/// The rule book's memory, read by `Fired` and `Counter` conditions.
#[derive(Clone, Copy, Debug)]
pub(super) struct Memory<'a> {
    /// Per rule: its `then` has run at least once.
    pub fired: &'a [bool],
    /// Per counter: its value.
    pub counters: &'a [i32],
}

/// The state of one remembering condition node.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) enum NodeState {
    /// `Times`: the sub-condition's last value and its rising edges so far.
    Times { was: bool, count: u32 },
    /// `Sequence`: each step's last value and how many steps were done in order.
    Sequence { was: Vec<bool>, done: u32 },
}

impl NodeState {
    /// The state as words for state hashes (`Times` as one word, as before sequences existed,
    /// so the hashes of levels without them did not change).
    pub(super) fn words(&self, out: &mut Vec<u64>) {
        match self {
            NodeState::Times { was, count } => out.push(u64::from(*was) | u64::from(*count) << 1),
            NodeState::Sequence { was, done } => {
                out.push(u64::from(*done) << 1 | 1 << 63);
                for chunk in was.chunks(64) {
                    out.push(
                        (chunk.iter().enumerate()).fold(0, |w, (i, &b)| w | u64::from(b) << i),
                    );
                }
            }
        }
    }
}

/// The remembering nodes of `c`, in the pre-order [`eval`] visits them, at their start.
pub(super) fn node_states(c: &Condition, out: &mut Vec<NodeState>) {
    match c {
        Condition::All(cs) | Condition::Any(cs) | Condition::AtLeast { of: cs, .. } => {
            cs.iter().for_each(|c| node_states(c, out))
        }
        Condition::Not(c) => node_states(c, out),
        Condition::Times { of, .. } => {
            out.push(NodeState::Times {
                was: false,
                count: 0,
            });
            node_states(of, out);
        }
        Condition::Sequence(steps) => {
            out.push(NodeState::Sequence {
                was: vec![false; steps.len()],
                done: 0,
            });
            steps.iter().for_each(|c| node_states(c, out));
        }
        _ => {}
    }
}

/// Evaluates `c` on `facts` and `memory`, updating its remembering nodes (`nodes`, from slot
/// `*next` on, in pre-order).
pub(super) fn eval(
    c: &Condition,
    facts: &Facts<'_>,
    memory: &Memory<'_>,
    nodes: &mut [NodeState],
    next: &mut usize,
) -> bool {
    let volume = |v: usize| facts.volumes.get(v).copied().unwrap_or_default();
    let all = |cs: &[Condition], nodes: &mut [NodeState], next: &mut usize| {
        cs.iter()
            .map(|c| eval(c, facts, memory, nodes, next))
            .collect::<Vec<bool>>()
    };
    match c {
        Condition::Occupied(v) => volume(*v).inside > 0,
        Condition::Entered(v) => volume(*v).entered > 0,
        Condition::Exited(v) => volume(*v).exited > 0,
        Condition::Occupants {
            volume: v,
            at_least,
        } => volume(*v).inside >= *at_least,
        Condition::Event(name) => facts.events.iter().any(|e| e == name),
        Condition::All(cs) => all(cs, nodes, next).iter().all(|&b| b),
        Condition::Any(cs) => all(cs, nodes, next).iter().any(|&b| b),
        Condition::Not(c) => !eval(c, facts, memory, nodes, next),
        Condition::AtLeast { at_least, of } => {
            all(of, nodes, next).iter().filter(|&&b| b).count() as u32 >= *at_least
        }
        Condition::LightsOn(group) => !facts.lights_off.contains(group),
        Condition::SunLit(v) => facts.sun_lit.get(*v).copied().unwrap_or(false),
        Condition::SunElevation { at_least, at_most } => facts
            .sun_elevation_deg
            .is_some_and(|e| (*at_least..=*at_most).contains(&e)),
        Condition::Fired(rule) => memory.fired.get(*rule).copied().unwrap_or(false),
        Condition::Counter {
            counter,
            at_least,
            at_most,
        } => memory
            .counters
            .get(*counter)
            .is_some_and(|v| (*at_least..=*at_most).contains(v)),
        Condition::Times { at_least, of } => {
            let slot = *next;
            *next += 1;
            let now = eval(of, facts, memory, nodes, next);
            let Some(NodeState::Times { was, count }) = nodes.get_mut(slot) else {
                return false;
            };
            if now && !*was {
                *count = count.saturating_add(1);
            }
            *was = now;
            *count >= *at_least
        }
        Condition::Sequence(steps) => {
            let slot = *next;
            *next += 1;
            let now = all(steps, nodes, next);
            let Some(NodeState::Sequence { was, done }) = nodes.get_mut(slot) else {
                return false;
            };
            let total = steps.len() as u32;
            for (i, (&is, was)) in now.iter().zip(was.iter_mut()).enumerate() {
                let rose = is && !*was;
                *was = is;
                if !rose || *done >= total {
                    continue;
                }
                *done = if i as u32 == *done {
                    *done + 1
                } else if i == 0 {
                    1
                } else {
                    0
                };
            }
            total > 0 && *done >= total
        }
    }
}
