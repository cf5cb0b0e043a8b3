// Two-level BVH8 traversal (TLAS over instances, one BLAS per mesh), twin of the scalar
// traversal in engine/src/trace/ (same tree, same order, same triangle test). Octant-ordered slab test: the near plane of each child box
// is read from min or max by the sign of the ray direction, children are visited in the
// node's precomputed front-to-back order for the ray's octant (GpuBvh8Node::perm), and a
// short stack holds (entry, entry distance) pairs so that far entries are culled when popped.

// 7 * (MAX_DEPTH - 1) + 8 entries fit (engine/src/accel/mod.rs), as in the CPU traversal.
const STACK_SIZE: u32 = 256u;

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

fn safe_rcp(d: vec3<f32>) -> vec3<f32> {
    let tiny = select(vec3<f32>(1e-20), vec3<f32>(-1e-20), d < vec3<f32>(0.0));
    return 1.0 / select(d, tiny, abs(d) < vec3<f32>(1e-20));
}

fn ray_octant(d: vec3<f32>) -> u32 {
    return select(0u, 1u, d.x < 0.0) | select(0u, 2u, d.y < 0.0) | select(0u, 4u, d.z < 0.0);
}

// Möller–Trumbore, two-sided, over the four lanes of a leaf block.
fn intersect_block(block_index: u32, o: vec3<f32>, d: vec3<f32>, t_min: f32, t_max: f32) -> BlasHit {
    var best = BlasHit(t_max, 0.0, 0.0, INVALID, false);
    let b = blocks[block_index];
    for (var k = 0u; k < 4u; k++) {
        if (b.prim[k] == INVALID) {
            continue;
        }
        let v0 = vec3<f32>(b.v0_x[k], b.v0_y[k], b.v0_z[k]);
        let e1 = vec3<f32>(b.e1_x[k], b.e1_y[k], b.e1_z[k]);
        let e2 = vec3<f32>(b.e2_x[k], b.e2_y[k], b.e2_z[k]);
        let pvec = cross(d, e2);
        let det = dot(e1, pvec);
        if (det == 0.0) {
            continue;
        }
        let inv = 1.0 / det;
        let tvec = o - v0;
        let u = dot(tvec, pvec) * inv;
        if (!(u >= 0.0 && u <= 1.0)) {
            continue;
        }
        let qvec = cross(tvec, e1);
        let v = dot(d, qvec) * inv;
        if (!(v >= 0.0 && u + v <= 1.0)) {
            continue;
        }
        let t = dot(e2, qvec) * inv;
        if (t > t_min && t < best.t) {
            best = BlasHit(t, u, v, b.prim[k], true);
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
    var o = ray.origin;
    var d = ray.direction;
    var rcp = safe_rcp(d);
    var shift = 3u * ray_octant(d);
    var neg = d < vec3<f32>(0.0);
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
            o = ray.origin;
            d = ray.direction;
            rcp = safe_rcp(d);
            shift = 3u * ray_octant(d);
            neg = d < vec3<f32>(0.0);
            node_base = frame.tlas_root;
        }
        if (sp == 0u) {
            break;
        }
        sp -= 1u;
        let entry = stack_entry[sp];
        let entry_t = stack_t[sp];
        if (entry_t > hit.t) {
            continue;
        }
        if ((entry & LEAF_BIT) != 0u) {
            let payload = entry & ~LEAF_BIT;
            if (in_blas) {
                let b = intersect_block(block_base + payload, o, d, ray.t_min, hit.t);
                if (b.found) {
                    hit = Hit(b.t, b.u, b.v, instance, b.prim, true);
                    if (any_hit) {
                        return hit;
                    }
                }
                continue;
            }
            // Enter instance `payload`: its BLAS root goes on the stack.
            let inst = instances[payload];
            if ((inst.flags & INSTANCE_FLAG_IDENTITY) == 0u) {
                let q = vec4<f32>(ray.origin, 1.0);
                let r = inst.object_from_world;
                o = vec3<f32>(dot(r[0], q), dot(r[1], q), dot(r[2], q));
                d = vec3<f32>(dot(r[0].xyz, ray.direction), dot(r[1].xyz, ray.direction), dot(r[2].xyz, ray.direction));
                rcp = safe_rcp(d);
                shift = 3u * ray_octant(d);
                neg = d < vec3<f32>(0.0);
            }
            node_base = inst.node_base;
            block_base = inst.block_base;
            instance = payload;
            in_blas = true;
            blas_floor = sp;
            stack_entry[sp] = 0u;
            stack_t[sp] = entry_t;
            sp += 1u;
            continue;
        }
        let n = node_base + entry;
        // Push in reverse front-to-back order so the nearest child is popped first.
        for (var i = 0u; i < 8u; i++) {
            let slot = (nodes[n].perm[7u - i] >> shift) & 7u;
            let child = nodes[n].child[slot];
            if (child == INVALID) {
                continue;
            }
            let lo = vec3<f32>(nodes[n].min_x[slot], nodes[n].min_y[slot], nodes[n].min_z[slot]);
            let hi = vec3<f32>(nodes[n].max_x[slot], nodes[n].max_y[slot], nodes[n].max_z[slot]);
            let t0 = (select(lo, hi, neg) - o) * rcp;
            let t1 = (select(hi, lo, neg) - o) * rcp;
            let tn = max(max(t0.x, t0.y), max(t0.z, ray.t_min));
            let tf = min(min(t1.x, t1.y), min(t1.z, hit.t));
            if (tn <= tf && sp < STACK_SIZE) {
                stack_entry[sp] = child;
                stack_t[sp] = tn;
                sp += 1u;
            }
        }
    }
    return hit;
}
