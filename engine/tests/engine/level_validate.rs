//! The one level validator (`level::validate_level`): each kind of mistake is found as a typed
//! problem naming the right item kind, index and field; all problems come in one pass; the
//! loader refuses a level with the first of them (naming the file); the full load's problems
//! (a sound that does not decode) are typed too.

use std::path::Path;

use candela::assets::{AssetError, AssetRoot, Level};
use candela::level::{ItemRef, LevelProblem, level_problems, load_level, validate_level};

/// A valid level using every kind of item the validator checks.
pub(crate) const GOOD: &str = r#"Level(
    materials: [(name: "grey", kind: Diffuse), (name: "lamp", kind: Diffuse, emission: (4, 4, 4))],
    boxes: [(name: "box", size: (1, 1, 1), material: "grey"),
            (name: "lamp", size: (1, 0.1, 1), material: "lamp")],
    instances: [
        (model: "box", name: "plate", body: Sensor(shape: Box)),
        (model: "box", name: "door", transform: (translation: (0, 0, -3)), body: Kinematic(shape: Box)),
        (model: "box", name: "crate", transform: (translation: (0, 2, 0)), body: Dynamic(shape: Box)),
        (model: "lamp", name: "lamp", transform: (translation: (0, 3, 0)), light_group: 2),
        (model: "box", name: "switch", transform: (translation: (2, 0, 0))),
    ],
    camera: (position: (0, 2, 6), look_at: (0, 0, 0), vertical_fov_deg: 45),
    gameplay: (
        sounds: [(name: "ding", path: "sounds/ding.wav")],
        music: (sound: "ding", volume: 0.5),
        emitters: [(instance: "lamp", sound: "ding", volume: 1)],
        animations: [(name: "door_open", tracks: [(target: "door", property: Translation,
            interpolation: Linear, keys: [(time_seconds: 0, value: [0, 0, 0]),
                                          (time_seconds: 1, value: [1, 0, 0])])],
            events: [(time_seconds: 1, name: "opened")])],
        autoplay: [(clip: "door_open")],
        lights_off: [2],
        volumes: [(name: "plate", instance: "plate")],
        lasers: [(instance: "switch", direction: (1, 0, 0), beam: None)],
        usables: [(instance: "switch", prompt: "Press E", event: "lever")],
        events: ["lever"],
        rules: [
            (name: "press", when: Occupied("plate"),
             then: [Play(clip: "door_open"), Lights(group: 2, on: true)],
             otherwise: [Material(instance: "crate", material: "lamp")]),
            (name: "done", when: Event("opened"), then: [Win]),
            (name: "pulled", when: Event("lever"), then: [Count(counter: "pulls")]),
            (name: "in_order",
             when: Sequence([Fired("press"), Counter(counter: "pulls", at_least: Some(2)), LightsOn(2)]),
             then: [SetCounter(counter: "pulls", value: 0)]),
        ],
        counters: [(name: "pulls")],
    ),
)"#;

/// `GOOD` with `from` replaced by `to`, parsed.
pub(crate) fn with(from: &str, to: &str) -> Level {
    assert!(GOOD.contains(from), "the good level has no {from:?}");
    Level::parse(Path::new("good.ron"), &GOOD.replace(from, to)).expect("parses")
}

/// The only problem of `GOOD` with one mistake.
fn only_problem(from: &str, to: &str) -> LevelProblem {
    let problems = validate_level(&with(from, to));
    assert_eq!(problems.len(), 1, "{from:?} → {to:?}: {problems:#?}");
    problems.into_iter().next().expect("one problem")
}

#[test]
fn the_good_level_has_no_problem() {
    assert_eq!(validate_level(&with("", "")), []);
}

#[test]
fn each_kind_of_problem_names_its_item_and_field() {
    let cases: &[(&str, &str, ItemRef, &str)] = &[
        (
            r#"(model: "box", name: "plate""#,
            r#"(model: "cube", name: "plate""#,
            ItemRef::Instance(0),
            "model",
        ),
        (
            r#"name: "crate", "#,
            r#"name: "crate", material: "gold", "#,
            ItemRef::Instance(2),
            "material",
        ),
        (
            "(translation: (0, 3, 0))",
            "(translation: (0, 3, 0), scale: (1, 0, 1))",
            ItemRef::Instance(3),
            "transform",
        ),
        (
            r#"(1, 1, 1), material: "grey""#,
            r#"(1, 1, 1), material: "gray""#,
            ItemRef::Box(0),
            "material",
        ),
        (
            "(4, 4, 4))]",
            r#"(4, 4, 4)), (name: "grey", kind: Diffuse)]"#,
            ItemRef::Material(2),
            "name",
        ),
        (
            "vertical_fov_deg: 45",
            "vertical_fov_deg: 0",
            ItemRef::Camera,
            "vertical_fov_deg",
        ),
        (
            r#"look_at: (0, 0, 0)"#,
            r#"look_at: (0, 2, 6)"#,
            ItemRef::Camera,
            "look_at",
        ),
        (
            r#"music: (sound: "ding""#,
            r#"music: (sound: "dong""#,
            ItemRef::Music,
            "sound",
        ),
        (
            "sound: \"ding\", volume: 1)",
            "sound: \"ding\", volume: 20)",
            ItemRef::Emitter(0),
            "volume",
        ),
        (
            r#"(instance: "lamp", sound"#,
            r#"(instance: "lamb", sound"#,
            ItemRef::Emitter(0),
            "instance",
        ),
        (
            r#"(target: "door""#,
            r#"(target: "crate""#,
            ItemRef::Clip(0),
            "tracks",
        ),
        (
            r#"autoplay: [(clip: "door_open")]"#,
            r#"autoplay: [(clip: "open")]"#,
            ItemRef::Autoplay(0),
            "clip",
        ),
        (
            "lights_off: [2]",
            "lights_off: [3]",
            ItemRef::LightsOff(0),
            "",
        ),
        (
            r#"(name: "plate", instance: "plate")"#,
            r#"(name: "plate", instance: "crate")"#,
            ItemRef::Volume(0),
            "instance",
        ),
        (
            "direction: (1, 0, 0)",
            "direction: (0, 0, 0)",
            ItemRef::Laser(0),
            "direction",
        ),
        (
            r#"(instance: "switch", direction"#,
            r#"(instance: "swich", direction"#,
            ItemRef::Laser(0),
            "instance",
        ),
        (
            r#"prompt: "Press E""#,
            r#"prompt: " ""#,
            ItemRef::Usable(0),
            "prompt",
        ),
        (
            r#"event: "lever")"#,
            r#"event: "pull")"#,
            ItemRef::Usable(0),
            "event",
        ),
        (
            r#"Occupied("plate")"#,
            r#"Occupied("plat")"#,
            ItemRef::Rule(0),
            "when",
        ),
        (
            r#"Event("opened")"#,
            r#"Event("open")"#,
            ItemRef::Rule(1),
            "when",
        ),
        (
            r#"Play(clip: "door_open")"#,
            r#"Play(clip: "open")"#,
            ItemRef::Rule(0),
            "then",
        ),
        (
            "Lights(group: 2",
            "Lights(group: 3",
            ItemRef::Rule(0),
            "then",
        ),
        (
            r#"material: "lamp")]),"#,
            r#"material: "gold")]),"#,
            ItemRef::Rule(0),
            "otherwise",
        ),
        (
            r#"Material(instance: "crate""#,
            r#"Material(instance: "box""#,
            ItemRef::Rule(0),
            "otherwise",
        ),
    ];
    for &(from, to, item, field) in cases {
        let problem = only_problem(from, to);
        assert_eq!(
            (problem.item, problem.field),
            (item, field),
            "{from:?} → {to:?}: {problem}"
        );
        assert!(!problem.message.is_empty());
    }
}

#[test]
fn the_rules_memory_is_checked() {
    let sequence =
        r#"Sequence([Fired("press"), Counter(counter: "pulls", at_least: Some(2)), LightsOn(2)])"#;
    let cases: &[(&str, &str, ItemRef, &str)] = &[
        (
            r#"Count(counter: "pulls")"#,
            r#"Count(counter: "pull")"#,
            ItemRef::Rule(2),
            "then",
        ),
        (
            r#"SetCounter(counter: "pulls""#,
            r#"SetCounter(counter: "weights""#,
            ItemRef::Rule(3),
            "then",
        ),
        (
            r#"Fired("press")"#,
            r#"Fired("pres")"#,
            ItemRef::Rule(3),
            "when",
        ),
        (
            "at_least: Some(2))",
            "at_least: Some(2), at_most: Some(1))",
            ItemRef::Rule(3),
            "when",
        ),
        (
            r#"counter: "pulls", at_least: Some(2))"#,
            r#"counter: "pulls")"#,
            ItemRef::Rule(3),
            "when",
        ),
        (
            r#"counter: "pulls", at_least: Some(2))"#,
            r#"counter: "weight", at_least: Some(2))"#,
            ItemRef::Rule(3),
            "when",
        ),
        ("LightsOn(2)", "LightsOn(7)", ItemRef::Rule(3), "when"),
        // The level has no sun.
        (
            "LightsOn(2)",
            r#"SunLit("plate")"#,
            ItemRef::Rule(3),
            "when",
        ),
        (sequence, "Sequence([])", ItemRef::Rule(3), "when"),
        (
            r#"counters: [(name: "pulls")]"#,
            r#"counters: [(name: "pulls"), (name: "pulls", start: 3)]"#,
            ItemRef::Counter(1),
            "name",
        ),
        (
            r#"counters: [(name: "pulls")]"#,
            r#"counters: [(name: "pulls"), (name: " ")]"#,
            ItemRef::Counter(1),
            "name",
        ),
    ];
    for (from, to, item, field) in cases {
        let p = only_problem(from, to);
        assert_eq!((p.item, p.field), (*item, *field), "{from:?} → {to:?}: {p}");
    }
}

#[test]
fn a_declared_event_no_rule_waits_for_is_a_lever_wired_to_nothing() {
    let p = only_problem(
        r#"when: Event("lever"), then: [Count"#,
        r#"when: Event("opened"), then: [Count"#,
    );
    assert_eq!((p.item, p.field), (ItemRef::Event(0), ""));
    assert!(p.to_string().contains("wired to nothing"), "{p}");
    assert!(p.to_string().contains("switch"), "names the lever: {p}");
    // A rule that waits for it inside a sequence counts.
    let level = with(
        r#"when: Event("lever"), then: [Count"#,
        r#"when: Sequence([Entered("plate"), Event("lever")]), then: [Count"#,
    );
    assert_eq!(validate_level(&level), []);
}

#[test]
fn names_used_twice_are_problems_of_the_second_item() {
    let p = only_problem(
        r#"sounds: [(name: "ding", path: "sounds/ding.wav")]"#,
        r#"sounds: [(name: "ding", path: "sounds/ding.wav"), (name: "ding", path: "x.wav")]"#,
    );
    assert_eq!((p.item, p.field), (ItemRef::Sound(1), "name"));
    // Two instances of one name are a problem only where gameplay uses the name.
    let level = with(r#"name: "switch""#, r#"name: "crate""#);
    let items: Vec<_> = validate_level(&level).iter().map(|p| p.item).collect();
    assert_eq!(
        items,
        [ItemRef::Laser(0), ItemRef::Usable(0), ItemRef::Rule(0)]
    );
}

#[test]
fn every_problem_is_found_in_one_pass() {
    let text = GOOD
        .replace(
            r#"(model: "box", name: "plate""#,
            r#"(model: "cube", name: "plate""#,
        )
        .replace("lights_off: [2]", "lights_off: [3]")
        .replace(r#"Occupied("plate")"#, r#"Occupied("plat")"#)
        .replace(r#"Event("opened")"#, r#"Event("open")"#);
    let level = Level::parse(Path::new("bad.ron"), &text).expect("parses");
    let found: Vec<_> = validate_level(&level)
        .into_iter()
        .map(|p| (p.item, p.field))
        .collect();
    assert_eq!(
        found,
        [
            (ItemRef::Instance(0), "model"),
            (ItemRef::LightsOff(0), ""),
            (ItemRef::Rule(0), "when"),
            (ItemRef::Rule(1), "when"),
        ]
    );
}

struct Dir(std::path::PathBuf);

impl Drop for Dir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

fn dir(test: &str) -> Dir {
    let path = std::env::temp_dir().join(format!("candela_validate_{test}_{}", std::process::id()));
    std::fs::create_dir_all(&path).expect("temp dir");
    Dir(path)
}

/// `GOOD` with its sound written as a file that does not decode.
fn write_level(d: &Dir, text: &str, wav: &[u8]) -> std::path::PathBuf {
    std::fs::create_dir_all(d.0.join("sounds")).expect("dir");
    std::fs::write(d.0.join("sounds/ding.wav"), wav).expect("write");
    let path = d.0.join("level.ron");
    std::fs::write(&path, text).expect("write level");
    path
}

#[test]
fn the_loader_refuses_a_level_with_its_first_problem() {
    let d = dir("first");
    let text = GOOD
        .replace("lights_off: [2]", "lights_off: [3]")
        .replace(r#"Event("opened")"#, r#"Event("open")"#);
    let path = write_level(&d, &text, b"");
    let level = Level::read(&path).expect("reads");
    let first = validate_level(&level).remove(0);
    assert_eq!(first.item, ItemRef::LightsOff(0));
    let root = AssetRoot::new(&d.0).expect("root");
    match load_level(&path, &root) {
        Err(AssetError::Level { path: p, message }) => {
            assert_eq!(p, path);
            assert_eq!(message, format!("gameplay: {}", first.message));
        }
        Err(other) => panic!("expected a level error, got {other}"),
        Ok(_) => panic!("the level loaded"),
    }
    assert_eq!(level_problems(&path, &level, &root).len(), 2);
}

#[test]
fn the_full_loads_problems_are_typed_too() {
    let d = dir("full");
    let path = write_level(&d, GOOD, b"RIFF\x10\0\0\0WAVEnot really");
    let level = Level::read(&path).expect("reads");
    assert_eq!(validate_level(&level), []);
    let root = AssetRoot::new(&d.0).expect("root");
    let problems = level_problems(&path, &level, &root);
    assert_eq!(problems.len(), 1, "{problems:?}");
    assert_eq!(
        (problems[0].item, problems[0].field),
        (ItemRef::Sound(0), "path")
    );
    assert!(problems[0].message.contains("ding.wav"), "{}", problems[0]);
}
