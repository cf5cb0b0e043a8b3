// The cloud layer (twin of `cloud_transmittance` in engine/src/sky/clouds.rs and of
// engine/src/render/cpu/clouds.rs): the one transmittance both estimators of the primary disc
// are multiplied by, and the sky seen through the layer. The optical depths follow the
// sun's and the moon's sky-view tables in binding 16, four to a texel (engine/src/render/gpu/upload.rs).

fn cloud_tau(i: u32) -> f32 {
    let texel = sky_view[2u * SKY_VIEW_WIDTH * SKY_VIEW_HEIGHT + i / 4u];
    return texel[i % 4u];
}

// exp(−τ) where the ray from `p` along unit `w` crosses the plane going up; 1 otherwise.
fn cloud_transmittance(p: vec3<f32>, w: vec3<f32>) -> f32 {
    let plane = frame.cloud_plane;
    let n = frame.cloud_texels;
    let have = 2u * SKY_VIEW_WIDTH * SKY_VIEW_HEIGHT * 4u;
    if (plane.w <= 0.0 || n == 0u || arrayLength(&sky_view) * 4u < have + n * n
        || w.y <= 0.0 || p.y >= plane.x) {
        return 1.0;
    }
    let t = (plane.x - p.y) / w.y;
    let x = p.x + w.x * t - plane.y;
    let z = p.z + w.z * t - plane.z;
    let scale = f32(n) / plane.w;
    let fx = x * scale - 0.5;
    let fz = z * scale - 0.5;
    let cx = floor(fx);
    let cz = floor(fz);
    let tx = fx - cx;
    let tz = fz - cz;
    let ni = i32(n);
    let x0 = u32(((i32(cx) % ni) + ni) % ni);
    let z0 = u32(((i32(cz) % ni) + ni) % ni);
    let x1 = (x0 + 1u) % n;
    let z1 = (z0 + 1u) % n;
    let a = cloud_tau(z0 * n + x0);
    let b = cloud_tau(z0 * n + x1);
    let c = cloud_tau(z1 * n + x0);
    let d = cloud_tau(z1 * n + x1);
    let row0 = a + (b - a) * tx;
    let row1 = c + (d - c) * tx;
    return exp(-(row0 + (row1 - row0) * tz));
}

// The sky seen through a cloud of transmittance `t`, with the cloud's in-scatter.
fn cloud_through(sky: vec3<f32>, t: f32) -> vec3<f32> {
    if (t == 1.0) {
        return sky;
    }
    return sky * t + frame.cloud_light * (1.0 - t);
}
