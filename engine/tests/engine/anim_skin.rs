//! Skinning and morphing of normals and tangents (which the three.js reference does not
//! cover), checked against properties that hold exactly: a rotation turns normals and
//! tangents with it, a non-uniform scale keeps normals perpendicular to tangents, a mirror
//! flips tangent handedness, a 50/50 blend lands halfway. Then the mesh-space output of a
//! skinned glTF model feeds `accel::Upkeep::deform`, the deforming-mesh refit path.
//! Tolerances: 1e-6 on unit vectors (a few float32 roundings); 1e-5 relative on positions
//! passed through a matrix and its inverse.

use std::path::{Path, PathBuf};

use candela::accel::Upkeep;
use candela::assets::load_model_file;
use candela::scene::SceneWrite;
use candela::sim::animation::{
    Influence, MorphTarget, deform_mesh, load_animation_file, morph_normals, skin_vertices,
    world_positions,
};
use glam::{Mat4, Vec3, Vec4};

type TestResult = Result<(), Box<dyn std::error::Error>>;

const EPS: f32 = 1e-6;

fn external(relative: &str) -> PathBuf {
    Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../shared/external/gltf"
    ))
    .join(relative)
}

/// One vertex at (1, 0, 0) fully on joint 1, one split evenly over joints 0 and 1.
fn influences() -> Vec<Influence> {
    vec![
        Influence::normalized([1, 0, 0, 0], [1.0, 0.0, 0.0, 0.0]),
        Influence::normalized([0, 1, 0, 0], [2.0, 2.0, 0.0, 0.0]),
    ]
}

#[test]
fn rotation_turns_normals_and_tangents() {
    let quarter_turn = Mat4::from_rotation_z(std::f32::consts::FRAC_PI_2);
    let matrices = [Mat4::IDENTITY, quarter_turn];
    let positions = [Vec3::X, Vec3::X];
    let normals = [Vec3::X, Vec3::X];
    let tangents = [Vec4::new(0.0, 1.0, 0.0, 1.0); 2];
    let skinned = skin_vertices(
        &positions,
        Some(&normals),
        Some(&tangents),
        &influences(),
        &matrices,
    );
    // Vertex 0: turned a quarter about Z.
    assert!(skinned.positions[0].abs_diff_eq(Vec3::Y, EPS));
    let n = skinned.normals.as_ref().map(|n| n[0]).unwrap_or_default();
    assert!(n.abs_diff_eq(Vec3::Y, EPS), "{n}");
    let t = skinned.tangents.as_ref().map(|t| t[0]).unwrap_or_default();
    assert!(t.abs_diff_eq(Vec4::new(-1.0, 0.0, 0.0, 1.0), EPS), "{t}");
    // Vertex 1: weights 2 and 2 are scaled to 0.5 each; the blend lands halfway.
    assert!(
        skinned.positions[1].abs_diff_eq(Vec3::new(0.5, 0.5, 0.0), EPS),
        "{}",
        skinned.positions[1]
    );
    let n = skinned.normals.as_ref().map(|n| n[1]).unwrap_or_default();
    assert!(
        (n.length() - 1.0).abs() < EPS,
        "skinned normals are unit length"
    );
}

#[test]
fn non_uniform_scale_keeps_normals_perpendicular() {
    let stretch = Mat4::from_scale(Vec3::new(2.0, 1.0, 1.0));
    let matrices = [Mat4::IDENTITY, stretch];
    let normal = Vec3::new(1.0, 1.0, 0.0).normalize();
    let tangent = Vec3::new(1.0, -1.0, 0.0).normalize();
    let skinned = skin_vertices(
        &[Vec3::X],
        Some(&[normal]),
        Some(&[tangent.extend(1.0)]),
        &influences()[..1],
        &matrices,
    );
    let n = skinned.normals.as_ref().map(|n| n[0]).unwrap_or_default();
    let t = skinned.tangents.as_ref().map(|t| t[0]).unwrap_or_default();
    assert!(n.dot(t.truncate()).abs() < EPS, "n {n} t {t}");
    assert!((n.length() - 1.0).abs() < EPS && (t.truncate().length() - 1.0).abs() < EPS);
    // Transforming the normal like a position would tilt it off the surface.
    let naive = (stretch.transform_vector3(normal)).normalize();
    assert!(naive.dot(t.truncate()).abs() > 0.1);
}

#[test]
fn a_mirror_flips_tangent_handedness() {
    let mirror = Mat4::from_scale(Vec3::new(-1.0, 1.0, 1.0));
    let skinned = skin_vertices(
        &[Vec3::X],
        None,
        Some(&[Vec4::new(0.0, 0.0, 1.0, 1.0)]),
        &influences()[..1],
        &[Mat4::IDENTITY, mirror],
    );
    assert_eq!(skinned.tangents.map(|t| t[0].w), Some(-1.0));
}

#[test]
fn morphed_normals_are_renormalised() {
    let target = MorphTarget {
        positions: None,
        normals: Some(vec![Vec3::new(1.0, 0.0, -1.0)]),
        tangents: None,
    };
    let half = morph_normals(&[Vec3::Z], std::slice::from_ref(&target), &[0.5]);
    assert!(half[0].abs_diff_eq(Vec3::new(1.0, 0.0, 1.0).normalize(), EPS));
    let full = morph_normals(&[Vec3::Z], &[target], &[1.0]);
    assert!(full[0].abs_diff_eq(Vec3::X, EPS));
}

#[test]
fn skinned_mesh_feeds_the_deforming_mesh_path() -> TestResult {
    let path = external("CesiumMan/glTF-Binary/CesiumMan.glb");
    let animated = load_animation_file(&path)?;
    let model = load_model_file(&path)?;
    let placement = model
        .placements
        .first()
        .ok_or("CesiumMan has no placement")?;
    let node = animated
        .nodes
        .nodes
        .iter()
        .position(|n| n.skin.is_some())
        .ok_or("CesiumMan has no skinned node")?;
    let pose = animated.pose_at(0, 1.0);
    let world = animated.world_matrices(&pose);
    let deformed = deform_mesh(&animated, &pose, &world, node, placement.model_from_mesh)
        .ok_or("no deformed mesh")?;
    let mesh = &model.meshes[placement.mesh];
    assert_eq!(deformed.positions.len(), mesh.positions.len());
    // Placed by the renderer's instance transform, the mesh-space output is the skinned pose.
    let expected = world_positions(&animated, &pose);
    let size = expected
        .iter()
        .map(|p| p.abs().max_element())
        .fold(0.0, f32::max);
    for (p, e) in deformed.positions.iter().zip(&expected) {
        let placed = placement.model_from_mesh.transform_point3(*p);
        assert!(
            (placed - *e).abs().max_element() <= 1e-5 * size,
            "{placed} vs {e}"
        );
    }
    let normals = deformed.normals.as_deref().ok_or("CesiumMan has normals")?;
    assert!(normals.iter().all(|n| (n.length() - 1.0).abs() < 1e-5));
    // The pose differs from the bind pose the renderer loaded.
    assert!(
        deformed
            .positions
            .iter()
            .zip(&mesh.positions)
            .any(|(d, m)| (*d - *m).length() > 0.01)
    );

    let mut upkeep = Upkeep::new();
    let handle = upkeep.add_model(&model);
    upkeep.finish_frame();
    upkeep.deform(handle, placement.mesh, &deformed.positions, Some(normals));
    let (writes, _, stats) = upkeep.finish_frame();
    assert_eq!(stats.blas_refits + stats.blas_rebuilds, 1);
    let written: Vec<Vec3> = writes
        .iter()
        .filter_map(|w| match w {
            SceneWrite::Vertices { data, .. } => Some(data),
            _ => None,
        })
        .flatten()
        .map(|v| Vec3::from(v.position))
        .collect();
    assert_eq!(written, deformed.positions);
    Ok(())
}
