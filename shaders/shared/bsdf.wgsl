// Scattering models, twin of engine/src/render/cpu/bsdf.rs. Local frame (normal = +z);
// directions point away from the surface; eval returns BSDF * |cos(theta_i)|.

const ALPHA_DELTA: f32 = 1e-4;
const ALPHA_MIN_METAL_ROUGH: f32 = 2e-3;

struct Bsdf {
    kind: u32,
    base_color: vec3<f32>,
    alpha: f32,
    metallic: f32,
    ior: f32,
    transmission: f32,
}

struct BsdfEval {
    value: vec3<f32>,
    pdf: f32,
}

struct BsdfSample {
    wi: vec3<f32>,
    weight: vec3<f32>,
    pdf: f32,
    delta: bool,
    valid: bool,
}

struct DielectricEval {
    value: f32,
    pdf_reflect: f32,
    pdf_transmit: f32,
    pdf_refract_always: f32,
}

fn no_sample() -> BsdfSample {
    return BsdfSample(vec3<f32>(0.0), vec3<f32>(0.0), 0.0, false, false);
}

fn bsdf_is_delta(b: Bsdf) -> bool {
    return (b.kind == MATERIAL_CONDUCTOR || b.kind == MATERIAL_DIELECTRIC) && b.alpha < ALPHA_DELTA;
}

fn bsdf_is_two_sided(b: Bsdf) -> bool {
    return b.kind != MATERIAL_DIELECTRIC && b.transmission <= 0.0;
}

fn conductor_eval(f0: vec3<f32>, alpha: f32, wo: vec3<f32>, wi: vec3<f32>) -> BsdfEval {
    if (wo.z <= 0.0 || wi.z <= 0.0) {
        return BsdfEval(vec3<f32>(0.0), 0.0);
    }
    let m = normalize(wo + wi);
    let d = ggx_d(m, alpha);
    let value = fresnel_schlick(f0, dot(wo, m)) * (d * ggx_g2(wo, wi, alpha) / (4.0 * wo.z));
    let pdf = ggx_vndf_pdf(wo, m, alpha) / (4.0 * dot(wo, m));
    return BsdfEval(value, pdf);
}

fn rough_dielectric_eval(ior: f32, alpha: f32, wo_in: vec3<f32>, wi_in: vec3<f32>) -> DielectricEval {
    let none = DielectricEval(0.0, 0.0, 0.0, 0.0);
    if (wo_in.z == 0.0 || wi_in.z == 0.0) {
        return none;
    }
    var s = 1.0;
    var eta = ior;
    if (wo_in.z < 0.0) {
        s = -1.0;
        eta = 1.0 / ior;
    }
    let wo = vec3<f32>(wo_in.xy, wo_in.z * s);
    let wi = vec3<f32>(wi_in.xy, wi_in.z * s);
    if (wi.z > 0.0) {
        let m = normalize(wo + wi);
        let wo_m = dot(wo, m);
        if (wo_m <= 0.0) {
            return none;
        }
        let f = fresnel_dielectric(wo_m, eta).x;
        let value = f * ggx_d(m, alpha) * ggx_g2(wo, wi, alpha) / (4.0 * wo.z);
        let pdf = f * ggx_vndf_pdf(wo, m, alpha) / (4.0 * wo_m);
        return DielectricEval(value, pdf, 0.0, 0.0);
    }
    var m = -normalize(wo + wi * eta);
    if (m.z < 0.0) {
        m = -m;
    }
    let wo_m = dot(wo, m);
    let wi_m = dot(wi, m);
    if (wo_m <= 0.0 || wi_m >= 0.0) {
        return none;
    }
    let f = fresnel_dielectric(wo_m, eta).x;
    let denom = wo_m + eta * wi_m;
    let denom2 = denom * denom;
    let value = (1.0 - f) * ggx_d(m, alpha) * ggx_g2(wo, wi, alpha) * wo_m * (-wi_m) / (wo.z * denom2);
    let pdf_always = ggx_vndf_pdf(wo, m, alpha) * (-wi_m) * eta * eta / denom2;
    return DielectricEval(value, 0.0, (1.0 - f) * pdf_always, pdf_always);
}

// Lobe probabilities of the metallic-roughness model: (specular, diffuse, transmission).
fn metal_rough_lobes(b: Bsdf, wo: vec3<f32>) -> vec3<f32> {
    let f0d = pow((b.ior - 1.0) / (b.ior + 1.0), 2.0);
    let f0 = mix(vec3<f32>(f0d), b.base_color, b.metallic);
    let fresnel = fresnel_schlick(f0, abs(wo.z));
    let spec = max(luminance(fresnel), 0.05);
    let rest = (1.0 - b.metallic) * (1.0 - luminance(fresnel)) * max(luminance(b.base_color), 0.05);
    let diffuse = rest * (1.0 - b.transmission);
    let trans = rest * b.transmission;
    let total = spec + diffuse + trans;
    return vec3<f32>(spec, diffuse, trans) / total;
}

fn metal_rough_f0(b: Bsdf) -> vec3<f32> {
    let f0d = pow((b.ior - 1.0) / (b.ior + 1.0), 2.0);
    return mix(vec3<f32>(f0d), b.base_color, b.metallic);
}

fn metal_rough_eval(b: Bsdf, wo: vec3<f32>, wi: vec3<f32>) -> BsdfEval {
    if (wo.z <= 0.0) {
        return BsdfEval(vec3<f32>(0.0), 0.0);
    }
    let alpha = max(b.alpha, ALPHA_MIN_METAL_ROUGH);
    let f0 = metal_rough_f0(b);
    let p = metal_rough_lobes(b, wo);
    var value = vec3<f32>(0.0);
    var pdf = 0.0;
    if (wi.z > 0.0) {
        let spec = conductor_eval(f0, alpha, wo, wi);
        let diffuse_scale = (1.0 - b.metallic) * (1.0 - b.transmission);
        let coat_o = vec3<f32>(1.0) - fresnel_schlick(f0, wo.z);
        let coat_i = vec3<f32>(1.0) - fresnel_schlick(f0, wi.z);
        value += spec.value + b.base_color * coat_o * coat_i * (diffuse_scale * wi.z / PI);
        pdf += p.x * spec.pdf + p.y * wi.z / PI;
    } else if (b.transmission > 0.0) {
        let d = rough_dielectric_eval(b.ior, alpha, wo, wi);
        value += b.base_color * d.value * ((1.0 - b.metallic) * b.transmission);
        pdf += p.z * d.pdf_refract_always;
    }
    return BsdfEval(value, pdf);
}

fn bsdf_eval(b: Bsdf, wo: vec3<f32>, wi: vec3<f32>) -> BsdfEval {
    if (b.kind == MATERIAL_DIFFUSE) {
        if (wo.z <= 0.0 || wi.z <= 0.0) {
            return BsdfEval(vec3<f32>(0.0), 0.0);
        }
        return BsdfEval(b.base_color * (wi.z / PI), wi.z / PI);
    }
    if (b.kind == MATERIAL_CONDUCTOR) {
        if (b.alpha < ALPHA_DELTA) {
            return BsdfEval(vec3<f32>(0.0), 0.0);
        }
        return conductor_eval(b.base_color, b.alpha, wo, wi);
    }
    if (b.kind == MATERIAL_DIELECTRIC) {
        if (b.alpha < ALPHA_DELTA) {
            return BsdfEval(vec3<f32>(0.0), 0.0);
        }
        let d = rough_dielectric_eval(b.ior, b.alpha, wo, wi);
        var tint = vec3<f32>(1.0);
        if (wo.z * wi.z < 0.0) {
            tint = b.base_color;
        }
        return BsdfEval(tint * d.value, d.pdf_reflect + d.pdf_transmit);
    }
    return metal_rough_eval(b, wo, wi);
}

fn sample_from_eval(b: Bsdf, wo: vec3<f32>, wi: vec3<f32>) -> BsdfSample {
    let e = bsdf_eval(b, wo, wi);
    if (e.pdf > 0.0 && max(e.value.x, max(e.value.y, e.value.z)) > 0.0) {
        return BsdfSample(wi, e.value / e.pdf, e.pdf, false, true);
    }
    return no_sample();
}

fn dielectric_sample(b: Bsdf, wo: vec3<f32>, u: vec3<f32>) -> BsdfSample {
    var s = 1.0;
    var eta = b.ior;
    if (wo.z < 0.0) {
        s = -1.0;
        eta = 1.0 / b.ior;
    }
    let wo_up = vec3<f32>(wo.xy, wo.z * s);
    if (b.alpha < ALPHA_DELTA) {
        let fr = fresnel_dielectric(wo_up.z, eta);
        if (u.z < fr.x) {
            return BsdfSample(vec3<f32>(-wo.x, -wo.y, wo.z), vec3<f32>(1.0), fr.x, true, true);
        }
        let t = refract_through(wo_up, vec3<f32>(0.0, 0.0, 1.0), eta, fr.y);
        return BsdfSample(vec3<f32>(t.xy, t.z * s), b.base_color / (eta * eta), 1.0 - fr.x, true, true);
    }
    let m = ggx_sample_vndf(wo_up, b.alpha, u.xy);
    let fr = fresnel_dielectric(dot(wo_up, m), eta);
    let reflected = u.z < fr.x;
    var wi_up: vec3<f32>;
    if (reflected) {
        wi_up = reflect_about(wo_up, m);
    } else {
        wi_up = refract_through(wo_up, m, eta, fr.y);
    }
    // A microfacet can send the direction to the other side of the macro surface: lost.
    if ((wi_up.z > 0.0) != reflected) {
        return no_sample();
    }
    return sample_from_eval(b, wo, vec3<f32>(wi_up.xy, wi_up.z * s));
}

fn bsdf_sample(b: Bsdf, wo: vec3<f32>, u: vec3<f32>) -> BsdfSample {
    if (b.kind == MATERIAL_DIFFUSE) {
        if (wo.z <= 0.0) {
            return no_sample();
        }
        let wi = cosine_hemisphere(u.xy);
        return BsdfSample(wi, b.base_color, wi.z / PI, false, true);
    }
    if (b.kind == MATERIAL_CONDUCTOR) {
        if (wo.z <= 0.0) {
            return no_sample();
        }
        if (b.alpha < ALPHA_DELTA) {
            return BsdfSample(vec3<f32>(-wo.x, -wo.y, wo.z), fresnel_schlick(b.base_color, wo.z), 1.0, true, true);
        }
        let wi = reflect_about(wo, ggx_sample_vndf(wo, b.alpha, u.xy));
        if (wi.z <= 0.0) {
            return no_sample();
        }
        let e = conductor_eval(b.base_color, b.alpha, wo, wi);
        if (e.pdf > 0.0) {
            return BsdfSample(wi, e.value / e.pdf, e.pdf, false, true);
        }
        return no_sample();
    }
    if (b.kind == MATERIAL_DIELECTRIC) {
        return dielectric_sample(b, wo, u);
    }
    // Metallic-roughness.
    if (wo.z <= 0.0) {
        return no_sample();
    }
    let alpha = max(b.alpha, ALPHA_MIN_METAL_ROUGH);
    let p = metal_rough_lobes(b, wo);
    var wi: vec3<f32>;
    if (u.z < p.x) {
        wi = reflect_about(wo, ggx_sample_vndf(wo, alpha, u.xy));
    } else if (u.z < p.x + p.y) {
        wi = cosine_hemisphere(u.xy);
    } else {
        let m = ggx_sample_vndf(wo, alpha, u.xy);
        let fr = fresnel_dielectric(dot(wo, m), b.ior);
        if (fr.x >= 1.0) {
            return no_sample();
        }
        wi = refract_through(wo, m, b.ior, fr.y);
    }
    // Reflection lobes stay above, the transmission lobe below the macro surface.
    if ((wi.z > 0.0) != (u.z < p.x + p.y)) {
        return no_sample();
    }
    return sample_from_eval(b, wo, wi);
}
