// Two-level BVH8 traversal (TLAS over instances, one BLAS per mesh), twin of the scalar
// reference in engine/src/trace/ (scalar.rs, ray.rs, triangle.rs): the same conservative slab
// test (safe reciprocals, far side widened by ROBUST_FAR and an absolute margin, one fused
// multiply-add per plane), the same front-to-back child order per ray octant (GpuBvh8Node::perm),
// the same culling of popped entries, and the same watertight-style triangle test with the same
// fused multiply-adds, so that both tracers find the same hits.

// 7 * (MAX_DEPTH - 1) + 8 entries fit (engine/src/accel/mod.rs), as in the CPU traversal.
const STACK_SIZE: u32 = 256u;
// engine/src/trace/ray.rs: RCP_MIN_ABS, ROBUST_FAR (1 + 2^-21).
const RCP_MIN_ABS: f32 = 1e-30;
const ROBUST_FAR: f32 = 1.000000476837158;
// engine/src/trace/triangle.rs: DEGENERATE_RATIO (2^-18), SLACK_SCALE (2^-21), EDGE_SLACK (2^-20).
const DEGENERATE_RATIO: f32 = 3.814697265625e-6;
const SLACK_SCALE: f32 = 4.76837158203125e-7;
const EDGE_SLACK: f32 = 9.5367431640625e-7;

struct Ray {
    origin: vec3<f32>,
    t_min: f32,
    direction: vec3<f32>,
    t_max: f32,
}

struct Hit {
    t: f32,
    u: f32,
    v: f32,
    instance: u32,
    triangle: u32,
    found: bool,
}

struct BlasHit {
    t: f32,
    u: f32,
    v: f32,
    prim: u32,
    found: bool,
}

// Per-ray constants of the slab test (engine/src/trace/ray.rs, SlabRay).
struct SlabRay {
    rcp: vec3<f32>,
    near_orcp: vec3<f32>,
    far_rcp: vec3<f32>,
    far_sub: vec3<f32>,
    margin: f32,
    octant: u32,
}

fn sign_bits(d: vec3<f32>) -> vec3<bool> {
    return (bitcast<vec3<u32>>(d) >> vec3<u32>(31u)) == vec3<u32>(1u);
}

fn slab_ray(o: vec3<f32>, d: vec3<f32>) -> SlabRay {
    var s: SlabRay;
    var far_orcp: vec3<f32>;
    var largest = 0.0;
    let negative = sign_bits(d);
    for (var axis = 0u; axis < 3u; axis++) {
        if (abs(d[axis]) < RCP_MIN_ABS) {
            let sign = select(1.0, -1.0, negative[axis]);
            let delta = abs(o[axis]) * (1.0 / 1048576.0) + 1e-20;
            s.rcp[axis] = sign * (1.0 / RCP_MIN_ABS);
            s.near_orcp[axis] = (o[axis] + sign * delta) * s.rcp[axis];
            far_orcp[axis] = (o[axis] - sign * delta) * s.rcp[axis];
        } else {
            s.rcp[axis] = 1.0 / d[axis];
            s.near_orcp[axis] = o[axis] * s.rcp[axis];
            far_orcp[axis] = s.near_orcp[axis];
            largest = max(largest, abs(s.near_orcp[axis]));
        }
    }
    s.margin = largest * (1.0 / 1048576.0);
    s.far_rcp = s.rcp * ROBUST_FAR;
    s.far_sub = fma(far_orcp, vec3<f32>(ROBUST_FAR), vec3<f32>(-s.margin));
    s.octant = select(0u, 1u, negative.x) | select(0u, 2u, negative.y) | select(0u, 4u, negative.z);
    return s;
}

fn far_limit(s: SlabRay, t: f32) -> f32 {
    return fma(t, ROBUST_FAR, s.margin);
}

// Per-ray constants of the triangle test (engine/src/trace/triangle.rs, TriRay): axes permuted
// so that k.z is the dominant direction axis, origin in that order, shear.
struct TriRay {
    k: vec3<u32>,
    origin: vec3<f32>,
    shear: vec3<f32>,
}

fn tri_ray(o: vec3<f32>, d: vec3<f32>) -> TriRay {
    let a = abs(d);
    var kz = 2u;
    if (a.x >= a.y && a.x >= a.z) {
        kz = 0u;
    } else if (a.y >= a.z) {
        kz = 1u;
    }
    let kx = (kz + 1u) % 3u;
    let ky = (kx + 1u) % 3u;
    let sz = 1.0 / d[kz];
    return TriRay(vec3<u32>(kx, ky, kz), vec3<f32>(o[kx], o[ky], o[kz]), vec3<f32>(d[kx] * sz, d[ky] * sz, sz));
}

// Closest hit among the four lanes of a leaf block in (t_min, t_max).
fn intersect_block(block_index: u32, r: TriRay, t_min: f32, t_max: f32) -> BlasHit {
    var best = BlasHit(t_max, 0.0, 0.0, INVALID, false);
    let b = blocks[block_index];
    let k = r.k;
    for (var lane = 0u; lane < 4u; lane++) {
        if (b.prim[lane] == INVALID) {
            continue;
        }
        let v0f = vec3<f32>(b.v0_x[lane], b.v0_y[lane], b.v0_z[lane]);
        let e1f = vec3<f32>(b.e1_x[lane], b.e1_y[lane], b.e1_z[lane]);
        let e2f = vec3<f32>(b.e2_x[lane], b.e2_y[lane], b.e2_z[lane]);
        let v0 = vec3<f32>(v0f[k.x], v0f[k.y], v0f[k.z]);
        let e1 = vec3<f32>(e1f[k.x], e1f[k.y], e1f[k.z]);
        let e2 = vec3<f32>(e2f[k.x], e2f[k.y], e2f[k.z]);
        let a = v0 - r.origin;
        let ax = fma(-r.shear.x, a.z, a.x);
        let ay = fma(-r.shear.y, a.z, a.y);
        let e1x = fma(-r.shear.x, e1.z, e1.x);
        let e1y = fma(-r.shear.y, e1.z, e1.y);
        let e2x = fma(-r.shear.x, e2.z, e2.x);
        let e2y = fma(-r.shear.y, e2.z, e2.y);
        let w1 = fma(ax, e2y, -(ay * e2x));
        let w2 = fma(e1x, ay, -(e1y * ax));
        let p2 = e2y * e1x;
        let det = fma(e2x, e1y, -p2);
        let bound = abs(p2) * DEGENERATE_RATIO;
        let inv_det = 1.0 / det;
        let u = w1 * inv_det;
        let v = w2 * inv_det;
        let t = fma(v, e2.z, fma(u, e1.z, a.z)) * r.shear.z;
        // The watertight rounding-error slack per edge, in triangle.rs's order.
        let c = (abs(ax) + abs(ay) + abs(a.z)) * (abs(inv_det) * SLACK_SCALE);
        let len1 = abs(e1x) + abs(e1y) + abs(e1.z);
        let len2 = abs(e2x) + abs(e2y) + abs(e2.z);
        // u >= -(c·len2 + EDGE_SLACK) tested as c·len2 + u >= -EDGE_SLACK, as triangle.rs.
        let inside_u = fma(c, len2, u) >= -EDGE_SLACK;
        let inside_v = fma(c, len1, v) >= -EDGE_SLACK;
        let inside_w = fma(-c, len1 + len2, u + v) <= 1.0 + EDGE_SLACK;
        if (abs(det) > bound && inside_u && inside_v && inside_w && t > t_min && t < best.t) {
            best = BlasHit(t, u, v, b.prim[lane], true);
        }
    }
    return best;
}

// Closest (or, with any_hit, first found) hit in the scene: the TLAS at frame.tlas_root, then
// the BLAS of each instance it reaches. One loop and one stack serve both levels (lavapipe
// inlines every call, so one traversal loop keeps the compiled shader small): entering an
// instance remembers the stack depth, and when the stack drops back to it the world-space ray
// is restored and the TLAS traversal resumes.
fn trace_ray(ray: Ray, any_hit: bool) -> Hit {
    var hit = Hit(ray.t_max, 0.0, 0.0, INVALID, INVALID, false);
    let world_slab = slab_ray(ray.origin, ray.direction);
    var slab = world_slab;
    var tri = tri_ray(ray.origin, ray.direction);
    var node_base = frame.tlas_root;
    var block_base = 0u;
    var instance = INVALID;
    var in_blas = false;
    var blas_floor = 0u;
    var stack_entry: array<u32, STACK_SIZE>;
    var stack_t: array<f32, STACK_SIZE>;
    var sp = 1u;
    stack_entry[0] = 0u;
    stack_t[0] = ray.t_min;
    loop {
        if (in_blas && sp == blas_floor) {
            // This instance is done: back to the TLAS in world space.
            in_blas = false;
            slab = world_slab;
            node_base = frame.tlas_root;
        }
        if (sp == 0u) {
            break;
        }
        sp -= 1u;
        let entry = stack_entry[sp];
        let entry_t = stack_t[sp];
        if (!(entry_t <= far_limit(slab, hit.t))) {
            continue;
        }
        if ((entry & LEAF_BIT) != 0u) {
            let payload = entry & ~LEAF_BIT;
            if (in_blas) {
                // The leaf's consecutive blocks, in order (engine/src/trace/scalar.rs, leaf_blocks).
                let first = block_base + (payload & LEAF_INDEX_MASK);
                let count = (payload >> LEAF_COUNT_SHIFT) + 1u;
                for (var k = 0u; k < count; k++) {
                    let b = intersect_block(first + k, tri, ray.t_min, hit.t);
                    if (b.found) {
                        hit = Hit(b.t, b.u, b.v, instance, b.prim, true);
                        if (any_hit) {
                            return hit;
                        }
                    }
                }
                continue;
            }
            // Enter instance `payload` (engine/src/trace/ray.rs, to_object_space).
            let inst = instances[payload];
            var o = ray.origin;
            var d = ray.direction;
            if ((inst.flags & INSTANCE_FLAG_IDENTITY) == 0u) {
                let m = inst.object_from_world;
                o = vec3<f32>(
                    m[0].x * o.x + m[0].y * o.y + m[0].z * o.z + m[0].w,
                    m[1].x * o.x + m[1].y * o.y + m[1].z * o.z + m[1].w,
                    m[2].x * o.x + m[2].y * o.y + m[2].z * o.z + m[2].w,
                );
                d = vec3<f32>(
                    m[0].x * d.x + m[0].y * d.y + m[0].z * d.z,
                    m[1].x * d.x + m[1].y * d.y + m[1].z * d.z,
                    m[2].x * d.x + m[2].y * d.y + m[2].z * d.z,
                );
            }
            slab = slab_ray(o, d);
            tri = tri_ray(o, d);
            node_base = inst.node_base;
            block_base = inst.block_base;
            instance = payload;
            in_blas = true;
            blas_floor = sp;
            stack_entry[sp] = 0u;
            stack_t[sp] = ray.t_min;
            sp += 1u;
            continue;
        }
        let n = node_base + entry;
        let shift = 3u * slab.octant;
        let neg = vec3<bool>((slab.octant & 1u) != 0u, (slab.octant & 2u) != 0u, (slab.octant & 4u) != 0u);
        let t_limit = far_limit(slab, hit.t);
        // All eight slab tests four lanes at a time (a node is 16 vec4 loads).
        var t_near: array<vec4<f32>, 2>;
        var accept: array<vec4<bool>, 2>;
        for (var h = 0u; h < 2u; h++) {
            let min_x = nodes[n].min_x[h];
            let max_x = nodes[n].max_x[h];
            let min_y = nodes[n].min_y[h];
            let max_y = nodes[n].max_y[h];
            let min_z = nodes[n].min_z[h];
            let max_z = nodes[n].max_z[h];
            let near_x = fma(select(min_x, max_x, neg.x), vec4<f32>(slab.rcp.x), vec4<f32>(-slab.near_orcp.x));
            let near_y = fma(select(min_y, max_y, neg.y), vec4<f32>(slab.rcp.y), vec4<f32>(-slab.near_orcp.y));
            let near_z = fma(select(min_z, max_z, neg.z), vec4<f32>(slab.rcp.z), vec4<f32>(-slab.near_orcp.z));
            let far_x = fma(select(max_x, min_x, neg.x), vec4<f32>(slab.far_rcp.x), vec4<f32>(-slab.far_sub.x));
            let far_y = fma(select(max_y, min_y, neg.y), vec4<f32>(slab.far_rcp.y), vec4<f32>(-slab.far_sub.y));
            let far_z = fma(select(max_z, min_z, neg.z), vec4<f32>(slab.far_rcp.z), vec4<f32>(-slab.far_sub.z));
            let tn = max(max(max(near_x, near_y), near_z), vec4<f32>(ray.t_min));
            let tf = min(min(min(far_x, far_y), far_z), vec4<f32>(t_limit));
            t_near[h] = tn;
            accept[h] = (tn <= tf) & (nodes[n].child[h] != vec4<u32>(INVALID));
        }
        let perm = array<vec4<u32>, 2>(nodes[n].perm[0], nodes[n].perm[1]);
        let child = array<vec4<u32>, 2>(nodes[n].child[0], nodes[n].child[1]);
        // Push in reverse front-to-back order so the nearest child is popped first.
        for (var i = 0u; i < 8u; i++) {
            let rank = 7u - i;
            let slot = (perm[rank >> 2u][rank & 3u] >> shift) & 7u;
            let half = slot >> 2u;
            let lane = slot & 3u;
            if (accept[half][lane] && sp < STACK_SIZE) {
                stack_entry[sp] = child[half][lane];
                stack_t[sp] = t_near[half][lane];
                sp += 1u;
            }
        }
    }
    return hit;
}
