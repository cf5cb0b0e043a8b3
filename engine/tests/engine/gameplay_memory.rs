//! Rules with memory (`sim::triggers`): ordered sequences that reset on a wrong step,
//! counters changed by rules and read by later rules in the same step, `Fired` conditions,
//! light groups as conditions (through the engine's frame loop, as the game and the rules
//! switch them), and state hashes that hold the memory while the hashes of levels without it
//! are unchanged.

use candela::app::{Engine, Step};
use candela::assets::AssetRoot;
use candela::level::load_level;
use candela::render::RenderConfig;
use candela::sim::triggers::{Action, Condition, Facts, Outcome, Rule, RuleBook, VolumeFacts};

fn rule(name: &str, when: Condition, then: Vec<Action>) -> Rule {
    Rule {
        name: name.into(),
        when,
        then,
        otherwise: Vec::new(),
        once: false,
    }
}

/// One step with volumes `inside` occupied (counts), events `events` and groups off.
fn step(book: &mut RuleBook, inside: &[u32], events: &[&str], lights_off: &[u32]) -> Vec<String> {
    let volumes: Vec<VolumeFacts> = (inside.iter())
        .map(|&inside| VolumeFacts {
            inside,
            ..Default::default()
        })
        .collect();
    let events: Vec<String> = events.iter().map(|e| e.to_string()).collect();
    let (firings, _) = book.step(&Facts {
        volumes: &volumes,
        events: &events,
        lights_off,
        sun_lit: &[],
        sun_elevation_deg: None,
    });
    (firings.iter())
        .filter(|f| f.rising)
        .map(|f| book.rules()[f.rule].name.clone())
        .collect()
}

/// Three braziers (volumes 0, 1, 2) lit in order open the shrine.
fn shrine() -> RuleBook {
    let steps = (0..3).map(Condition::Occupied).collect();
    RuleBook::new(vec![rule(
        "open",
        Condition::Sequence(steps),
        vec![Action::Win],
    )])
}

/// Runs `visits` (one brazier entered per visit, then left) and returns the visit after which
/// the shrine opened.
fn opens_after(visits: &[usize]) -> Option<usize> {
    let mut book = shrine();
    for (n, &v) in visits.iter().enumerate() {
        let mut inside = [0; 3];
        inside[v] = 1;
        if !step(&mut book, &inside, &[], &[]).is_empty() {
            return Some(n);
        }
        step(&mut book, &[0, 0, 0], &[], &[]);
    }
    None
}

#[test]
fn a_sequence_opens_in_order_and_a_wrong_step_resets_it() {
    assert_eq!(opens_after(&[0, 1, 2]), Some(2));
    assert_eq!(opens_after(&[1, 2, 0]), None, "out of order");
    assert_eq!(
        opens_after(&[0, 2, 1, 2]),
        None,
        "a wrong step resets to nothing done"
    );
    assert_eq!(
        opens_after(&[0, 2, 0, 1, 2]),
        Some(4),
        "after a reset the sequence starts again"
    );
    assert_eq!(
        opens_after(&[0, 1, 0, 1, 2]),
        Some(4),
        "a wrong first step starts the sequence over from that step"
    );
    assert_eq!(
        opens_after(&[0, 0, 1, 2]),
        Some(3),
        "repeating the done step"
    );
    // Once open it stays open: a wrong step afterwards changes nothing, and it fired once.
    let mut book = shrine();
    let fired: Vec<usize> = [
        [1, 0, 0],
        [0, 1, 0],
        [0, 0, 1],
        [1, 0, 0],
        [0, 1, 0],
        [0, 0, 0],
    ]
    .iter()
    .enumerate()
    .filter(|(_, inside)| !step(&mut book, *inside, &[], &[]).is_empty())
    .map(|(i, _)| i)
    .collect();
    assert_eq!(fired, [2]);
}

#[test]
fn counters_count_and_later_rules_see_the_new_value_in_the_same_step() {
    let weigh = |at_least| Condition::Counter {
        counter: 0,
        at_least,
        at_most: i32::MAX,
    };
    let mut book = RuleBook::new(vec![
        rule("early", weigh(3), vec![]),
        rule(
            "add",
            Condition::Event("weight".into()),
            vec![Action::Count { counter: 0, add: 1 }],
        ),
        rule("late", weigh(3), vec![]),
        rule(
            "clear",
            Condition::Event("clear".into()),
            vec![Action::SetCounter {
                counter: 0,
                value: -2,
            }],
        ),
    ])
    .with_counters(vec![1]);
    assert!(step(&mut book, &[], &[], &[]).is_empty());
    assert_eq!(step(&mut book, &[], &["weight"], &[]), ["add"]);
    assert_eq!(book.counters(), [2]);
    step(&mut book, &[], &[], &[]);
    assert_eq!(
        step(&mut book, &[], &["weight"], &[]),
        ["add", "late"],
        "the rule after the count sees 3 at once"
    );
    assert_eq!(
        step(&mut book, &[], &[], &[]),
        ["early"],
        "the one before, a step later"
    );
    step(&mut book, &[], &["clear"], &[]);
    assert_eq!(book.counters(), [-2]);
    // Saturating at the bounds of i32.
    let mut book = RuleBook::new(vec![rule(
        "add",
        Condition::Event("weight".into()),
        vec![Action::Count {
            counter: 0,
            add: i32::MAX,
        }],
    )])
    .with_counters(vec![5]);
    step(&mut book, &[], &["weight"], &[]);
    assert_eq!(book.counters(), [i32::MAX]);
}

#[test]
fn fired_remembers_a_rule_and_lights_on_reads_the_light_groups() {
    let mut book = RuleBook::new(vec![
        rule("after_lever", Condition::Fired(1), vec![]),
        rule("lever", Condition::Event("lever".into()), vec![]),
        rule("lit", Condition::LightsOn(4), vec![]),
    ]);
    assert_eq!(step(&mut book, &[], &[], &[4]), Vec::<String>::new());
    assert_eq!(step(&mut book, &[], &["lever"], &[4]), ["lever"]);
    assert!(book.fired(1) && !book.fired(0));
    assert_eq!(
        step(&mut book, &[], &[], &[2, 4]),
        ["after_lever"],
        "a rule before the one it waits for sees it fire a step later, and stays fired"
    );
    assert_eq!(step(&mut book, &[], &[], &[2]), ["lit"]);
}

#[test]
fn state_words_hold_the_memory_and_old_levels_hash_as_before() {
    // A level without memory: one word per rule and one per `Times` node, as before.
    let times = Condition::Times {
        at_least: 2,
        of: Box::new(Condition::Occupied(0)),
    };
    let mut book = RuleBook::new(vec![rule("t", times, vec![])]);
    step(&mut book, &[1], &[], &[]);
    let mut words = Vec::new();
    book.state_words(&mut words);
    assert_eq!(
        words,
        [0, 1 | 1 << 1],
        "(was, spent), (value, one rising edge)"
    );
    // Counters, fired flags and sequence progress are part of the state.
    let hash = |book: &RuleBook| {
        let mut w = Vec::new();
        book.state_words(&mut w);
        w
    };
    let mut a = shrine();
    let b = shrine();
    step(&mut a, &[1, 0, 0], &[], &[]);
    assert_ne!(hash(&a), hash(&b), "a step of the sequence done");
    let counting = || {
        RuleBook::new(vec![
            rule(
                "c",
                Condition::Event("e".into()),
                vec![Action::Count { counter: 0, add: 1 }],
            ),
            rule("f", Condition::Fired(0), vec![]),
        ])
        .with_counters(vec![0])
    };
    let (mut a, b) = (counting(), counting());
    step(&mut a, &[], &["e"], &[]);
    assert_ne!(hash(&a), hash(&b));
}

/// Through the engine: the level starts with group 2 off; a rule waits for it to be on and
/// counts; the game switches it on, and the rules see it in the next step.
#[test]
fn a_rule_sees_the_light_groups_the_game_switches() -> anyhow::Result<()> {
    let dir = std::env::temp_dir().join(format!("candela_memory_{}", std::process::id()));
    std::fs::create_dir_all(&dir)?;
    let path = dir.join("lights.ron");
    std::fs::write(
        &path,
        r#"Level(
    materials: [(name: "lamp", kind: Diffuse, emission: (4, 4, 4))],
    boxes: [(name: "lamp", size: (1, 0.1, 1), material: "lamp")],
    instances: [(model: "lamp", name: "lamp", light_group: 2)],
    camera: (position: (0, 2, 6), look_at: (0, 0, 0), vertical_fov_deg: 45),
    gameplay: (
        lights_off: [2],
        counters: [(name: "lit", start: 10)],
        rules: [
            (name: "on", when: LightsOn(2), then: [Count(counter: "lit", add: 5)]),
            (name: "done", when: All([Fired("on"), Counter(counter: "lit", at_least: 15)]),
             then: [Win]),
        ],
    ),
)"#,
    )?;
    let scene = load_level(&path, &AssetRoot::new(&dir)?)?;
    let mut engine = Engine::new(
        RenderConfig::cpu(16, 8),
        candela::app::Environment::of(&scene.scene),
    )?;
    let _spawned = engine.spawn_level(&scene);
    let mut log = Vec::new();
    for frame in 0..6u32 {
        engine.frame(1.0 / 60.0, &mut |s: &mut Step<'_>| {
            if frame == 3 {
                s.commands.set_light_group(2, true);
            }
        })?;
        let _ = engine.rendered();
        log.push((
            engine.logic().counter("lit"),
            engine.logic().rule_fired("on"),
            engine.logic().outcome().cloned(),
        ));
    }
    let _ = std::fs::remove_dir_all(&dir);
    drop(engine.shutdown());
    for (frame, (lit, on, outcome)) in log.iter().enumerate() {
        let switched = frame >= 3;
        assert_eq!(
            *lit,
            Some(if switched { 15 } else { 10 }),
            "frame {frame}: {log:?}"
        );
        assert_eq!(*on, switched, "frame {frame}");
        assert_eq!(outcome.is_some(), switched, "frame {frame}");
    }
    assert_eq!(log[5].2, Some(Outcome::Won("done".into())));
    Ok(())
}
