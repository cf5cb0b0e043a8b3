// Batch ray tracing: one invocation per ray of `batch_rays`, closest hit or any hit (by
// `batch.any_hit`), written to `batch_hits`. Used by benchmarks to measure traversal alone.
// Composed after the shared pieces like trace.wgsl; group 0 is the scene (its film and counter
// bindings are unused here).

struct BatchParams {
    count: u32,
    any_hit: u32,
    _padding: vec2<u32>,
}

@group(1) @binding(0) var<uniform> batch: BatchParams;
@group(1) @binding(1) var<storage, read> batch_rays: array<GpuRay>;
@group(1) @binding(2) var<storage, read_write> batch_hits: array<GpuHit>;

@compute @workgroup_size(64, 1, 1)
fn ray_batch_main(@builtin(global_invocation_id) id: vec3<u32>) {
    let index = id.x + id.y * 65535u * 64u;
    if (index >= batch.count) {
        return;
    }
    let r = batch_rays[index];
    let hit = trace_ray(Ray(r.origin, r.t_min, r.direction, r.t_max), batch.any_hit != 0u);
    var out: GpuHit;
    out.t = hit.t;
    out.u = hit.u;
    out.v = hit.v;
    out.instance = select(INVALID, hit.instance, hit.found);
    out.triangle = select(INVALID, hit.triangle, hit.found);
    batch_hits[index] = out;
}
