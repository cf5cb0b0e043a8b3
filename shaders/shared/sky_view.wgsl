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

// The table's radiance for a view at `elevation` radians and `azimuth` radians from the sun's
// azimuth (any sign, any turn); the table starts at texel `base` (0: the sun's, W·H: the
// moon's).
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
    return mix(row0, row1, ty);
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
