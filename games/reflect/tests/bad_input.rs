//! Bad chamber and game files get a clear error naming the file and the item, never a panic:
//! a receiver wired to a door that does not exist, a mirror cap below zero, a missing art
//! file, a chamber whose names clash with another's, a replay of another version of the world.
//! Each test copies the game's files into a fresh asset root and breaks one thing.

use std::path::{Path, PathBuf};

use candela::assets::AssetRoot;
use reflect::world::ReflectWorld;

fn assets() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../assets")
}

fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).expect("mkdir");
    for entry in std::fs::read_dir(from).expect("read_dir") {
        let entry = entry.expect("entry");
        let target = to.join(entry.file_name());
        if entry.file_type().expect("type").is_dir() {
            copy_dir(&entry.path(), &target);
        } else {
            std::fs::copy(entry.path(), &target).expect("copy");
        }
    }
}

/// A fresh asset root holding Reflect's files (the replays left out).
fn fresh_root(name: &str) -> PathBuf {
    let root = std::env::temp_dir().join(format!("reflect-bad-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&root);
    for dir in ["reflect/levels", "reflect/kit", "common/sounds"] {
        copy_dir(&assets().join(dir), &root.join(dir));
    }
    std::fs::copy(
        assets().join("reflect/reflect.ron"),
        root.join("reflect/reflect.ron"),
    )
    .expect("copy");
    root
}

fn edit(path: &Path, from: &str, to: &str) {
    let text = std::fs::read_to_string(path).expect("read");
    assert!(text.contains(from), "{} has no {from:?}", path.display());
    std::fs::write(path, text.replacen(from, to, 1)).expect("write");
}

fn load_error(root: &Path) -> String {
    let asset_root = AssetRoot::new(root).expect("root");
    match ReflectWorld::load(&root.join("reflect/reflect.ron"), &asset_root) {
        Ok(_) => panic!("the broken world loaded"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn the_unbroken_copy_loads() {
    let root = fresh_root("none");
    let asset_root = AssetRoot::new(&root).expect("root");
    let world = ReflectWorld::load(&root.join("reflect/reflect.ron"), &asset_root).expect("loads");
    assert_eq!(world.chambers.len(), 5);
    let _ = std::fs::remove_dir_all(root);
}

#[test]
fn a_receiver_wired_to_an_unknown_door_names_the_chamber_file_and_the_rule() {
    let root = fresh_root("door");
    edit(
        &root.join("reflect/levels/chamber_2.ron"),
        r#"Play(clip: "door_2_open")"#,
        r#"Play(clip: "door_9_open")"#,
    );
    let e = load_error(&root);
    assert!(e.contains("chamber_2.ron"), "{e}");
    assert!(e.contains("door_9_open"), "{e}");
    assert!(e.contains("solve_2"), "the rule is not named: {e}");
    let _ = std::fs::remove_dir_all(root);
}

#[test]
fn a_mirror_cap_below_zero_names_the_game_file_and_the_chamber() {
    let root = fresh_root("cap");
    edit(
        &root.join("reflect/reflect.ron"),
        "mirrors: 2",
        "mirrors: -1",
    );
    let e = load_error(&root);
    assert!(e.contains("reflect.ron"), "{e}");
    assert!(e.contains("chamber_4") && e.contains("-1"), "{e}");
    let _ = std::fs::remove_dir_all(root);
}

#[test]
fn a_missing_art_file_names_the_file_that_asks_for_it() {
    let root = fresh_root("art");
    std::fs::remove_file(root.join("reflect/kit/receiver.gltf")).expect("rm");
    let e = load_error(&root);
    assert!(e.contains("common.ron"), "{e}");
    assert!(e.contains("receiver.gltf"), "{e}");
    let _ = std::fs::remove_dir_all(root);
}

#[test]
fn a_name_used_by_two_chambers_names_the_later_file() {
    let root = fresh_root("clash");
    edit(
        &root.join("reflect/levels/chamber_3.ron"),
        r#"name: "cube_3""#,
        r#"name: "cube_1""#,
    );
    let e = load_error(&root);
    assert!(e.contains("chamber_3.ron") && e.contains("cube_1"), "{e}");
    let _ = std::fs::remove_dir_all(root);
}

#[test]
fn a_chamber_file_that_does_not_parse_names_its_line() {
    let root = fresh_root("syntax");
    edit(
        &root.join("reflect/levels/chamber_1.ron"),
        "instances: [",
        "instances: [[",
    );
    let e = load_error(&root);
    assert!(e.contains("chamber_1.ron"), "{e}");
    let _ = std::fs::remove_dir_all(root);
}

#[test]
fn a_replay_of_another_version_of_the_world_is_refused() {
    let root = fresh_root("replay");
    edit(
        &root.join("reflect/levels/chamber_1.ron"),
        "(3, 0, -11)",
        "(3.5, 0, -11)",
    );
    let asset_root = AssetRoot::new(&root).expect("root");
    let world = ReflectWorld::load(&root.join("reflect/reflect.ron"), &asset_root).expect("loads");
    let replay = assets().join("reflect/replays/chamber_1.replay");
    let e = reflect::replays::open_replay(&world, &replay)
        .err()
        .expect("refused")
        .to_string();
    assert!(e.contains("chamber_1.replay"), "{e}");
    let _ = std::fs::remove_dir_all(root);
}
