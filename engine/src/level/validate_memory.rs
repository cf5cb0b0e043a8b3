//! The rules' memory in [`super::validate_level`]: counters (named once, each counter a rule
//! uses declared), `Fired` naming a rule that exists, `Counter` conditions with a bound and an
//! ordered range, `LightsOn` naming a light group some instance or beam belongs to, `SunLit`
//! and `SunElevation` in a level with a sun (its own or a physical sky's), elevation bounds
//! that are numbers within ±90° and ordered, sequences with steps — and every name in `gameplay.events` waited for by some rule, so a lever that
//! sends it is never wired to nothing.
//!
//! Any thread (reads the level only). Must not: read files or modify the level.

use std::collections::HashSet;

use crate::assets::{ActionEntry, ConditionEntry, Level};

use super::item::ItemRef;
use super::validate::Problems;

/// Checks the memory the rules of `level` use; `groups` are the light groups that exist.
pub(super) fn memory(c: &mut Problems, level: &Level, groups: &HashSet<u32>) {
    let g = &level.gameplay;
    for (i, counter) in g.counters.iter().enumerate() {
        if counter.name.trim().is_empty() {
            c.report(
                ItemRef::Counter(i),
                "name",
                "a counter has an empty name".into(),
            );
        }
    }
    let counters = c.unique(
        "counter",
        (g.counters.iter().enumerate()).map(|(i, k)| (ItemRef::Counter(i), k.name.as_str())),
    );
    let rules: HashSet<&str> = g.rules.iter().map(|r| r.name.as_str()).collect();
    let mut waited: HashSet<&str> = HashSet::new();
    for (i, rule) in g.rules.iter().enumerate() {
        let (item, user) = (ItemRef::Rule(i), format!("rule {:?}", rule.name));
        let mut nodes = Vec::new();
        walk(&rule.when, &mut nodes);
        for node in nodes {
            let message = match node {
                ConditionEntry::Event(name) => {
                    waited.insert(name.as_str());
                    None
                }
                ConditionEntry::Fired(name) if !rules.contains(name.as_str()) => Some(format!(
                    "{user} waits for the rule {name:?} to fire, which the level does not define"
                )),
                ConditionEntry::Counter { counter, .. } if !counters.contains(counter.as_str()) => {
                    Some(format!(
                        "{user} reads the counter {counter:?}, which `counters` does not declare"
                    ))
                }
                ConditionEntry::Counter {
                    counter,
                    at_least,
                    at_most,
                } => match (at_least, at_most) {
                    (None, None) => Some(format!(
                        "{user} reads the counter {counter:?} without a bound (give at_least, \
                         at_most or both)"
                    )),
                    (Some(lo), Some(hi)) if lo > hi => Some(format!(
                        "{user} wants the counter {counter:?} at least {lo} and at most {hi}, \
                         which no value is"
                    )),
                    _ => None,
                },
                ConditionEntry::LightsOn(group) if !groups.contains(group) => Some(format!(
                    "{user} waits for light group {group}, which no instance belongs to"
                )),
                ConditionEntry::SunLit(volume)
                    if level.sun.is_none()
                        && !matches!(level.sky, crate::assets::SkyDesc::Physical(_)) =>
                {
                    Some(format!(
                        "{user} asks whether the volume {volume:?} sees the sun, but the level has \
                         no sun (a `sun`, or a physical sky that places one)"
                    ))
                }
                ConditionEntry::SunElevation { at_least, at_most } => {
                    sun_elevation(&user, level, *at_least, *at_most)
                }
                ConditionEntry::Sequence(steps) if steps.is_empty() => {
                    Some(format!("{user} has a sequence without steps"))
                }
                _ => None,
            };
            if let Some(message) = message {
                c.report(item, "when", message);
            }
        }
        let actions = (rule.then.iter().map(|a| ("then", a)))
            .chain(rule.otherwise.iter().map(|a| ("otherwise", a)));
        for (field, action) in actions {
            if let ActionEntry::Count { counter, .. } | ActionEntry::SetCounter { counter, .. } =
                action
                && !counters.contains(counter.as_str())
            {
                let message = format!(
                    "{user} changes the counter {counter:?}, which `counters` does not declare"
                );
                c.report(item, field, message);
            }
        }
    }
    for (i, event) in g.events.iter().enumerate() {
        if !waited.contains(event.as_str()) {
            let senders: Vec<&str> = (g.usables.iter())
                .filter(|u| &u.event == event)
                .map(|u| u.instance.as_str())
                .collect();
            let message = if senders.is_empty() {
                format!("the event {event:?} is declared, but no rule waits for it")
            } else {
                format!(
                    "the event {event:?} (sent by {senders:?}) is wired to nothing: no rule waits \
                     for it"
                )
            };
            c.report(ItemRef::Event(i), "", message);
        }
    }
}

/// Every node of `c`, in pre-order.
fn walk<'a>(c: &'a ConditionEntry, out: &mut Vec<&'a ConditionEntry>) {
    out.push(c);
    match c {
        ConditionEntry::All(cs)
        | ConditionEntry::Any(cs)
        | ConditionEntry::AtLeast { of: cs, .. }
        | ConditionEntry::Sequence(cs) => cs.iter().for_each(|c| walk(c, out)),
        ConditionEntry::Not(c) | ConditionEntry::Times { of: c, .. } => walk(c, out),
        _ => {}
    }
}

/// What is wrong with a `SunElevation` condition of `user` (`None`: nothing).
fn sun_elevation(
    user: &str,
    level: &Level,
    at_least: Option<f32>,
    at_most: Option<f32>,
) -> Option<String> {
    let bad = |b: Option<f32>| b.is_some_and(|d| !(-90.0..=90.0).contains(&d));
    if level.sun.is_none() && !matches!(level.sky, crate::assets::SkyDesc::Physical(_)) {
        return Some(format!(
            "{user} reads the sun's elevation, but the level has no sun (a `sun`, or a physical \
             sky that places one)"
        ));
    }
    match (at_least, at_most) {
        (None, None) => Some(format!(
            "{user} reads the sun's elevation without a bound (give at_least, at_most or both)"
        )),
        _ if bad(at_least) || bad(at_most) => Some(format!(
            "{user} bounds the sun's elevation by {at_least:?} / {at_most:?} degrees: each bound \
             must be a number from -90 to 90"
        )),
        (Some(lo), Some(hi)) if lo > hi => Some(format!(
            "{user} wants the sun at least {lo}° and at most {hi}° high, which no elevation is"
        )),
        _ => None,
    }
}
