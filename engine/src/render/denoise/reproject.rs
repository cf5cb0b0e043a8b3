//! Per-pixel reprojection of the denoiser's history (issue 13, part 2): where each pixel of
//! this frame was in the previous one, and whether the history found there is the same
//! surface.
//!
//! Owns: [`PrevFrame`] (what reprojection keeps of the previous frame: its view, guides and
//! the instances' transforms) and [`reproject`]. A pixel's guide point is its guide depth
//! along its guide's ray (through the pixel's [`View::jitter`] offset: the centre for the
//! guide pass, the frame's jitter for guides recorded at the tracer's first hits); a point on
//! an instance moves with the instance (previous world-from-object times this frame's
//! object-from-world), then projects into the previous view. That motion, applied to the
//! pixel's centre, finds where the pixel was: the history lives on pixel centres (each pixel's
//! history is the mean of the samples inside it). The history is gathered bilinearly from the
//! 2×2 previous pixels around that place, each tap kept only if it saw the same instance, a
//! normal within [`NORMAL_COS`] and a plane through its own guide point within
//! [`PLANE_TOLERANCE`] of this point. Where no tap saw this surface, the taps whose own
//! surface still covers part of the pixel are taken (`reproject_edge`: a pixel on an edge
//! whose jittered guide changed side keeps the mean of both sides). Nothing found, a specular
//! first hit (its
//! reflection moves differently from its surface) or a point off screen resets the pixel's
//! history (length 0). A place within [`SNAP_PIXELS`] of a pixel centre takes that pixel
//! alone, so a still camera over a still scene reprojects every pixel onto itself exactly and
//! converges as before. Positions are in the frame uniforms' space (camera-relative to the
//! scene origin; a moved origin is a cut). Render thread (rows on rayon's pool).
//! Must not: trace rays or blend (see `temporal`).

use glam::{Affine3A, Mat3A, Vec3, Vec3A, Vec4};
use rayon::prelude::*;

use super::guides::{Guides, NO_INSTANCE};
use super::planes::{Simd, dispatch};
use super::reproject_edge::mixed_tap;
use super::temporal::History;
use super::view::View;
use crate::layout::GpuInstance;

/// Smallest cosine between a pixel's normal and a history tap's normal (about 25°).
pub const NORMAL_COS: f32 = 0.9;
/// Largest distance of a pixel's point from a history tap's surface plane (through the tap's
/// point, along the tap's normal), relative to the point's distance from the previous camera.
/// A plane rather than a depth: a tap a pixel away on a floor seen at a grazing angle lies
/// much nearer or farther along its ray, but on the same plane.
pub const PLANE_TOLERANCE: f32 = 0.02;
/// A reprojected point this close to a pixel centre (in pixels) takes that pixel alone.
pub const SNAP_PIXELS: f32 = 1e-2;

/// An instance's world-from-object transform (its three packed rows), as [`PrevFrame`] and
/// [`reproject`] take them.
pub fn world_from_object(instance: &GpuInstance) -> Affine3A {
    let [r0, r1, r2] = instance.world_from_object;
    Affine3A {
        matrix3: Mat3A::from_cols(
            Vec3A::new(r0[0], r1[0], r2[0]),
            Vec3A::new(r0[1], r1[1], r2[1]),
            Vec3A::new(r0[2], r1[2], r2[2]),
        ),
        translation: Vec3A::new(r0[3], r1[3], r2[3]),
    }
}

/// Each instance's motion since the previous frame: its previous world-from-object times this
/// frame's object-from-world (a point on it now, in world space, to where it was), by instance
/// index; identity for an instance the previous frame did not have. The GPU twin uploads these.
pub fn motions(before: &[Affine3A], now: &[Affine3A]) -> Vec<Affine3A> {
    now.iter()
        .enumerate()
        .map(|(k, now)| match before.get(k) {
            Some(before) => *before * now.inverse(),
            None => Affine3A::IDENTITY,
        })
        .collect()
}

/// What reprojection keeps of the previous frame.
#[derive(Clone, Debug)]
pub struct PrevFrame {
    pub view: View,
    pub guides: Guides,
    /// World-from-object of every instance, by instance index (the guides' ids).
    pub world_from_object: Vec<Affine3A>,
}

/// How many pixels kept their history.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ReprojectStats {
    pub kept: usize,
    pub reset: usize,
}

/// The history of `prev` moved onto this frame's pixels (`guides`, `view`,
/// `world_from_object` of this frame). Pixels without a matching history get length 0.
pub fn reproject(
    history: &History,
    prev: &PrevFrame,
    guides: &Guides,
    view: &View,
    world_from_object: &[Affine3A],
) -> (History, ReprojectStats) {
    let mut out = History::default();
    let mut points = Vec::new();
    let frame = (prev, guides, view, world_from_object);
    let stats = reproject_into(history, frame, &mut out, &mut points);
    (out, stats)
}

/// [`reproject`] into `out` (resized; every pixel written), with `points` as scratch: the
/// denoiser keeps both between frames, so a frame allocates nothing here (fresh allocations
/// of a few MB a frame were page faults on the render thread's serial path).
pub fn reproject_into(
    history: &History,
    (prev, guides, view, world_from_object): (&PrevFrame, &Guides, &View, &[Affine3A]),
    out: &mut History,
    points: &mut Vec<Vec3>,
) -> ReprojectStats {
    let (w, h) = (guides.width, guides.height);
    let n = w as usize * h as usize;
    out.width = w;
    out.height = h;
    if history.width != prev.view.width
        || history.height != prev.view.height
        || !prev.guides.is_consistent()
        || prev.guides.width != prev.view.width
        || prev.guides.height != prev.view.height
        || w == 0
        || h == 0
    {
        *out = History::new(w, h);
        return ReprojectStats { kept: 0, reset: n };
    }
    // Every pixel is written below: only the sizes are set here.
    out.illumination.resize(n, Vec4::ZERO);
    out.moments.resize(n, Vec4::ZERO);
    // Each instance's motion, once per frame rather than once per pixel, both ways.
    let moved = motions(&prev.world_from_object, world_from_object);
    let forward: Vec<Affine3A> = moved.iter().map(|m| m.inverse()).collect();
    // Every previous pixel's guide point relative to the previous camera, once per frame
    // rather than once per tap (the same arithmetic, so the same bits).
    let pw = prev.view.width as usize;
    points.resize(prev.guides.depth.len(), Vec3::ZERO);
    (points.par_iter_mut().zip(prev.guides.depth.par_iter()))
        .enumerate()
        .for_each(|(j, (p, &depth))| {
            *p = prev.view.sample_direction((j % pw) as u32, (j / pw) as u32) * depth;
        });
    let with_albedo = history.albedo.len() == history.illumination.len()
        && history.normal_depth.len() == history.illumination.len();
    let frame = Frame {
        history,
        prev,
        guides,
        view,
        moved: &moved,
        forward: &forward,
        points,
        with_albedo,
    };
    let row = w as usize;
    let simd = Simd::detect();
    let rows = out
        .illumination
        .par_chunks_mut(row)
        .zip(out.moments.par_chunks_mut(row));
    let kept: usize = if with_albedo {
        out.albedo.resize(n, Vec4::ONE);
        out.normal_depth.resize(n, Vec4::ZERO);
        let extra = out
            .albedo
            .par_chunks_mut(row)
            .zip(out.normal_depth.par_chunks_mut(row));
        rows.zip(extra)
            .enumerate()
            .map(|(y, ((il, mo), (al, nd)))| {
                row_simd(simd, &frame, y as u32, il, mo, Some((al, nd)))
            })
            .sum()
    } else {
        out.albedo.clear();
        out.normal_depth.clear();
        rows.enumerate()
            .map(|(y, (il, mo))| row_simd(simd, &frame, y as u32, il, mo, None))
            .sum()
    };
    ReprojectStats {
        kept,
        reset: n - kept,
    }
}

/// One frame's reprojection inputs, shared by its rows.
struct Frame<'a> {
    history: &'a History,
    prev: &'a PrevFrame,
    guides: &'a Guides,
    view: &'a View,
    /// Each instance's motion from this frame back to the previous one, and forward.
    moved: &'a [Affine3A],
    forward: &'a [Affine3A],
    /// Each previous pixel's guide point, relative to the previous camera (metres).
    points: &'a [Vec3],
    /// The history keeps an albedo and normal/depth too.
    with_albedo: bool,
}

/// Row `y` of the reprojected history into `il`, `mo` (and the albedo and normal/depth planes
/// when kept); returns how many of its pixels kept a history. Compiled at the CPU's vector
/// width (`planes::dispatch`): the same arithmetic, with the rounding instructions inline.
fn row_simd(
    simd: Simd,
    frame: &Frame<'_>,
    y: u32,
    il: &mut [Vec4],
    mo: &mut [Vec4],
    extra: Option<(&mut [Vec4], &mut [Vec4])>,
) -> usize {
    let mut kept = 0;
    row_kept(simd, frame, y, il, mo, extra, &mut kept);
    kept
}

dispatch!(
    /// [`row`] at the CPU's vector width.
    fn row_kept => row(
        frame: &Frame<'_>,
        y: u32,
        il: &mut [Vec4],
        mo: &mut [Vec4],
        extra: Option<(&mut [Vec4], &mut [Vec4])>,
        kept: &mut usize,
    )
);

/// [`row_simd`]'s body; adds the row's kept pixels to `kept`.
#[inline(always)]
fn row(
    frame: &Frame<'_>,
    y: u32,
    il: &mut [Vec4],
    mo: &mut [Vec4],
    mut extra: Option<(&mut [Vec4], &mut [Vec4])>,
    kept: &mut usize,
) {
    let w = frame.guides.width;
    for x in 0..w {
        let i = y as usize * w as usize + x as usize;
        let (h, m, a, nd) = pixel(frame, (x, y), i);
        *kept += usize::from(h.w > 0.0);
        il[x as usize] = h;
        mo[x as usize] = m;
        if let Some((al, nds)) = extra.as_mut() {
            al[x as usize] = a;
            nds[x as usize] = nd;
        }
    }
}

/// A pixel's gathered (illumination with length, moments, albedo); length 0 when nothing
/// matched (the albedo is 1 when the history keeps none).
type Gathered = (Vec4, Vec4, Vec4, Vec4);

/// What a pixel saw, as the previous frame's taps are tested against it.
struct Seen {
    sky: bool,
    instance: u32,
    normal: Vec3,
    /// The guide point relative to the previous camera, where it was then (metres).
    before: Vec3,
    /// Its distance from the previous camera (metres; 0 for the sky).
    expected: f32,
}

/// Whether the previous frame's pixel `j` (its guide point `points[j]`, relative to the
/// previous camera) saw the same surface as `seen`.
#[inline(always)]
fn same_surface(prev: &PrevFrame, points: &[Vec3], j: usize, seen: &Seen) -> bool {
    let g = &prev.guides;
    if seen.sky {
        return g.instance[j] == NO_INSTANCE;
    }
    if g.instance[j] != seen.instance || g.specular[j] || g.normal[j].dot(seen.normal) < NORMAL_COS
    {
        return false;
    }
    g.normal[j].dot(seen.before - points[j]).abs() <= PLANE_TOLERANCE * seen.expected
}

/// One pixel's [`Gathered`] history: the taps that saw its surface, else the taps whose
/// surface still covers part of it (`reproject_edge`), else none.
#[inline(always)]
fn pixel(frame: &Frame, (x, y): (u32, u32), i: usize) -> Gathered {
    let Frame {
        prev,
        guides,
        view,
        moved,
        ..
    } = *frame;
    let none = (Vec4::ZERO, Vec4::ZERO, Vec4::ONE, Vec4::ZERO);
    if guides.specular.get(i).copied().unwrap_or(true) {
        return none;
    }
    let (instance, depth, normal) = (guides.instance[i], guides.depth[i], guides.normal[i]);
    let sky = instance == NO_INSTANCE || !(depth > 0.0);
    let dir = view.sample_direction(x, y);
    // Where the point was, and the direction and distance it had from the previous camera.
    let (before, expected) = if sky {
        (dir, 0.0)
    } else {
        let world = view.position + dir * depth;
        let moved = moved
            .get(instance as usize)
            .copied()
            .unwrap_or(Affine3A::IDENTITY);
        let before = moved.transform_point3(world) - prev.view.position;
        (before, before.length())
    };
    let Some((qx, qy)) = prev.view.project_direction(before) else {
        return none;
    };
    let seen = Seen {
        sky,
        instance,
        normal,
        before,
        expected,
    };
    // The guide point's motion moves the pixel's centre: (x + 0.5, y + 0.5) + (q − (x, y) −
    // jitter), whose previous pixel index coordinates are q − jitter.
    let (fx, fy) = (qx - view.jitter.0, qy - view.jitter.1);
    let (x0, y0) = (fx.floor(), fy.floor());
    let (ax, ay) = (fx - x0, fy - y0);
    let taps: [(f32, f32, f32); 4] = if (ax.min(1.0 - ax)).max(ay.min(1.0 - ay)) < SNAP_PIXELS {
        [
            (fx.round(), fy.round(), 1.0),
            (0.0, 0.0, 0.0),
            (0.0, 0.0, 0.0),
            (0.0, 0.0, 0.0),
        ]
    } else {
        [
            (x0, y0, (1.0 - ax) * (1.0 - ay)),
            (x0 + 1.0, y0, ax * (1.0 - ay)),
            (x0, y0 + 1.0, (1.0 - ax) * ay),
            (x0 + 1.0, y0 + 1.0, ax * ay),
        ]
    };
    gather(frame, &seen, &taps, (x, y), false)
        .or_else(|| gather(frame, &seen, &taps, (x, y), true))
        .unwrap_or(none)
}

/// The history gathered from the `taps` (previous pixel coordinates and bilinear weight) that
/// saw `seen`'s surface, or (`edge`) whose surface still covers part of pixel (x, y);
/// `None` when no tap counts.
#[inline(always)]
fn gather(
    frame: &Frame,
    seen: &Seen,
    taps: &[(f32, f32, f32); 4],
    (x, y): (u32, u32),
    edge: bool,
) -> Option<Gathered> {
    let Frame {
        history,
        prev,
        guides,
        view,
        forward,
        points,
        with_albedo,
        ..
    } = *frame;
    let inside = |tx: f32, ty: f32| {
        tx >= 0.0 && ty >= 0.0 && tx < prev.view.width as f32 && ty < prev.view.height as f32
    };
    let (mut il, mut mo, mut al, mut nd, mut weight, mut length) = (
        Vec4::ZERO,
        Vec4::ZERO,
        Vec4::ZERO,
        Vec4::ZERO,
        0.0f32,
        f32::MAX,
    );
    for &(tx, ty, wt) in taps {
        if wt <= 0.0 || !inside(tx, ty) {
            continue;
        }
        let j = ty as usize * prev.view.width as usize + tx as usize;
        let hist = history.illumination[j];
        if hist.w <= 0.0 {
            continue;
        }
        let taken = match edge {
            false => same_surface(prev, points, j, seen),
            true => mixed_tap(prev, j, guides, view, forward, (x, y)),
        };
        if !taken {
            continue;
        }
        il += hist * wt;
        mo += history.moments[j] * wt;
        if with_albedo {
            al += history.albedo[j] * wt;
            nd += history.normal_depth[j] * wt;
        }
        weight += wt;
        length = length.min(hist.w);
    }
    let (albedo, nd) = match with_albedo {
        true => (al / weight, nd / weight),
        false => (Vec4::ONE, Vec4::ZERO),
    };
    (weight > 0.0).then(|| {
        (
            (il / weight).truncate().extend(length),
            mo / weight,
            albedo,
            nd,
        )
    })
}
