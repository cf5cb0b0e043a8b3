//! Every GPU struct has the same size and field offsets in Rust (`engine/src/layout.rs`) and in
//! WGSL (`shaders/shared/types.wgsl`, parsed with naga, which applies WGSL's layout rules).

use std::collections::HashMap;
use std::mem::{offset_of, size_of};

use candela::layout::*;

/// (struct name, size, [(field, offset)]) of the Rust side.
type RustLayout = (&'static str, usize, Vec<(&'static str, usize)>);

macro_rules! rust_layout {
    ($ty:ident { $($field:ident),* $(,)? }) => {
        (stringify!($ty), size_of::<$ty>(), vec![$((stringify!($field), offset_of!($ty, $field))),*])
    };
}

fn rust_layouts() -> Vec<RustLayout> {
    vec![
        rust_layout!(GpuBvh8Node {
            min_x,
            max_x,
            min_y,
            max_y,
            min_z,
            max_z,
            child,
            perm
        }),
        rust_layout!(GpuTri4 {
            v0_x,
            v0_y,
            v0_z,
            e1_x,
            e1_y,
            e1_z,
            e2_x,
            e2_y,
            e2_z,
            prim
        }),
        rust_layout!(GpuInstance {
            world_from_object,
            object_from_world,
            node_base,
            block_base,
            triangle_base,
            vertex_base,
            material_override,
            flags,
            _padding
        }),
        rust_layout!(GpuTriangle { indices, material }),
        rust_layout!(GpuVertex {
            position,
            u,
            normal,
            v,
            tangent
        }),
        rust_layout!(GpuMaterial {
            base_color,
            emission,
            absorption,
            kind,
            roughness,
            metallic,
            ior,
            transmission,
            normal_scale,
            flags,
            base_color_texture,
            normal_texture,
            emission_texture,
            metal_rough_texture,
            _padding
        }),
        rust_layout!(GpuTexture {
            texel_offset,
            width,
            height,
            flags
        }),
        rust_layout!(GpuLight {
            p0,
            instance,
            p1,
            triangle,
            p2,
            weight,
            alias_threshold,
            alias_index,
            _padding
        }),
        rust_layout!(GpuLine {
            start,
            radius,
            end,
            _padding,
            radiance
        }),
        rust_layout!(GpuLightNode {
            bounds_min,
            phi,
            bounds_max,
            cos_theta_o,
            axis,
            cos_theta_e,
            child,
            parent,
            flags,
            _padding
        }),
        rust_layout!(GpuFrameUniforms {
            camera_position,
            lens_radius,
            camera_right,
            focus_distance,
            camera_up,
            film_blend,
            camera_forward,
            method,
            sun_direction,
            sun_cos_radius,
            sun_radiance,
            sun_solid_angle,
            sky_zenith,
            sky_horizon,
            sky_ground,
            width,
            height,
            spp,
            sample_base,
            seed,
            max_bounces,
            roulette_start,
            light_count,
            light_weight_total,
            roulette_scale,
            sky_kind,
            tlas_root,
            sun_terminator,
            sun_sin_radius,
            second_direction,
            second_cos_radius,
            second_radiance,
            second_sin_radius,
            second_terminator,
            star_radiance,
            airglow,
            star_sin_radius,
            zenith_transmittance,
            pixel_jitter,
            celestial_x,
            celestial_y,
            celestial_z,
            cloud_plane,
            cloud_light,
            cloud_texels,
            moon_sky
        }),
        rust_layout!(GpuRay {
            origin,
            t_min,
            direction,
            t_max
        }),
        rust_layout!(GpuHit {
            t,
            u,
            v,
            instance,
            triangle,
            _padding
        }),
        rust_layout!(GpuPresentUniforms {
            film_width,
            film_height,
            target_width,
            target_height,
            exposure_scale,
            filmic,
            encode_srgb,
            _padding
        }),
        rust_layout!(GpuDenoiseUniforms {
            width,
            height,
            step,
            remodulate,
            blend,
            sigma_z,
            sigma_l,
            radius
        }),
        rust_layout!(GpuReprojectUniforms {
            camera_position,
            mode,
            camera_forward,
            instances,
            camera_right,
            jitter_x,
            camera_up,
            jitter_y,
            prev_position,
            prev_width,
            prev_forward,
            prev_height,
            prev_right,
            prev_jitter_x,
            prev_up,
            prev_jitter_y
        }),
        rust_layout!(GpuMotion {
            prev_from_now,
            now_from_prev
        }),
    ]
}

#[test]
fn rust_and_wgsl_layouts_agree() {
    let path = candela_tests::repo().join("shaders/shared/types.wgsl");
    let source = std::fs::read_to_string(&path).expect("shaders/shared/types.wgsl is readable");
    let module = naga::front::wgsl::parse_str(&source)
        .unwrap_or_else(|e| panic!("{}", e.emit_to_string(&source)));
    let mut wgsl: HashMap<String, (u32, Vec<(String, u32)>)> = HashMap::new();
    for (_, ty) in module.types.iter() {
        if let (Some(name), naga::TypeInner::Struct { members, span }) = (&ty.name, &ty.inner) {
            let fields = members
                .iter()
                .map(|m| (m.name.clone().unwrap_or_default(), m.offset))
                .collect();
            wgsl.insert(name.clone(), (*span, fields));
        }
    }
    let rust = rust_layouts();
    assert_eq!(
        rust.len(),
        wgsl.len(),
        "every Gpu struct needs a twin on the other side (WGSL has {:?})",
        wgsl.keys().collect::<Vec<_>>()
    );
    for (name, size, fields) in rust {
        let (wgsl_size, wgsl_fields) = wgsl
            .get(name)
            .unwrap_or_else(|| panic!("{name} has no WGSL twin in types.wgsl"));
        assert_eq!(size as u32, *wgsl_size, "{name}: size differs (Rust, WGSL)");
        let rust_fields: Vec<(String, u32)> = fields
            .iter()
            .map(|(f, o)| (f.to_string(), *o as u32))
            .collect();
        assert_eq!(
            &rust_fields, wgsl_fields,
            "{name}: field names/offsets differ (Rust vs WGSL)"
        );
    }
}

/// The constants both sides use to read the layout (sentinels, leaf payload encoding, flags) have
/// the same values in Rust and in `types.wgsl`.
#[test]
fn rust_and_wgsl_constants_agree() {
    let path = candela_tests::repo().join("shaders/shared/types.wgsl");
    let source = std::fs::read_to_string(&path).expect("shaders/shared/types.wgsl is readable");
    let module = naga::front::wgsl::parse_str(&source)
        .unwrap_or_else(|e| panic!("{}", e.emit_to_string(&source)));
    let wgsl: HashMap<String, u32> = module
        .constants
        .iter()
        .filter_map(|(_, c)| match module.global_expressions[c.init] {
            naga::Expression::Literal(naga::Literal::U32(v)) => Some((c.name.clone()?, v)),
            _ => None,
        })
        .collect();
    for (name, value) in [
        ("INVALID", INVALID),
        ("LEAF_BIT", LEAF_BIT),
        ("LEAF_COUNT_SHIFT", LEAF_COUNT_SHIFT),
        ("LEAF_INDEX_MASK", LEAF_INDEX_MASK),
        ("MAX_LEAF_BLOCKS", MAX_LEAF_BLOCKS),
        ("INSTANCE_FLAG_IDENTITY", INSTANCE_FLAG_IDENTITY),
        ("INSTANCE_FLAG_EMISSION_OFF", INSTANCE_FLAG_EMISSION_OFF),
        ("INSTANCE_FLAG_UNSAMPLED", INSTANCE_FLAG_UNSAMPLED),
        ("UNIT_ROWS", UNIT_ROWS),
        ("METHOD_NEE", METHOD_NEE),
        ("METHOD_MIS", METHOD_MIS),
        ("METHOD_LIGHTS_BY_POWER", METHOD_LIGHTS_BY_POWER),
        ("METHOD_LIGHT_TREE", METHOD_LIGHT_TREE),
        ("METHOD_SINGLE_PICK", METHOD_SINGLE_PICK),
        ("METHOD_INDIRECT_HALF", METHOD_INDIRECT_HALF),
        ("METHOD_INDIRECT_QUARTER", METHOD_INDIRECT_QUARTER),
        ("LIGHT_NODE_LEAF", LIGHT_NODE_LEAF),
        ("LIGHT_NODE_TWO_SIDED", LIGHT_NODE_TWO_SIDED),
        (
            "MATERIAL_FLAG_TWO_SIDED_EMISSION",
            MATERIAL_FLAG_TWO_SIDED_EMISSION,
        ),
        ("MATERIAL_FLAG_LINE", MATERIAL_FLAG_LINE),
        ("MAX_LINES", candela::scene::MAX_LINES as u32),
        ("SKY_CONSTANT", SKY_CONSTANT),
        ("SKY_GRADIENT", SKY_GRADIENT),
        ("SKY_PHYSICAL", SKY_PHYSICAL),
        ("STAR_CELLS", candela::layout::STAR_CELLS),
        ("STAR_THRESHOLD", candela::layout::STAR_THRESHOLD),
        ("SKY_VIEW_WIDTH", candela::sky::VIEW_WIDTH as u32),
        ("SKY_VIEW_HEIGHT", candela::sky::VIEW_HEIGHT as u32),
    ] {
        assert_eq!(wgsl.get(name), Some(&value), "{name} (WGSL vs Rust)");
    }
}

/// The triangle test's f32 constants in `shaders/shared/traverse.wgsl` equal Rust's bit for bit
/// (the tracers must make the same hit decisions).
#[test]
fn triangle_test_constants_agree() {
    use candela::trace::triangle::{DEGENERATE_RATIO, EDGE_SLACK, SLACK_SCALE};
    let path = candela_tests::repo().join("shaders/shared/traverse.wgsl");
    let source = std::fs::read_to_string(&path).expect("shaders/shared/traverse.wgsl is readable");
    for (name, value) in [
        ("DEGENERATE_RATIO", DEGENERATE_RATIO),
        ("SLACK_SCALE", SLACK_SCALE),
        ("EDGE_SLACK", EDGE_SLACK),
    ] {
        let prefix = format!("const {name}: f32 = ");
        let wgsl: f32 = source
            .lines()
            .find_map(|l| l.trim().strip_prefix(&prefix))
            .and_then(|rest| rest.trim_end_matches(';').parse().ok())
            .unwrap_or_else(|| panic!("{name} not found as an f32 literal in traverse.wgsl"));
        assert_eq!(
            wgsl.to_bits(),
            value.to_bits(),
            "{name}: WGSL {wgsl} vs Rust {value}"
        );
    }
}

/// The reprojection's thresholds are the same numbers in both twins.
#[test]
fn reprojection_constants_agree() {
    use candela::render::denoise::{NORMAL_COS, PLANE_TOLERANCE, SNAP_PIXELS};
    let path = candela_tests::repo().join("shaders/denoise_reproject.wgsl");
    let source =
        std::fs::read_to_string(&path).expect("shaders/denoise_reproject.wgsl is readable");
    for (name, value) in [
        ("NORMAL_COS", NORMAL_COS),
        ("PLANE_TOLERANCE", PLANE_TOLERANCE),
        ("SNAP_PIXELS", SNAP_PIXELS),
    ] {
        let prefix = format!("const {name}: f32 = ");
        let wgsl: f32 = source
            .lines()
            .find_map(|l| l.trim().strip_prefix(&prefix))
            .and_then(|rest| rest.trim_end_matches(';').parse().ok())
            .unwrap_or_else(|| {
                panic!("{name} not found as an f32 literal in denoise_reproject.wgsl")
            });
        assert_eq!(
            wgsl.to_bits(),
            value.to_bits(),
            "{name}: WGSL {wgsl} vs Rust {value}"
        );
    }
}
