//! `bench memory`: what a scene holds in memory, by kind (triangles, BVH, instances, textures,
//! lights), beside Brigade's 737 MB for its 1.4 M-triangle scene (paper §6.2: 175 MB triangles,
//! 42 MB BVH, 520 MB textures).
//!
//! Rows: Reflect's five chambers (one composed level), and a generated stone ruin of 1.4 M
//! placed triangles twice: every stone stored once (1.4 M unique triangles, the paper's case)
//! and the same ruin instanced from 12 stones. Both ruins carry the same 12 stone textures of
//! `--texture` texels square. Counts are [`candela::scene::SceneMemory`] (vector lengths ×
//! element sizes of the flattened scene both tracers read). Prints a table and draws
//! `docs/charts/scene_memory.png`. Owns: the ruin generator and the table. Must not: time.

use std::path::PathBuf;

use candela::assets::{
    CameraDesc, Material, Mesh, Model, Placement, SceneDesc, Texture, TextureRef,
};
use candela::scene::{RenderScene, SceneMemory};
use clap::Args;
use glam::{Mat4, Quat, Vec2, Vec3};
use half::f16;

#[derive(Args, Debug)]
pub struct MemoryArgs {
    /// Placed triangles in the ruin (rounded to whole stones of 4,800).
    #[arg(long, default_value_t = 1_400_000)]
    triangles: usize,
    /// Texels along each side of the ruin's 12 stone textures.
    #[arg(long, default_value_t = 1024)]
    texture: u32,
    /// Where the chart goes.
    #[arg(long, default_value = "docs/charts/scene_memory.png")]
    chart: PathBuf,
}

/// Quads along each edge of a stone's faces: 6 faces × 20² quads × 2 = 4,800 triangles.
const STONE_QUADS: u32 = 20;
const VARIANTS: usize = 12;

/// One measured row.
pub struct Row {
    pub name: String,
    pub unique_triangles: usize,
    pub placed_triangles: usize,
    pub memory: SceneMemory,
}

/// A hash of three integers in [0, 1), for deterministic displacement and texels.
fn hash(a: u32, b: u32, c: u32) -> f32 {
    let mut h =
        a.wrapping_mul(0x9E37_79B1) ^ b.wrapping_mul(0x85EB_CA77) ^ c.wrapping_mul(0xC2B2_AE3D);
    h ^= h >> 15;
    h = h.wrapping_mul(0x2C1B_3C6D);
    h ^= h >> 12;
    (h & 0xFF_FFFF) as f32 / 16_777_216.0
}

/// A roughly cut stone: a unit cube's faces subdivided and pushed in and out by up to 3 cm.
fn stone(variant: u32) -> Mesh {
    let n = STONE_QUADS;
    let (mut positions, mut uvs, mut triangles) = (Vec::new(), Vec::new(), Vec::new());
    for face in 0..6u32 {
        let axis = (face / 2) as usize;
        let sign = if face % 2 == 0 { 1.0 } else { -1.0 };
        let base = positions.len() as u32;
        for j in 0..=n {
            for i in 0..=n {
                let (u, v) = (i as f32 / n as f32, j as f32 / n as f32);
                let mut p = [0.0f32; 3];
                p[axis] = 0.5 * sign;
                p[(axis + 1) % 3] = (u - 0.5) * sign;
                p[(axis + 2) % 3] = v - 0.5;
                let bump = 0.03 * (hash(variant, face * 1024 + j, i) - 0.5);
                positions.push(Vec3::from(p) * (1.0 + bump));
                uvs.push(Vec2::new(u, v));
            }
        }
        for j in 0..n {
            for i in 0..n {
                let a = base + j * (n + 1) + i;
                let (b, c, d) = (a + 1, a + n + 1, a + n + 2);
                triangles.push([a, b, d]);
                triangles.push([a, d, c]);
            }
        }
    }
    let count = triangles.len();
    Mesh {
        name: format!("stone {variant}"),
        positions,
        normals: None,
        uvs: Some(uvs),
        tangents: None,
        triangles,
        triangle_materials: vec![variant % VARIANTS as u32; count],
    }
}

/// A stone texture: grey-brown with speckles.
fn stone_texture(variant: u32, side: u32) -> Texture {
    let texels = (0..side * side)
        .map(|k| {
            let g = 0.35 + 0.3 * hash(variant, k % side, k / side);
            [g, g * 0.9, g * 0.75, 1.0].map(f16::from_f32)
        })
        .collect();
    Texture {
        name: format!("stone texture {variant}"),
        width: side,
        height: side,
        texels,
        ..Texture::default()
    }
}

/// The ruin: `stones` stones on a grid of walls and columns, each stone its own mesh
/// (`instanced` false) or one of 12 meshes placed many times.
fn ruin(stones: usize, texture: u32, instanced: bool) -> SceneDesc {
    let meshes: Vec<Mesh> = (0..if instanced { VARIANTS } else { stones })
        .map(|i| stone(i as u32))
        .collect();
    let materials = (0..VARIANTS)
        .map(|i| Material {
            name: format!("stone {i}"),
            base_color: Vec3::ONE,
            base_color_texture: Some(TextureRef(i)),
            ..Material::default()
        })
        .collect();
    let textures = (0..VARIANTS as u32)
        .map(|i| stone_texture(i, texture))
        .collect();
    let side = (stones as f32).sqrt().ceil() as usize;
    let placements = (0..stones)
        .map(|k| {
            let (x, z) = ((k % side) as f32 * 1.2, (k / side) as f32 * 1.2);
            let turn = Quat::from_rotation_y(hash(7, k as u32, 0) * 0.3);
            Placement {
                mesh: if instanced { k % VARIANTS } else { k },
                model_from_mesh: Mat4::from_rotation_translation(turn, Vec3::new(x, 0.5, z)),
            }
        })
        .collect();
    let model = Model {
        name: "ruin".into(),
        meshes,
        materials,
        textures,
        placements,
        notes: Vec::new(),
    };
    let camera = CameraDesc {
        position: [-5.0, 8.0, -5.0],
        look_at: [side as f32 * 0.6, 0.0, side as f32 * 0.6],
        up: [0.0, 1.0, 0.0],
        vertical_fov_deg: 50.0,
        aperture_radius: 0.0,
        focus_distance: None,
    };
    SceneDesc::single(model, camera)
}

fn row(name: &str, desc: &SceneDesc) -> Row {
    let scene = RenderScene::build(desc);
    Row {
        name: name.into(),
        unique_triangles: scene.stats.unique_triangles,
        placed_triangles: scene.stats.instanced_triangles,
        memory: scene.memory(),
    }
}

pub fn run(args: &MemoryArgs) -> anyhow::Result<()> {
    let per_stone = (6 * STONE_QUADS * STONE_QUADS * 2) as usize;
    let stones = args.triangles.div_ceil(per_stone).max(1);
    let mut rows = Vec::new();
    let (path, root) = reflect::cli::locate(None)?;
    let world = reflect::world::ReflectWorld::load(&path, &root)?;
    rows.push(row("Reflect, five chambers", &world.playable.scene));
    rows.push(row(
        "ruin, each stone stored",
        &ruin(stones, args.texture, false),
    ));
    rows.push(row(
        "ruin, 12 stones instanced",
        &ruin(stones, args.texture, true),
    ));
    let mb = |b: usize| b as f64 / 1e6;
    println!(
        "{:<28} {:>10} {:>10} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9}",
        "scene",
        "unique tri",
        "placed tri",
        "tri MB",
        "BVH MB",
        "inst MB",
        "tex MB",
        "light MB",
        "other MB",
        "total MB"
    );
    for r in &rows {
        let m = &r.memory;
        println!(
            "{:<28} {:>10} {:>10} {:>9.1} {:>9.1} {:>9.2} {:>9.1} {:>9.2} {:>9.2} {:>9.1}",
            r.name,
            r.unique_triangles,
            r.placed_triangles,
            mb(m.triangles),
            mb(m.bvh),
            mb(m.instances),
            mb(m.textures),
            mb(m.lights),
            mb(m.other),
            mb(m.total())
        );
    }
    println!(
        "{:<28} {:>10} {:>10} {:>9.1} {:>9.1} {:>9} {:>9.1} {:>9} {:>9} {:>9.1}",
        "Brigade (paper §6.2)", 1_400_000, "", 175.0, 42.0, "", 520.0, "", "", 737.0
    );
    if let Some(ruin) = rows.get(1) {
        let m = &ruin.memory;
        println!(
            "ruin stored once against Brigade: triangles {:.0} B each (Brigade {:.0}), BVH {:.0} B \
             per triangle (Brigade {:.0})",
            m.triangles as f64 / ruin.unique_triangles as f64,
            175e6 / 1.4e6,
            m.bvh as f64 / ruin.unique_triangles as f64,
            42e6 / 1.4e6
        );
    }
    super::memory_plot::draw(&args.chart, &rows)?;
    println!("wrote {}", args.chart.display());
    Ok(())
}
