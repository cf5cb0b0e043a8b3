//! Visible laser beams: each straight piece of a [`LaserPath`] drawn as a thin emissive square
//! prism, so the beam shows and lights the rooms it crosses. Its material is a line emitter
//! (`Material::line`): the camera sees it as a prefiltered line, continuous at any resolution.
//!
//! Owns: the unit beam model ([`beam_model`]: one per laser, for its colour), the pool of
//! segment entities on each laser ([`BeamPool`], [`BeamSegment`]) and placing them
//! ([`update_beams`], after the beams are traced, every fixed step). The segments are ordinary
//! dynamic renderables (`Transform` + `Renderable` + the laser's `LightGroup`), so the
//! extractor and the upkeep handle them like any mover: a moved piece is one instance row
//! (and the light table rebuilt, as for every moving emitter), an unchanged one costs nothing.
//! Pieces the path does not use are hidden by a zero scale rather than despawned: a hidden
//! row stays where it is (no row swapped into its place, no `TruncateInstances`), its
//! triangles have no area so the light table skips them, and showing it again rewrites that
//! one row. Main thread, fixed step. Must not: trace (the laser does; its queries skip
//! [`BeamSegment`] entities, so a beam never blocks or turns a laser).
//! Units: metres, world space, right-handed, +Y up; radiance W·sr⁻¹·m⁻², linear RGB.

use glam::{Mat4, Quat, Vec3};
use hecs::{Entity, World};

use super::laser::{LaserBeam, LaserPath};
use super::plan::PlannedBeam;
use crate::assets::{Material, MaterialKind, Mesh, Model, Placement};
use crate::ecs::{LightGroup, ModelHandle, Renderable, Transform};

/// Most pieces a laser's beam shows; a path with more (more than 15 turns) shows its first
/// ones. 16 pieces × 8 triangles per laser.
pub const MAX_BEAM_SEGMENTS: usize = 16;

/// On a segment entity: the laser it belongs to and which piece of its path it shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BeamSegment {
    pub laser: Entity,
    pub index: u32,
}

/// On a laser entity with a visible beam: its segment entities, in path order.
#[derive(Clone, Debug, PartialEq)]
pub struct BeamPool {
    pub segments: Vec<Entity>,
    /// Half the prism's width, metres.
    pub radius: f32,
}

/// The unit beam: a square prism open at both ends, x and y in [−½, ½], z in [0, 1], its four
/// sides facing out, emitting `beam.radiance` from their outer faces and reflecting nothing.
/// Open ends: a laser ray running down the axis never meets its own beam's walls.
pub fn beam_model(beam: &PlannedBeam) -> Model {
    let mut mesh = Mesh {
        name: "beam".into(),
        ..Default::default()
    };
    for n in [Vec3::X, Vec3::Y, Vec3::NEG_X, Vec3::NEG_Y] {
        // (p1 − p0) × (p2 − p0) = t × (t + z) = n: counter-clockwise seen from outside.
        let t = Vec3::Z.cross(n);
        let base = mesh.positions.len() as u32;
        let c = 0.5 * n;
        mesh.positions.extend([
            c - 0.5 * t,
            c + 0.5 * t,
            c + 0.5 * t + Vec3::Z,
            c - 0.5 * t + Vec3::Z,
        ]);
        mesh.triangles
            .extend([[base, base + 1, base + 2], [base, base + 2, base + 3]]);
    }
    mesh.triangle_materials = vec![0; mesh.triangles.len()];
    Model {
        name: "laser beam".into(),
        meshes: vec![mesh],
        materials: vec![Material {
            name: "laser beam".into(),
            kind: MaterialKind::Diffuse,
            base_color: Vec3::ZERO,
            emission: beam.radiance,
            // Seen from the camera as a prefiltered line: continuous at any resolution.
            line: true,
            ..Default::default()
        }],
        textures: Vec::new(),
        placements: vec![Placement {
            mesh: 0,
            model_from_mesh: Mat4::IDENTITY,
        }],
        notes: Vec::new(),
    }
}

/// The transform that lays the unit beam from `a` to `b` (world metres) with half-width
/// `radius`; a piece shorter than a micrometre is hidden (zero scale at `a`).
pub fn segment_transform(a: Vec3, b: Vec3, radius: f32) -> Transform {
    let d = b - a;
    let length = d.length();
    if !(length > 1e-6 && length.is_finite()) {
        return hidden(a);
    }
    Transform {
        translation: a,
        rotation: Quat::from_rotation_arc(Vec3::Z, d / length),
        scale: Vec3::new(2.0 * radius, 2.0 * radius, length),
    }
}

/// A segment the path does not use: zero scale (no area, no light) at `at`.
fn hidden(at: Vec3) -> Transform {
    Transform {
        translation: if at.is_finite() { at } else { Vec3::ZERO },
        rotation: Quat::IDENTITY,
        scale: Vec3::ZERO,
    }
}

/// Spawns the segment entities of `laser`'s beam (one per piece its path can have, at most
/// [`MAX_BEAM_SEGMENTS`]), hidden until the first [`update_beams`], showing `model` (made by
/// [`beam_model`] and registered by the caller) in `beam.light_group`, and puts the
/// [`BeamPool`] on the laser. Returns the segments; nothing when `laser` has no [`LaserBeam`].
pub fn spawn_beam_pool(
    world: &mut World,
    laser: Entity,
    model: ModelHandle,
    beam: &PlannedBeam,
) -> Vec<Entity> {
    let Ok(turns) = world.get::<&LaserBeam>(laser).map(|b| b.max_reflections) else {
        return Vec::new();
    };
    let count = (turns as usize).saturating_add(1).min(MAX_BEAM_SEGMENTS);
    let start = world
        .get::<&Transform>(laser)
        .map(|t| t.translation)
        .unwrap_or(Vec3::ZERO);
    let renderable = Renderable {
        model,
        material_override: None,
    };
    let segments: Vec<Entity> = (0..count as u32)
        .map(|index| {
            let e = world.spawn((hidden(start), renderable, BeamSegment { laser, index }));
            if let Some(group) = beam.light_group {
                let _ = world.insert_one(e, LightGroup(group));
            }
            e
        })
        .collect();
    let pool = BeamPool {
        segments: segments.clone(),
        radius: beam.radius,
    };
    let _ = world.insert_one(laser, pool);
    segments
}

/// Lays every laser's segments along its current [`LaserPath`] (piece `i` on segment `i`, the
/// rest hidden). Writes a `Transform` only where it changed, so a still beam makes no scene
/// change.
pub fn update_beams(world: &mut World) {
    let mut placements: Vec<(Entity, Transform)> = Vec::new();
    for (path, pool) in world.query::<(&LaserPath, &BeamPool)>().iter() {
        // Hidden pieces wait 1 mm behind the beam's start (inside the emitter): off every
        // ray the laser traces, so their point-sized bounds are never on its path.
        let start = match path.segments().next() {
            Some((a, b)) => a - (b - a).normalize_or_zero() * 1e-3,
            None => path.points.first().copied().unwrap_or(Vec3::ZERO),
        };
        let mut pieces = path.segments();
        for &segment in &pool.segments {
            let transform = match pieces.next() {
                Some((a, b)) => segment_transform(a, b, pool.radius),
                None => hidden(start),
            };
            placements.push((segment, transform));
        }
    }
    for (segment, transform) in placements {
        if let Ok(mut t) = world.get::<&mut Transform>(segment)
            && *t != transform
        {
            *t = transform;
        }
    }
}

/// Whether `entity` is a piece of some laser's beam (laser queries pass through these).
pub fn is_beam(world: &World, entity: Entity) -> bool {
    world.get::<&BeamSegment>(entity).is_ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_segment_transform_maps_the_unit_axis_onto_the_piece() {
        let (a, b) = (Vec3::new(1.0, 2.0, 3.0), Vec3::new(-2.0, 2.5, 7.0));
        let m = segment_transform(a, b, 0.01).matrix();
        assert!((m.transform_point3(Vec3::ZERO) - a).length() < 1e-5);
        assert!((m.transform_point3(Vec3::Z) - b).length() < 1e-5);
        // The width: a unit x step is 2 × radius long, across the beam.
        let across = m.transform_vector3(Vec3::X);
        assert!((across.length() - 0.02).abs() < 1e-6);
        assert!(across.dot(b - a).abs() < 1e-5);
        assert_eq!(segment_transform(a, a, 0.01).scale, Vec3::ZERO);
    }

    #[test]
    fn the_unit_beam_faces_outward() {
        let model = beam_model(&PlannedBeam {
            radiance: Vec3::ONE,
            radius: 0.01,
            light_group: None,
        });
        let mesh = &model.meshes[0];
        assert_eq!(mesh.triangles.len(), 8);
        for t in &mesh.triangles {
            let [p0, p1, p2] = t.map(|i| mesh.positions[i as usize]);
            let n = (p1 - p0).cross(p2 - p0);
            let centre = (p0 + p1 + p2) / 3.0;
            let outward = Vec3::new(centre.x, centre.y, 0.0);
            assert!(n.dot(outward) > 0.0, "{t:?}");
        }
    }
}
