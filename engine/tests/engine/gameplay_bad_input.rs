//! Bad gameplay data in a level file: every case is refused at load time with an
//! `AssetError::Level` whose message names the level file, the item that is wrong and the
//! name it got wrong; nothing panics. One good level is changed one mistake at a time.

use std::path::{Path, PathBuf};

use candela::assets::{AssetError, AssetRoot};
use candela::level::load_level;

const GOOD: &str = r#"Level(
    materials: [(name: "grey", kind: Diffuse), (name: "lamp", kind: Diffuse, emission: (4, 4, 4))],
    boxes: [(name: "box", size: (1, 1, 1), material: "grey"),
            (name: "lamp", size: (1, 0.1, 1), material: "lamp")],
    instances: [
        (model: "box", name: "plate", body: Sensor(shape: Box)),
        (model: "box", name: "door", transform: (translation: (0, 0, -3)), body: Kinematic(shape: Box)),
        (model: "box", name: "crate", transform: (translation: (0, 2, 0)), body: Dynamic(shape: Box)),
        (model: "lamp", name: "lamp", transform: (translation: (0, 3, 0)), light_group: 2),
    ],
    camera: (position: (0, 2, 6), look_at: (0, 0, 0), vertical_fov_deg: 45),
    gameplay: (
        animations: [(name: "door_open", tracks: [(target: "door", property: Translation,
            interpolation: Linear, keys: [(time_seconds: 0, value: [0, 0, 0]),
                                          (time_seconds: 1, value: [1, 0, 0])])],
            events: [(time_seconds: 1, name: "opened")])],
        lights_off: [2],
        volumes: [(name: "plate", instance: "plate")],
        rules: [
            (name: "press", when: Occupied("plate"),
             then: [Play(clip: "door_open"), Lights(group: 2, on: true),
                    Material(instance: "crate", material: "lamp")]),
            (name: "done", when: Event("opened"), then: [Win]),
        ],
    ),
)"#;

struct Dir(PathBuf);

impl Drop for Dir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

fn dir(test: &str) -> Dir {
    let path = std::env::temp_dir().join(format!(
        "candela_gameplay_bad_{test}_{}",
        std::process::id()
    ));
    std::fs::create_dir_all(&path).expect("temp dir");
    Dir(path)
}

/// Loads `GOOD` with `from` replaced by `to`; returns the error message.
fn refused(dir: &Path, file: &str, from: &str, to: &str) -> String {
    assert!(GOOD.contains(from), "the good level has no {from:?}");
    let path = dir.join(file);
    std::fs::write(&path, GOOD.replace(from, to)).expect("write level");
    let root = AssetRoot::new(dir).expect("root");
    match load_level(&path, &root) {
        Err(e @ AssetError::Level { .. }) => {
            let message = e.to_string();
            assert!(message.contains(file), "{message:?} does not name {file}");
            message
        }
        Err(other) => panic!("{file}: expected a level error, got {other}"),
        Ok(_) => panic!("{file}: the level loaded"),
    }
}

fn says(message: &str, parts: &[&str]) {
    for part in parts {
        assert!(message.contains(part), "{message:?} does not say {part:?}");
    }
}

#[test]
fn the_good_level_loads() -> Result<(), AssetError> {
    let d = dir("the");
    let path = d.0.join("good.ron");
    std::fs::write(&path, GOOD).expect("write");
    let scene = load_level(&path, &AssetRoot::new(&d.0)?)?;
    assert_eq!(scene.gameplay.rules.len(), 2);
    assert_eq!(scene.gameplay.clip_targets, vec![1]);
    assert!(
        scene.scene.instances[1].dynamic,
        "a clip target is not static"
    );
    Ok(())
}

#[test]
fn unknown_trigger_targets_are_named() {
    let d = dir("unknown");
    let m = refused(
        &d.0,
        "volume_name.ron",
        r#"Occupied("plate")"#,
        r#"Occupied("plat")"#,
    );
    says(&m, &["rule \"press\"", "volume \"plat\""]);
    let m = refused(
        &d.0,
        "volume_instance.ron",
        r#"(name: "plate", instance: "plate")"#,
        r#"(name: "plate", instance: "plat")"#,
    );
    says(&m, &["volume \"plate\"", "instance \"plat\""]);
    let m = refused(
        &d.0,
        "clip.ron",
        r#"Play(clip: "door_open")"#,
        r#"Play(clip: "open")"#,
    );
    says(&m, &["rule \"press\"", "clip \"open\""]);
    let m = refused(
        &d.0,
        "material.ron",
        r#"Material(instance: "crate", material: "lamp")"#,
        r#"Material(instance: "crate", material: "gold")"#,
    );
    says(&m, &["rule \"press\"", "material \"gold\""]);
    let m = refused(
        &d.0,
        "target.ron",
        r#"(instance: "crate","#,
        r#"(instance: "box","#,
    );
    says(&m, &["rule \"press\"", "instance \"box\""]);
    let m = refused(&d.0, "group.ron", "Lights(group: 2,", "Lights(group: 3,");
    says(&m, &["rule \"press\"", "light group 3"]);
    let m = refused(&d.0, "event.ron", r#"Event("opened")"#, r#"Event("open")"#);
    says(&m, &["rule \"done\"", "event \"open\""]);
}

#[test]
fn animation_of_a_missing_node_is_named() {
    let d = dir("animation");
    let m = refused(
        &d.0,
        "anim.ron",
        r#"(target: "door","#,
        r#"(target: "dor","#,
    );
    says(&m, &["clip \"door_open\"", "instance \"dor\""]);
    let m = refused(
        &d.0,
        "anim_keys.ron",
        "(time_seconds: 1, value: [1, 0, 0])",
        "(time_seconds: 1, value: [1, 0])",
    );
    says(&m, &["door_open", "key 1"]);
}

#[test]
fn gameplay_that_cannot_work_is_refused() {
    let d = dir("gameplay");
    // A volume needs a sensor to see anything.
    let m = refused(
        &d.0,
        "no_sensor.ron",
        r#"(name: "plate", instance: "plate")"#,
        r#"(name: "plate", instance: "crate")"#,
    );
    says(&m, &["volume \"plate\"", "Sensor"]);
    // A clip and the physics solver may not both move a body.
    let m = refused(
        &d.0,
        "dynamic.ron",
        r#"(target: "door","#,
        r#"(target: "crate","#,
    );
    says(&m, &["clip \"door_open\"", "\"crate\"", "Kinematic"]);
    // Unknown fields: the line and the field.
    let m = refused(
        &d.0,
        "field.ron",
        "lights_off: [2],",
        "lights_off: [2], light_off: [1],",
    );
    says(&m, &["light_off", "line 17"]);
}

#[test]
fn a_sound_that_fails_to_decode_is_named() {
    let d = dir("sound");
    std::fs::create_dir_all(d.0.join("sounds")).expect("dir");
    std::fs::write(
        d.0.join("sounds/broken.wav"),
        b"RIFF\x10\0\0\0WAVEnot really",
    )
    .expect("write");
    let m = refused(
        &d.0,
        "sound.ron",
        "lights_off: [2],",
        r#"lights_off: [2], sounds: [(name: "ding", path: "sounds/broken.wav")],"#,
    );
    says(&m, &["sound \"ding\"", "broken.wav"]);
    let m = refused(
        &d.0,
        "missing_sound.ron",
        "lights_off: [2],",
        r#"lights_off: [2], sounds: [(name: "ding", path: "sounds/none.wav")],"#,
    );
    says(&m, &["sound \"ding\"", "none.wav"]);
    let m = refused(
        &d.0,
        "unknown_sound.ron",
        "Lights(group: 2, on: true),",
        r#"Lights(group: 2, on: true), Sound(sound: "dong"),"#,
    );
    says(&m, &["rule \"press\"", "sound \"dong\""]);
}

/// The editor saves levels: the gameplay section survives an atomic write and read unchanged.
#[test]
fn gameplay_round_trips_through_an_atomic_save() -> Result<(), AssetError> {
    use candela::assets::Level;
    let d = dir("save");
    let source =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/test_scenes/gameplay/plate_door.ron");
    let level = Level::read(&source)?;
    assert!(!level.gameplay.is_empty());
    let saved = d.0.join("saved.ron");
    level.write_atomic(&saved)?;
    assert_eq!(Level::read(&saved)?, level);
    Ok(())
}
