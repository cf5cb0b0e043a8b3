// The physical sky's lookup for an escaping ray: twin of `lookup_view`
// (engine/src/sky/sky_view.rs) and `sky_view_radiance` (engine/src/sky/physical.rs), the same
// indexing and the same bilinear arithmetic (glam's lerp is a·(1 − t) + b·t, WGSL's mix too).
// Reads binding 16 (`sky_view`: the sun's table, then the moon's); the table layout is in
// engine/src/sky/sky_view.rs.

const SKY_PI: f32 = 3.14159265358979323846;
const SKY_TAU: f32 = 6.28318530717958647692;
const SKY_FRAC_PI_2: f32 = 1.57079632679489661923;

fn sky_view_texel(base: u32, x: u32, y: u32) -> vec3<f32> {
    return sky_view[base + y * SKY_VIEW_WIDTH + x].xyz;
}

// Radiance at or below which a texel counts as dark (twin of `DARK`).
const SKY_DARK: f32 = 1e-30;

// Catmull–Rom spline through p0..p3 at t between p1 and p2 (twin of `catmull_rom`).
fn sky_catmull_rom(p0: vec3<f32>, p1: vec3<f32>, p2: vec3<f32>, p3: vec3<f32>, t: f32) -> vec3<f32> {
    let t2 = t * t;
    let t3 = t * t * t;
    return 0.5 * (2.0 * p1
        + (p2 - p0) * t
        + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * t2
        + (3.0 * p1 - p0 - 3.0 * p2 + p3) * t3);
}

// Whether row y's two texels at x0, x1 are dark, per channel.
fn sky_dark_row(base: u32, x0: u32, x1: u32, y: u32) -> vec3<bool> {
    return min(sky_view_texel(base, x0, y), sky_view_texel(base, x1, y)) <= vec3<f32>(SKY_DARK);
}

// The log of row y's radiance, linear in azimuth.
fn sky_log_row(base: u32, x0: u32, x1: u32, y: u32, tx: f32) -> vec3<f32> {
    let a = log(max(sky_view_texel(base, x0, y), vec3<f32>(SKY_DARK)));
    let b = log(max(sky_view_texel(base, x1, y), vec3<f32>(SKY_DARK)));
    return mix(a, b, tx);
}

// The table's radiance for a view at `elevation` radians and `azimuth` radians from the sun's
// azimuth (any sign, any turn); the table starts at texel `base` (0: the sun's, W·H: the
// moon's). Below the horizon bilinear; above it the log of the radiance, linear in azimuth and
// Catmull–Rom over four rows in elevation (the rules are `lookup_view`'s).
fn sky_lookup_view(base: u32, elevation: f32, azimuth: f32) -> vec3<f32> {
    let a = abs(azimuth) % SKY_TAU;
    var phi = a;
    if (a > SKY_PI) {
        phi = SKY_TAU - a;
    }
    let u = phi / SKY_PI;
    let e = clamp(elevation / SKY_FRAC_PI_2, -1.0, 1.0);
    // Rust's signum is ±1 at ±0 where WGSL's sign is 0; both multiply sqrt(0) = 0 there.
    let v = 0.5 + 0.5 * sign(e) * sqrt(abs(e));
    let fx = clamp(u, 0.0, 1.0) * f32(SKY_VIEW_WIDTH - 1u);
    let fy = clamp(v, 0.0, 1.0) * f32(SKY_VIEW_HEIGHT - 1u);
    let x0 = u32(floor(fx));
    let y0 = u32(floor(fy));
    let x1 = min(x0 + 1u, SKY_VIEW_WIDTH - 1u);
    let y1 = min(y0 + 1u, SKY_VIEW_HEIGHT - 1u);
    let tx = fx - f32(x0);
    let ty = fy - f32(y0);
    let row0 = mix(sky_view_texel(base, x0, y0), sky_view_texel(base, x1, y0), tx);
    let row1 = mix(sky_view_texel(base, x0, y1), sky_view_texel(base, x1, y1), tx);
    let linear = mix(row0, row1, ty);
    let horizon = (SKY_VIEW_HEIGHT - 1u) / 2u;
    if (y0 < horizon || y1 == y0) {
        return linear;
    }
    let q1 = sky_log_row(base, x0, x1, y0, tx);
    let q2 = sky_log_row(base, x0, x1, y1, tx);
    let below = 2.0 * q1 - q2;
    let above = 2.0 * q2 - q1;
    var q0 = below;
    if (y0 > horizon) {
        q0 = select(sky_log_row(base, x0, x1, y0 - 1u, tx), below, sky_dark_row(base, x0, x1, y0 - 1u));
    }
    var q3 = above;
    if (y1 + 1u < SKY_VIEW_HEIGHT) {
        q3 = select(sky_log_row(base, x0, x1, y1 + 1u, tx), above, sky_dark_row(base, x0, x1, y1 + 1u));
    }
    let spline = exp(sky_catmull_rom(q0, q1, q2, q3, ty));
    let dark = sky_dark_row(base, x0, x1, y0) | sky_dark_row(base, x0, x1, y1);
    return select(spline, linear, dark);
}

// The lookup both tracers do: elevation from `d.y`, azimuth from the sun's horizontal
// direction `sun_azimuth` (unit, engine space).
fn sky_view_radiance_at(base: u32, sun_azimuth: vec3<f32>, d: vec3<f32>) -> vec3<f32> {
    let elevation = asin(clamp(d.y, -1.0, 1.0));
    let side = cross(vec3<f32>(0.0, 1.0, 0.0), sun_azimuth);
    let azimuth = atan2(dot(d, side), dot(d, sun_azimuth));
    return sky_lookup_view(base, elevation, azimuth);
}

fn sky_view_radiance(sun_azimuth: vec3<f32>, d: vec3<f32>) -> vec3<f32> {
    return sky_view_radiance_at(0u, sun_azimuth, d);
}

// The moonlit sky: twin of `moon_view_radiance` (engine/src/sky/physical.rs). The moon's table
// follows the sun's in binding 16 (zeros when there is none; engine/src/render/gpu/upload.rs),
// seen in the frame of `moon_sky.xyz` and multiplied by `moon_sky.w` (0: none, nothing read).
fn moon_view_radiance(moon_sky: vec4<f32>, d: vec3<f32>) -> vec3<f32> {
    if (moon_sky.w <= 0.0) {
        return vec3<f32>(0.0);
    }
    return sky_view_radiance_at(SKY_VIEW_WIDTH * SKY_VIEW_HEIGHT, moon_sky.xyz, d) * moon_sky.w;
}
