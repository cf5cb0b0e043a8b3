//! Grids the engine makes from a level's description (water surfaces, test floors).
//!
//! Owns: turning a [`GridEntry`] into a one-mesh [`Model`]: `divisions` quads per axis over
//! `size` metres in x and z, centred on the origin, facing +Y, with normals and texture
//! coordinates (u along +x, v along +z, both 0..1). Must not: animate it (see `app::waves`).

use glam::{Mat4, Vec2, Vec3};

use super::level::GridEntry;
use super::model::{Material, Mesh, Model, Placement};

/// The model of `grid`, drawn with `material`.
pub fn grid_model(grid: &GridEntry, material: Material) -> Model {
    let [nx, nz] = grid.divisions;
    let [sx, sz] = grid.size;
    let mut positions = Vec::with_capacity(((nx + 1) * (nz + 1)) as usize);
    let mut uvs = Vec::with_capacity(positions.capacity());
    for z in 0..=nz {
        for x in 0..=nx {
            let (u, v) = (x as f32 / nx as f32, z as f32 / nz as f32);
            positions.push(Vec3::new((u - 0.5) * sx, 0.0, (v - 0.5) * sz));
            uvs.push(Vec2::new(u, v));
        }
    }
    let mut triangles = Vec::with_capacity((2 * nx * nz) as usize);
    for z in 0..nz {
        for x in 0..nx {
            let i = z * (nx + 1) + x;
            triangles.push([i, i + nx + 1, i + 1]);
            triangles.push([i + 1, i + nx + 1, i + nx + 2]);
        }
    }
    let count = triangles.len();
    Model {
        name: grid.name.clone(),
        meshes: vec![Mesh {
            name: grid.name.clone(),
            normals: Some(vec![Vec3::Y; positions.len()]),
            positions,
            uvs: Some(uvs),
            tangents: None,
            triangles,
            triangle_materials: vec![0; count],
        }],
        materials: vec![material],
        textures: Vec::new(),
        placements: vec![Placement {
            mesh: 0,
            model_from_mesh: Mat4::IDENTITY,
        }],
        notes: Vec::new(),
    }
}
