// The physical sky's lookup for an escaping ray: twin of `lookup_view`
// (engine/src/sky/sky_view.rs) and `sky_view_radiance` (engine/src/sky/physical.rs), the same
// indexing and the same bilinear arithmetic (glam's lerp is a·(1 − t) + b·t, WGSL's mix too).
// Reads binding 16 (`sky_view`); the table layout is in engine/src/sky/sky_view.rs.

const SKY_PI: f32 = 3.14159265358979323846;
const SKY_TAU: f32 = 6.28318530717958647692;
const SKY_FRAC_PI_2: f32 = 1.57079632679489661923;

fn sky_view_texel(x: u32, y: u32) -> vec3<f32> {
    return sky_view[y * SKY_VIEW_WIDTH + x].xyz;
}

// The table's radiance for a view at `elevation` radians and `azimuth` radians from the sun's
// azimuth (any sign, any turn).
fn sky_lookup_view(elevation: f32, azimuth: f32) -> vec3<f32> {
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
    let row0 = mix(sky_view_texel(x0, y0), sky_view_texel(x1, y0), tx);
    let row1 = mix(sky_view_texel(x0, y1), sky_view_texel(x1, y1), tx);
    return mix(row0, row1, ty);
}

// The lookup both tracers do: elevation from `d.y`, azimuth from the sun's horizontal
// direction `sun_azimuth` (unit, engine space).
fn sky_view_radiance(sun_azimuth: vec3<f32>, d: vec3<f32>) -> vec3<f32> {
    let elevation = asin(clamp(d.y, -1.0, 1.0));
    let side = cross(vec3<f32>(0.0, 1.0, 0.0), sun_azimuth);
    let azimuth = atan2(dot(d, side), dot(d, sun_azimuth));
    return sky_lookup_view(elevation, azimuth);
}
