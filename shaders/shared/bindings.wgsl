// The scene bindings every tracing pass sees (group 0), in the order of
// engine/src/render/gpu/bindings.rs. All scene buffers are read-only; the film and the ray
// counters are written.

@group(0) @binding(0) var<uniform> frame: GpuFrameUniforms;
@group(0) @binding(1) var<storage, read> nodes: array<GpuBvh8Node>;
@group(0) @binding(2) var<storage, read> blocks: array<GpuTri4>;
@group(0) @binding(3) var<storage, read> instances: array<GpuInstance>;
@group(0) @binding(4) var<storage, read> triangles: array<GpuTriangle>;
@group(0) @binding(5) var<storage, read> vertices: array<GpuVertex>;
@group(0) @binding(6) var<storage, read> materials: array<GpuMaterial>;
@group(0) @binding(7) var<storage, read> textures: array<GpuTexture>;
@group(0) @binding(8) var<storage, read> texels: array<vec2<u32>>;
@group(0) @binding(9) var<storage, read> lights: array<GpuLight>;
// The converged mean radiance per pixel (rgb), rows top to bottom.
@group(0) @binding(10) var<storage, read_write> film: array<vec4<f32>>;
// Rays traced: camera, bounce, shadow; and dropped (non-finite) samples.
@group(0) @binding(11) var<storage, read_write> counters: array<atomic<u32>, 4>;
// The work units this pass renders: their count, then each unit's index (UNIT_ROWS rows each).
@group(0) @binding(12) var<storage, read> work_units: array<u32>;
// The light tree (engine/src/scene/light_tree.rs): its nodes, root first.
@group(0) @binding(13) var<storage, read> light_nodes: array<GpuLightNode>;
// The hit lookup: [0] instances covered, [1 + i] instance i's table (INVALID: none), then per
// mesh-local triangle its leaf node or INVALID.
@group(0) @binding(14) var<storage, read> light_lookup: array<u32>;
// The line emitters the camera sees prefiltered (engine/src/scene/lines.rs): MAX_LINES + 1
// entries, the scene's first; a zero radius ends the list.
@group(0) @binding(15) var<storage, read> lines: array<GpuLine>;
// The physical sky's sky-view table (engine/src/scene/sky_table.rs): always SKY_VIEW_WIDTH ×
// SKY_VIEW_HEIGHT texels, rgb radiance + padding, row-major; zeros when the sky is not physical;
// then the cloud layer's optical depths, four to a texel (shared/clouds.wgsl).
@group(0) @binding(16) var<storage, read> sky_view: array<vec4<f32>>;
