// The night sky that escaping rays see: twin of engine/src/render/cpu/night.rs (the lit part
// of a disc, the second disc, the hashed star field and the airglow, read from the frame
// uniforms that engine/src/scene/discs.rs fills). Same operations in the same order.

const VAN_RHIJN_K: f32 = 0.97232;
const NIGHT_LOG10_2: f32 = 0.30102999566;
const NIGHT_LOG2_10: f32 = 3.32192809489;

// Whether `d`, inside the disc of centre `centre`, falls on its lit part (zero terminator:
// always).
fn disc_lit(d: vec3<f32>, centre: vec3<f32>, sin_radius: f32, terminator: vec3<f32>) -> bool {
    if (all(terminator == vec3<f32>(0.0)) || sin_radius <= 0.0) {
        return true;
    }
    let p = (d - centre * dot(d, centre)) / sin_radius;
    let q = min(dot(p, p), 1.0);
    let normal = p - centre * sqrt(1.0 - q);
    return dot(normal, terminator) >= 0.0;
}

// Whether `d` falls inside the disc (|d × centre| ≤ sin r on the near side).
fn disc_inside(d: vec3<f32>, centre: vec3<f32>, sin_radius: f32) -> bool {
    let x = cross(d, centre);
    return dot(d, centre) > 0.0 && dot(x, x) <= sin_radius * sin_radius;
}

fn second_disc(d: vec3<f32>) -> vec3<f32> {
    let centre = frame.second_direction;
    if (frame.second_sin_radius <= 0.0 || !disc_inside(d, centre, frame.second_sin_radius)) {
        return vec3<f32>(0.0);
    }
    if (!disc_lit(d, centre, frame.second_sin_radius, frame.second_terminator)) {
        return vec3<f32>(0.0);
    }
    return frame.second_radiance;
}

fn night_pcg(v: u32) -> u32 {
    let state = v * 747796405u + 2891336453u;
    let word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

fn night_unit(h: u32) -> f32 {
    return f32(h >> 8u) / 16777216.0;
}

// The star of the cell of celestial direction `c`: xyz its direction, w its magnitude; w > 99
// when the cell holds none.
fn cell_star(c: vec3<f32>) -> vec4<f32> {
    let a = abs(c);
    var face = 0u;
    var uu = 0.0;
    var vv = 0.0;
    var major = 0.0;
    if (a.x >= a.y && a.x >= a.z) {
        face = select(0u, 1u, c.x < 0.0);
        uu = c.y / a.x;
        vv = c.z / a.x;
        major = a.x;
    } else if (a.y >= a.z) {
        face = 2u + select(0u, 1u, c.y < 0.0);
        uu = c.x / a.y;
        vv = c.z / a.y;
        major = a.y;
    } else {
        face = 4u + select(0u, 1u, c.z < 0.0);
        uu = c.x / a.z;
        vv = c.y / a.z;
        major = a.z;
    }
    if (major <= 0.0) {
        return vec4<f32>(0.0, 0.0, 0.0, 100.0);
    }
    let n = f32(STAR_CELLS);
    let i = min(u32((uu + 1.0) * 0.5 * n), STAR_CELLS - 1u);
    let j = min(u32((vv + 1.0) * 0.5 * n), STAR_CELLS - 1u);
    let h0 = night_pcg((face * STAR_CELLS + j) * STAR_CELLS + i);
    if (h0 >= STAR_THRESHOLD) {
        return vec4<f32>(0.0, 0.0, 0.0, 100.0);
    }
    let h1 = night_pcg(h0);
    let h2 = night_pcg(h1);
    let h3 = night_pcg(h2);
    let su = (f32(i) + 0.2 + 0.6 * night_unit(h1)) / n * 2.0 - 1.0;
    let sv = (f32(j) + 0.2 + 0.6 * night_unit(h2)) / n * 2.0 - 1.0;
    let sign_ = select(1.0, -1.0, face % 2u == 1u);
    var s = vec3<f32>(su, sv, sign_);
    if (face / 2u == 0u) {
        s = vec3<f32>(sign_, su, sv);
    } else if (face / 2u == 1u) {
        s = vec3<f32>(su, sign_, sv);
    }
    let magnitude = max(6.5 + log2(max(night_unit(h3), 1e-7)) * NIGHT_LOG10_2 / 0.48, -1.5);
    return vec4<f32>(normalize(s), magnitude);
}

fn night_extinction(mu: f32) -> vec3<f32> {
    let air_mass = 1.0 / (mu + 0.025 * exp(-11.0 * mu));
    return pow(frame.zenith_transmittance, vec3<f32>(air_mass));
}

// Stars and airglow towards `d` (zero below the horizon), after the air's extinction.
fn star_field(d: vec3<f32>) -> vec3<f32> {
    if (d.y <= 0.0 || (frame.star_radiance <= 0.0 && all(frame.airglow == vec3<f32>(0.0)))) {
        return vec3<f32>(0.0);
    }
    let van_rhijn = 1.0 / sqrt(1.0 - VAN_RHIJN_K * (1.0 - d.y * d.y));
    var light = frame.airglow * van_rhijn;
    if (frame.star_radiance > 0.0) {
        let c = vec3<f32>(
            dot(d, frame.celestial_x.xyz),
            dot(d, frame.celestial_y.xyz),
            dot(d, frame.celestial_z.xyz),
        );
        let star = cell_star(c);
        let x = cross(c, star.xyz);
        if (star.w < 99.0 && dot(c, star.xyz) > 0.0
            && dot(x, x) <= frame.star_sin_radius * frame.star_sin_radius) {
            light += vec3<f32>(frame.star_radiance * exp2(-0.4 * star.w * NIGHT_LOG2_10));
        }
    }
    return light * night_extinction(d.y);
}

fn night_radiance(d: vec3<f32>) -> vec3<f32> {
    return second_disc(d) + star_field(d) + moon_view_radiance(frame.moon_sky, d);
}
