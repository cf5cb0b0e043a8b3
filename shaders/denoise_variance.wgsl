// SVGF's variance estimate (twin: engine/src/render/denoise/variance.rs): the variance of each
// pixel's luminance estimate from the temporal moments (4 frames of history or more), else
// from a 7×7 neighbourhood weighted by depth and normal. Out: (illumination, variance), with
// variance −1 for a pixel without a valid sample. Entry point denoise_variance.

@group(0) @binding(3) var<storage, read> history: array<vec4<f32>>;
@group(0) @binding(4) var<storage, read> moments: array<vec4<f32>>;
@group(0) @binding(5) var<storage, read_write> out_rows: array<vec4<f32>>;

const SPATIAL_RADIUS: i32 = 3;

fn variance_of(x: i32, y: i32) -> vec4<f32> {
    let i = pixel_index(x, y);
    let h = history[i];
    if h.w <= 0.0 {
        return vec4<f32>(0.0, 0.0, 0.0, -1.0);
    }
    if h.w >= MIN_TEMPORAL_FRAMES {
        let m = moments[i];
        let v = max(m.y - m.x * m.x, 0.0) / (h.w - 1.0);
        return vec4<f32>(h.xyz, v);
    }
    let p = guide_at(x, y);
    if p.w <= 0.0 {
        return vec4<f32>(h.xyz, 0.0);
    }
    let gradient = depth_gradient(x, y);
    var sum_w = 0.0;
    var s1 = 0.0;
    var s2 = 0.0;
    for (var dy = -SPATIAL_RADIUS; dy <= SPATIAL_RADIUS; dy++) {
        for (var dx = -SPATIAL_RADIUS; dx <= SPATIAL_RADIUS; dx++) {
            let qx = x + dx;
            let qy = y + dy;
            if !inside(qx, qy) {
                continue;
            }
            let hq = history[pixel_index(qx, qy)];
            if hq.w <= 0.0 {
                continue;
            }
            let q = guide_at(qx, qy);
            let offset = vec2<f32>(f32(dx), f32(dy));
            let w = edge_weight(p, gradient, q, offset, du.sigma_z, 0.0, 0.0, -1.0);
            let l = denoise_luminance(hq.xyz);
            sum_w += w;
            s1 += w * l;
            s2 += w * l * l;
        }
    }
    var v = 0.0;
    if sum_w > 0.0 {
        let m1 = s1 / sum_w;
        v = max(s2 / sum_w - m1 * m1, 0.0);
    }
    return vec4<f32>(h.xyz, v);
}

@compute @workgroup_size(8, 8)
fn denoise_variance(@builtin(global_invocation_id) id: vec3<u32>) {
    if id.x >= du.width || id.y >= du.height {
        return;
    }
    out_rows[id.y * du.width + id.x] = variance_of(i32(id.x), i32(id.y));
}
