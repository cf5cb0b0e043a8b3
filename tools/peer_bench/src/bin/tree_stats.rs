//! tree_stats: what a BLAS costs the peer benchmark's rays, counted rather than timed: per ray,
//! inner nodes visited, blocks tested, triangle lanes tested, and 64-byte lines that miss a
//! simulated 2 MiB, 16-way LRU cache (a stand-in for the L2) when the rays run in file order.
//!
//! Usage: `tree_stats DIR [--quality binned-sah]`. Walks exactly like `trace/scalar.rs` (same
//! visiting order and culling), so the counts are those of the CPU kernels up to tie order.

#[path = "../load.rs"]
mod load;

use anyhow::Result;
use candela::accel::build_blas;
use candela::layout::{GpuBvh8Node, GpuTri4, INVALID, LEAF_BIT, LEAF_COUNT_SHIFT, LEAF_INDEX_MASK};
use candela::trace::ray::SlabRay;
use candela::trace::triangle::{TriRay, intersect_lane};
use clap::Parser;
use load::{RayRecord, load_rays, load_triangles};

#[derive(Parser)]
struct Args {
    dir: String,
}

/// A set-associative LRU cache of 64-byte lines.
struct Cache {
    sets: Vec<Vec<(u64, u64)>>,
    ways: usize,
    clock: u64,
    misses: u64,
}

impl Cache {
    fn new(bytes: usize, ways: usize) -> Self {
        Self {
            sets: vec![Vec::with_capacity(ways); bytes / 64 / ways],
            ways,
            clock: 0,
            misses: 0,
        }
    }
    fn touch(&mut self, line: u64) {
        self.clock += 1;
        let n = self.sets.len() as u64;
        let set = &mut self.sets[(line % n) as usize];
        if let Some(e) = set.iter_mut().find(|e| e.0 == line) {
            e.1 = self.clock;
            return;
        }
        self.misses += 1;
        if set.len() < self.ways {
            set.push((line, self.clock));
        } else if let Some(e) = set.iter_mut().min_by_key(|e| e.1) {
            *e = (line, self.clock);
        }
    }
    fn range(&mut self, start: u64, bytes: u64) {
        for line in start / 64..(start + bytes).div_ceil(64) {
            self.touch(line);
        }
    }
}

#[derive(Default)]
struct Counts {
    hist: [u64; 4],
    nodes: u64,
    leaves: u64,
    blocks: u64,
    lanes: u64,
}

const BLOCK_BASE: u64 = 1 << 40;

fn walk(
    nodes: &[GpuBvh8Node],
    blocks: &[GpuTri4],
    r: &RayRecord,
    any: bool,
    c: &mut Counts,
    cache: &mut Cache,
) {
    let (o, d) = (glam::Vec3::from(r.origin), glam::Vec3::from(r.direction));
    let slab = SlabRay::new(o, d);
    let tri = TriRay::new(o, d);
    let shift = 3 * slab.octant;
    let neg = [
        slab.octant & 1 != 0,
        slab.octant & 2 != 0,
        slab.octant & 4 != 0,
    ];
    let mut t_max = r.t_far;
    let mut stack: Vec<(u32, f32)> = vec![(0, r.t_near)];
    while let Some((entry, t_entry)) = stack.pop() {
        if t_entry > slab.far_limit(t_max) {
            continue;
        }
        if entry & LEAF_BIT != 0 {
            let first = (entry & LEAF_INDEX_MASK) as usize;
            let count = ((entry & !LEAF_BIT) >> LEAF_COUNT_SHIFT) as usize + 1;
            c.leaves += 1;
            for block in &blocks[first..first + count] {
                c.blocks += 1;
                cache.range(
                    BLOCK_BASE + (block as *const GpuTri4 as u64 - blocks.as_ptr() as u64),
                    160,
                );
                for lane in 0..4 {
                    if block.prim[lane] == INVALID {
                        continue;
                    }
                    c.lanes += 1;
                    if let Some((t, _, _)) = intersect_lane(block, lane, &tri, r.t_near, t_max) {
                        t_max = t;
                        if any {
                            return;
                        }
                    }
                }
            }
            continue;
        }
        let node = &nodes[entry as usize];
        c.nodes += 1;
        let before = stack.len();
        cache.range(256 * entry as u64, 256);
        for rank in (0..8).rev() {
            let s = ((node.perm[rank] >> shift) & 7) as usize;
            let p = |min: f32, max: f32, n: bool| if n { (max, min) } else { (min, max) };
            let (nx, fx) = p(node.min_x[s], node.max_x[s], neg[0]);
            let (ny, fy) = p(node.min_y[s], node.max_y[s], neg[1]);
            let (nz, fz) = p(node.min_z[s], node.max_z[s], neg[2]);
            let (rc, on, rf, of) = (slab.rcp, slab.near_orcp, slab.far_rcp, slab.far_sub);
            let t_near = nx
                .mul_add(rc.x, -on.x)
                .max(ny.mul_add(rc.y, -on.y))
                .max(nz.mul_add(rc.z, -on.z))
                .max(r.t_near);
            let t_far = fx
                .mul_add(rf.x, -of.x)
                .min(fy.mul_add(rf.y, -of.y))
                .min(fz.mul_add(rf.z, -of.z))
                .min(slab.far_limit(t_max));
            if t_near <= t_far && node.child[s] != INVALID {
                stack.push((node.child[s], t_near));
            }
        }
        c.hist[(stack.len() - before).min(3)] += 1;
    }
}

fn main() -> Result<()> {
    let args = Args::parse();
    let (positions, triangles) = load_triangles(&format!("{}/scene.tri", args.dir))?;
    let t0 = std::time::Instant::now();
    let blas = build_blas(&positions, &triangles);
    let build_ms = t0.elapsed().as_secs_f64() * 1e3;
    let used: u64 = blas
        .blocks
        .iter()
        .map(|b| b.prim.iter().filter(|&&p| p != INVALID).count() as u64)
        .sum();
    println!(
        "{} triangles: {} nodes, {} blocks ({:.2} triangles per block), SAH {:.3}, build {build_ms:.0} ms",
        triangles.len(),
        blas.nodes.len(),
        blas.blocks.len(),
        used as f64 / blas.blocks.len().max(1) as f64,
        blas.sah_cost
    );
    let mut sizes = [0u32; 5];
    for node in blas.nodes.iter() {
        for &c in &node.child {
            if c != INVALID && c & LEAF_BIT != 0 {
                sizes[(((c & !LEAF_BIT) >> LEAF_COUNT_SHIFT) + 1) as usize] += 1;
            }
        }
    }
    println!("leaves with 1 / 2 / 3 / 4 blocks: {:?}", &sizes[1..]);
    for (kind, any) in [("primary", false), ("shadow", true), ("bounce", false)] {
        let rays = load_rays(&format!("{}/{kind}.rays", args.dir))?;
        let mut c = Counts::default();
        let mut cache = Cache::new(2 << 20, 16);
        // One pass to warm the cache, one counted.
        for r in &rays {
            walk(&blas.nodes, &blas.blocks, r, any, &mut c, &mut cache);
        }
        c = Counts::default();
        cache.misses = 0;
        for r in &rays {
            walk(&blas.nodes, &blas.blocks, r, any, &mut c, &mut cache);
        }
        let n = rays.len() as f64;
        println!(
            "{kind:8} per ray: nodes {:.2}, leaves {:.2}, blocks {:.2}, lanes {:.2}, L2-sim missed lines {:.2}",
            c.nodes as f64 / n,
            c.leaves as f64 / n,
            c.blocks as f64 / n,
            c.lanes as f64 / n,
            cache.misses as f64 / n
        );
        println!(
            "         node visits with 0 / 1 / 2 / 3+ hit children: {:.2} / {:.2} / {:.2} / {:.2}",
            c.hist[0] as f64 / n,
            c.hist[1] as f64 / n,
            c.hist[2] as f64 / n,
            c.hist[3] as f64 / n
        );
    }
    Ok(())
}
