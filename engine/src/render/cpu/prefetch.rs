//! Cache prefetch hints for the CPU integrator: start loading a record that a later step of the
//! same path will read (a texel row, a light-table entry), so that its cache miss overlaps
//! other work instead of stalling that step.
//!
//! Owns: [`line`], one hint per 64-byte line, and the light-table hints [`alias_pick`],
//! [`alias_second`]. Any thread; a hint never changes a result (a wrong
//! or stale address only wastes the load). Must not: read or write through the pointer.

use super::rng::Rng;
use crate::layout::{GpuFrameUniforms, METHOD_LIGHT_TREE, METHOD_LIGHTS_BY_POWER, METHOD_NEE};
use crate::scene::RenderScene;

/// Hints the CPU to load the cache line holding `*value` into every cache level. On x86-64 the
/// `prefetcht0` instruction (SSE, part of the x86-64 baseline, so no run-time detection is
/// needed); a no-op elsewhere.
#[inline(always)]
pub fn line<T>(value: &T) {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{_MM_HINT_T0, _mm_prefetch};
        // SAFETY: prefetching never faults and reads nothing the program can observe; the
        // pointer comes from a live reference.
        unsafe { _mm_prefetch::<_MM_HINT_T0>((value as *const T).cast::<i8>()) };
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = value;
}

/// The light-table entry the next event estimation at the coming hit picks first when lights
/// are picked by power from the alias table (the integrator's `next_event` draws `xi[0]`,
/// `xi[1]` as the next two numbers of `rng` after the hit; nothing draws in between), with
/// `xi[1]`; its line starts loading now, while the ray is traced. `None` (no hint) for the other
/// light-picking methods or no lights.
pub fn alias_pick(scene: &RenderScene, u: &GpuFrameUniforms, rng: &Rng) -> Option<(usize, f32)> {
    let alias = u.method & METHOD_NEE != 0 && u.method & METHOD_LIGHT_TREE == 0;
    if !alias || u.light_count == 0 {
        return None;
    }
    let mut peek = *rng;
    let (xi0, xi1) = (peek.next_f32(), peek.next_f32());
    let pick = ((xi0 * u.light_count as f32) as u32).min(u.light_count - 1) as usize;
    line(scene.lights.lights.get(pick)?);
    Some((pick, xi1))
}

/// After [`alias_pick`]'s entry has had the trace to load: starts loading the alias entry
/// the pick moves to (by power, when `xi1` is at or past the entry's threshold).
pub fn alias_second(scene: &RenderScene, u: &GpuFrameUniforms, pick: Option<(usize, f32)>) {
    let Some((pick, xi1)) = pick else {
        return;
    };
    let lights = &scene.lights.lights;
    if u.method & METHOD_LIGHTS_BY_POWER != 0
        && let Some(light) = lights.get(pick)
        && xi1 >= light.alias_threshold
        && let Some(other) = lights.get(light.alias_index as usize)
    {
        line(other);
    }
}
