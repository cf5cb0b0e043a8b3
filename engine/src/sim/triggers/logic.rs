//! Rules: conditions evaluated every fixed step over volume counts, clip events, light groups
//! and the rules' own memory, fired on their edges.
//!
//! Owns: [`RuleBook`] (the rules and their state: the last value of each rule's condition,
//! whether a `once` rule is spent, whether each rule has fired, the counters, and the
//! remembering condition nodes, `conditions.rs`) and [`RuleFiring`]. A rule runs `then` when
//! its condition goes from false to true and `otherwise` when it goes back; before the first
//! step every condition counts as false. Rules run in level order: the same facts give the
//! same firings, and a rule's counter actions and its having fired are seen by the rules
//! after it in the same step. The counter actions are carried out here, as the rule fires.
//! Must not: carry out the other actions (`LevelLogic` does) or look at the world.

pub use super::conditions::Facts;
use super::conditions::{Memory, NodeState, eval, node_states};
use super::plan::{Action, Condition, Rule};

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
    /// The condition's remembering nodes, in pre-order.
    nodes: Vec<NodeState>,
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
    /// Per rule: its `then` has run at least once.
    fired: Vec<bool>,
    /// Whether any condition reads `fired` (only then is it part of the state hash).
    reads_fired: bool,
    counters: Vec<i32>,
}

fn reads_fired(c: &Condition) -> bool {
    match c {
        Condition::Fired(_) => true,
        Condition::All(cs) | Condition::Any(cs) | Condition::AtLeast { of: cs, .. } => {
            cs.iter().any(reads_fired)
        }
        Condition::Sequence(cs) => cs.iter().any(reads_fired),
        Condition::Not(c) | Condition::Times { of: c, .. } => reads_fired(c),
        _ => false,
    }
}

impl RuleBook {
    /// `rules` in level order, with no counters.
    pub fn new(rules: Vec<Rule>) -> Self {
        let state = rules
            .iter()
            .map(|r| {
                let mut nodes = Vec::new();
                node_states(&r.when, &mut nodes);
                RuleState {
                    nodes,
                    ..Default::default()
                }
            })
            .collect();
        Self {
            fired: vec![false; rules.len()],
            reads_fired: rules.iter().any(|r| reads_fired(&r.when)),
            rules,
            state,
            counters: Vec::new(),
        }
    }

    /// The same with counters starting at `start` (by index, as the rules' counter indices).
    pub fn with_counters(mut self, start: Vec<i32>) -> Self {
        self.counters = start;
        self
    }

    pub fn rules(&self) -> &[Rule] {
        &self.rules
    }

    /// The counters' values, by index.
    pub fn counters(&self) -> &[i32] {
        &self.counters
    }

    /// Whether rule `index`'s condition held in the last step.
    pub fn holds(&self, index: usize) -> bool {
        self.state.get(index).is_some_and(|s| s.was)
    }

    /// Whether rule `index` has run its `then` at least once.
    pub fn fired(&self, index: usize) -> bool {
        self.fired.get(index).copied().unwrap_or(false)
    }

    /// The rules' state as words, rule by rule (last value, spent, each remembering node),
    /// then, where the level uses them, which rules have fired and the counters; for state
    /// hashes. A level without counters or `Fired` conditions hashes as before they existed.
    pub fn state_words(&self, out: &mut Vec<u64>) {
        for s in &self.state {
            out.push(u64::from(s.was) | u64::from(s.spent) << 1);
            s.nodes.iter().for_each(|n| n.words(out));
        }
        if self.reads_fired {
            out.extend(self.fired.iter().map(|&f| u64::from(f)));
        }
        out.extend(self.counters.iter().map(|&v| u64::from(v as u32)));
    }

    /// Carries out a counter action now (the rules after this one see it); other actions are
    /// left to the caller.
    fn count(&mut self, action: &Action) {
        match *action {
            Action::Count { counter, add } => {
                if let Some(v) = self.counters.get_mut(counter) {
                    *v = v.saturating_add(add);
                }
            }
            Action::SetCounter { counter, value } => {
                if let Some(v) = self.counters.get_mut(counter) {
                    *v = value;
                }
            }
            _ => {}
        }
    }

    /// Evaluates every rule on `facts`; returns the rules that fired and, in order, the
    /// actions to carry out (counter actions included, already carried out here).
    pub fn step(&mut self, facts: &Facts<'_>) -> (Vec<RuleFiring>, Vec<Action>) {
        let mut firings = Vec::new();
        let mut actions = Vec::new();
        for index in 0..self.rules.len() {
            let memory = Memory {
                fired: &self.fired,
                counters: &self.counters,
            };
            let state = &mut self.state[index];
            let now = eval(
                &self.rules[index].when,
                facts,
                &memory,
                &mut state.nodes,
                &mut 0,
            );
            let was = std::mem::replace(&mut state.was, now);
            if now == was || state.spent {
                continue;
            }
            let rule = &self.rules[index];
            let list = if now {
                state.spent = rule.once;
                rule.then.clone()
            } else {
                rule.otherwise.clone()
            };
            if now {
                self.fired[index] = true;
            }
            list.iter().for_each(|a| self.count(a));
            actions.extend(list);
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
    use super::super::volumes::VolumeFacts;
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
                    lights_off: &[],
                    sun_lit: &[],
                    sun_elevation_deg: None,
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
            lights_off: &[],
            sun_lit: &[],
            sun_elevation_deg: None,
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
            lights_off: &[],
            sun_lit: &[],
            sun_elevation_deg: None,
        });
        assert_eq!(actions, vec![Action::Lose], "an event holds for one step");
    }
}
