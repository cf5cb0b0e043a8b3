//! The flattened scene layout that both tracers read: every `Gpu…` struct of the engine.
//!
//! Owns: the byte layout of the buffers the GPU tracer binds and the CPU tracer walks
//! (BVH nodes, triangle blocks, instances, triangles, vertices, materials, textures, lights,
//! the per-frame uniforms). Each struct here is `#[repr(C)]` + `bytemuck::Pod` with explicit
//! padding and a compile-time size assertion, and has a twin of the same name, field order
//! and size in `shaders/shared/types.wgsl`; `tests/cross/layout.rs` parses the WGSL with naga and
//! compares sizes and offsets of every field.
//!
//! One file past the ~400-line guide on purpose: it is the one twin of `types.wgsl`, so a
//! reader compares the two side by side, struct by struct, in the same order.
//! Must not: hold logic beyond constructors and bit-packing helpers. This file is top-level
//! (not under `render/` or `accel/`) because `accel` writes the BVH structs, `render` writes
//! the rest, and both tracers and `query` read all of them.
//!
//! Conventions (shared by every module of the engine): right-handed, +Y up, metres, seconds,
//! radians; colours are linear Rec.709 radiance (W·sr⁻¹·m⁻²) until tonemapping. Matrices are
//! named `to_from` (`world_from_object` maps object-space points to world space) and stored
//! as three rows of a 3×4 affine matrix.

use bytemuck::{Pod, Zeroable};

/// Marks an empty slot: no child, no texture, no material override.
pub const INVALID: u32 = u32::MAX;

/// Set in a [`GpuBvh8Node::child`] entry when the child is a leaf. The low 31 bits then hold the
/// leaf payload: a run of [`GpuTri4`] blocks (relative to the mesh's `block_base`, see
/// [`LEAF_COUNT_SHIFT`]) in a BLAS, or an instance index in the TLAS.
pub const LEAF_BIT: u32 = 1 << 31;

/// A BLAS leaf payload is `(blocks - 1) << LEAF_COUNT_SHIFT | first_block`: the leaf's
/// triangles fill `blocks` (1 to [`MAX_LEAF_BLOCKS`]) consecutive [`GpuTri4`] blocks from
/// `first_block` (relative to the mesh's `block_base`), every block but the last one full.
/// A TLAS leaf payload is the instance index (all 31 bits; TLAS leaves hold one instance).
pub const LEAF_COUNT_SHIFT: u32 = 29;

/// The low bits of a BLAS leaf payload: its first block.
pub const LEAF_INDEX_MASK: u32 = (1 << LEAF_COUNT_SHIFT) - 1;

/// Most consecutive blocks one BLAS leaf may reference (two bits of the payload).
pub const MAX_LEAF_BLOCKS: u32 = 4;

/// Pixel rows per work unit of a frame split over several tracers (Brigade §4.3.2: "one work
/// unit equals four scanlines"); the GPU tracer renders the units its unit list names.
pub const UNIT_ROWS: u32 = 4;

/// One node of an 8-wide BVH, shared by every BLAS (one per mesh) and the TLAS.
///
/// Child bounds are stored structure-of-arrays so that a CPU can test all eight children with
/// one 8-lane SIMD slab test (Fuetterling et al. 2017, "Accelerated Single Ray Tracing for Wide
/// Vector Units"; the same layout as tinybvh's `BVH8_CPU`). Empty slots have `min = +inf`,
/// `max = -inf` and `child = INVALID`: the octant-ordered slab test, which reads the near plane
/// from `min` for positive direction components and from `max` for negative ones, never hits them.
///
/// `child[i]`: `INVALID` (empty), `LEAF_BIT | payload` (leaf) or the index of an inner node,
/// relative to the tree's first node (the instance's `node_base` for a BLAS,
/// `GpuFrameUniforms::tlas_root` for the TLAS). Every tree's root is its first node.
///
/// `perm[i]`: front-to-back child order per ray octant. For octant `o = (dx<0) | (dy<0)<<1 |
/// (dz<0)<<2`, bits `3o..3o+3` of `perm[i]` hold the slot of the child that comes `i`-th
/// (sorted by the child-box centre projected on the octant's diagonal direction).
/// 256 bytes: four 64-byte cache lines.
#[repr(C, align(64))]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct GpuBvh8Node {
    pub min_x: [f32; 8],
    pub max_x: [f32; 8],
    pub min_y: [f32; 8],
    pub max_y: [f32; 8],
    pub min_z: [f32; 8],
    pub max_z: [f32; 8],
    pub child: [u32; 8],
    pub perm: [u32; 8],
}
const _: () = assert!(size_of::<GpuBvh8Node>() == 256);

impl GpuBvh8Node {
    /// A node whose eight slots are all empty.
    pub const EMPTY: Self = Self {
        min_x: [f32::INFINITY; 8],
        max_x: [f32::NEG_INFINITY; 8],
        min_y: [f32::INFINITY; 8],
        max_y: [f32::NEG_INFINITY; 8],
        min_z: [f32::INFINITY; 8],
        max_z: [f32::NEG_INFINITY; 8],
        child: [INVALID; 8],
        perm: [0; 8],
    };
}

/// A leaf block of up to four triangles, structure-of-arrays (Embree's `triangle4`): first
/// vertex and the two edges `e1 = v1 - v0`, `e2 = v2 - v0`, in the mesh's object space (metres).
/// Unused lanes have zero edges (never hit: their determinant is 0) and `prim = INVALID`.
/// `prim[i]` is the mesh-local triangle index (into the mesh's [`GpuTriangle`] range).
/// 160 bytes.
#[repr(C, align(16))]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct GpuTri4 {
    pub v0_x: [f32; 4],
    pub v0_y: [f32; 4],
    pub v0_z: [f32; 4],
    pub e1_x: [f32; 4],
    pub e1_y: [f32; 4],
    pub e1_z: [f32; 4],
    pub e2_x: [f32; 4],
    pub e2_y: [f32; 4],
    pub e2_z: [f32; 4],
    pub prim: [u32; 4],
}
const _: () = assert!(size_of::<GpuTri4>() == 160);

impl GpuTri4 {
    /// A block with four unused lanes.
    pub const EMPTY: Self = Self {
        v0_x: [0.0; 4],
        v0_y: [0.0; 4],
        v0_z: [0.0; 4],
        e1_x: [0.0; 4],
        e1_y: [0.0; 4],
        e1_z: [0.0; 4],
        e2_x: [0.0; 4],
        e2_y: [0.0; 4],
        e2_z: [0.0; 4],
        prim: [INVALID; 4],
    };
}

/// One placed copy of a mesh. Affine transforms are stored as the three rows of a 3×4 matrix
/// (the fourth row is implicitly `0 0 0 1`). Shading normals go to world space with the
/// transpose of `object_from_world`'s 3×3 part. "World" here is render space: world minus
/// the scene's origin (`RenderScene::origin`, camera-relative rendering; see `accel::origin`).
/// 128 bytes.
#[repr(C, align(16))]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct GpuInstance {
    pub world_from_object: [[f32; 4]; 3],
    pub object_from_world: [[f32; 4]; 3],
    /// First node of this mesh's BLAS in the node buffer; child indices are relative to it.
    pub node_base: u32,
    /// First [`GpuTri4`] block of this mesh's BLAS.
    pub block_base: u32,
    /// First [`GpuTriangle`] of the mesh; `GpuTri4::prim` is relative to it.
    pub triangle_base: u32,
    /// First [`GpuVertex`] of the mesh; `GpuTriangle` indices are relative to it.
    pub vertex_base: u32,
    /// A material index that replaces every triangle's own material, or [`INVALID`].
    pub material_override: u32,
    /// Bit set of `INSTANCE_FLAG_*`.
    pub flags: u32,
    pub _padding: [u32; 2],
}
const _: () = assert!(size_of::<GpuInstance>() == 128);

/// `GpuInstance::flags`: the transform is the identity (rays need not be transformed).
pub const INSTANCE_FLAG_IDENTITY: u32 = 1;
/// `GpuInstance::flags`: the instance's light group is switched off: its emissive triangles
/// emit nothing and are absent from the light table (Brigade §6.1: not just multiplied by zero).
pub const INSTANCE_FLAG_EMISSION_OFF: u32 = 2;
/// `GpuInstance::flags`: the instance's light group is out of sight of the render area the
/// camera is in (`assets::RenderArea`): its emissive triangles are absent from the light table,
/// so next-event estimation never picks them, but they still emit when a path hits them, and
/// that hit takes MIS weight 1 (the only strategy that can reach them), so the estimate stays
/// unbiased (both tracers: `render/cpu/integrator.rs`, `shaders/trace.wgsl`).
pub const INSTANCE_FLAG_UNSAMPLED: u32 = 4;

/// Vertex indices (relative to the instance's `vertex_base`) and the global material index.
/// 16 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable, PartialEq, Eq)]
pub struct GpuTriangle {
    pub indices: [u32; 3],
    pub material: u32,
}
const _: () = assert!(size_of::<GpuTriangle>() == 16);

/// Shading attributes of one vertex in object space. A zero `normal` means "no shading normal":
/// the tracers then shade with the geometric normal (flat shading, as glTF 2.0 requires for
/// meshes without normals). `tangent.w` is the bitangent sign (MikkTSpace); a zero tangent
/// means "no tangent frame", and normal maps are then ignored for that vertex.
/// 48 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable, PartialEq)]
pub struct GpuVertex {
    pub position: [f32; 3],
    pub u: f32,
    pub normal: [f32; 3],
    pub v: f32,
    pub tangent: [f32; 4],
}
const _: () = assert!(size_of::<GpuVertex>() == 48);

/// A thin emissive line seen from the camera (one per instance of a [`MATERIAL_FLAG_LINE`]
/// material: the segment from the instance's origin to its +z end, in render space, metres).
/// Both tracers add its radiance prefiltered over the pixel's footprint (`render/cpu/lines.rs`,
/// `shaders/shared/lines.wgsl`). 48 bytes.
#[repr(C, align(16))]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable, PartialEq)]
pub struct GpuLine {
    pub start: [f32; 3],
    /// Half the line's width, metres (0: an unused slot).
    pub radius: f32,
    pub end: [f32; 3],
    pub _padding: u32,
    /// Emitted radiance, linear RGB (W·sr⁻¹·m⁻²); `w` unused.
    pub radiance: [f32; 4],
}
const _: () = assert!(size_of::<GpuLine>() == 48);

/// `GpuMaterial::kind`: Lambertian diffuse, two-sided.
pub const MATERIAL_DIFFUSE: u32 = 0;
/// `GpuMaterial::kind`: conductor; GGX microfacets, a perfect mirror when `roughness == 0`.
/// `base_color` is the reflectance at normal incidence (Schlick Fresnel).
pub const MATERIAL_CONDUCTOR: u32 = 1;
/// `GpuMaterial::kind`: dielectric with Fresnel reflection and refraction; smooth when
/// `roughness == 0`, GGX otherwise; Beer–Lambert absorption inside (`absorption`).
pub const MATERIAL_DIELECTRIC: u32 = 2;
/// `GpuMaterial::kind`: glTF metallic-roughness: a diffuse base under a GGX dielectric coat
/// (F0 = 0.04) mixed with a GGX conductor (F0 = base colour) by `metallic`.
pub const MATERIAL_METAL_ROUGH: u32 = 3;

/// `GpuMaterial::flags`: emits from both faces (otherwise only along the geometric normal).
pub const MATERIAL_FLAG_TWO_SIDED_EMISSION: u32 = 1;
/// `GpuMaterial::flags`: a thin line emitter (a laser beam, `assets::Material::line`). Rays from
/// the camera (directly or through perfect mirrors and smooth glass) pass through its triangles
/// and see the prefiltered line of [`GpuLine`] instead, so it reads as a continuous line at any
/// resolution; every other ray (bounces off rough surfaces, light sampling) meets the triangles.
pub const MATERIAL_FLAG_LINE: u32 = 2;

/// A material as the tracers evaluate it. Texture fields index the texture table or are
/// [`INVALID`]. Texture lookups multiply the matching factor.
/// 96 bytes.
#[repr(C, align(16))]
#[derive(Clone, Copy, Debug, Pod, Zeroable, PartialEq)]
pub struct GpuMaterial {
    /// Linear RGB albedo (diffuse), F0 (conductor) or transmission tint (dielectric); `w` unused.
    pub base_color: [f32; 4],
    /// Emitted radiance, linear RGB (W·sr⁻¹·m⁻², strength already applied); `w` is the scalar
    /// weight used to pick this material's triangles as lights (luminance × mean texture value).
    pub emission: [f32; 4],
    /// Absorption coefficient inside a dielectric, per metre, linear RGB (Beer–Lambert); `w` unused.
    pub absorption: [f32; 4],
    pub kind: u32,
    /// Perceptual roughness in [0, 1]; GGX α = roughness².
    pub roughness: f32,
    pub metallic: f32,
    /// Index of refraction of the inside (dielectric) or of the coat (metal-rough).
    pub ior: f32,
    /// glTF `KHR_materials_transmission` factor for `MATERIAL_METAL_ROUGH`.
    pub transmission: f32,
    /// Scale of the tangent-space normal map's xy.
    pub normal_scale: f32,
    pub flags: u32,
    pub base_color_texture: u32,
    pub normal_texture: u32,
    pub emission_texture: u32,
    /// glTF metallic-roughness texture: roughness in G, metallic in B.
    pub metal_rough_texture: u32,
    pub _padding: u32,
}
const _: () = assert!(size_of::<GpuMaterial>() == 96);

/// `GpuTexture::flags` bits 0–1 / 2–3: wrap mode in u / v.
pub const WRAP_REPEAT: u32 = 0;
pub const WRAP_CLAMP: u32 = 1;
pub const WRAP_MIRROR: u32 = 2;
/// `GpuTexture::flags` bit 4: nearest filtering on level 0 (otherwise bilinear on the level the
/// ray cone picks).
pub const TEXTURE_FLAG_NEAREST: u32 = 1 << 4;
/// `GpuTexture::flags` bits 8–12: the number of mip levels (0 reads as 1: level 0 only).
pub const TEXTURE_LEVELS_SHIFT: u32 = 8;
pub const TEXTURE_LEVELS_MASK: u32 = 31;

/// One texture in the shared texel buffer: its mip chain from `texel_offset`, level 0
/// (`width × height`) first, then each level of floor-halved size down to 1×1
/// (`scene/mips.rs`); rows top to bottom, each texel four f16 values (linear RGBA, sRGB already
/// decoded) packed in two u32. 16 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable, PartialEq, Eq)]
pub struct GpuTexture {
    pub texel_offset: u32,
    pub width: u32,
    pub height: u32,
    pub flags: u32,
}
const _: () = assert!(size_of::<GpuTexture>() == 16);

/// One emissive triangle in world space, and its entry of the alias table that picks lights in
/// proportion to `weight` (area × material emission weight). Pick `i` uniformly, keep it if a
/// second uniform number is below `alias_threshold`, else take `alias_index`.
/// 64 bytes.
#[repr(C, align(16))]
#[derive(Clone, Copy, Debug, Pod, Zeroable, PartialEq)]
pub struct GpuLight {
    pub p0: [f32; 3],
    pub instance: u32,
    pub p1: [f32; 3],
    /// Mesh-local triangle index.
    pub triangle: u32,
    pub p2: [f32; 3],
    pub weight: f32,
    pub alias_threshold: f32,
    pub alias_index: u32,
    pub _padding: [u32; 2],
}
const _: () = assert!(size_of::<GpuLight>() == 64);

/// One node of the light tree (PBRT-v4's BVH light sampler; built by `scene::light_tree`,
/// sampled by `render::cpu::light_tree` and its twin `shaders/shared/light_tree.wgsl`): the
/// render-space box, power bound and orientation cone of the emissive triangles below it.
/// Interior nodes: the first child is the next node, the second is `child`; leaves
/// ([`LIGHT_NODE_LEAF`]): `child` is the light's index in the light table. `parent` is
/// [`INVALID`] at the root (index 0). 64 bytes, aligned to 64 on the CPU so that a node is one
/// cache line (the walk loads two per level; aligned to 16, most straddled two lines).
#[repr(C, align(64))]
#[derive(Clone, Copy, Debug, Pod, Zeroable, PartialEq)]
pub struct GpuLightNode {
    /// Render-space box of the emitters below, metres.
    pub bounds_min: [f32; 3],
    /// Power φ of the emitters below (area × emission weight, twice for two-sided emitters;
    /// relative units, only ratios matter).
    pub phi: f32,
    pub bounds_max: [f32; 3],
    /// cos θ_o: every emitter's normal lies within θ_o of `axis`.
    pub cos_theta_o: f32,
    /// Unit axis of the normal cone.
    pub axis: [f32; 3],
    /// cos θ_e: every emitter emits within θ_e of its normal (0, θ_e = π/2, for area lights).
    pub cos_theta_e: f32,
    /// Second child (interior) or light index (leaf).
    pub child: u32,
    pub parent: u32,
    /// [`LIGHT_NODE_LEAF`] | [`LIGHT_NODE_TWO_SIDED`].
    pub flags: u32,
    pub _padding: u32,
}
const _: () = assert!(size_of::<GpuLightNode>() == 64);

/// `GpuLightNode::flags`: a leaf (one light).
pub const LIGHT_NODE_LEAF: u32 = 1;
/// `GpuLightNode::flags`: some emitter below emits from both faces (the cone then bounds
/// ±normal: the importance uses |cos θ_w|).
pub const LIGHT_NODE_TWO_SIDED: u32 = 2;

/// `GpuFrameUniforms::method`: sample lights explicitly (next-event estimation).
pub const METHOD_NEE: u32 = 1;
/// `GpuFrameUniforms::method`: weight light and BSDF samples by multiple importance sampling
/// (without it, emitters hit by BSDF sampling count only after specular bounces).
pub const METHOD_MIS: u32 = 2;
/// `GpuFrameUniforms::method`: pick lights in proportion to power (otherwise uniformly).
pub const METHOD_LIGHTS_BY_POWER: u32 = 4;
/// `GpuFrameUniforms::method`: pick lights by the light tree (importance from each shading
/// point, PBRT-v4's `LightBounds::Importance`); takes precedence over
/// [`METHOD_LIGHTS_BY_POWER`].
pub const METHOD_LIGHT_TREE: u32 = 8;
/// `GpuFrameUniforms::method`: plain single-pick next-event estimation: the primary disc (sun
/// or moon) is one more entry of the one light pick, chosen by its share of power
/// (`render/cpu/direct.rs` `pick_chances`), so a hit samples one light. Without it a hit samples
/// two: the disc and one triangle (Brigade §6.2.3). For the comparison in `bench two-lights`.
pub const METHOD_SINGLE_PICK: u32 = 16;
/// `GpuFrameUniforms::method`: interleaved indirect light, one pixel in two. A path's first
/// diffuse or glossy bounce (the first scattering that is not a perfect mirror or smooth glass
/// turn) is traced from one pixel of each checkerboard pair per sample, weighted ×2; the other
/// pixel ends its path after that vertex's next-event estimate. Which pixel alternates with the
/// sample index, so two consecutive samples of a pixel hold exactly one indirect estimate
/// (`render/cpu/interleave.rs`). Direct light, mirrors and glass stay at every pixel.
pub const METHOD_INDIRECT_HALF: u32 = 32;
/// `GpuFrameUniforms::method`: interleaved indirect light, one pixel in four (each 2×2 block's
/// pixels in turn over four consecutive samples), weighted ×4. Takes precedence over
/// [`METHOD_INDIRECT_HALF`].
pub const METHOD_INDIRECT_QUARTER: u32 = 64;
/// The default estimator.
pub const METHOD_DEFAULT: u32 = METHOD_NEE | METHOD_MIS | METHOD_LIGHTS_BY_POWER;

/// `GpuFrameUniforms::sky_kind`: constant radiance `sky_zenith`.
pub const SKY_CONSTANT: u32 = 0;
/// `GpuFrameUniforms::sky_kind`: zenith → horizon → ground gradient.
pub const SKY_GRADIENT: u32 = 1;
/// `GpuFrameUniforms::sky_kind`: the physical sky's sky-view table (`scene::SkyTable`), seen
/// in the frame whose unit horizontal vector towards the sun's azimuth is `sky_horizon.xyz`.
pub const SKY_PHYSICAL: u32 = 2;
/// Star cells along each edge of the cube the star field is hashed on (`render/cpu/night.rs`).
pub const STAR_CELLS: u32 = 128;
/// A cell holds a star when its hash is below this (0.0916 × 2³²: about 9000 on the sphere).
pub const STAR_THRESHOLD: u32 = 393_400_000;

/// Everything that changes per frame or per render: camera, sun, sky, image size, sampling.
/// The camera basis vectors are pre-scaled: a pixel's direction is
/// `forward + sx * right + sy * up` with `sx, sy` in [-1, 1] over the image.
/// 336 bytes.
#[repr(C, align(16))]
#[derive(Clone, Copy, Debug, Pod, Zeroable, PartialEq)]
pub struct GpuFrameUniforms {
    pub camera_position: [f32; 3],
    /// Thin-lens aperture radius in metres (0: pinhole).
    pub lens_radius: f32,
    /// Camera right, scaled by `tan(vfov/2) * aspect`.
    pub camera_right: [f32; 3],
    /// Distance to the plane in focus, metres.
    pub focus_distance: f32,
    /// Camera up, scaled by `tan(vfov/2)`.
    pub camera_up: [f32; 3],
    /// How this render's mean enters the film: `film = mix(film, new_mean, film_blend)`.
    /// `spp / (samples so far + spp)` keeps an exact running mean; 1 replaces the film;
    /// the converging policy (Brigade §4.5) sets it from camera and object motion.
    pub film_blend: f32,
    pub camera_forward: [f32; 3],
    /// Which estimator runs: bit set of `METHOD_*` (all three set is the default, NEE + MIS
    /// with lights picked by power). The other combinations exist for speed-against-accuracy
    /// measurements (`tools/bench`).
    pub method: u32,
    /// Unit vector towards the sun.
    pub sun_direction: [f32; 3],
    /// Cosine of the sun's angular radius (1 for a delta sun).
    pub sun_cos_radius: f32,
    /// Radiance of the sun disc, or irradiance for a delta sun (linear RGB).
    pub sun_radiance: [f32; 3],
    /// Solid angle of the sun disc in sr; 0 for a delta sun; negative when there is no sun.
    pub sun_solid_angle: f32,
    pub sky_zenith: [f32; 4],
    pub sky_horizon: [f32; 4],
    pub sky_ground: [f32; 4],
    pub width: u32,
    pub height: u32,
    /// Samples per pixel traced in this dispatch.
    pub spp: u32,
    /// Index of the first sample of this dispatch (samples accumulate across dispatches).
    pub sample_base: u32,
    pub seed: u32,
    /// Maximum number of scattering events on a path (Mitsuba's `max_depth - 1`).
    pub max_bounces: u32,
    /// Scattering events before Russian roulette may end a path.
    pub roulette_start: u32,
    pub light_count: u32,
    /// Sum of all lights' `weight`.
    pub light_weight_total: f32,
    /// Multiplies the roulette survival probability (1: default; lower trades noise for speed).
    pub roulette_scale: f32,
    pub sky_kind: u32,
    /// Index of the TLAS root in the node buffer.
    pub tlas_root: u32,
    // The night (`scene/discs.rs` fills these; `render/cpu/night.rs`, `shaders/shared/night.wgsl`).
    /// Unit vector from the primary disc towards what lights it (the moon: the sun); zero: the
    /// whole disc is lit (the sun). The lit part is where the visible hemisphere's normal
    /// faces it.
    pub sun_terminator: [f32; 3],
    /// Sine of the primary disc's angular radius.
    pub sun_sin_radius: f32,
    /// Unit vector towards the second disc (the fainter of sun and moon), seen by escaping
    /// rays only.
    pub second_direction: [f32; 3],
    /// Cosine of the second disc's angular radius (1: no second disc).
    pub second_cos_radius: f32,
    /// Radiance of the lit part of the second disc, linear RGB.
    pub second_radiance: [f32; 3],
    /// Sine of the second disc's angular radius.
    pub second_sin_radius: f32,
    /// As `sun_terminator`, for the second disc.
    pub second_terminator: [f32; 3],
    /// Radiance of a magnitude-0 star's disc (grey; 0: no stars), before extinction.
    pub star_radiance: f32,
    /// Airglow radiance at the zenith, linear RGB, before extinction (0: none).
    pub airglow: [f32; 3],
    /// Sine of a star disc's angular radius.
    pub star_sin_radius: f32,
    /// The air's transmittance straight up; along `d` it is this to the air mass of `d.y`.
    pub zenith_transmittance: [f32; 3],
    /// A fixed offset of every camera sample inside its pixel, for temporal upscaling
    /// (`render::jitter`: 0 = uniform in the pixel, the box filter; else bit 31 and x, y in
    /// 1/32768 of a pixel in bits 0–14 and 15–29).
    pub pixel_jitter: u32,
    /// Rows of the rotation from engine space to the celestial frame (x: equinox, z: north
    /// celestial pole; `sky::celestial_frame`); `w` unused.
    pub celestial_x: [f32; 4],
    pub celestial_y: [f32; 4],
    pub celestial_z: [f32; 4],
    /// The cloud layer (`sky/clouds.rs`; `scene/lights.rs` fills it, `render/camera.rs` moves
    /// it into render space): x the plane's height (render-space y, metres), y and z where the
    /// texture's origin sits now (render-space x, z, metres: the wind's drift), w the tile's
    /// side in metres (0: no clouds).
    pub cloud_plane: [f32; 4],
    /// Radiance of an opaque cloud lit by the primary disc, linear RGB (escaping rays see
    /// sky · T + this · (1 − T)).
    pub cloud_light: [f32; 3],
    /// Texels per side of the optical-depth texture (the CPU tracer reads `SkyTable::clouds`;
    /// on the GPU they follow the sky view in binding 16, four to a texel).
    pub cloud_texels: u32,
    /// The moonlit sky (`sky::MoonSky`; `scene/discs.rs` fills it): xyz the unit horizontal
    /// vector towards the moon's azimuth (the frame of the moon's sky-view table, which
    /// follows the sun's), w the moon's share of the sun's irradiance that table is multiplied
    /// by (0: no moonlit sky, by day or with the moon down).
    pub moon_sky: [f32; 4],
}
const _: () = assert!(size_of::<GpuFrameUniforms>() == 384);

impl GpuFrameUniforms {
    /// All zeros: for passes that read nothing but `tlas_root` (batch ray tracing).
    pub fn zeroed_for_batch() -> Self {
        Self::zeroed()
    }
}

/// A ray for batch tracing on the GPU (benchmarks, batched queries): origin and direction in
/// world space, hits counted for `t_min < t < t_max` in units of `direction`. 32 bytes.
#[repr(C, align(16))]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable, PartialEq)]
pub struct GpuRay {
    pub origin: [f32; 3],
    pub t_min: f32,
    pub direction: [f32; 3],
    pub t_max: f32,
}
const _: () = assert!(size_of::<GpuRay>() == 32);

/// What a batch-traced ray hit: `t` (or `t_max` on a miss), barycentrics, instance and
/// mesh-local triangle (`INVALID` on a miss). 32 bytes.
#[repr(C, align(16))]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable, PartialEq)]
pub struct GpuHit {
    pub t: f32,
    pub u: f32,
    pub v: f32,
    pub instance: u32,
    pub triangle: u32,
    pub _padding: [u32; 3],
}
const _: () = assert!(size_of::<GpuHit>() == 32);

/// Uniforms of the present pass (`shaders/present.wgsl`, render thread): the film (linear
/// radiance, `film_width × film_height`, rows top to bottom) is upscaled bilinearly to the
/// `target_width × target_height` frame and tonemapped exactly as
/// `render::film::linear_to_srgb8` does on the CPU. 32 bytes.
#[repr(C, align(16))]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable, PartialEq)]
pub struct GpuPresentUniforms {
    pub film_width: u32,
    pub film_height: u32,
    /// The frame (window) size in physical pixels.
    pub target_width: u32,
    pub target_height: u32,
    /// Radiance is multiplied by this: 2^exposure_ev.
    pub exposure_scale: f32,
    /// 1: the ACES fit (Narkowicz 2015) before clamping to [0, 1]; 0: clamp only.
    pub filmic: u32,
    /// 1: the target format is not sRGB, so the shader applies the sRGB transfer function;
    /// 0: the target is an sRGB format and the hardware encodes.
    pub encode_srgb: u32,
    pub _padding: u32,
}
const _: () = assert!(size_of::<GpuPresentUniforms>() == 32);

/// Uniforms of one denoiser pass (`shaders/denoise_*.wgsl`, render thread): the image size,
/// the à-trous step in pixels, whether this pass remodulates (1: the last à-trous pass), the
/// new frame's blend factor (temporal pass; 1 restarts) and the edge-stopping scales σ_z
/// (depth) and σ_l (luminance), and the à-trous kernel's radius in taps (1: 3×3, 2: 5×5). Twin of
/// `render::denoise`'s `Pass` and `SvgfParams`. 32 bytes.
#[repr(C, align(16))]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable, PartialEq)]
pub struct GpuDenoiseUniforms {
    pub width: u32,
    pub height: u32,
    pub step: u32,
    pub remodulate: u32,
    pub blend: f32,
    pub sigma_z: f32,
    pub sigma_l: f32,
    pub radius: u32,
}
const _: () = assert!(size_of::<GpuDenoiseUniforms>() == 32);

/// Uniforms of the denoiser's reprojection (`shaders/denoise_reproject.wgsl`, and the temporal
/// pass's `mode`; render thread): this frame's and the previous frame's pinhole cameras as
/// `render::denoise::View` holds them (position, metres, in the frame uniforms' space; the
/// pre-scaled `forward`, `right`, `up`; where in their pixels each frame's guides were taken,
/// `jitter`, pixels from the top left corner), the previous image's size, how many instance motions
/// the motion buffer holds, and `mode` (0: identity, each pixel keeps its own history; 1: the
/// history was reprojected, the temporal weight is at least 1/(length + 1)). Twin of
/// `render::denoise::reproject`'s inputs. 128 bytes.
#[repr(C, align(16))]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable, PartialEq)]
pub struct GpuReprojectUniforms {
    pub camera_position: [f32; 3],
    pub mode: u32,
    pub camera_forward: [f32; 3],
    pub instances: u32,
    pub camera_right: [f32; 3],
    pub jitter_x: f32,
    pub camera_up: [f32; 3],
    pub jitter_y: f32,
    pub prev_position: [f32; 3],
    pub prev_width: u32,
    pub prev_forward: [f32; 3],
    pub prev_height: u32,
    pub prev_right: [f32; 3],
    pub prev_jitter_x: f32,
    pub prev_up: [f32; 3],
    pub prev_jitter_y: f32,
}
const _: () = assert!(size_of::<GpuReprojectUniforms>() == 128);

/// One instance's motion since the previous frame, for the denoiser's reprojection: its
/// previous world-from-object times this frame's object-from-world (a point on the instance
/// now, in world space, to where it was), and that motion's inverse (where a point of the
/// previous frame is now: the edge rule, `denoise::reproject_edge`), each three rows of a 3×4
/// affine matrix. 96 bytes.
#[repr(C, align(16))]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable, PartialEq)]
pub struct GpuMotion {
    pub prev_from_now: [[f32; 4]; 3],
    pub now_from_prev: [[f32; 4]; 3],
}
const _: () = assert!(size_of::<GpuMotion>() == 96);
