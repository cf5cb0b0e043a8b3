// Texture lookups, twin of engine/src/render/cpu/texture.rs (f16 texels, wrap, bilinear, the
// mip level a ray cone picks), and the ray cone itself, twin of engine/src/render/cpu/cone.rs.

// IEEE half → f32, exact (done by hand: unpack2x16float needs a capability not every
// adapter offers).
fn half_to_f32(h: u32) -> f32 {
    let sign = (h >> 15u) & 1u;
    let exponent = (h >> 10u) & 31u;
    let mantissa = h & 1023u;
    var magnitude: f32;
    if (exponent == 0u) {
        magnitude = f32(mantissa) * (1.0 / 16777216.0);
    } else if (exponent == 31u) {
        magnitude = bitcast<f32>(0x7f800000u | (mantissa << 13u));
    } else {
        magnitude = bitcast<f32>(((exponent + 112u) << 23u) | (mantissa << 13u));
    }
    return select(magnitude, -magnitude, sign == 1u);
}

fn texel_unpack(t: vec2<u32>) -> vec4<f32> {
    return vec4<f32>(
        half_to_f32(t.x & 0xffffu),
        half_to_f32(t.x >> 16u),
        half_to_f32(t.y & 0xffffu),
        half_to_f32(t.y >> 16u),
    );
}

fn wrap_texel(i: i32, size: i32, mode: u32) -> i32 {
    if (mode == WRAP_CLAMP) {
        return clamp(i, 0, size - 1);
    }
    if (mode == WRAP_MIRROR) {
        let m = ((i % (2 * size)) + 2 * size) % (2 * size);
        return select(m, 2 * size - 1 - m, m >= size);
    }
    return ((i % size) + size) % size;
}

// Where a lookup's footprint lies on the mip chain (twin of `Lod`): λ of a w × h texture is
// footprint + ½·log2(w·h); -1e30 reads level 0.
struct Lod {
    footprint: f32,
    random: f32,
}

const BOUNCE_SPREAD_MAX: f32 = 1.0;

// A path's ray cone (twin of `Cone`): width in metres, spread in radians.
struct Cone {
    width: f32,
    spread: f32,
}

fn cone_camera() -> Cone {
    return Cone(0.0, 2.0 * length(frame.camera_up) / f32(max(frame.height, 1u)));
}

fn cone_lod(c: Cone, uv_density: f32, normal: vec3<f32>, direction: vec3<f32>, random: f32) -> Lod {
    let cosine = max(abs(dot(normal, direction)), 1e-6);
    let ratio = c.width / cosine;
    if (!(ratio > 0.0) || !(uv_density > 0.0)) {
        return Lod(-1e30, random);
    }
    return Lod(log2(ratio) + 0.5 * log2(uv_density), random);
}

fn cone_bounce(c: Cone, pdf: f32, delta: bool) -> Cone {
    if (delta) {
        return c;
    }
    var widen = BOUNCE_SPREAD_MAX;
    if (pdf > 0.0) {
        widen = min(2.0 * sqrt(1.0 / (PI * pdf)), BOUNCE_SPREAD_MAX);
    }
    return Cone(c.width, c.spread + widen);
}

fn texture_levels(t: GpuTexture) -> u32 {
    return max((t.flags >> TEXTURE_LEVELS_SHIFT) & TEXTURE_LEVELS_MASK, 1u);
}

// ⌊λ⌋ or ⌊λ⌋ + 1 with probability frac(λ), within [0, levels - 1].
fn lod_level(lod: Lod, t: GpuTexture, levels: u32) -> u32 {
    let lambda = lod.footprint + 0.5 * log2(f32(t.width) * f32(t.height));
    if (!(lambda > 0.0) || levels <= 1u) {
        return 0u;
    }
    let top = f32(levels - 1u);
    if (lambda >= top) {
        return levels - 1u;
    }
    let lower = floor(lambda);
    return u32(lower) + select(0u, 1u, lod.random < lambda - lower);
}

// Texel (x, y), wrapped, of the level `w × h` texels from `base`.
fn texel_fetch_level(base: u32, w: i32, h: i32, flags: u32, x: i32, y: i32) -> vec4<f32> {
    let xi = wrap_texel(x, w, flags & 3u);
    let yi = wrap_texel(y, h, (flags >> 2u) & 3u);
    let index = base + u32(yi * w + xi);
    if (index >= arrayLength(&texels)) {
        return vec4<f32>(1.0);
    }
    return texel_unpack(texels[index]);
}

// Level 0 (light sampling reads emission there, as the CPU twin does).
fn sample_texture(index: u32, uv_in: vec2<f32>) -> vec4<f32> {
    return sample_texture_lod(index, uv_in, Lod(-1e30, 0.0));
}

fn sample_texture_lod(index: u32, uv_in: vec2<f32>, lod: Lod) -> vec4<f32> {
    if (index >= arrayLength(&textures)) {
        return vec4<f32>(1.0);
    }
    let t = textures[index];
    if (t.width == 0u || t.height == 0u) {
        return vec4<f32>(1.0);
    }
    var uv = uv_in;
    // NaN or infinite coordinates sample the origin (x != x is the portable NaN test).
    if (uv.x != uv.x || uv.y != uv.y || abs(uv.x) > 1e30 || abs(uv.y) > 1e30) {
        uv = vec2<f32>(0.0);
    }
    var level = 0u;
    if ((t.flags & TEXTURE_FLAG_NEAREST) == 0u) {
        level = lod_level(lod, t, texture_levels(t));
    }
    // Levels lie one after the other from texel_offset (floor halving, at least 1).
    var base = t.texel_offset;
    for (var l = 0u; l < level; l += 1u) {
        base += max(t.width >> l, 1u) * max(t.height >> l, 1u);
    }
    let lw = max(t.width >> level, 1u);
    let lh = max(t.height >> level, 1u);
    let w = i32(lw);
    let h = i32(lh);
    let x = clamp(uv.x * f32(lw), -1e6, 1e6);
    let y = clamp(uv.y * f32(lh), -1e6, 1e6);
    if ((t.flags & TEXTURE_FLAG_NEAREST) != 0u) {
        return texel_fetch_level(base, w, h, t.flags, i32(floor(x)), i32(floor(y)));
    }
    let xs = x - 0.5;
    let ys = y - 0.5;
    let x0 = floor(xs);
    let y0 = floor(ys);
    let fx = xs - x0;
    let fy = ys - y0;
    let xi = i32(x0);
    let yi = i32(y0);
    let top = texel_fetch_level(base, w, h, t.flags, xi, yi) * (1.0 - fx) + texel_fetch_level(base, w, h, t.flags, xi + 1, yi) * fx;
    let bottom = texel_fetch_level(base, w, h, t.flags, xi, yi + 1) * (1.0 - fx) + texel_fetch_level(base, w, h, t.flags, xi + 1, yi + 1) * fx;
    return top * (1.0 - fy) + bottom * fy;
}
