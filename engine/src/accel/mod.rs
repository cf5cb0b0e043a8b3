//! Acceleration structures: BLAS per mesh, TLAS over instances, in the 8-wide layout of
//! [`crate::layout::GpuBvh8Node`] / [`crate::layout::GpuTri4`] that both tracers read.
//!
//! Inputs: mesh positions and triangles (BLAS), instance bounds (TLAS). Outputs: node and block
//! vectors whose indices are relative to their own first element; the caller concatenates them
//! into the frame's buffers. Main thread; no shared state. Must not: trace rays (see
//! [`crate::trace`]) or know about materials and lights.
//!
//! Phases (one file each): `bounds` (the box type), `bvh2` (binary build: obvhs PLOC presets
//! or the balanced fallback) and `binned` (our binned SAH build, the default), `collapse`
//! (SAH-optimal 8-wide collapse), `octant_order` (the per-octant child orders), `blas` (triangle blocks),
//! `tlas` (instances).
//!
//! # Why this layout and this build (measured)
//!
//! Machine: 2 vCPU KVM guest, Intel Xeon with AVX-512 (48 KiB L1d and 2 MiB L2 per core),
//! Debian 12, rustc 1.95; scenes and rays of the peer benchmark (`shared/peers`, 640×360, seed 1);
//! Mrays/s on one thread, medians of 3 measurements of ≥ 200 ms, all three layouts in one process
//! (`cargo run --release -p peer_bench --bin layout_compare -- DIR`), 2026-11-22:
//!
//! | scene (triangles) | kind | obvhs BVH2 | obvhs CWBVH | 8-wide SoA (this) |
//! |---|---|---:|---:|---:|
//! | bunny (3,674) | primary / shadow / bounce | 10.6 / 5.8 / 4.0 | 9.6 / 5.3 / 3.9 | 22.2 / 13.0 / 10.3 |
//! | dragon (202,520) | primary / shadow / bounce | 5.9 / 2.4 / 1.5 | 5.2 / 2.7 / 1.6 | 12.4 / 6.3 / 4.6 |
//! | cornell (9,048) | primary / shadow / bounce | 20.9 / 15.1 / 7.8 | 21.6 / 22.5 / 10.2 | 32.6 / 41.3 / 16.1 |
//!
//! obvhs's layouts traverse one ray with 4-wide (CWBVH) or 2-wide tests and call back per
//! triangle; the SoA node tests all eight children in one AVX-512 pass and a `GpuTri4` block
//! tests four triangles at once, so it is 1.5–2.9× faster on every row. (obvhs's CWBVH stays the
//! better GPU format on paper: 80-byte nodes. On the GPU we traverse the same 8-wide layout.)
//!
//! Binary build, by preset (build time on one thread, SAH cost of the collapsed tree with
//! `BLAS_NODE_COST = BLAS_LEAF_COST = 1`, dragon traversal Mrays/s on one thread):
//!
//! | preset | dragon build ms | 1M-triangle build ms | dragon SAH | dragon primary / shadow / bounce |
//! |---|---:|---:|---:|---:|
//! | PLOC fastest | 88 | 447 | 17.3 | 10.9 / 5.6 / 4.0 |
//! | PLOC fast | 110 | 520 | 15.8 | 11.8 / 5.9 / 4.4 |
//! | PLOC medium | 146 | 816–936 | 15.6 | 11.5 / 5.8 / 4.2 |
//! | PLOC slow (pre-splits) | 375 | 2651 | 15.0 | 10.9 / 5.7 / 4.0 |
//! | PLOC very slow | 1104 | 7532 | 14.5 | 11.6 / 6.0 / 4.4 |
//! | **binned SAH (ours)** | **140** | **738–768** | **14.4** | **12.8 / 6.3 / 4.6** |
//!
//! The binned top-down build gives the lowest SAH cost and the fastest traversal at the build
//! time of PLOC medium, so it is the default ([`BuildQuality::BinnedSah`]). On bunny and cornell
//! all presets trace within ±5 % of each other. The TLAS (rebuilt every frame) uses the binned
//! SAH build up to 2,048 instances (3 % faster traversal in Reflect's chamber 1; `tlas.rs`) and
//! PLOC very fast above: 2.7 ms for 10,000 instances, 43 ms for 100,000 (the collapse is most
//! of it).
//!
//! Leaves hold up to four consecutive triangle blocks ([`BlasParams`]: block cost 0.25 of a
//! node visit, SAH counted in whole blocks) and the SIMD kernels test two blocks per 8-lane
//! pass, from 2 MiB-aligned huge-page buffers (`trace::TraceBuffer`). Against one block per
//! leaf with the 4-lane kernel (commit 30fffc0), dragon, one thread, process CPU time, three
//! interleaved runs of `engine_bench --cpu-time` (2026-11-22): primary 13.2–13.4 vs 11.9–12.0,
//! shadow 6.4–6.6 vs 5.8–5.9, bounce 4.6–4.9 vs 4.0–4.2 Mrays/s (+11 to +15 %). The watertight
//! triangle test (`trace/triangle.rs`) then cost, same method: primary −1 %, shadow −5 %,
//! bounce −10 % (medians 15.35 / 7.33 / 5.50 before, 15.20 / 6.96 / 4.94 after).

mod binned;
pub(crate) mod blas;
mod flatten;

mod bvh2;
mod collapse;
mod octant_order;
pub mod origin;
pub(crate) mod refit;
pub(crate) mod tlas;
mod upkeep;
mod upkeep_deform;
mod upkeep_instances;
mod upkeep_lights;
mod upkeep_materials;
mod upkeep_report;

pub use crate::scene::Aabb;
pub use blas::{Blas, BlasParams, build_blas, build_blas_with, build_blas_with_params};
pub use bvh2::BuildQuality;
pub use refit::{
    Refit, rebuild_bound, refit_blas, refit_blas_measured, sah_cost, triangle_area_ratio,
};
pub use tlas::build_tlas;
pub use upkeep::{REBUILD_RATIO, Upkeep, UpkeepStats};
pub use upkeep_report::MeshCost;

pub use crate::trace::MAX_DEPTH;
