// Counter-based RNG, twin of engine/src/render/cpu/rng.rs: pcg4d (Jarzynski & Olano 2020)
// keyed by (pixel x, pixel y, global sample index, seed * golden ratio + block counter); each
// hash gives four numbers (draw k is lane k % 4 of block k / 4).

struct Rng {
    pixel: vec2<u32>,
    sample: u32,
    stream: u32,
    block: vec4<u32>,
    used: u32,
}

fn pcg4d(v_in: vec4<u32>) -> vec4<u32> {
    var v = v_in * 1664525u + 1013904223u;
    v.x += v.y * v.w;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v.w += v.y * v.z;
    v = v ^ (v >> vec4<u32>(16u));
    v.x += v.y * v.w;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v.w += v.y * v.z;
    return v;
}

fn rng_new(pixel: vec2<u32>, sample: u32, seed: u32) -> Rng {
    return Rng(pixel, sample, seed * 0x9e3779b9u, vec4<u32>(0u), 4u);
}

fn rng_next(rng: ptr<function, Rng>) -> f32 {
    if ((*rng).used == 4u) {
        (*rng).block = pcg4d(vec4<u32>((*rng).pixel, (*rng).sample, (*rng).stream));
        (*rng).stream += 1u;
        (*rng).used = 0u;
    }
    let x = (*rng).block[(*rng).used];
    (*rng).used += 1u;
    return f32(x >> 8u) * (1.0 / 16777216.0);
}
