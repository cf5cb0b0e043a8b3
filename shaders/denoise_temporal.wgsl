// SVGF's temporal stage (twin: engine/src/render/denoise/temporal.rs): blends this frame's
// demodulated illumination and its luminance moments into each pixel's history, updated in
// place: the pixel's own (ru.mode 0, identity) or the one denoise_reproject.wgsl moved onto it
// (ru.mode 1: the weight is at least 1/(length + 1), as Reprojection::Moved). Entry point
// denoise_temporal.

@group(0) @binding(3) var<storage, read> frame: array<vec4<f32>>;
@group(0) @binding(4) var<storage, read_write> history: array<vec4<f32>>;
@group(0) @binding(5) var<storage, read_write> moments: array<vec4<f32>>;
@group(0) @binding(6) var<uniform> ru: GpuReprojectUniforms;

@compute @workgroup_size(8, 8)
fn denoise_temporal(@builtin(global_invocation_id) id: vec3<u32>) {
    if id.x >= du.width || id.y >= du.height {
        return;
    }
    let i = id.y * du.width + id.x;
    let h = history[i];
    var blend = du.blend;
    if ru.mode == 1u {
        blend = max(blend, 1.0 / (max(h.w, 0.0) + 1.0));
    }
    let restart = !(blend < 1.0);
    let c = frame[i].xyz;
    let m = moments[i];
    if !finite3(c) {
        if restart {
            history[i] = vec4<f32>(0.0);
            moments[i] = vec4<f32>(0.0);
        }
        return;
    }
    let illum = max(c, vec3<f32>(0.0)) / demodulator(albedo[i].xyz);
    let l = denoise_luminance(illum);
    if restart || h.w <= 0.0 {
        history[i] = vec4<f32>(illum, 1.0);
        moments[i] = vec4<f32>(l, l * l, 0.0, 0.0);
        return;
    }
    let old = h.xyz;
    let mixed = old + (illum - old) * blend;
    let m1 = m.x + (l - m.x) * blend;
    let m2 = m.y + (l * l - m.y) * blend;
    let cap = max(floor(1.0 / blend + 0.5), 1.0);
    let length = min(h.w + 1.0, cap);
    history[i] = vec4<f32>(mixed, length);
    moments[i] = vec4<f32>(m1, m2, 0.0, 0.0);
}
