// Sampling helpers, twin of engine/src/render/cpu/sampling.rs.

const PI: f32 = 3.14159265358979;

fn luminance(c: vec3<f32>) -> f32 {
    return dot(c, vec3<f32>(0.2126, 0.7152, 0.0722));
}

struct Frame {
    t: vec3<f32>,
    b: vec3<f32>,
    n: vec3<f32>,
}

// Duff et al. 2017.
fn basis(n: vec3<f32>) -> Frame {
    let s = select(-1.0, 1.0, n.z >= 0.0);
    let a = -1.0 / (s + n.z);
    let b = n.x * n.y * a;
    return Frame(
        vec3<f32>(1.0 + s * n.x * n.x * a, s * b, -s * n.x),
        vec3<f32>(b, s + n.y * n.y * a, -n.y),
        n,
    );
}

fn to_world(l: vec3<f32>, f: Frame) -> vec3<f32> {
    return f.t * l.x + f.b * l.y + f.n * l.z;
}

fn to_local(v: vec3<f32>, f: Frame) -> vec3<f32> {
    return vec3<f32>(dot(v, f.t), dot(v, f.b), dot(v, f.n));
}

fn cosine_hemisphere(u: vec2<f32>) -> vec3<f32> {
    let r = sqrt(u.x);
    let phi = 2.0 * PI * u.y;
    return vec3<f32>(r * cos(phi), r * sin(phi), sqrt(max(1.0 - u.x, 0.0)));
}

fn uniform_cone(u: vec2<f32>, cos_max: f32) -> vec3<f32> {
    // As the CPU: the sine from 1 − cos keeps full precision for tiny cones.
    let one_minus_cos = u.x * (1.0 - cos_max);
    let cos_theta = 1.0 - one_minus_cos;
    let sin_theta = sqrt(max(one_minus_cos * (2.0 - one_minus_cos), 0.0));
    let phi = 2.0 * PI * u.y;
    return vec3<f32>(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta);
}

fn concentric_disc(u: vec2<f32>) -> vec2<f32> {
    let a = 2.0 * u - vec2<f32>(1.0);
    if (a.x == 0.0 && a.y == 0.0) {
        return vec2<f32>(0.0);
    }
    var r: f32;
    var phi: f32;
    if (abs(a.x) > abs(a.y)) {
        r = a.x;
        phi = (PI / 4.0) * (a.y / a.x);
    } else {
        r = a.y;
        phi = PI / 2.0 - (PI / 4.0) * (a.x / a.y);
    }
    return vec2<f32>(r * cos(phi), r * sin(phi));
}

fn uniform_triangle(u: vec2<f32>) -> vec2<f32> {
    let su = sqrt(u.x);
    return vec2<f32>(u.y * su, 1.0 - su);
}

fn power_heuristic(a: f32, b: f32) -> f32 {
    let a2 = a * a;
    let b2 = b * b;
    if (a2 + b2 > 0.0) {
        return a2 / (a2 + b2);
    }
    return 0.0;
}
