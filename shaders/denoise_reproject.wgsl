// The denoiser's per-pixel reprojection (twin: engine/src/render/denoise/reproject.rs, the
// reference): where each pixel of this frame was in the previous one, and whether the history
// found there is the same surface. A pixel's guide point is its depth along its guide's ray
// (through the frame's jitter offset in the pixel: the centre for the guide pass); a point on
// an instance moves with the instance (its GpuMotion), then projects into the previous view;
// that motion applied to the pixel's centre finds where the pixel was (the history lives on
// pixel centres). The history is gathered bilinearly from the 2×2 previous pixels around that
// place, each tap kept only if it saw the same instance, a normal within NORMAL_COS and a plane
// through its own guide point within PLANE_TOLERANCE of this point; where none did, the taps
// whose surface still covers part of the pixel (mixed_tap, twin of reproject_edge.rs); a place
// within SNAP_PIXELS of a pixel centre takes that pixel alone. Nothing found, a specular
// pixel or a point off screen: length 0. Formulas and their order match the Rust twin (glam's
// Vec3 dot, normalize and Affine3A::transform_point3), so the two differ only by f32 rounding.
// Entry point denoise_reproject.
//
// Bindings besides the shared ones (0 uniforms, 1 guides: its xyz is the raw normal): 3 the
// reprojection uniforms; 4 this frame's and 6 the previous frame's ids (instance, specular,
// raw depth bits, 0); 5 the previous guides; 7 the previous history (illumination rows
// 0..n, moments rows n..2n); 8 the instances' motions; 9, 10 the reprojected history out.

@group(0) @binding(3) var<uniform> ru: GpuReprojectUniforms;
@group(0) @binding(4) var<storage, read> ids: array<vec4<u32>>;
@group(0) @binding(5) var<storage, read> prev_guides: array<vec4<f32>>;
@group(0) @binding(6) var<storage, read> prev_ids: array<vec4<u32>>;
@group(0) @binding(7) var<storage, read> prev_history: array<vec4<f32>>;
@group(0) @binding(8) var<storage, read> motions: array<GpuMotion>;
@group(0) @binding(9) var<storage, read_write> history: array<vec4<f32>>;
@group(0) @binding(10) var<storage, read_write> moments: array<vec4<f32>>;

const NORMAL_COS: f32 = 0.9;
const PLANE_TOLERANCE: f32 = 0.02;
const SNAP_PIXELS: f32 = 1e-2;
const NO_INSTANCE: u32 = 0xffffffffu;

// glam's Vec3::dot, in its order (no fused multiply-add asked for).
fn dot3(a: vec3<f32>, b: vec3<f32>) -> f32 {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

// Unit direction of pixel (x, y)'s guide in this frame (View::sample_direction).
fn sample_direction(x: u32, y: u32) -> vec3<f32> {
    let sx = 2.0 * (f32(x) + ru.jitter_x) / f32(du.width) - 1.0;
    let sy = 1.0 - 2.0 * (f32(y) + ru.jitter_y) / f32(du.height);
    let d = ru.camera_forward + ru.camera_right * sx + ru.camera_up * sy;
    return d * (1.0 / sqrt(dot3(d, d)));
}

// Unit direction of previous pixel (x, y)'s guide (View::sample_direction, previous view).
fn prev_sample_direction(x: u32, y: u32) -> vec3<f32> {
    let sx = 2.0 * (f32(x) + ru.prev_jitter_x) / f32(ru.prev_width) - 1.0;
    let sy = 1.0 - 2.0 * (f32(y) + ru.prev_jitter_y) / f32(ru.prev_height);
    let d = ru.prev_forward + ru.prev_right * sx + ru.prev_up * sy;
    return d * (1.0 / sqrt(dot3(d, d)));
}

// View::project_direction: image coordinates (pixels, centres at +0.5) of direction `d` in the
// view (forward, right, up, width, height) in xy, z 1 when it projects (in front of the
// camera, finite), else 0.
fn project(d: vec3<f32>, fw: vec3<f32>, rt: vec3<f32>, up: vec3<f32>, w: u32, h: u32) -> vec3<f32> {
    let f2 = dot3(fw, fw);
    let r2 = dot3(rt, rt);
    let u2 = dot3(up, up);
    if f2 <= 0.0 || r2 <= 0.0 || u2 <= 0.0 {
        return vec3<f32>(0.0);
    }
    let t = dot3(d, fw) / f2;
    if !(t > 0.0) {
        return vec3<f32>(0.0);
    }
    let sx = dot3(d, rt) / r2 / t;
    let sy = dot3(d, up) / u2 / t;
    let x = (sx + 1.0) * 0.5 * f32(w);
    let y = (1.0 - sy) * 0.5 * f32(h);
    if !(is_finite(x) && is_finite(y)) {
        return vec3<f32>(0.0);
    }
    return vec3<f32>(x, y, 1.0);
}

// In the previous view.
fn project_previous(d: vec3<f32>) -> vec3<f32> {
    return project(d, ru.prev_forward, ru.prev_right, ru.prev_up, ru.prev_width, ru.prev_height);
}

// In this frame's view.
fn project_current(d: vec3<f32>) -> vec3<f32> {
    return project(d, ru.camera_forward, ru.camera_right, ru.camera_up, du.width, du.height);
}

// Affine3A::transform_point3 by the rows `r`.
fn transform_rows(r: array<vec4<f32>, 3>, p: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(
        r[0].x * p.x + r[0].y * p.y + r[0].z * p.z + r[0].w,
        r[1].x * p.x + r[1].y * p.y + r[1].z * p.z + r[1].w,
        r[2].x * p.x + r[2].y * p.y + r[2].z * p.z + r[2].w,
    );
}

// Affine3A::transform_point3 by instance `k`'s motion (identity past the motions given).
fn moved_point(k: u32, p: vec3<f32>) -> vec3<f32> {
    if k >= ru.instances {
        return p;
    }
    return transform_rows(motions[k].prev_from_now, p);
}

// The same forward: where a point of instance `k` in the previous frame is now.
fn forward_point(k: u32, p: vec3<f32>) -> vec3<f32> {
    if k >= ru.instances {
        return p;
    }
    return transform_rows(motions[k].now_from_prev, p);
}

fn reset_pixel(i: u32) {
    history[i] = vec4<f32>(0.0);
    moments[i] = vec4<f32>(0.0);
}

// What this pixel saw (reproject.rs's Seen): sky, instance, normal, its guide point relative
// to the previous camera where it was then, and that point's distance.
struct Seen {
    sky: bool,
    instance: u32,
    normal: vec3<f32>,
    before: vec3<f32>,
    expected: f32,
}

// Whether previous pixel j saw the same surface as `seen` (reproject.rs's same_surface).
fn same_surface(j: u32, seen: Seen) -> bool {
    let other = prev_ids[j];
    if seen.sky {
        return other.x == NO_INSTANCE;
    }
    let n = prev_guides[j].xyz;
    if other.x != seen.instance || other.y != 0u || dot3(n, seen.normal) < NORMAL_COS {
        return false;
    }
    let tap = prev_sample_direction(j % ru.prev_width, j / ru.prev_width) * bitcast<f32>(other.z);
    return abs(dot3(n, seen.before - tap)) <= PLANE_TOLERANCE * seen.expected;
}

// Whether previous pixel j's surface still covers part of this frame's pixel (x, y)
// (reproject_edge.rs's mixed_tap): its guide point moved forward with its instance projects
// inside the pixel's square, and a pixel of the 3×3 neighbourhood sees that instance (or the
// sky) with its point within PLANE_TOLERANCE of the moved point's plane.
fn mixed_tap(j: u32, x: u32, y: u32) -> bool {
    let other = prev_ids[j];
    if other.y != 0u {
        return false;
    }
    let dir = prev_sample_direction(j % ru.prev_width, j / ru.prev_width);
    let instance = other.x;
    let depth = bitcast<f32>(other.z);
    let sky = instance == NO_INSTANCE || !(depth > 0.0);
    var now = dir;
    if !sky {
        let world = ru.prev_position + dir * depth;
        now = forward_point(instance, world) - ru.camera_position;
    }
    let q = project_current(now);
    if q.z == 0.0 {
        return false;
    }
    let px = f32(x);
    let py = f32(y);
    if !(q.x >= px && q.x < px + 1.0 && q.y >= py && q.y < py + 1.0) {
        return false;
    }
    let expected = sqrt(dot3(now, now));
    let y0 = select(y - 1u, 0u, y == 0u);
    let x0 = select(x - 1u, 0u, x == 0u);
    let y1 = min(y + 1u, du.height - 1u);
    let x1 = min(x + 1u, du.width - 1u);
    for (var ny = y0; ny <= y1; ny++) {
        for (var nx = x0; nx <= x1; nx++) {
            let k = ny * du.width + nx;
            let me = ids[k];
            if me.y != 0u {
                continue;
            }
            let d = bitcast<f32>(me.z);
            let other_sky = me.x == NO_INSTANCE || !(d > 0.0);
            if sky || other_sky {
                if sky && other_sky {
                    return true;
                }
                continue;
            }
            if me.x != instance {
                continue;
            }
            let point = sample_direction(nx, ny) * d;
            if abs(dot3(guides[k].xyz, now - point)) <= PLANE_TOLERANCE * expected {
                return true;
            }
        }
    }
    return false;
}

var<private> tap_x: array<f32, 4>;
var<private> tap_y: array<f32, 4>;
var<private> tap_w: array<f32, 4>;

// The taps' weighted history (reproject.rs's gather): the taps with history that saw the
// same surface, or with `edge` those whose surface still covers part of pixel (x, y)
// (mixed_tap). Writes pixel i; false when no tap was taken.
fn gather(i: u32, n: u32, seen: Seen, edge: bool, x: u32, y: u32) -> bool {
    var il = vec4<f32>(0.0);
    var mo = vec4<f32>(0.0);
    var weight = 0.0;
    var shortest = 3.40282347e38;
    for (var k = 0; k < 4; k++) {
        let wt = tap_w[k];
        if wt <= 0.0 || tap_x[k] < 0.0 || tap_y[k] < 0.0
            || tap_x[k] >= f32(ru.prev_width) || tap_y[k] >= f32(ru.prev_height) {
            continue;
        }
        let j = u32(tap_y[k]) * ru.prev_width + u32(tap_x[k]);
        let hist = prev_history[j];
        if hist.w <= 0.0 {
            continue;
        }
        var taken = false;
        if edge {
            taken = mixed_tap(j, x, y);
        } else {
            taken = same_surface(j, seen);
        }
        if !taken {
            continue;
        }
        il = il + hist * wt;
        mo = mo + prev_history[n + j] * wt;
        weight = weight + wt;
        shortest = min(shortest, hist.w);
    }
    if weight <= 0.0 {
        return false;
    }
    let mean = il / weight;
    history[i] = vec4<f32>(mean.xyz, shortest);
    moments[i] = mo / weight;
    return true;
}

@compute @workgroup_size(8, 8)
fn denoise_reproject(@builtin(global_invocation_id) id: vec3<u32>) {
    if id.x >= du.width || id.y >= du.height {
        return;
    }
    let i = id.y * du.width + id.x;
    let n = du.width * du.height;
    let me = ids[i];
    if me.y != 0u {
        reset_pixel(i);
        return;
    }
    let instance = me.x;
    let depth = bitcast<f32>(me.z);
    let normal = guides[i].xyz;
    let sky = instance == NO_INSTANCE || !(depth > 0.0);
    let dir = sample_direction(id.x, id.y);
    var before = dir;
    var expected = 0.0;
    if !sky {
        let world = ru.camera_position + dir * depth;
        before = moved_point(instance, world) - ru.prev_position;
        expected = sqrt(dot3(before, before));
    }
    let q = project_previous(before);
    if q.z == 0.0 {
        reset_pixel(i);
        return;
    }
    let seen = Seen(sky, instance, normal, before, expected);
    let fx = q.x - ru.jitter_x;
    let fy = q.y - ru.jitter_y;
    let x0 = floor(fx);
    let y0 = floor(fy);
    let ax = fx - x0;
    let ay = fy - y0;
    tap_x = array<f32, 4>(x0, x0 + 1.0, x0, x0 + 1.0);
    tap_y = array<f32, 4>(y0, y0, y0 + 1.0, y0 + 1.0);
    tap_w = array<f32, 4>((1.0 - ax) * (1.0 - ay), ax * (1.0 - ay), (1.0 - ax) * ay, ax * ay);
    if max(min(ax, 1.0 - ax), min(ay, 1.0 - ay)) < SNAP_PIXELS {
        // Rust's f32::round (half away from zero); a snapped point is never halfway.
        tap_x = array<f32, 4>(round(fx), 0.0, 0.0, 0.0);
        tap_y = array<f32, 4>(round(fy), 0.0, 0.0, 0.0);
        tap_w = array<f32, 4>(1.0, 0.0, 0.0, 0.0);
    }
    if !gather(i, n, seen, false, id.x, id.y) && !gather(i, n, seen, true, id.x, id.y) {
        reset_pixel(i);
    }
}
