//! Reflect's world as built: the scene budget of the design (thousands of emissive triangles,
//! a light group per chamber, the later chambers dark at the start), every chamber file a level
//! a designer can load on its own over the base file, and the mirrorable panels each inside a
//! chamber.

use candela::assets::SceneDesc;
use candela::level::load_composed;
use reflect::world::ReflectWorld;

fn world() -> ReflectWorld {
    let (path, root) = reflect::cli::locate(None).expect("the game file");
    ReflectWorld::load(&path, &root).expect("the world loads")
}

/// (triangles, emissive triangles) of the scene's instances, by light group.
fn triangles(scene: &SceneDesc) -> (usize, std::collections::BTreeMap<Option<u32>, usize>) {
    let mut total = 0;
    let mut emissive = std::collections::BTreeMap::new();
    for instance in &scene.instances {
        let model = &scene.models[instance.model];
        let overridden = instance
            .material_override
            .map(|m| &scene.level_materials[m]);
        for placement in &model.placements {
            let mesh = &model.meshes[placement.mesh];
            total += mesh.triangles.len();
            let lit = mesh
                .triangle_materials
                .iter()
                .filter(|&&m| {
                    let material = overridden.unwrap_or(&model.materials[m as usize]);
                    material.emission.max_element() > 0.0
                })
                .count();
            *emissive.entry(instance.light_group).or_insert(0) += lit;
        }
    }
    (total, emissive)
}

/// Triangles in the composed world, instances counted (measured 2026-12-07: 243,140 before the
/// chambers' machinery, fans, pistons and crates, added 26,760).
const WORLD_TRIANGLES: usize = 269_900;
/// Emissive triangles among them, every light group on.
const WORLD_EMISSIVE: usize = 17_260;

#[test]
fn the_world_has_thousands_of_emissive_triangles_in_a_light_group_per_chamber() {
    let world = world();
    let (total, emissive) = triangles(&world.playable.scene);
    let lit: usize = emissive.values().sum();
    println!("{total} triangles, {lit} emissive: {emissive:?}");
    assert!(
        lit >= 5000,
        "{lit} emissive triangles, the design asks for thousands"
    );
    for group in 1..=5u32 {
        let n = emissive.get(&Some(group)).copied().unwrap_or(0);
        assert!(
            n >= 500,
            "chamber {group}'s light group has {n} emissive triangles"
        );
    }
    assert_eq!(
        emissive.get(&None).copied().unwrap_or(0),
        0,
        "every emitter belongs to a chamber's group"
    );
    // The generated world as committed (`tools/assetgen`): a lost chamber or model (each
    // chamber is about a fifth of it) falls outside 5 %; when the art changes on purpose, the
    // figures here change with it.
    let within = |n: usize, expected: usize| n.abs_diff(expected) * 20 <= expected;
    assert!(
        within(total, WORLD_TRIANGLES),
        "{total} triangles, the world has {WORLD_TRIANGLES} (± 5 %)"
    );
    assert!(
        within(lit, WORLD_EMISSIVE),
        "{lit} emissive triangles, the world has {WORLD_EMISSIVE} (± 5 %)"
    );
}

#[test]
fn only_the_first_chamber_is_lit_at_the_start() {
    let world = world();
    let mut off = world.level.gameplay.lights_off.clone();
    off.sort_unstable();
    assert_eq!(off, vec![2, 3, 4, 5]);
}

#[test]
fn every_chamber_file_loads_alone_over_the_base() {
    let world = world();
    let (_, root) = reflect::cli::locate(None).expect("the game file");
    let base = &world.files[0];
    for (i, part) in world.files[1..].iter().enumerate() {
        // Chambers may name items of the chambers before them (the door they close behind).
        let (level, _) = load_composed(base, &world.files[1..=i + 1], &root)
            .unwrap_or_else(|e| panic!("{}: {e}", part.display()));
        assert!(!level.instances.is_empty());
    }
}

#[test]
fn every_mirrorable_panel_belongs_to_a_chamber_with_mirrors() {
    let world = world();
    assert!(
        world.mirrorable.len() >= 5,
        "{} panels",
        world.mirrorable.len()
    );
    for &i in &world.mirrorable {
        let instance = &world.level.instances[i];
        let at = glam::Vec3::from(instance.transform.translation);
        let chamber = world
            .chambers
            .iter()
            .find(|c| c.contains(at))
            .unwrap_or_else(|| panic!("panel {:?} at {at} is in no chamber", instance.name));
        assert!(
            chamber.mirror_cap > 0,
            "panel {:?} is in {}, which allows no mirror",
            instance.name,
            chamber.id
        );
    }
}
