// Texture lookups, twin of engine/src/render/cpu/texture.rs (f16 texels, wrap, bilinear).

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

fn texel_fetch(t: GpuTexture, x: i32, y: i32) -> vec4<f32> {
    let w = i32(t.width);
    let h = i32(t.height);
    let xi = wrap_texel(x, w, t.flags & 3u);
    let yi = wrap_texel(y, h, (t.flags >> 2u) & 3u);
    let index = t.texel_offset + u32(yi * w + xi);
    if (index >= arrayLength(&texels)) {
        return vec4<f32>(1.0);
    }
    return texel_unpack(texels[index]);
}

fn sample_texture(index: u32, uv_in: vec2<f32>) -> vec4<f32> {
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
    let x = clamp(uv.x * f32(t.width), -1e6, 1e6);
    let y = clamp(uv.y * f32(t.height), -1e6, 1e6);
    if ((t.flags & TEXTURE_FLAG_NEAREST) != 0u) {
        return texel_fetch(t, i32(floor(x)), i32(floor(y)));
    }
    let xs = x - 0.5;
    let ys = y - 0.5;
    let x0 = floor(xs);
    let y0 = floor(ys);
    let fx = xs - x0;
    let fy = ys - y0;
    let xi = i32(x0);
    let yi = i32(y0);
    let top = texel_fetch(t, xi, yi) * (1.0 - fx) + texel_fetch(t, xi + 1, yi) * fx;
    let bottom = texel_fetch(t, xi, yi + 1) * (1.0 - fx) + texel_fetch(t, xi + 1, yi + 1) * fx;
    return top * (1.0 - fy) + bottom * fy;
}
