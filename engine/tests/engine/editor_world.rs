//! Keeping the world in step with the editor (issue 12): a small level spawned in a headless
//! engine (CPU tracer), edited through `EditorState`, its touches followed by `EditWorld`.
//! A moved cube is picked where it went and no longer where it was, its static floor too,
//! and its body is teleported; a material edit spawns the level again (old entities gone,
//! the new one drawn with the new material); deleting an instance sees through to the wall,
//! undo brings it back; an edit that does not load keeps the last good world.

use crate::editor_common;

use candela::app::edit::{EditTarget, EditWorld, Followed};
use candela::app::{Engine, Environment, Step};
use candela::assets::{AssetRoot, CameraDesc, Level, TransformDesc};
use candela::ecs::Renderable;
use candela::editor::{Edit, EditorState, InstanceField, MaterialField, pick, pixel_ray};
use candela::level::load_level;
use candela::render::RenderConfig;
use editor_common::Scratch;
use glam::Vec3;

const LEVEL: &str = r#"Level(
    materials: [(name: "grey", kind: Diffuse), (name: "red", kind: Diffuse, base_color: (0.8, 0.1, 0.1))],
    boxes: [
        (name: "floor", size: (20, 0.2, 20), material: "grey"),
        (name: "cube", size: (1, 1, 1), material: "grey"),
        (name: "wall", size: (20, 3, 0.2), material: "grey"),
    ],
    instances: [
        (model: "floor", transform: (translation: (0, -0.1, 0))),
        (model: "cube", name: "left", transform: (translation: (-1.5, 1, 0)), body: Static(shape: Box)),
        (model: "cube", name: "right", transform: (translation: (1.5, 1, 0))),
        (model: "wall", name: "wall", transform: (translation: (0, 1.5, -3))),
    ],
    camera: (position: (0, 1, 5), look_at: (0, 1, 0), vertical_fov_deg: 50),
    sky: Constant((0.2, 0.2, 0.2)),
)"#;

const W: u32 = 64;
const H: u32 = 48;

struct Setup {
    _scratch: Scratch,
    engine: Engine,
    state: EditorState,
    world: EditWorld,
    camera: CameraDesc,
}

fn setup(name: &str) -> anyhow::Result<Setup> {
    let scratch = Scratch::new(name);
    let path = scratch.path().join("level.ron");
    std::fs::write(&path, LEVEL)?;
    let root = AssetRoot::new(scratch.path())?;
    let level = load_level(&path, &root)?;
    let camera = level.scene.camera;
    let mut engine = Engine::new(RenderConfig::cpu(W, H), Environment::of(&level.scene))?;
    let spawned = engine.spawn_level(&level);
    let world = EditWorld::new(EditTarget::single_file(&path, root), spawned);
    let state = EditorState::open(&path)?;
    let mut s = Setup {
        _scratch: scratch,
        engine,
        state,
        world,
        camera,
    };
    frame(&mut s)?;
    Ok(s)
}

/// One engine frame (steps, upkeep, commit): afterwards the queries see the edits.
fn frame(s: &mut Setup) -> anyhow::Result<()> {
    s.engine.frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})?;
    let _ = s.engine.rendered();
    Ok(())
}

/// The instance drawn where world point `p` appears.
fn picked_at(s: &Setup, p: Vec3) -> Option<usize> {
    let size = glam::Vec2::new(W as f32, H as f32);
    let px = candela::app::edit::project(&s.camera, size, p)?;
    let ray = pixel_ray(&s.camera, W, H, px.x, px.y);
    let entities = s.world.entities(&s.state.doc.level);
    pick(&s.engine.queries(), entities, &ray).map(|p| p.instance)
}

fn apply(s: &mut Setup, edit: Edit) -> anyhow::Result<Followed> {
    let touch = s.state.apply(edit)?;
    Ok(s.world.follow(&mut s.engine, &s.state.doc.level, &touch)?)
}

fn moved(level: &Level, index: usize, to: [f32; 3]) -> Edit {
    let mut t: TransformDesc = level.instances[index].transform;
    t.translation = to;
    Edit::Instance {
        index,
        field: InstanceField::Transform(t),
    }
}

#[test]
fn a_moved_instance_is_picked_where_it_went_and_its_body_follows() -> anyhow::Result<()> {
    let mut s = setup("world_move")?;
    let left = s.world.entities(&s.state.doc.level)[1];
    assert_eq!(picked_at(&s, Vec3::new(-1.5, 1.0, 0.5)), Some(1));
    assert_eq!(picked_at(&s, Vec3::new(0.0, 1.0, 0.5)), Some(3), "the wall");
    let edit = moved(&s.state.doc.level, 1, [0.0, 1.0, 0.0]);
    assert_eq!(apply(&mut s, edit)?, Followed::Moved(1));
    frame(&mut s)?;
    assert_eq!(
        picked_at(&s, Vec3::new(0.0, 1.0, 0.5)),
        Some(1),
        "moved there"
    );
    assert_eq!(
        picked_at(&s, Vec3::new(-1.5, 1.0, 0.5)),
        Some(3),
        "gone from there"
    );
    assert_eq!(
        s.world.entities(&s.state.doc.level)[1],
        left,
        "moved in place"
    );
    let (at, _) = s.engine.physics().pose(left).expect("the cube's body");
    assert!(at.distance(Vec3::new(0.0, 1.0, 0.0)) < 1e-4, "body at {at}");
    // A static instance without a body (the floor) moves too: down out of view.
    let edit = moved(&s.state.doc.level, 0, [0.0, -5.0, 0.0]);
    apply(&mut s, edit)?;
    frame(&mut s)?;
    assert_eq!(
        picked_at(&s, Vec3::new(0.0, 0.0, 2.0)),
        None,
        "the floor left"
    );
    // Undo puts both back.
    for _ in 0..2 {
        let touch = s.state.undo()?.expect("something to undo");
        s.world.follow(&mut s.engine, &s.state.doc.level, &touch)?;
    }
    frame(&mut s)?;
    assert_eq!(picked_at(&s, Vec3::new(-1.5, 1.0, 0.5)), Some(1));
    assert_eq!(picked_at(&s, Vec3::new(0.0, 0.0, 2.0)), Some(0));
    Ok(())
}

#[test]
fn a_material_edit_spawns_the_level_again_with_the_new_look() -> anyhow::Result<()> {
    let mut s = setup("world_material")?;
    let before = s.world.entities(&s.state.doc.level).to_vec();
    let edit = Edit::Instance {
        index: 2,
        field: InstanceField::Material(Some("red".into())),
    };
    assert_eq!(apply(&mut s, edit)?, Followed::Respawned);
    frame(&mut s)?;
    let after = s.world.entities(&s.state.doc.level).to_vec();
    assert_eq!(after.len(), before.len());
    for e in &before {
        assert!(
            !s.engine.world().contains(*e),
            "old entity {e:?} left behind"
        );
    }
    let right = s.engine.world().get::<&Renderable>(after[2]).map(|r| *r)?;
    let left = s.engine.world().get::<&Renderable>(after[1]).map(|r| *r)?;
    assert!(right.material_override.is_some(), "{right:?}");
    assert_ne!(right.material_override, left.material_override);
    assert_eq!(picked_at(&s, Vec3::new(1.5, 1.0, 0.5)), Some(2));
    // A level material's colour: the level is spawned again, same shape.
    let edit = Edit::Material {
        index: 1,
        field: MaterialField::BaseColor([0.1, 0.8, 0.1]),
    };
    assert_eq!(apply(&mut s, edit)?, Followed::Respawned);
    frame(&mut s)?;
    assert_eq!(picked_at(&s, Vec3::new(1.5, 1.0, 0.5)), Some(2));
    Ok(())
}

/// Regression: every respawn appended the level's materials to the table again.
#[test]
fn respawns_write_the_level_materials_in_place_and_the_table_does_not_grow() -> anyhow::Result<()> {
    let mut s = setup("world_materials_reused")?;
    // The first respawn registers the models (as entering the editor does); later ones reuse
    // them.
    let level = s.state.doc.level.clone();
    s.world.respawn(&mut s.engine, &level)?;
    frame(&mut s)?;
    let table = s.engine.scene().materials.len();
    let rows_of = |s: &Setup, colour: [f32; 3]| {
        s.engine
            .scene()
            .materials
            .iter()
            .filter(|m| m.base_color[..3] == colour)
            .count()
    };
    let mut old = [0.8, 0.1, 0.1];
    assert_eq!(rows_of(&s, old), 1, "red, once");
    for k in 0..5 {
        let colour = [0.1, 0.2 + 0.1 * k as f32, 0.1];
        let edit = Edit::Material {
            index: 1,
            field: MaterialField::BaseColor(colour),
        };
        assert_eq!(apply(&mut s, edit)?, Followed::Respawned);
        frame(&mut s)?;
        assert_eq!(s.engine.scene().materials.len(), table, "respawn {k}");
        assert_eq!(rows_of(&s, colour), 1, "the new colour, once");
        assert_eq!(rows_of(&s, old), 0, "written over the old one");
        old = colour;
    }
    Ok(())
}

#[test]
fn deleting_an_instance_sees_through_it_and_undo_brings_it_back() -> anyhow::Result<()> {
    let mut s = setup("world_delete")?;
    assert_eq!(
        apply(&mut s, Edit::DeleteInstance { index: 2 })?,
        Followed::Respawned
    );
    frame(&mut s)?;
    assert_eq!(s.world.entities(&s.state.doc.level).len(), 3);
    assert_eq!(
        picked_at(&s, Vec3::new(1.5, 1.0, 0.5)),
        Some(2),
        "the wall, now 2"
    );
    let touch = s.state.undo()?.expect("the delete");
    s.world.follow(&mut s.engine, &s.state.doc.level, &touch)?;
    frame(&mut s)?;
    assert_eq!(
        picked_at(&s, Vec3::new(1.5, 1.0, 0.5)),
        Some(2),
        "the cube again"
    );
    assert_eq!(picked_at(&s, Vec3::new(0.0, 1.0, 0.5)), Some(3), "the wall");
    Ok(())
}

#[test]
fn an_edit_that_does_not_load_keeps_the_last_good_world() -> anyhow::Result<()> {
    let mut s = setup("world_bad")?;
    let before = s.world.entities(&s.state.doc.level).to_vec();
    let edit = Edit::Instance {
        index: 2,
        field: InstanceField::Model("no_such_model".into()),
    };
    let touch = s.state.apply(edit)?;
    assert!(
        s.world
            .follow(&mut s.engine, &s.state.doc.level, &touch)
            .is_err()
    );
    frame(&mut s)?;
    assert_eq!(s.world.entities(&s.state.doc.level), &before[..]);
    assert_eq!(picked_at(&s, Vec3::new(1.5, 1.0, 0.5)), Some(2));
    Ok(())
}

/// A room the level darkens until the player walks in is lit while it is edited, and dark
/// again when play resumes (the level's rules light it as at its start).
#[test]
fn rooms_the_level_starts_dark_are_lit_while_editing() -> anyhow::Result<()> {
    let path = editor_common::assets().join("test_scenes/platform/first_person.ron");
    let root = AssetRoot::new(editor_common::assets())?;
    let level = load_level(&path, &root)?;
    assert_eq!(
        level.gameplay.lights_off,
        vec![2],
        "the test level's dark room"
    );
    let mut engine = Engine::new(RenderConfig::cpu(W, H), Environment::of(&level.scene))?;
    let spawned = engine.spawn_level(&level);
    assert!(!engine.light_group_on(2), "dark as the level starts");
    let mut world = EditWorld::new(EditTarget::single_file(&path, root), spawned);
    let doc = EditorState::open(&path)?.doc;
    world.respawn(&mut engine, &doc.level)?;
    assert!(engine.light_group_on(2), "lit while editing");
    world.leave_lights(&mut engine);
    assert!(!engine.light_group_on(2), "dark again for play");
    Ok(())
}
