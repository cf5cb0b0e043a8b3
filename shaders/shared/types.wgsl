// Twins of the `Gpu…` structs in engine/src/layout.rs: same names, field order, sizes.
// tests/cross/layout.rs parses this file with naga and compares every size and offset.
// Conventions: right-handed, +Y up, metres; colours are linear Rec.709 radiance.

const INVALID: u32 = 0xffffffffu;
const LEAF_BIT: u32 = 0x80000000u;
// A BLAS leaf payload is (blocks - 1) << LEAF_COUNT_SHIFT | first block (engine/src/layout.rs).
const LEAF_COUNT_SHIFT: u32 = 29u;
const LEAF_INDEX_MASK: u32 = 0x1fffffffu;
const MAX_LEAF_BLOCKS: u32 = 4u;
// Pixel rows per work unit (engine/src/layout.rs UNIT_ROWS); trace_main renders listed units.
const UNIT_ROWS: u32 = 4u;

const INSTANCE_FLAG_IDENTITY: u32 = 1u;
const INSTANCE_FLAG_EMISSION_OFF: u32 = 2u;
const INSTANCE_FLAG_UNSAMPLED: u32 = 4u;

const MATERIAL_DIFFUSE: u32 = 0u;
const MATERIAL_CONDUCTOR: u32 = 1u;
const MATERIAL_DIELECTRIC: u32 = 2u;
const MATERIAL_METAL_ROUGH: u32 = 3u;
const MATERIAL_FLAG_TWO_SIDED_EMISSION: u32 = 1u;
const MATERIAL_FLAG_LINE: u32 = 2u;
// Most line emitters a render sees (engine/src/scene/lines.rs MAX_LINES).
const MAX_LINES: u32 = 256u;

const WRAP_REPEAT: u32 = 0u;
const WRAP_CLAMP: u32 = 1u;
const WRAP_MIRROR: u32 = 2u;
const TEXTURE_FLAG_NEAREST: u32 = 16u;
const TEXTURE_LEVELS_SHIFT: u32 = 8u;
const TEXTURE_LEVELS_MASK: u32 = 31u;

const METHOD_NEE: u32 = 1u;
const METHOD_MIS: u32 = 2u;
const METHOD_LIGHTS_BY_POWER: u32 = 4u;
const METHOD_LIGHT_TREE: u32 = 8u;
const METHOD_SINGLE_PICK: u32 = 16u;
const METHOD_INDIRECT_HALF: u32 = 32u;
const METHOD_INDIRECT_QUARTER: u32 = 64u;

const LIGHT_NODE_LEAF: u32 = 1u;
const LIGHT_NODE_TWO_SIDED: u32 = 2u;

const SKY_CONSTANT: u32 = 0u;
const SKY_GRADIENT: u32 = 1u;
const SKY_PHYSICAL: u32 = 2u;
const STAR_CELLS: u32 = 128u;
const STAR_THRESHOLD: u32 = 393400000u;
// The sky-view table's nodes (engine/src/sky/sky_view.rs VIEW_WIDTH, VIEW_HEIGHT).
const SKY_VIEW_WIDTH: u32 = 128u;
const SKY_VIEW_HEIGHT: u32 = 129u;

// Eight lanes as two vec4 halves (lanes 0-3, 4-7): the same bytes as Rust's [f32; 8], loaded
// four lanes at a time.
struct GpuBvh8Node {
    min_x: array<vec4<f32>, 2>,
    max_x: array<vec4<f32>, 2>,
    min_y: array<vec4<f32>, 2>,
    max_y: array<vec4<f32>, 2>,
    min_z: array<vec4<f32>, 2>,
    max_z: array<vec4<f32>, 2>,
    child: array<vec4<u32>, 2>,
    perm: array<vec4<u32>, 2>,
}

struct GpuTri4 {
    v0_x: vec4<f32>,
    v0_y: vec4<f32>,
    v0_z: vec4<f32>,
    e1_x: vec4<f32>,
    e1_y: vec4<f32>,
    e1_z: vec4<f32>,
    e2_x: vec4<f32>,
    e2_y: vec4<f32>,
    e2_z: vec4<f32>,
    prim: vec4<u32>,
}

struct GpuInstance {
    world_from_object: array<vec4<f32>, 3>,
    object_from_world: array<vec4<f32>, 3>,
    node_base: u32,
    block_base: u32,
    triangle_base: u32,
    vertex_base: u32,
    material_override: u32,
    flags: u32,
    _padding: vec2<u32>,
}

struct GpuTriangle {
    indices: array<u32, 3>,
    material: u32,
}

struct GpuVertex {
    position: array<f32, 3>,
    u: f32,
    normal: array<f32, 3>,
    v: f32,
    tangent: vec4<f32>,
}

struct GpuMaterial {
    base_color: vec4<f32>,
    emission: vec4<f32>,
    absorption: vec4<f32>,
    kind: u32,
    roughness: f32,
    metallic: f32,
    ior: f32,
    transmission: f32,
    normal_scale: f32,
    flags: u32,
    base_color_texture: u32,
    normal_texture: u32,
    emission_texture: u32,
    metal_rough_texture: u32,
    _padding: u32,
}

struct GpuTexture {
    texel_offset: u32,
    width: u32,
    height: u32,
    flags: u32,
}

struct GpuLight {
    p0: vec3<f32>,
    instance: u32,
    p1: vec3<f32>,
    triangle: u32,
    p2: vec3<f32>,
    weight: f32,
    alias_threshold: f32,
    alias_index: u32,
    _padding: vec2<u32>,
}

// One node of the light tree: box, power and normal cone of the emitters below. Interior: the
// first child is the next node, the second `child`; leaf: `child` is the light index.
// A thin emissive line seen from the camera (engine/src/layout.rs GpuLine).
struct GpuLine {
    start: vec3<f32>,
    radius: f32,
    end: vec3<f32>,
    _padding: u32,
    radiance: vec4<f32>,
}

struct GpuLightNode {
    bounds_min: vec3<f32>,
    phi: f32,
    bounds_max: vec3<f32>,
    cos_theta_o: f32,
    axis: vec3<f32>,
    cos_theta_e: f32,
    child: u32,
    parent: u32,
    flags: u32,
    _padding: u32,
}

struct GpuFrameUniforms {
    camera_position: vec3<f32>,
    lens_radius: f32,
    camera_right: vec3<f32>,
    focus_distance: f32,
    camera_up: vec3<f32>,
    film_blend: f32,
    camera_forward: vec3<f32>,
    method: u32,
    sun_direction: vec3<f32>,
    sun_cos_radius: f32,
    sun_radiance: vec3<f32>,
    sun_solid_angle: f32,
    sky_zenith: vec4<f32>,
    sky_horizon: vec4<f32>,
    sky_ground: vec4<f32>,
    width: u32,
    height: u32,
    spp: u32,
    sample_base: u32,
    seed: u32,
    max_bounces: u32,
    roulette_start: u32,
    light_count: u32,
    light_weight_total: f32,
    roulette_scale: f32,
    sky_kind: u32,
    tlas_root: u32,
    sun_terminator: vec3<f32>,
    sun_sin_radius: f32,
    second_direction: vec3<f32>,
    second_cos_radius: f32,
    second_radiance: vec3<f32>,
    second_sin_radius: f32,
    second_terminator: vec3<f32>,
    star_radiance: f32,
    airglow: vec3<f32>,
    star_sin_radius: f32,
    zenith_transmittance: vec3<f32>,
    pixel_jitter: u32,
    celestial_x: vec4<f32>,
    celestial_y: vec4<f32>,
    celestial_z: vec4<f32>,
    cloud_plane: vec4<f32>,
    cloud_light: vec3<f32>,
    cloud_texels: u32,
    moon_sky: vec4<f32>,
}

struct GpuRay {
    origin: vec3<f32>,
    t_min: f32,
    direction: vec3<f32>,
    t_max: f32,
}

struct GpuHit {
    t: f32,
    u: f32,
    v: f32,
    instance: u32,
    triangle: u32,
    _padding: array<u32, 3>,
}

struct GpuPresentUniforms {
    film_width: u32,
    film_height: u32,
    target_width: u32,
    target_height: u32,
    exposure_scale: f32,
    filmic: u32,
    encode_srgb: u32,
    _padding: u32,
}

struct GpuDenoiseUniforms {
    width: u32,
    height: u32,
    step: u32,
    remodulate: u32,
    blend: f32,
    sigma_z: f32,
    sigma_l: f32,
    radius: u32,
}

struct GpuReprojectUniforms {
    camera_position: vec3<f32>,
    mode: u32,
    camera_forward: vec3<f32>,
    instances: u32,
    camera_right: vec3<f32>,
    jitter_x: f32,
    camera_up: vec3<f32>,
    jitter_y: f32,
    prev_position: vec3<f32>,
    prev_width: u32,
    prev_forward: vec3<f32>,
    prev_height: u32,
    prev_right: vec3<f32>,
    prev_jitter_x: f32,
    prev_up: vec3<f32>,
    prev_jitter_y: f32,
}

struct GpuMotion {
    prev_from_now: array<vec4<f32>, 3>,
    now_from_prev: array<vec4<f32>, 3>,
}
