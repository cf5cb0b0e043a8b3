// The present pass (render thread): the film — converged mean linear radiance, rows top to
// bottom, possibly smaller than the window when workload scaling lowered the resolution — is
// upscaled to the frame by a separable Catmull-Rom bicubic with clamped edges, and tonemapped exactly as `linear_to_srgb8` in
// engine/src/render/film/tonemap.rs: exposure, optional ACES fit, NaN to black, clamp to [0, 1],
// sRGB transfer (by the hardware for an sRGB target, here otherwise). Composed after
// shared/types.wgsl only (it binds nothing of the tracing pass).

@group(0) @binding(0) var<uniform> present: GpuPresentUniforms;
// One vec4 per film pixel (xyz = radiance; w unused): the GPU tracer's film buffer itself, or
// the CPU tracer's film uploaded in the same form.
@group(0) @binding(1) var<storage, read> film: array<vec4<f32>>;

struct PresentVertex {
    @builtin(position) position: vec4<f32>,
}

// One triangle that covers the whole target: vertices (-1,-1), (3,-1), (-1,3) in clip space.
@vertex
fn present_vs(@builtin(vertex_index) index: u32) -> PresentVertex {
    let corner = vec2<f32>(f32((index << 1u) & 2u), f32(index & 2u));
    return PresentVertex(vec4<f32>(corner * 2.0 - 1.0, 0.0, 1.0));
}

fn is_nan(x: f32) -> bool {
    return (bitcast<u32>(x) & 0x7fffffffu) > 0x7f800000u;
}

// NaN → 0 and ±infinity → ±1e30, per channel: the bicubic weights of neighbours (0 at equal
// sizes) would otherwise spread a bad value (0 × inf = NaN), and the tonemap below then maps
// these exactly as the CPU maps NaN and infinity.
fn finite(c: vec3<f32>) -> vec3<f32> {
    let n = vec3<f32>(select(c.x, 0.0, is_nan(c.x)), select(c.y, 0.0, is_nan(c.y)), select(c.z, 0.0, is_nan(c.z)));
    return clamp(n, vec3<f32>(-1e30), vec3<f32>(1e30));
}

// A film pixel, clamped to the edge.
fn film_texel(x: i32, y: i32) -> vec3<f32> {
    let cx = u32(clamp(x, 0, i32(present.film_width) - 1));
    let cy = u32(clamp(y, 0, i32(present.film_height) - 1));
    return finite(film[cy * present.film_width + cx].xyz);
}

// Catmull-Rom weights of the film pixels at base - 1 .. base + 2 for a sample t past base, as
// `catmull_rom` in engine/src/render/present/cpu_compose.rs (t = 0: (0, 1, 0, 0)).
fn catmull_rom(t: f32) -> vec4<f32> {
    let t2 = t * t;
    let t3 = t2 * t;
    return vec4<f32>(
        (-t3 + 2.0 * t2 - t) * 0.5,
        (3.0 * t3 - 5.0 * t2 + 2.0) * 0.5,
        (-3.0 * t3 + 4.0 * t2 + t) * 0.5,
        (t3 - t2) * 0.5,
    );
}

fn srgb_encode(c: f32) -> f32 {
    if (c <= 0.0031308) {
        return 12.92 * c;
    }
    return 1.055 * pow(c, 1.0 / 2.4) - 0.055;
}

@fragment
fn present_fs(vertex: PresentVertex) -> @location(0) vec4<f32> {
    // vertex.position.xy is the target pixel's centre (x + 0.5, y + 0.5), y downward like the
    // film's rows. Map it to film pixel coordinates (centres at integer + 0.5).
    let scale = vec2<f32>(
        f32(present.film_width) / f32(present.target_width),
        f32(present.film_height) / f32(present.target_height),
    );
    let f = vertex.position.xy * scale - 0.5;
    let base = floor(f);
    let t = f - base;
    let x = i32(base.x);
    let y = i32(base.y);
    let wx = catmull_rom(t.x);
    let wy = catmull_rom(t.y);
    // Across first (each of the four rows), then down: the CPU compose's order.
    var sum = vec3<f32>(0.0);
    for (var j = 0; j < 4; j = j + 1) {
        let row = y - 1 + j;
        let across = film_texel(x - 1, row) * wx.x + film_texel(x, row) * wx.y
            + film_texel(x + 1, row) * wx.z + film_texel(x + 2, row) * wx.w;
        sum = sum + across * wy[j];
    }
    var c = sum * present.exposure_scale;
    if (present.filmic != 0u) {
        c = (c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14);
    }
    // NaN (the filmic curve of a huge value is inf / inf) maps to black, as on the CPU.
    c = vec3<f32>(select(c.x, 0.0, is_nan(c.x)), select(c.y, 0.0, is_nan(c.y)), select(c.z, 0.0, is_nan(c.z)));
    c = clamp(c, vec3<f32>(0.0), vec3<f32>(1.0));
    if (present.encode_srgb != 0u) {
        c = vec3<f32>(srgb_encode(c.x), srgb_encode(c.y), srgb_encode(c.z));
    }
    return vec4<f32>(c, 1.0);
}
