// Two-level BVH8 traversal (TLAS over instances, one BLAS per mesh), twin of the scalar
// traversal in engine/src/trace/. Octant-ordered slab test: the near plane of each child box
// is read from min or max by the sign of the ray direction, children are visited in the
// node's precomputed front-to-back order for the ray's octant (GpuBvh8Node::perm), and a
// short stack holds (entry, entry distance) pairs so that far entries are culled when popped.

const STACK_SIZE: u32 = 96u;

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
fn intersect_block(block_index: u32, o: vec3<f32>, d: vec3<f32>, t_min: f32, best: ptr<function, BlasHit>, any_hit: bool) {
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
        if (t > t_min && t < (*best).t) {
            *best = BlasHit(t, u, v, b.prim[k], true);
            if (any_hit) {
                return;
            }
        }
    }
}

// Closest (or, with any_hit, first found) hit in one BLAS, in its object space.
fn traverse_blas(node_base: u32, block_base: u32, o: vec3<f32>, d: vec3<f32>, t_min: f32, t_max: f32, any_hit: bool) -> BlasHit {
    var best = BlasHit(t_max, 0.0, 0.0, INVALID, false);
    let rcp = safe_rcp(d);
    let oct = ray_octant(d);
    let shift = 3u * oct;
    let neg = d < vec3<f32>(0.0);
    var stack_entry: array<u32, STACK_SIZE>;
    var stack_t: array<f32, STACK_SIZE>;
    var sp = 1u;
    stack_entry[0] = 0u;
    stack_t[0] = t_min;
    while (sp > 0u) {
        sp -= 1u;
        let entry = stack_entry[sp];
        if (stack_t[sp] > best.t) {
            continue;
        }
        if ((entry & LEAF_BIT) != 0u) {
            intersect_block(block_base + (entry & ~LEAF_BIT), o, d, t_min, &best, any_hit);
            if (any_hit && best.found) {
                return best;
            }
            continue;
        }
        let node = nodes[node_base + entry];
        // Push in reverse front-to-back order so the nearest child is popped first.
        for (var i = 0; i < 8; i++) {
            let slot = (node.perm[7 - i] >> shift) & 7u;
            let child = node.child[slot];
            if (child == INVALID) {
                continue;
            }
            let near = vec3<f32>(
                select(node.min_x[slot], node.max_x[slot], neg.x),
                select(node.min_y[slot], node.max_y[slot], neg.y),
                select(node.min_z[slot], node.max_z[slot], neg.z),
            );
            let far = vec3<f32>(
                select(node.max_x[slot], node.min_x[slot], neg.x),
                select(node.max_y[slot], node.min_y[slot], neg.y),
                select(node.max_z[slot], node.min_z[slot], neg.z),
            );
            let t0 = (near - o) * rcp;
            let t1 = (far - o) * rcp;
            let tn = max(max(t0.x, t0.y), max(t0.z, t_min));
            let tf = min(min(t1.x, t1.y), min(t1.z, best.t));
            if (tn <= tf && sp < STACK_SIZE) {
                stack_entry[sp] = child;
                stack_t[sp] = tn;
                sp += 1u;
            }
        }
    }
    return best;
}

// The scene: TLAS at frame.tlas_root, BLAS per instance.
fn trace_ray(ray: Ray, any_hit: bool) -> Hit {
    var hit = Hit(ray.t_max, 0.0, 0.0, INVALID, INVALID, false);
    let o = ray.origin;
    let d = ray.direction;
    let rcp = safe_rcp(d);
    let shift = 3u * ray_octant(d);
    let neg = d < vec3<f32>(0.0);
    let root = frame.tlas_root;
    var stack_entry: array<u32, 64>;
    var stack_t: array<f32, 64>;
    var sp = 1u;
    stack_entry[0] = 0u;
    stack_t[0] = ray.t_min;
    while (sp > 0u) {
        sp -= 1u;
        let entry = stack_entry[sp];
        if (stack_t[sp] > hit.t) {
            continue;
        }
        if ((entry & LEAF_BIT) != 0u) {
            let index = entry & ~LEAF_BIT;
            let inst = instances[index];
            var lo = o;
            var ld = d;
            if ((inst.flags & INSTANCE_FLAG_IDENTITY) == 0u) {
                let q = vec4<f32>(o, 1.0);
                lo = vec3<f32>(dot(inst.object_from_world[0], q), dot(inst.object_from_world[1], q), dot(inst.object_from_world[2], q));
                ld = vec3<f32>(dot(inst.object_from_world[0].xyz, d), dot(inst.object_from_world[1].xyz, d), dot(inst.object_from_world[2].xyz, d));
            }
            let b = traverse_blas(inst.node_base, inst.block_base, lo, ld, ray.t_min, hit.t, any_hit);
            if (b.found) {
                hit = Hit(b.t, b.u, b.v, index, b.prim, true);
                if (any_hit) {
                    return hit;
                }
            }
            continue;
        }
        let node = nodes[root + entry];
        for (var i = 0; i < 8; i++) {
            let slot = (node.perm[7 - i] >> shift) & 7u;
            let child = node.child[slot];
            if (child == INVALID) {
                continue;
            }
            let near = vec3<f32>(
                select(node.min_x[slot], node.max_x[slot], neg.x),
                select(node.min_y[slot], node.max_y[slot], neg.y),
                select(node.min_z[slot], node.max_z[slot], neg.z),
            );
            let far = vec3<f32>(
                select(node.max_x[slot], node.min_x[slot], neg.x),
                select(node.max_y[slot], node.min_y[slot], neg.y),
                select(node.max_z[slot], node.min_z[slot], neg.z),
            );
            let t0 = (near - o) * rcp;
            let t1 = (far - o) * rcp;
            let tn = max(max(t0.x, t0.y), max(t0.z, ray.t_min));
            let tf = min(min(t1.x, t1.y), min(t1.z, hit.t));
            if (tn <= tf && sp < 64u) {
                stack_entry[sp] = child;
                stack_t[sp] = tn;
                sp += 1u;
            }
        }
    }
    return hit;
}
