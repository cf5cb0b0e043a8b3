//! Engine-made models a level can ask for besides `grids`: boxes (props, movers, lamps) and
//! heightfield terrains, so that big geometry is generated at load time instead of stored.
//!
//! Owns: the level entries [`BoxEntry`] and [`TerrainEntry`] and turning them into one-mesh
//! [`Model`]s. Deterministic: the same entry gives the same bits (the terrain's noise is a
//! hash of integer lattice points and the seed). Box cities are in `city.rs`.
//! Must not: read files or check names (level loading does).

use glam::{Mat4, Vec2, Vec3};
use serde::{Deserialize, Serialize};

use super::grid::grid_model;
use super::level::GridEntry;
use super::model::{Material, Mesh, Model, Placement};

/// A box centred on the origin, `size` metres along x, y, z, with flat normals.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BoxEntry {
    pub name: String,
    pub size: [f32; 3],
    /// Name of a level material.
    pub material: String,
}

/// A heightfield over `size` metres in x and z (centred on the origin), `divisions` quads along
/// each: fractal value noise (5 octaves) scaled to `height` metres, flat at y = 0 within
/// `flat_radius` metres of the origin and rising to full height over the next `ramp` metres.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TerrainEntry {
    pub name: String,
    pub size: [f32; 2],
    pub divisions: [u32; 2],
    /// Metres: the highest the noise reaches.
    pub height: f32,
    /// Metres: wavelength of the largest hills.
    pub feature_size: f32,
    #[serde(default)]
    pub seed: u32,
    #[serde(default)]
    pub flat_radius: f32,
    #[serde(default)]
    pub ramp: f32,
    /// Name of a level material.
    pub material: String,
}

/// A one-mesh model at the identity placement.
pub(super) fn one_mesh_model(name: &str, mesh: Mesh, materials: Vec<Material>) -> Model {
    Model {
        name: name.to_string(),
        meshes: vec![mesh],
        materials,
        textures: Vec::new(),
        placements: vec![Placement {
            mesh: 0,
            model_from_mesh: Mat4::IDENTITY,
        }],
        notes: Vec::new(),
    }
}

/// Appends the faces of an axis-aligned box from `min` to `max` to `mesh` (flat normals,
/// counter-clockwise seen from outside); the bottom face only when `bottom`. The top face gets
/// material `top_material`, the others `side_material`.
pub(super) fn push_box(
    mesh: &mut Mesh,
    min: Vec3,
    max: Vec3,
    bottom: bool,
    side_material: u32,
    top_material: u32,
) {
    let c = |x: bool, y: bool, z: bool| {
        Vec3::new(
            if x { max.x } else { min.x },
            if y { max.y } else { min.y },
            if z { max.z } else { min.z },
        )
    };
    // Each face: normal and its corners counter-clockwise seen from outside.
    let faces = [
        (
            Vec3::X,
            [
                c(true, false, true),
                c(true, false, false),
                c(true, true, false),
                c(true, true, true),
            ],
        ),
        (
            Vec3::NEG_X,
            [
                c(false, false, false),
                c(false, false, true),
                c(false, true, true),
                c(false, true, false),
            ],
        ),
        (
            Vec3::Z,
            [
                c(false, false, true),
                c(true, false, true),
                c(true, true, true),
                c(false, true, true),
            ],
        ),
        (
            Vec3::NEG_Z,
            [
                c(true, false, false),
                c(false, false, false),
                c(false, true, false),
                c(true, true, false),
            ],
        ),
        (
            Vec3::Y,
            [
                c(false, true, true),
                c(true, true, true),
                c(true, true, false),
                c(false, true, false),
            ],
        ),
        (
            Vec3::NEG_Y,
            [
                c(false, false, false),
                c(true, false, false),
                c(true, false, true),
                c(false, false, true),
            ],
        ),
    ];
    let normals = mesh.normals.get_or_insert_with(Vec::new);
    let uvs = mesh.uvs.get_or_insert_with(Vec::new);
    for (normal, corners) in faces {
        if normal == Vec3::NEG_Y && !bottom {
            continue;
        }
        let base = mesh.positions.len() as u32;
        mesh.positions.extend(corners);
        normals.extend([normal; 4]);
        uvs.extend([Vec2::ZERO, Vec2::X, Vec2::ONE, Vec2::Y]);
        mesh.triangles.push([base, base + 1, base + 2]);
        mesh.triangles.push([base, base + 2, base + 3]);
        let m = if normal == Vec3::Y {
            top_material
        } else {
            side_material
        };
        mesh.triangle_materials.extend([m, m]);
    }
}

/// The model of `entry`, drawn with `material`.
pub fn box_model(entry: &BoxEntry, material: Material) -> Model {
    let half = Vec3::from(entry.size) * 0.5;
    let mut mesh = Mesh {
        name: entry.name.clone(),
        ..Default::default()
    };
    push_box(&mut mesh, -half, half, true, 0, 0);
    one_mesh_model(&entry.name, mesh, vec![material])
}

/// A hash of a lattice point and the seed to [0, 1) (integer mixing, platform independent).
fn lattice(x: i32, z: i32, seed: u32) -> f32 {
    let mut h = (x as u32).wrapping_mul(0x8da6_b343) ^ (z as u32).wrapping_mul(0xd816_3841);
    h ^= seed.wrapping_mul(0xcb1a_b31f);
    h ^= h >> 15;
    h = h.wrapping_mul(0x2c1b_3c6d);
    h ^= h >> 12;
    h = h.wrapping_mul(0x297a_2d39);
    h ^= h >> 15;
    (h >> 8) as f32 / (1u32 << 24) as f32
}

/// Value noise in [0, 1) with quintic smoothing.
fn value_noise(p: Vec2, seed: u32) -> f32 {
    let (fx, fz) = (p.x.floor(), p.y.floor());
    let (x, z) = (fx as i32, fz as i32);
    let s = |t: f32| t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
    let (u, v) = (s(p.x - fx), s(p.y - fz));
    let a = lattice(x, z, seed) + (lattice(x + 1, z, seed) - lattice(x, z, seed)) * u;
    let b = lattice(x, z + 1, seed) + (lattice(x + 1, z + 1, seed) - lattice(x, z + 1, seed)) * u;
    a + (b - a) * v
}

/// Terrain height (metres) at `(x, z)`.
fn terrain_height(entry: &TerrainEntry, x: f32, z: f32) -> f32 {
    let mut p = Vec2::new(x, z) / entry.feature_size.max(1e-3);
    let (mut sum, mut amplitude, mut total) = (0.0, 1.0, 0.0);
    for octave in 0..5u32 {
        sum += amplitude * value_noise(p, entry.seed.wrapping_add(octave));
        total += amplitude;
        amplitude *= 0.5;
        p *= 2.0;
    }
    let n = sum / total;
    let r = Vec2::new(x, z).length();
    let t = ((r - entry.flat_radius) / entry.ramp.max(1e-3)).clamp(0.0, 1.0);
    let rise = t * t * (3.0 - 2.0 * t);
    entry.height * n * n * rise
}

/// The model of `entry`, drawn with `material`.
pub fn terrain_model(entry: &TerrainEntry, material: Material) -> Model {
    let grid = GridEntry {
        name: entry.name.clone(),
        size: entry.size,
        divisions: entry.divisions,
        material: String::new(),
    };
    let mut model = grid_model(&grid, material);
    let step =
        Vec2::from(entry.size) / Vec2::new(entry.divisions[0] as f32, entry.divisions[1] as f32);
    if let Some(mesh) = model.meshes.first_mut() {
        let mut normals = Vec::with_capacity(mesh.positions.len());
        for p in &mut mesh.positions {
            p.y = terrain_height(entry, p.x, p.z);
            let dx =
                terrain_height(entry, p.x + step.x, p.z) - terrain_height(entry, p.x - step.x, p.z);
            let dz =
                terrain_height(entry, p.x, p.z + step.y) - terrain_height(entry, p.x, p.z - step.y);
            normals.push(Vec3::new(-dx / (2.0 * step.x), 1.0, -dz / (2.0 * step.y)).normalize());
        }
        mesh.normals = Some(normals);
    }
    model
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn box_is_closed_and_outward() {
        let m = box_model(
            &BoxEntry {
                name: "b".into(),
                size: [2.0, 4.0, 6.0],
                material: "m".into(),
            },
            Material::default(),
        );
        let mesh = &m.meshes[0];
        assert_eq!(mesh.triangles.len(), 12);
        let normals = mesh.normals.as_ref().expect("normals");
        for t in &mesh.triangles {
            let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
            let n = (b - a).cross(c - a).normalize();
            assert!(
                (n - normals[t[0] as usize]).length() < 1e-6,
                "winding matches normal"
            );
            assert!(n.dot((a + b + c) / 3.0) > 0.0, "faces point outwards");
        }
    }

    #[test]
    fn terrain_is_flat_inside_and_deterministic() {
        let e = TerrainEntry {
            name: "t".into(),
            size: [200.0, 200.0],
            divisions: [64, 64],
            height: 30.0,
            feature_size: 40.0,
            seed: 3,
            flat_radius: 40.0,
            ramp: 20.0,
            material: "m".into(),
        };
        let a = terrain_model(&e, Material::default());
        let b = terrain_model(&e, Material::default());
        assert_eq!(a.meshes[0].positions, b.meshes[0].positions);
        let p = &a.meshes[0].positions;
        assert!(
            p.iter()
                .filter(|v| v.x.hypot(v.z) < 40.0)
                .all(|v| v.y == 0.0)
        );
        let max = p.iter().map(|v| v.y).fold(0.0, f32::max);
        assert!(max > 3.0 && max <= 30.0, "hills rise outside: {max}");
    }
}
