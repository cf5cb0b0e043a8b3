//! The denoiser's reprojection with guides taken at a jittered offset in each pixel (the CPU
//! tracer's first hits under the frame's jitter, `render::denoise::reproject`): a still view
//! keeps every pixel's history exactly whatever the two frames' offsets, a floor seen at a
//! grazing angle keeps it under a sub-pixel move (a plane test: the taps' depths along their
//! own rays differ by more than the old 5 % depth test allowed), and a surface the previous
//! frame did not see restarts while the one beside it keeps its history (but for the pixels on
//! the edge between them that the floor still covers in part: `reproject_edge`).

use candela::render::denoise::{Guides, History, PrevFrame, View, reproject};
use glam::{Affine3A, Vec3, Vec4};

const W: u32 = 48;
const H: u32 = 32;

/// A camera at the origin looking down −Z and 15° down, its guides at `jitter`.
fn view(jitter: (f32, f32)) -> View {
    let pitch = (-15.0f32).to_radians();
    let forward = Vec3::new(0.0, pitch.sin(), -pitch.cos());
    let right = Vec3::X * 0.5;
    let up = right.cross(forward).normalize() * (0.5 * H as f32 / W as f32) * -1.0;
    View {
        position: Vec3::ZERO,
        forward,
        right,
        up: if up.y < 0.0 { -up } else { up },
        width: W,
        height: H,
        jitter,
    }
}

/// The guides of a floor at y = −1 (instance 0) under the sky, each pixel's along its sample
/// direction; instance `wall` (x ≥ `edge_x`, a vertical wall face at x = `edge_x` seen edge on
/// is not needed: pixels whose floor point has x ≥ edge_x) where given.
fn floor_guides(view: &View, split: Option<(f32, u32)>) -> Guides {
    let mut g = Guides::sky(view.width, view.height);
    for y in 0..view.height {
        for x in 0..view.width {
            let i = (y * view.width + x) as usize;
            let d = view.sample_direction(x, y);
            if d.y >= -1e-3 {
                continue;
            }
            let t = -1.0 / d.y;
            let p = d * t;
            g.normal[i] = Vec3::Y;
            g.depth[i] = t;
            g.albedo[i] = Vec3::ONE;
            g.instance[i] = match split {
                Some((edge_x, other)) if p.x >= edge_x => other,
                _ => 0,
            };
        }
    }
    g
}

/// A history whose illumination is each pixel's index (length 4).
fn indexed_history() -> History {
    let mut h = History::new(W, H);
    for (i, v) in h.illumination.iter_mut().enumerate() {
        *v = Vec4::new(i as f32, 0.0, 0.0, 4.0);
    }
    h
}

fn prev_frame(view: View, guides: Guides) -> PrevFrame {
    PrevFrame {
        view,
        guides,
        world_from_object: vec![Affine3A::IDENTITY; 3],
    }
}

#[test]
fn a_still_view_keeps_every_history_exactly_whatever_the_offsets() {
    let (before, now) = (view((0.1, 0.85)), view((0.8, 0.3)));
    let (g0, g1) = (floor_guides(&before, None), floor_guides(&now, None));
    // The two frames' guides of one pixel are different points of the floor: at this grazing
    // angle many lie farther apart along the view than the old 5 % depth test allowed.
    let far = (0..g0.len())
        .filter(|&i| g0.depth[i] > 0.0 && g1.depth[i] > 0.0)
        .filter(|&i| (g0.depth[i] - g1.depth[i]).abs() > 0.05 * g1.depth[i])
        .count();
    assert!(far > 20, "only {far} pixels differ by > 5 % in depth");
    let history = indexed_history();
    let (moved, stats) = reproject(&history, &prev_frame(before, g0), &g1, &now, &[]);
    assert_eq!(stats.reset, 0, "a still view keeps every pixel");
    assert_eq!(
        moved.illumination, history.illumination,
        "each pixel its own history"
    );
}

#[test]
fn a_grazing_floor_keeps_its_history_under_a_sub_pixel_move() {
    let before = view((0.5, 0.5));
    let mut now = view((0.3, 0.6));
    now.position = Vec3::new(0.004, 0.0, -0.01);
    let (g0, g1) = (floor_guides(&before, None), floor_guides(&now, None));
    let history = indexed_history();
    let (moved, _) = reproject(&history, &prev_frame(before, g0), &g1, &now, &[]);
    // Away from the image's border and the horizon every floor pixel keeps its history.
    let mut checked = 0;
    for y in 2..H - 1 {
        for x in 1..W - 1 {
            let i = (y * W + x) as usize;
            let horizon = (y.saturating_sub(2)..=y + 1).any(|yy| {
                g1.depth
                    .get((yy * W + x) as usize)
                    .is_none_or(|d| *d <= 0.0)
            });
            if horizon {
                continue;
            }
            checked += 1;
            assert_eq!(
                moved.illumination[i].w, 4.0,
                "floor pixel ({x}, {y}) restarted"
            );
        }
    }
    assert!(checked > 500, "{checked} floor pixels checked");
}

#[test]
fn a_new_surface_restarts_and_the_one_beside_it_keeps_its_history() {
    let (before, now) = (view((0.2, 0.5)), view((0.8, 0.5)));
    let history = indexed_history();
    let g0 = floor_guides(&before, Some((0.013, 1)));
    // The right part is now a surface (instance 2) the previous frame never saw.
    let g_new = floor_guides(&now, Some((0.013, 2)));
    let (moved, _) = reproject(&history, &prev_frame(before, g0.clone()), &g_new, &now, &[]);
    let new: Vec<usize> = (0..g_new.len())
        .filter(|&i| g_new.instance[i] == 2)
        .collect();
    assert!(new.len() > 100);
    // A pixel on the edge whose guide saw the floor a frame ago (the offsets differ) is a mixed
    // pixel: the floor still covers part of it, so it keeps the floor's history, its own
    // (`reproject_edge`). Every other pixel of the new surface restarts.
    let mut edge = 0;
    for &i in &new {
        let h = moved.illumination[i];
        if g0.instance[i] == 0 && h.w > 0.0 {
            assert_eq!(
                h, history.illumination[i],
                "edge pixel {i}: not its own history"
            );
            edge += 1;
            continue;
        }
        assert_eq!(h.w, 0.0, "pixel {i} of a new surface kept history");
    }
    assert!(
        edge <= H as usize && new.len() - edge > 100,
        "{edge} edge pixels of {} kept the floor's history",
        new.len()
    );
    let old: Vec<usize> = (0..g_new.len())
        .filter(|&i| g_new.instance[i] == 0 && g_new.depth[i] > 0.0)
        .collect();
    assert!(old.len() > 100);
    for &i in &old {
        assert_eq!(
            moved.illumination[i].w, 4.0,
            "pixel {i} of the floor restarted"
        );
    }
}

/// A still view over an edge between two surfaces: where the two frames' offsets put a pixel's
/// guide on different sides, the pixel keeps its own history (the edge rule,
/// `reproject_edge`) instead of restarting each time the jitter changes side. Without the rule
/// every such pixel restarted, and a still view with jittered guides shimmered along every
/// edge (`docs/ACCURACY.md`).
#[test]
fn an_edge_pixel_whose_guide_changed_side_keeps_its_history() {
    let (before, now) = (view((0.2, 0.5)), view((0.8, 0.5)));
    let g0 = floor_guides(&before, Some((0.013, 1)));
    let g1 = floor_guides(&now, Some((0.013, 1)));
    let history = indexed_history();
    let (moved, stats) = reproject(&history, &prev_frame(before, g0.clone()), &g1, &now, &[]);
    let changed: Vec<usize> = (0..g1.len())
        .filter(|&i| g0.depth[i] > 0.0 && g1.depth[i] > 0.0 && g0.instance[i] != g1.instance[i])
        .collect();
    assert!(changed.len() >= 5, "{} pixels changed side", changed.len());
    for &i in &changed {
        assert_eq!(
            moved.illumination[i], history.illumination[i],
            "edge pixel {i} did not keep its own history"
        );
    }
    assert_eq!(stats.reset, 0, "a still view keeps every pixel");
}
