//! Box cities made by the engine from a level entry: a grid of blocks separated by streets,
//! each block cut into lots, each lot a building of one to three stacked boxes (setbacks), with
//! an optional empty plaza around the origin. Static geometry in bulk without storing it.
//!
//! Owns: [`CityEntry`] and [`city_model`]. Deterministic (a small integer RNG seeded by the
//! entry). Must not: read files or check names (level loading does).

use glam::Vec3;
use serde::{Deserialize, Serialize};

use super::model::{Material, Mesh, Model};
use super::shapes::{one_mesh_model, push_box};

/// A city centred on the origin, ground at y = 0.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CityEntry {
    pub name: String,
    /// Blocks along x and z.
    pub blocks: [u32; 2],
    /// Metres: edge of a (square) block.
    pub block_size: f32,
    /// Metres between blocks.
    pub street_width: f32,
    /// Lots along each edge of a block (`lots²` buildings per block).
    pub lots: u32,
    /// Metres: lowest and highest building.
    pub height: [f32; 2],
    /// Metres: no building whose lot centre is this close to the origin.
    #[serde(default)]
    pub plaza_radius: f32,
    #[serde(default)]
    pub seed: u32,
    /// Names of level materials for walls and roofs.
    pub wall_material: String,
    pub roof_material: String,
}

/// xorshift32: enough randomness for building sizes, identical on every platform.
struct Rng(u32);

impl Rng {
    fn next(&mut self) -> f32 {
        let mut x = self.0;
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        self.0 = x;
        (x >> 8) as f32 / (1u32 << 24) as f32
    }
}

impl CityEntry {
    /// Metres from one block's start to the next one's.
    fn pitch(&self) -> f32 {
        self.block_size + self.street_width
    }

    /// World x (or z) of the start of block `i` along an axis with `n` blocks.
    fn block_start(&self, i: u32, n: u32) -> f32 {
        let extent = n as f32 * self.pitch() - self.street_width;
        -extent / 2.0 + i as f32 * self.pitch()
    }

    /// Centres of the street crossings between blocks (x, z), for placing lamps and cars.
    pub fn crossings(&self) -> Vec<[f32; 2]> {
        let mut out = Vec::new();
        let [nx, nz] = self.blocks;
        for iz in 0..nz.saturating_sub(1) {
            for ix in 0..nx.saturating_sub(1) {
                let x = self.block_start(ix, nx) + self.block_size + self.street_width / 2.0;
                let z = self.block_start(iz, nz) + self.block_size + self.street_width / 2.0;
                out.push([x, z]);
            }
        }
        out
    }

    /// Metres: half the city's extent along x and z.
    pub fn half_extent(&self) -> [f32; 2] {
        self.blocks
            .map(|n| (n as f32 * self.pitch() - self.street_width) / 2.0)
    }
}

/// The model of `entry`: material 0 `walls`, material 1 `roofs`.
pub fn city_model(entry: &CityEntry, walls: Material, roofs: Material) -> Model {
    let mut rng = Rng(entry.seed.wrapping_mul(0x9e37_79b9) | 1);
    let mut mesh = Mesh {
        name: entry.name.clone(),
        ..Default::default()
    };
    let [nx, nz] = entry.blocks;
    let lot = entry.block_size / entry.lots.max(1) as f32;
    let [low, high] = entry.height;
    for bz in 0..nz {
        for bx in 0..nx {
            let (x0, z0) = (entry.block_start(bx, nx), entry.block_start(bz, nz));
            for lz in 0..entry.lots {
                for lx in 0..entry.lots {
                    let centre = Vec3::new(
                        x0 + (lx as f32 + 0.5) * lot,
                        0.0,
                        z0 + (lz as f32 + 0.5) * lot,
                    );
                    // Draw every number even for skipped lots: the rest of the city does not
                    // change when the plaza does.
                    let (fx, fz, fh, tiers) = (rng.next(), rng.next(), rng.next(), rng.next());
                    if centre.x.hypot(centre.z) < entry.plaza_radius {
                        continue;
                    }
                    // Most buildings low, a few towers; towers nearer the centre.
                    let towers = 1.0 - (centre.x.hypot(centre.z) / 400.0).min(0.6);
                    let height = low + (high - low) * fh * fh * towers;
                    let mut half = Vec3::new(0.3 + 0.15 * fx, 0.0, 0.3 + 0.15 * fz) * lot;
                    let mut base = 0.0;
                    let levels = (1 + (tiers * 3.0 * height / high.max(1e-3)) as u32).min(3);
                    // Tier k is 1/(k+1) as tall as the first; together they make `height`.
                    let parts: f32 = (0..levels).map(|k| 1.0 / (k as f32 + 1.0)).sum();
                    for level in 0..levels {
                        let h = height / (level as f32 + 1.0) / parts;
                        let min = Vec3::new(centre.x - half.x, base, centre.z - half.z);
                        let max = Vec3::new(centre.x + half.x, base + h, centre.z + half.z);
                        push_box(&mut mesh, min, max, false, 0, 1);
                        base += h;
                        half *= 0.7;
                    }
                }
            }
        }
    }
    one_mesh_model(&entry.name, mesh, vec![walls, roofs])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn entry() -> CityEntry {
        CityEntry {
            name: "c".into(),
            blocks: [4, 3],
            block_size: 20.0,
            street_width: 8.0,
            lots: 3,
            height: [5.0, 40.0],
            plaza_radius: 15.0,
            seed: 2,
            wall_material: "w".into(),
            roof_material: "r".into(),
        }
    }

    #[test]
    fn buildings_stay_in_blocks_and_out_of_the_plaza() {
        let e = entry();
        let m = city_model(&e, Material::default(), Material::default());
        let mesh = &m.meshes[0];
        assert!(!mesh.triangles.is_empty());
        assert_eq!(mesh.triangles.len() % 10, 0, "five faces per box");
        let [hx, hz] = e.half_extent();
        for p in &mesh.positions {
            assert!(p.x.abs() <= hx + 1e-3 && p.z.abs() <= hz + 1e-3, "{p}");
            assert!(p.y >= 0.0 && p.y <= 40.0 + 1e-3, "{p}");
        }
        // No roof inside the plaza (lot centres farther than the radius; lot half-size 10/3 m).
        for (t, m) in mesh.triangles.iter().zip(&mesh.triangle_materials) {
            let c = t.iter().map(|&i| mesh.positions[i as usize]).sum::<Vec3>() / 3.0;
            if *m == 1 {
                assert!(c.x.hypot(c.z) > 15.0 - 10.0 / 3.0 * 2f32.sqrt(), "{c}");
            }
        }
        // Crossings lie in the streets.
        assert_eq!(e.crossings().len(), 3 * 2);
        assert_eq!(
            city_model(&e, Material::default(), Material::default()).meshes[0].positions,
            mesh.positions
        );
    }
}
