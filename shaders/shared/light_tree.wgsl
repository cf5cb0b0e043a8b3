// Sampling the light tree, twin of engine/src/render/cpu/light_tree.rs (PBRT-v4's
// BVHLightSampler::Sample and PMF, LightBounds::Importance). Points in render space, n the
// shading normal.

const LIGHT_ONE_MINUS_EPSILON: f32 = 0.99999994;
const LIGHT_MAX_WALK: u32 = 128u;

fn light_safe_sqrt(x: f32) -> f32 {
    return sqrt(max(x, 0.0));
}

// cos(max(0, θa − θb)).
fn light_cos_sub(sin_a: f32, cos_a: f32, sin_b: f32, cos_b: f32) -> f32 {
    if (cos_a > cos_b) {
        return 1.0;
    }
    return cos_a * cos_b + sin_a * sin_b;
}

// sin(max(0, θa − θb)).
fn light_sin_sub(sin_a: f32, cos_a: f32, sin_b: f32, cos_b: f32) -> f32 {
    if (cos_a > cos_b) {
        return 0.0;
    }
    return sin_a * cos_b - cos_a * sin_b;
}

// PBRT-v4's LightBounds::Importance with every sine and cosine a root of a quantity known
// once p − c is, times 1/|p − c| (the CPU twin packs two nodes' roots into 4-wide ones).
fn light_importance(node: GpuLightNode, p: vec3<f32>, n: vec3<f32>) -> f32 {
    if (!(node.phi > 0.0)) {
        return 0.0;
    }
    let pc = (node.bounds_min + node.bounds_max) * 0.5;
    let to_p = p - pc;
    let len2 = dot(to_p, to_p);
    let r = node.bounds_max - pc;
    let r2 = dot(r, r);
    var along_axis = dot(node.axis, to_p);
    if ((node.flags & LIGHT_NODE_TWO_SIDED) != 0u) {
        along_axis = abs(along_axis);
    }
    let along_normal = abs(dot(n, to_p));
    let roots = sqrt(max(vec4<f32>(len2, len2 - along_axis * along_axis, len2 - r2,
        len2 - along_normal * along_normal), vec4<f32>(0.0)));
    let radius = sqrt(r2);
    let sin_o = light_safe_sqrt(1.0 - node.cos_theta_o * node.cos_theta_o);
    let inv_d2 = 1.0 / max(len2, radius);
    var importance = 0.0;
    if (len2 < r2) {
        // Inside the bounding sphere: cos θ' = 1 and the normal's factor 1.
        if (1.0 <= node.cos_theta_e) {
            return 0.0;
        }
        importance = node.phi * inv_d2;
    } else {
        let inv_len = 1.0 / roots.x;
        let cos_w = along_axis * inv_len;
        let sin_w = roots.y * inv_len;
        let cos_b = roots.z * inv_len;
        let sin_b = radius * inv_len;
        let cos_o = node.cos_theta_o;
        let cos_x = light_cos_sub(sin_w, cos_w, sin_o, cos_o);
        let sin_x = light_sin_sub(sin_w, cos_w, sin_o, cos_o);
        let cos_p = light_cos_sub(sin_x, cos_x, sin_b, cos_b);
        if (!(cos_p > node.cos_theta_e)) {
            return 0.0;
        }
        importance = node.phi * cos_p * inv_d2;
        if (any(n != vec3<f32>(0.0))) {
            let cos_i = along_normal * inv_len;
            let sin_i = roots.w * inv_len;
            importance *= light_cos_sub(sin_i, cos_i, sin_b, cos_b);
        }
    }
    if (!(importance >= 0.0 && importance <= 3.4e38)) {
        return 0.0;
    }
    return importance;
}

struct LightPick {
    found: bool,
    light: u32,
    pmf: f32,
}

// One light for point p (normal n) by one uniform number u: a walk from the root.
fn light_tree_sample(count: u32, p: vec3<f32>, n: vec3<f32>, u_in: f32) -> LightPick {
    let total = arrayLength(&light_nodes);
    var index = 0u;
    var pmf = 1.0;
    var u = u_in;
    for (var step = 0u; step < LIGHT_MAX_WALK; step++) {
        if (index >= total) {
            break;
        }
        let node = light_nodes[index];
        if ((node.flags & LIGHT_NODE_LEAF) != 0u) {
            let reachable = index > 0u || light_importance(node, p, n) > 0.0;
            return LightPick(reachable && node.child < count, node.child, pmf);
        }
        let second = node.child;
        if (index + 1u >= total || second >= total) {
            break;
        }
        let i0 = light_importance(light_nodes[index + 1u], p, n);
        let i1 = light_importance(light_nodes[second], p, n);
        let sum = i0 + i1;
        if (!(sum > 0.0)) {
            break;
        }
        let p0 = i0 / sum;
        if (u < p0) {
            pmf *= p0;
            u = min(u / p0, LIGHT_ONE_MINUS_EPSILON);
            index += 1u;
        } else {
            let p1 = i1 / sum;
            pmf *= p1;
            u = min((u - p0) / p1, LIGHT_ONE_MINUS_EPSILON);
            index = second;
        }
    }
    return LightPick(false, 0u, 0.0);
}

// The leaf of the light on mesh-local `triangle` of `instance`, or INVALID.
fn light_leaf_of(instance: u32, triangle: u32) -> u32 {
    let size = arrayLength(&light_lookup);
    if (instance >= light_lookup[0] || 1u + instance >= size) {
        return INVALID;
    }
    let base = light_lookup[1u + instance];
    if (base == INVALID || base + triangle >= size) {
        return INVALID;
    }
    return light_lookup[base + triangle];
}

// The probability light_tree_sample picks the light of `leaf` from p (normal n).
fn light_tree_pmf(leaf: u32, p: vec3<f32>, n: vec3<f32>) -> f32 {
    let total = arrayLength(&light_nodes);
    if (leaf >= total) {
        return 0.0;
    }
    if (leaf == 0u) {
        return select(0.0, 1.0, light_importance(light_nodes[0], p, n) > 0.0);
    }
    var pmf = 1.0;
    var index = leaf;
    var parent = light_nodes[leaf].parent;
    for (var step = 0u; step < LIGHT_MAX_WALK; step++) {
        if (parent == INVALID) {
            return pmf;
        }
        if (parent + 1u >= total) {
            return 0.0;
        }
        let up = light_nodes[parent];
        if (up.child >= total) {
            return 0.0;
        }
        let i0 = light_importance(light_nodes[parent + 1u], p, n);
        let i1 = light_importance(light_nodes[up.child], p, n);
        let sum = i0 + i1;
        if (!(sum > 0.0)) {
            return 0.0;
        }
        pmf *= select(i1, i0, index == parent + 1u) / sum;
        index = parent;
        parent = up.parent;
    }
    return 0.0;
}
