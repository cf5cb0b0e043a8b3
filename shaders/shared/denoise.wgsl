// The per-pixel arithmetic every SVGF pass shares (twin: engine/src/render/denoise/weights.rs):
// safe guide reads, demodulation, luminance, the depth gradient and the edge-stopping weight.
// Every pass binds the uniforms, the guides (normal xyz, depth w; 0 = sky) and the albedo here.
// Formulas and their order match the Rust twin so that the two differ only by f32 rounding.

@group(0) @binding(0) var<uniform> du: GpuDenoiseUniforms;
@group(0) @binding(1) var<storage, read> guides: array<vec4<f32>>;
@group(0) @binding(2) var<storage, read> albedo: array<vec4<f32>>;

const ALBEDO_MIN: f32 = 1e-3;
const MIN_TEMPORAL_FRAMES: f32 = 4.0;
const DEPTH_EPS_REL: f32 = 1e-2;
const LUMINANCE_EPS: f32 = 1e-10;
const NORMAL_SQUARINGS: u32 = 7u;

// WGSL has no isnan/isinf: an exponent of all ones is inf or NaN.
fn is_finite(x: f32) -> bool {
    return (bitcast<u32>(x) & 0x7f800000u) != 0x7f800000u;
}

fn finite3(c: vec3<f32>) -> bool {
    return is_finite(c.x) && is_finite(c.y) && is_finite(c.z);
}

fn denoise_luminance(c: vec3<f32>) -> f32 {
    return c.x * 0.2126 + c.y * 0.7152 + c.z * 0.0722;
}

fn normal_depth(raw: vec4<f32>) -> vec4<f32> {
    if finite3(raw.xyz) && is_finite(raw.w) && raw.w > 0.0 {
        return raw;
    }
    return vec4<f32>(0.0);
}

fn demod_channel(a: f32) -> f32 {
    if is_finite(a) && a >= ALBEDO_MIN {
        return a;
    }
    return 1.0;
}

fn demodulator(a: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(demod_channel(a.x), demod_channel(a.y), demod_channel(a.z));
}

// The B3-spline à-trous kernel per axis, by offset −2…2.
fn kernel(i: i32) -> f32 {
    let a = abs(i);
    if a == 0 {
        return 3.0 / 8.0;
    }
    if a == 1 {
        return 1.0 / 4.0;
    }
    return 1.0 / 16.0;
}

// The 3×3 Gaussian per axis, by offset −1…1.
// The à-trous kernel per axis at tap offset i: radius 1 the 3×3 Gaussian, 2 the 5×5 B3 spline
// (twin: weights.rs `atrous_tap`).
fn atrous_tap(i: i32, radius: i32) -> f32 {
    if radius == 1 {
        return gauss3(i);
    }
    return kernel(i);
}

fn gauss3(i: i32) -> f32 {
    if i == 0 {
        return 0.5;
    }
    return 0.25;
}

fn inside(x: i32, y: i32) -> bool {
    return x >= 0 && y >= 0 && x < i32(du.width) && y < i32(du.height);
}

fn pixel_index(x: i32, y: i32) -> u32 {
    return u32(y) * du.width + u32(x);
}

fn guide_at(x: i32, y: i32) -> vec4<f32> {
    if !inside(x, y) {
        return vec4<f32>(0.0);
    }
    return normal_depth(guides[pixel_index(x, y)]);
}

fn axis_gradient(zc: f32, zm: f32, zp: f32) -> f32 {
    let has_m = zm > 0.0;
    let has_p = zp > 0.0;
    let dm = zc - zm;
    let dp = zp - zc;
    if has_m && has_p {
        if abs(dp) < abs(dm) {
            return dp;
        }
        return dm;
    }
    if has_p {
        return dp;
    }
    if has_m {
        return dm;
    }
    return 0.0;
}

fn depth_gradient(x: i32, y: i32) -> vec2<f32> {
    let zc = guide_at(x, y).w;
    return vec2<f32>(
        axis_gradient(zc, guide_at(x - 1, y).w, guide_at(x + 1, y).w),
        axis_gradient(zc, guide_at(x, y - 1).w, guide_at(x, y + 1).w),
    );
}

fn edge_weight(
    p: vec4<f32>,
    gradient: vec2<f32>,
    q: vec4<f32>,
    offset: vec2<f32>,
    sigma_z: f32,
    lp: f32,
    lq: f32,
    lum_scale: f32,
) -> f32 {
    if q.w <= 0.0 {
        return 0.0;
    }
    var wn = max(p.x * q.x + p.y * q.y + p.z * q.z, 0.0);
    for (var i = 0u; i < NORMAL_SQUARINGS; i++) {
        wn = wn * wn;
    }
    let slope = abs(gradient.x * offset.x + gradient.y * offset.y);
    let dz = abs(p.w - q.w) / (sigma_z * slope + DEPTH_EPS_REL * p.w);
    var dl = 0.0;
    if lum_scale >= 0.0 {
        dl = abs(lp - lq) / lum_scale;
    }
    return wn * exp(-(dz + dl));
}
