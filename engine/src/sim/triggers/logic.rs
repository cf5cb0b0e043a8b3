//! Rules: conditions evaluated every fixed step over volume counts and clip events, fired on
//! their edges.
//!
//! Owns: [`RuleBook`] (the rules and their state: the last value of each rule's condition,
//! whether a `once` rule has fired, and the edge counters of `Times` conditions) and
//! [`RuleFiring`]. A rule runs `then` when its condition goes from false to true and
//! `otherwise` when it goes back; before the first step every condition counts as false.
//! Every sub-condition is evaluated every step (no short-circuit), so `Times` counters never
//! miss an edge. Rules run in level order: the same facts give the same firings.
//! Must not: carry out actions (`LevelLogic` does) or look at the world.

use super::plan::{Action, Condition, Rule};
use super::volumes::VolumeFacts;

/// What the conditions read in one step.
#[derive(Clone, Copy, Debug)]
pub struct Facts<'a> {
    /// Per volume, in level order.
    pub volumes: &'a [VolumeFacts],
    /// Names of the clip events fired in this step.
    pub events: &'a [String],
}

/// A rule whose condition changed in a step.
#[derive(Clone, Debug, PartialEq)]
pub struct RuleFiring {
    /// Index of the rule in the level's list.
    pub rule: usize,
    /// `true`: the condition became true (`then` ran); `false`: it became false (`otherwise`).
    pub rising: bool,
}

#[derive(Clone, Debug, Default)]
struct RuleState {
    was: bool,
    spent: bool,
    /// Per `Times` node in pre-order: the sub-condition's last value and its rising edges.
    times: Vec<(bool, u32)>,
}

/// FNV-1a of `text` (names folded into state hashes).
pub(super) fn text_bits(text: &str) -> u64 {
    text.bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

/// The level's rules and their state.
#[derive(Clone, Debug, Default)]
pub struct RuleBook {
    rules: Vec<Rule>,
    state: Vec<RuleState>,
}

fn count_times(c: &Condition) -> usize {
    match c {
        Condition::All(cs) | Condition::Any(cs) | Condition::AtLeast { of: cs, .. } => {
            cs.iter().map(count_times).sum()
        }
        Condition::Not(c) => count_times(c),
        Condition::Times { of, .. } => 1 + count_times(of),
        _ => 0,
    }
}

fn eval(c: &Condition, facts: &Facts<'_>, times: &mut [(bool, u32)], next: &mut usize) -> bool {
    let volume = |v: usize| facts.volumes.get(v).copied().unwrap_or_default();
    let all = |cs: &[Condition], times: &mut [(bool, u32)], next: &mut usize| {
        cs.iter()
            .map(|c| eval(c, facts, times, next))
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
        Condition::All(cs) => all(cs, times, next).iter().all(|&b| b),
        Condition::Any(cs) => all(cs, times, next).iter().any(|&b| b),
        Condition::Not(c) => !eval(c, facts, times, next),
        Condition::AtLeast { at_least, of } => {
            all(of, times, next).iter().filter(|&&b| b).count() as u32 >= *at_least
        }
        Condition::Times { at_least, of } => {
            let slot = *next;
            *next += 1;
            let now = eval(of, facts, times, next);
            let Some((was, count)) = times.get_mut(slot) else {
                return false;
            };
            if now && !*was {
                *count = count.saturating_add(1);
            }
            *was = now;
            *count >= *at_least
        }
    }
}

impl RuleBook {
    pub fn new(rules: Vec<Rule>) -> Self {
        let state = rules
            .iter()
            .map(|r| RuleState {
                times: vec![(false, 0); count_times(&r.when)],
                ..Default::default()
            })
            .collect();
        Self { rules, state }
    }

    pub fn rules(&self) -> &[Rule] {
        &self.rules
    }

    /// The rules' state as words, rule by rule (last value, spent, each `Times` node's value
    /// and count), for state hashes.
    pub fn state_words(&self, out: &mut Vec<u64>) {
        for s in &self.state {
            out.push(u64::from(s.was) | u64::from(s.spent) << 1);
            out.extend(
                s.times
                    .iter()
                    .map(|&(b, n)| u64::from(b) | u64::from(n) << 1),
            );
        }
    }

    /// Evaluates every rule on `facts`; returns the rules that fired and, in order, the
    /// actions to carry out.
    pub fn step(&mut self, facts: &Facts<'_>) -> (Vec<RuleFiring>, Vec<Action>) {
        let mut firings = Vec::new();
        let mut actions = Vec::new();
        for (index, (rule, state)) in self.rules.iter().zip(&mut self.state).enumerate() {
            let mut next = 0;
            let now = eval(&rule.when, facts, &mut state.times, &mut next);
            let was = std::mem::replace(&mut state.was, now);
            if now == was || state.spent {
                continue;
            }
            if now {
                actions.extend(rule.then.iter().cloned());
                state.spent = rule.once;
            } else {
                actions.extend(rule.otherwise.iter().cloned());
            }
            firings.push(RuleFiring {
                rule: index,
                rising: now,
            });
        }
        (firings, actions)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rule(when: Condition, once: bool) -> Rule {
        Rule {
            name: "r".into(),
            when,
            then: vec![Action::Win],
            otherwise: vec![Action::Lose],
            once,
        }
    }

    fn occupied(counts: &[u32]) -> Vec<VolumeFacts> {
        counts
            .iter()
            .map(|&inside| VolumeFacts {
                inside,
                ..Default::default()
            })
            .collect()
    }

    fn run(book: &mut RuleBook, steps: &[&[u32]]) -> Vec<Vec<Action>> {
        steps
            .iter()
            .map(|counts| {
                let volumes = occupied(counts);
                book.step(&Facts {
                    volumes: &volumes,
                    events: &[],
                })
                .1
            })
            .collect()
    }

    #[test]
    fn fires_on_edges_only() {
        let mut book = RuleBook::new(vec![rule(Condition::Occupied(0), false)]);
        let out = run(&mut book, &[&[0], &[1], &[2], &[0], &[0], &[1]]);
        let expected: Vec<Vec<Action>> = vec![
            vec![],
            vec![Action::Win],
            vec![],
            vec![Action::Lose],
            vec![],
            vec![Action::Win],
        ];
        assert_eq!(out, expected);
    }

    #[test]
    fn two_plates_open_a_door_and_once_fires_once() {
        let both = Condition::All(vec![Condition::Occupied(0), Condition::Occupied(1)]);
        let mut book = RuleBook::new(vec![rule(both, true)]);
        let out = run(&mut book, &[&[1, 0], &[1, 1], &[0, 1], &[1, 1]]);
        assert_eq!(out[0], vec![]);
        assert_eq!(out[1], vec![Action::Win]);
        assert_eq!(
            out[2],
            vec![],
            "a spent `once` rule runs nothing, not even `otherwise`"
        );
        assert_eq!(out[3], vec![]);
    }

    #[test]
    fn at_least_counts_conditions_and_times_counts_edges() {
        let two_of_three = Condition::AtLeast {
            at_least: 2,
            of: (0..3).map(Condition::Occupied).collect(),
        };
        let mut book = RuleBook::new(vec![rule(two_of_three, false)]);
        let out = run(&mut book, &[&[1, 0, 0], &[1, 0, 1], &[0, 0, 1]]);
        assert_eq!(out, vec![vec![], vec![Action::Win], vec![Action::Lose]]);

        let third_visit = Condition::Times {
            at_least: 3,
            of: Box::new(Condition::Occupied(0)),
        };
        let mut book = RuleBook::new(vec![rule(third_visit, false)]);
        let steps: &[&[u32]] = &[&[1], &[1], &[0], &[1], &[0], &[0], &[1], &[0]];
        let out = run(&mut book, steps);
        let fired: Vec<usize> = (0..out.len()).filter(|&i| !out[i].is_empty()).collect();
        assert_eq!(
            fired,
            vec![6],
            "third entry, counted once per entry, then it stays true"
        );
    }

    #[test]
    fn events_and_not() {
        let mut book = RuleBook::new(vec![rule(
            Condition::All(vec![
                Condition::Event("opened".into()),
                Condition::Not(Box::new(Condition::Occupied(0))),
            ]),
            false,
        )]);
        let volumes = occupied(&[0]);
        let (firings, actions) = book.step(&Facts {
            volumes: &volumes,
            events: &["opened".to_string()],
        });
        assert_eq!(
            firings,
            vec![RuleFiring {
                rule: 0,
                rising: true
            }]
        );
        assert_eq!(actions, vec![Action::Win]);
        let (_, actions) = book.step(&Facts {
            volumes: &volumes,
            events: &[],
        });
        assert_eq!(actions, vec![Action::Lose], "an event holds for one step");
    }
}
