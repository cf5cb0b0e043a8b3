//! CPU ray traversal over the flattened layout ([`crate::layout`]): the CPU path tracer and game
//! ray queries (lasers, picking, line of sight) both call it.
//!
//! Inputs: borrowed node / block / instance buffers ([`TraceScene`], or one BLAS) and a [`Ray`].
//! Outputs: the closest [`Hit`] or an occlusion flag. Any thread, read only, no allocation.
//! Must not: build or modify trees (see [`crate::accel`]).
//!
//! Files: [`ray`] (ray, hit, safe reciprocal, instance transform), `triangle` (the one
//! triangle test), `scalar` (reference traversal, the algorithm the WGSL twin follows), `scene`
//! (two-level queries and kernel choice), [`brute`] (brute-force reference for tests).

pub mod brute;
pub mod ray;
mod scalar;
mod scene;
pub mod triangle;

pub use ray::{Hit, Ray};
pub use scene::{TraceScene, closest_blas, closest_blas_with, occluded_blas, occluded_blas_with};

/// Entries of every traversal stack (node index + entry distance): enough for
/// [`crate::accel::MAX_DEPTH`] levels plus one 8-lane store.
pub(crate) const STACK_SIZE: usize = 256;
const _: () = assert!(7 * (crate::accel::MAX_DEPTH as usize - 1) + 8 + 8 <= STACK_SIZE);

/// A traversal implementation. All kernels return the same hits (bit-identical `t`, `u`, `v`;
/// where two triangles tie in `t` either may be returned).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kernel {
    /// One child at a time; every CPU.
    Scalar,
}

impl Kernel {
    /// The fastest kernel this CPU supports.
    pub fn best() -> Self {
        Self::Scalar
    }

    /// Every kernel this CPU supports, reference first.
    pub fn available() -> Vec<Self> {
        vec![Self::Scalar]
    }

    /// This kernel if this CPU supports it, else [`Kernel::Scalar`].
    fn checked(self) -> Self {
        self
    }
}
