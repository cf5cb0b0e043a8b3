// One variance-guided à-trous pass (twin: engine/src/render/denoise/atrous.rs): a 3×3 Gaussian
// (du.radius 1) or 5×5 B3-spline (du.radius 2) kernel with holes of du.step pixels, taps weighted by depth, normal and luminance;
// the variance filtered with the squared weights. du.remodulate = 1 on the last pass: rgb ×
// albedo, and a pixel still without a sample becomes 0. Entry point denoise_atrous.

@group(0) @binding(3) var<storage, read> in_rows: array<vec4<f32>>;
@group(0) @binding(4) var<storage, read_write> out_rows: array<vec4<f32>>;

fn prefiltered_variance(x: i32, y: i32) -> f32 {
    var sum = 0.0;
    var weight = 0.0;
    for (var dy = -1; dy <= 1; dy++) {
        for (var dx = -1; dx <= 1; dx++) {
            let qx = x + dx;
            let qy = y + dy;
            if !inside(qx, qy) {
                continue;
            }
            let v = in_rows[pixel_index(qx, qy)].w;
            if v < 0.0 {
                continue;
            }
            let k = gauss3(dx) * gauss3(dy);
            sum += k * v;
            weight += k;
        }
    }
    if weight > 0.0 {
        return sum / weight;
    }
    return -1.0;
}

fn atrous_of(x: i32, y: i32) -> vec4<f32> {
    let i = pixel_index(x, y);
    let centre = in_rows[i];
    let p = guide_at(x, y);
    var out = centre;
    if p.w > 0.0 {
        let gradient = depth_gradient(x, y);
        let valid = centre.w >= 0.0;
        let lp = denoise_luminance(centre.xyz);
        let v = prefiltered_variance(x, y);
        var lum_scale = -1.0;
        if valid && v >= 0.0 {
            lum_scale = du.sigma_l * sqrt(v) + LUMINANCE_EPS;
        }
        let step = i32(du.step);
        let r = i32(du.radius);
        var sum_c = vec3<f32>(0.0);
        var sum_v = 0.0;
        var sum_w = 0.0;
        for (var dy = -r; dy <= r; dy++) {
            for (var dx = -r; dx <= r; dx++) {
                let qx = x + dx * step;
                let qy = y + dy * step;
                if !inside(qx, qy) {
                    continue;
                }
                let row = in_rows[pixel_index(qx, qy)];
                if row.w < 0.0 {
                    continue;
                }
                let k = atrous_tap(dx, r) * atrous_tap(dy, r);
                var w = k;
                if dx != 0 || dy != 0 {
                    let q = guide_at(qx, qy);
                    let offset = vec2<f32>(f32(dx * step), f32(dy * step));
                    let lq = denoise_luminance(row.xyz);
                    w = k * edge_weight(p, gradient, q, offset, du.sigma_z, lp, lq, lum_scale);
                }
                sum_c += row.xyz * w;
                sum_v += row.w * w * w;
                sum_w += w;
            }
        }
        if sum_w > 0.0 {
            out = vec4<f32>(sum_c / sum_w, sum_v / (sum_w * sum_w));
        } else {
            out = vec4<f32>(0.0, 0.0, 0.0, -1.0);
        }
    }
    if du.remodulate != 0u {
        if out.w < 0.0 {
            return vec4<f32>(0.0);
        }
        return vec4<f32>(out.xyz * demodulator(albedo[i].xyz), 1.0);
    }
    return out;
}

@compute @workgroup_size(8, 8)
fn denoise_atrous(@builtin(global_invocation_id) id: vec3<u32>) {
    if id.x >= du.width || id.y >= du.height {
        return;
    }
    out_rows[id.y * du.width + id.x] = atrous_of(i32(id.x), i32(id.y));
}
