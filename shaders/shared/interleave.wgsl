// Interleaved indirect light (twin of `render/cpu/interleave.rs`): the weight of pixel
// (px, py)'s first diffuse or glossy bounce at sample index `sample`: 1 without interleaving,
// 0 when this pixel skips it this sample, 2 or 4 when it traces it for its neighbours.
// A 2×2 block's pixels (index x % 2 + 2 · (y % 2)) take their turns in the order 0, 3, 1, 2.
fn indirect_weight(method: u32, px: u32, py: u32, sample: u32) -> f32 {
    if ((method & METHOD_INDIRECT_QUARTER) != 0u) {
        let cell = (px & 1u) + 2u * (py & 1u);
        let order = array<u32, 4>(0u, 3u, 1u, 2u);
        return select(0.0, 4.0, cell == order[sample & 3u]);
    }
    if ((method & METHOD_INDIRECT_HALF) != 0u) {
        return select(0.0, 2.0, ((px + py + sample) & 1u) == 0u);
    }
    return 1.0;
}
