// Texture lookups, twin of engine/src/render/cpu/texture.rs (f16 texels, wrap, bilinear).

fn texel_unpack(t: vec2<u32>) -> vec4<f32> {
    return vec4<f32>(unpack2x16float(t.x), unpack2x16float(t.y));
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
