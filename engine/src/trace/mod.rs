//! CPU ray traversal over the flattened layout ([`crate::layout`]): the CPU path tracer and game
//! ray queries (lasers, picking, line of sight) both call it.
//!
//! Inputs: borrowed node / block / instance buffers ([`TraceScene`], or one BLAS) and a [`Ray`].
//! Outputs: the closest [`Hit`] or an occlusion flag. Any thread, read only, no allocation.
//! Must not: build or modify trees (`accel` does; it sits above this module and builds within
//! [`MAX_DEPTH`]).
//!
//! Files: [`ray`] (ray, hit, safe reciprocal, instance transform), `triangle` (the one
//! triangle test), `scalar` (reference traversal, the algorithm the WGSL twin follows), `scene`
//! (two-level queries and kernel choice), `simd` + `simd_block` + `simd_lanes` + `x86` (AVX2 /
//! AVX-512 kernels, x86-64 only), `buffer` ([`TraceBuffer`], the huge-page storage of nodes and
//! blocks), [`brute`] (brute-force reference for tests).
//!
//! # Speed (peer benchmark, `shared/peers`, this machine: 2 vCPU Intel Xeon with AVX-512)
//!
//! Single-ray Mrays/s, median of 3 rounds of `run_rounds.sh` with Embree 3.13.5 in the same
//! rounds (`tools/peer_bench`, `engine_bench`), 1 thread; ratio to Embree's `rtcIntersect1` /
//! `rtcOccluded1`: bunny 1.06 / 1.06 / 1.06 (primary / shadow / bounce), cornell 1.17 / 1.69 /
//! 1.07, dragon 0.94 / 0.93 / 0.94 (2 threads: bunny 1.16 / 1.11 / 1.09, cornell 1.21 / 1.70 /
//! 1.08, dragon 0.92 / 1.01 / 0.96). The dragon (202k triangles: 3.4 MB of nodes and 11.4 MB of
//! blocks against a 2 MiB L2) is bound by memory latency: in a profile the first load of each
//! triangle block and of each node's planes take about a quarter of the samples. What helped
//! (prefetching each node's child-index line, +7 % on dragon bounce rays) and what did not
//! (exact distance order for two hits, prefetching pushed or next-popped entries, BFS node
//! order, per-octant kernel copies: +3–8 % coherent, −5 % bounce) is measured in the commits.
//! Hit counts equal Embree's on bunny and dragon and on cornell primary rays.

pub mod brute;
mod buffer;
pub mod ray;
mod scalar;
mod scene;
#[cfg(target_arch = "x86_64")]
mod simd;
#[cfg(target_arch = "x86_64")]
mod simd_block;
#[cfg(target_arch = "x86_64")]
mod simd_lanes;
pub mod triangle;
#[cfg(target_arch = "x86_64")]
mod x86;

pub use buffer::{HUGE_MIN_BYTES, TraceBuffer};
pub use ray::{Hit, Ray};
pub(crate) use scalar::leaf_blocks;
pub use scene::{TraceScene, closest_blas, closest_blas_with, occluded_blas, occluded_blas_with};

/// Deepest tree (levels of 8-wide nodes) the builders emit and the tracers' fixed stacks hold.
/// A traversal pushes at most 7 entries per level plus 8 at the deepest node, so
/// `7 · (MAX_DEPTH - 1) + 8` entries (239) fit the 256-entry stacks of the traversal kernels with
/// room for one 8-lane vector store. Builds that would be deeper fall back to a balanced
/// binary tree, whose depth is at most `log2(primitives) + 1` (at most 33 for `u32` counts).
pub const MAX_DEPTH: u32 = 34;

/// Entries of every traversal stack (node index + entry distance): enough for
/// [`MAX_DEPTH`] levels plus one 8-lane store.
pub(crate) const STACK_SIZE: usize = 256;
const _: () = assert!(7 * (MAX_DEPTH as usize - 1) + 8 + 8 <= STACK_SIZE);

/// A traversal implementation. All kernels return the same hits (bit-identical `t`, `u`, `v`;
/// where two triangles tie in `t` either may be returned).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kernel {
    /// One child at a time; every CPU.
    Scalar,
    /// 8-lane node test with AVX2 (x86-64 with AVX2, FMA, POPCNT, BMI1).
    Avx2,
    /// 8-lane node test with AVX-512 mask compares and compress (x86-64 with AVX-512
    /// F/VL/BW/DQ, AVX2, FMA, POPCNT, BMI1).
    Avx512,
}

impl Kernel {
    /// The fastest kernel this CPU supports (detected once).
    pub fn best() -> Self {
        static BEST: std::sync::OnceLock<Kernel> = std::sync::OnceLock::new();
        *BEST.get_or_init(|| {
            [Self::Avx512, Self::Avx2]
                .into_iter()
                .find(|k| k.supported())
                .unwrap_or(Self::Scalar)
        })
    }

    /// Every kernel this CPU supports, reference first.
    pub fn available() -> Vec<Self> {
        [Self::Scalar, Self::Avx2, Self::Avx512]
            .into_iter()
            .filter(|k| k.supported())
            .collect()
    }

    /// Whether this CPU can run the kernel (feature detection is cached by `std`).
    pub fn supported(self) -> bool {
        match self {
            Self::Scalar => true,
            #[cfg(target_arch = "x86_64")]
            Self::Avx2 => {
                std::arch::is_x86_feature_detected!("avx2")
                    && std::arch::is_x86_feature_detected!("fma")
                    && std::arch::is_x86_feature_detected!("popcnt")
                    && std::arch::is_x86_feature_detected!("bmi1")
            }
            #[cfg(target_arch = "x86_64")]
            Self::Avx512 => {
                Self::Avx2.supported()
                    && std::arch::is_x86_feature_detected!("avx512f")
                    && std::arch::is_x86_feature_detected!("avx512vl")
                    && std::arch::is_x86_feature_detected!("avx512bw")
                    && std::arch::is_x86_feature_detected!("avx512dq")
            }
            #[cfg(not(target_arch = "x86_64"))]
            Self::Avx2 | Self::Avx512 => false,
        }
    }

    /// This kernel if this CPU supports it, else [`Kernel::Scalar`]. The SIMD entry points
    /// may only be called with a kernel returned from here.
    fn checked(self) -> Self {
        if self == Self::Scalar || self == Self::best() || self.supported() {
            self
        } else {
            Self::Scalar
        }
    }
}
