// GGX microfacets and Fresnel, twin of engine/src/render/cpu/microfacet.rs.
// Local shading frame (normal = +z), isotropic, alpha = roughness^2.

fn ggx_d(m: vec3<f32>, alpha: f32) -> f32 {
    if (m.z <= 0.0) {
        return 0.0;
    }
    let a2 = alpha * alpha;
    let t = m.z * m.z * (a2 - 1.0) + 1.0;
    return a2 / (PI * t * t);
}

fn ggx_lambda(w: vec3<f32>, alpha: f32) -> f32 {
    let z2 = w.z * w.z;
    if (z2 <= 0.0) {
        return 1e30;
    }
    let tan2 = (w.x * w.x + w.y * w.y) / z2;
    return 0.5 * (-1.0 + sqrt(1.0 + alpha * alpha * tan2));
}

fn ggx_g1(w: vec3<f32>, alpha: f32) -> f32 {
    return 1.0 / (1.0 + ggx_lambda(w, alpha));
}

fn ggx_g2(wo: vec3<f32>, wi: vec3<f32>, alpha: f32) -> f32 {
    return 1.0 / (1.0 + ggx_lambda(wo, alpha) + ggx_lambda(wi, alpha));
}

fn ggx_sample_vndf(wo: vec3<f32>, alpha: f32, u: vec2<f32>) -> vec3<f32> {
    let vh = normalize(vec3<f32>(alpha * wo.x, alpha * wo.y, wo.z));
    let len2 = vh.x * vh.x + vh.y * vh.y;
    var t1 = vec3<f32>(1.0, 0.0, 0.0);
    if (len2 > 0.0) {
        t1 = vec3<f32>(-vh.y, vh.x, 0.0) / sqrt(len2);
    }
    let t2 = cross(vh, t1);
    let r = sqrt(u.x);
    let phi = 2.0 * PI * u.y;
    let p1 = r * cos(phi);
    let s = 0.5 * (1.0 + vh.z);
    let p2 = (1.0 - s) * sqrt(max(1.0 - p1 * p1, 0.0)) + s * r * sin(phi);
    let nh = t1 * p1 + t2 * p2 + vh * sqrt(max(1.0 - p1 * p1 - p2 * p2, 0.0));
    return normalize(vec3<f32>(alpha * nh.x, alpha * nh.y, max(nh.z, 1e-7)));
}

fn ggx_vndf_pdf(wo: vec3<f32>, m: vec3<f32>, alpha: f32) -> f32 {
    let wo_m = dot(wo, m);
    if (wo_m <= 0.0 || wo.z <= 0.0) {
        return 0.0;
    }
    return ggx_g1(wo, alpha) * wo_m * ggx_d(m, alpha) / wo.z;
}

fn fresnel_schlick(f0: vec3<f32>, cos_theta: f32) -> vec3<f32> {
    let c = pow(1.0 - clamp(cos_theta, 0.0, 1.0), 5.0);
    return f0 + (vec3<f32>(1.0) - f0) * c;
}

// Returns (F, cos_t); F = 1 on total internal reflection. eta = eta_t / eta_i.
fn fresnel_dielectric(cos_i: f32, eta: f32) -> vec2<f32> {
    let sin2_t = max(1.0 - cos_i * cos_i, 0.0) / (eta * eta);
    if (sin2_t >= 1.0) {
        return vec2<f32>(1.0, 0.0);
    }
    let cos_t = sqrt(1.0 - sin2_t);
    let rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    let rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    return vec2<f32>(0.5 * (rs * rs + rp * rp), cos_t);
}

fn reflect_about(w: vec3<f32>, m: vec3<f32>) -> vec3<f32> {
    return 2.0 * dot(w, m) * m - w;
}

fn refract_through(w: vec3<f32>, m: vec3<f32>, eta: f32, cos_t: f32) -> vec3<f32> {
    let cos_i = dot(w, m);
    return normalize(-w / eta + m * (cos_i / eta - cos_t));
}
