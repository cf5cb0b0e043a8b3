//! glTF 2.0 loading against Khronos sample models: triangle and placement counts, node
//! transforms, instancing, sparse accessors, primitive modes, materials and their
//! extensions, samplers, texture sizes and the sRGB decoding of a known texel.

use std::path::{Path, PathBuf};

use candela::assets::{Material, MaterialKind, Model, Wrap, load_model_file};
use glam::{Mat4, Quat, Vec3};

type TestResult = Result<(), Box<dyn std::error::Error>>;

fn external(relative: &str) -> PathBuf {
    Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../shared/external/gltf"
    ))
    .join(relative)
}

fn load(relative: &str) -> Result<Model, Box<dyn std::error::Error>> {
    Ok(load_model_file(&external(relative))?)
}

fn triangles(model: &Model) -> usize {
    model.meshes.iter().map(|m| m.triangles.len()).sum()
}

fn material<'a>(model: &'a Model, name: &str) -> Result<&'a Material, String> {
    model
        .materials
        .iter()
        .find(|m| m.name == name)
        .ok_or_else(|| {
            format!(
                "no material {name:?} in {:?}",
                model.materials.iter().map(|m| &m.name).collect::<Vec<_>>()
            )
        })
}

fn srgb_to_linear(byte: u8) -> f32 {
    let c = f32::from(byte) / 255.0;
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

#[test]
fn box_in_all_three_packagings_has_the_same_geometry_and_transform() -> TestResult {
    // Node 0's matrix (column-major, as written in the file) turns +Y into -Z; its child holds the mesh.
    let expected = Mat4::from_cols_array(&[
        1.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0,
    ]);
    for file in [
        "Box/glTF/Box.gltf",
        "Box/glTF-Embedded/Box.gltf",
        "Box/glTF-Binary/Box.glb",
    ] {
        let model = load(file)?;
        assert_eq!((model.meshes.len(), triangles(&model)), (1, 12), "{file}");
        assert_eq!(model.placements.len(), 1, "{file}");
        assert_eq!(model.placements[0].model_from_mesh, expected, "{file}");
        let red = material(&model, "Red")?;
        assert_eq!(
            (red.kind, red.base_color, red.metallic, red.roughness),
            (MaterialKind::MetalRough, Vec3::new(0.8, 0.0, 0.0), 0.0, 1.0)
        );
        assert!(model.meshes[0].normals.is_some());
    }
    Ok(())
}

#[test]
fn box_textured_decodes_its_png_as_srgb() -> TestResult {
    let model = load("BoxTextured/glTF/BoxTextured.gltf")?;
    let texture_ref = material(&model, "Texture")?
        .base_color_texture
        .ok_or("no base colour texture")?;
    let texture = &model.textures[texture_ref.0];
    let png = image::open(external("BoxTextured/glTF/CesiumLogoFlat.png"))?.to_rgba8();
    assert_eq!((texture.width, texture.height), png.dimensions());
    assert_eq!(
        (texture.wrap_u, texture.wrap_v, texture.nearest),
        (Wrap::Repeat, Wrap::Repeat, false)
    );
    let mut compared = 0;
    for (x, y) in [(0, 0), (100, 37), (200, 150), (255, 255)] {
        let (x, y) = (x.min(png.width() - 1), y.min(png.height() - 1));
        let pixel = png.get_pixel(x, y).0;
        let texel = texture.texels[(y * texture.width + x) as usize];
        for c in 0..3 {
            let expected = srgb_to_linear(pixel[c]);
            assert!(
                (texel[c].to_f32() - expected).abs() <= expected * 1e-3 + 1e-6,
                "({x}, {y}) channel {c}: {} vs {expected}",
                texel[c]
            );
            compared += 1;
        }
    }
    assert_eq!(compared, 12);
    // The GLB packaging embeds the same image.
    let binary = load("BoxTextured/glTF-Binary/BoxTextured.glb")?;
    assert_eq!(binary.textures[0].texels, texture.texels);
    Ok(())
}

#[test]
fn duck_and_damaged_helmet() -> TestResult {
    let duck = load("Duck/glTF-Binary/Duck.glb")?;
    assert_eq!(
        (triangles(&duck), duck.placements.len(), duck.textures.len()),
        (4212, 1, 1)
    );
    assert_eq!(
        (duck.textures[0].width, duck.textures[0].height),
        (512, 512)
    );
    // Root matrix scales by 0.01; the camera node places nothing.
    assert!(
        duck.placements[0]
            .model_from_mesh
            .abs_diff_eq(Mat4::from_scale(Vec3::splat(0.01)), 1e-7)
    );

    let helmet = load("DamagedHelmet/glTF-Binary/DamagedHelmet.glb")?;
    assert_eq!((triangles(&helmet), helmet.placements.len()), (15452, 1));
    assert_eq!(
        helmet.textures.len(),
        4,
        "base colour, metal-rough, emissive, normal (occlusion unused)"
    );
    assert!(
        helmet
            .textures
            .iter()
            .all(|t| (t.width, t.height) == (2048, 2048))
    );
    let m = &helmet.materials[0];
    assert_eq!(
        (m.kind, m.metallic, m.roughness, m.emission),
        (MaterialKind::MetalRough, 1.0, 1.0, Vec3::ONE)
    );
    assert!(m.base_color_texture.is_some() && m.metal_rough_texture.is_some());
    assert!(m.normal_texture.is_some() && m.emission_texture.is_some());
    // Rotation (0.7071, 0, 0, 0.7071): 90° about +X, so +Y goes to +Z.
    let y = helmet.placements[0]
        .model_from_mesh
        .transform_vector3(Vec3::Y);
    assert!(y.abs_diff_eq(Vec3::Z, 1e-6), "{y}");
    assert!(
        helmet.meshes[0].tangents.is_some(),
        "normal-mapped without TANGENT: generated"
    );
    assert!(
        helmet
            .notes
            .iter()
            .any(|n| n.contains("generated tangents")),
        "{:?}",
        helmet.notes
    );
    Ok(())
}

#[test]
fn simple_instancing_places_every_instance() -> TestResult {
    let model = load("SimpleInstancing/glTF-Binary/SimpleInstancing.glb")?;
    assert_eq!((model.meshes.len(), model.placements.len()), (1, 125));
    // Instance 37 (read from the buffer with a script): T (2.5, 5, 5), R (0.0989, 0.1978, 0.1978, 0.9550), S (1.25, 1.5, 1.5).
    let expected = Mat4::from_scale_rotation_translation(
        Vec3::new(1.25, 1.5, 1.5),
        Quat::from_xyzw(0.098_891_3, 0.197_782_6, 0.197_782_6, 0.954_978_8).normalize(),
        Vec3::new(2.5, 5.0, 5.0),
    );
    assert!(
        model.placements[37]
            .model_from_mesh
            .abs_diff_eq(expected, 1e-5)
    );
    Ok(())
}

#[test]
fn negative_scale_and_multiple_scenes() -> TestResult {
    let model = load("NegativeScaleTest/glTF-Binary/NegativeScaleTest.glb")?;
    assert_eq!(model.placements.len(), 11);
    let negative = model
        .placements
        .iter()
        .filter(|p| p.model_from_mesh.determinant() < 0.0)
        .count();
    assert_eq!(
        negative, 4,
        "mirrored placements (counted from the node tree by a script)"
    );

    let scenes = load("MultipleScenes/glTF/MultipleScenes.gltf")?;
    assert_eq!(scenes.meshes.len(), 2, "both meshes load");
    assert_eq!(
        scenes.placements.len(),
        1,
        "only the default scene (1) is placed"
    );
    assert_eq!(scenes.placements[0].mesh, 1);
    assert!(
        scenes.notes.iter().any(|n| n.contains("scene 1 loaded")),
        "{:?}",
        scenes.notes
    );
    Ok(())
}

#[test]
fn non_indexed_sparse_and_strip_and_fan_primitives() -> TestResult {
    let triangle = load("TriangleWithoutIndices/glTF/TriangleWithoutIndices.gltf")?;
    let mesh = &triangle.meshes[0];
    assert_eq!(mesh.triangles, vec![[0, 1, 2]]);
    assert_eq!(mesh.positions, vec![Vec3::ZERO, Vec3::X, Vec3::Y]);

    let sparse = load("SimpleSparseAccessor/glTF/SimpleSparseAccessor.gltf")?;
    let positions = &sparse.meshes[0].positions;
    assert_eq!(positions.len(), 14);
    // Sparse indices 8, 10, 12 replace (1,1,0), (3,1,0), (5,1,0) by:
    assert_eq!(
        [positions[8], positions[10], positions[12]],
        [
            Vec3::new(1.0, 2.0, 0.0),
            Vec3::new(3.0, 3.0, 0.0),
            Vec3::new(5.0, 4.0, 0.0)
        ]
    );
    assert_eq!(
        positions[9],
        Vec3::new(2.0, 1.0, 0.0),
        "untouched base value"
    );

    let modes = load("MeshPrimitiveModes/glTF/MeshPrimitiveModes.gltf")?;
    let count = |name: &str| {
        modes
            .meshes
            .iter()
            .find(|m| m.name == name)
            .map(|m| m.triangles.len())
    };
    assert_eq!(count("mesh with TRIANGLES"), Some(6), "18 indices");
    assert_eq!(count("mesh with GL_TRIANGLE_STRIP"), Some(4), "6 indices");
    assert_eq!(count("mesh with GL_TRIANGLE_FAN"), Some(6), "8 indices");
    assert_eq!(modes.meshes.len(), 3, "points and lines are skipped");
    assert_eq!(
        modes
            .notes
            .iter()
            .filter(|n| n.contains("primitive skipped"))
            .count(),
        4
    );
    // Strip winding alternates so that every triangle faces the same way as the first.
    let strip = modes
        .meshes
        .iter()
        .find(|m| m.name == "mesh with GL_TRIANGLE_STRIP")
        .ok_or("strip")?;
    let facing: Vec<f32> = strip
        .triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|i| strip.positions[i as usize]);
            (b - a).cross(c - a).z
        })
        .collect();
    assert!(
        facing.iter().all(|z| z.signum() == facing[0].signum()),
        "{facing:?}"
    );
    Ok(())
}

#[test]
fn emissive_strength_multiplies_the_emissive_factor() -> TestResult {
    let model = load("EmissiveStrengthTest/glTF-Binary/EmissiveStrengthTest.glb")?;
    let factor = Vec3::new(0.1, 0.5, 0.9);
    for (name, strength) in [
        ("Emit1", 1.0),
        ("Emit2", 2.0),
        ("Emit4", 4.0),
        ("Emit8", 8.0),
        ("Emit16", 16.0),
    ] {
        let m = material(&model, name)?;
        assert!(
            m.emission.abs_diff_eq(factor * strength, 1e-6),
            "{name}: {}",
            m.emission
        );
        assert_eq!(m.base_color, Vec3::ZERO);
    }
    Ok(())
}

#[test]
fn texture_settings_map_samplers_and_share_decoded_images() -> TestResult {
    let model = load("TextureSettingsTest/glTF-Binary/TextureSettingsTest.glb")?;
    let texture = |name: &str| -> Result<&candela::assets::Texture, String> {
        let r = material(&model, name)?
            .base_color_texture
            .ok_or(format!("{name}: no texture"))?;
        Ok(&model.textures[r.0])
    };
    let (mirror_t, clamp_t, repeat_t) = (
        texture("TextureMirrorMaterialT")?,
        texture("TextureClampMaterialT")?,
        texture("TextureRepeatMaterialT")?,
    );
    assert_eq!(
        (mirror_t.wrap_u, mirror_t.wrap_v),
        (Wrap::Repeat, Wrap::Mirror)
    );
    assert_eq!(
        (clamp_t.wrap_u, clamp_t.wrap_v),
        (Wrap::Repeat, Wrap::Clamp)
    );
    assert_eq!(
        (repeat_t.wrap_u, repeat_t.wrap_v),
        (Wrap::Clamp, Wrap::Repeat)
    );
    assert_eq!(
        mirror_t.texels, clamp_t.texels,
        "same image, different samplers"
    );
    // 9 glTF textures, 8 distinct (image, sampler) pairs: DoubleSided and SingleSided share one.
    assert_eq!(model.textures.len(), 8);
    assert_eq!(
        material(&model, "DoubleSidedMaterial")?.base_color_texture,
        material(&model, "SingleSidedMaterial")?.base_color_texture
    );
    assert!(material(&model, "DoubleSidedMaterial")?.two_sided_emission);
    assert!(!material(&model, "SingleSidedMaterial")?.two_sided_emission);
    Ok(())
}

#[test]
fn unicode_names_and_file_names_with_spaces() -> TestResult {
    let unicode = load("UnicodeTest/glTF-Binary/UnicodeTest.glb")?;
    assert_eq!((triangles(&unicode), unicode.textures.len()), (2, 1));
    assert!(
        material(&unicode, "Unicode❤♻Material")?
            .base_color_texture
            .is_some()
    );

    let spaces = load("BoxWithSpaces/glTF/Box With Spaces.gltf")?;
    assert_eq!((triangles(&spaces), spaces.textures.len()), (12, 3));
    let m = &spaces.materials[0];
    assert!(
        m.base_color_texture.is_some()
            && m.metal_rough_texture.is_some()
            && m.normal_texture.is_some()
    );
    Ok(())
}

#[test]
fn transmission_ior_volume_and_data_uri_buffers() -> TestResult {
    let dir =
        std::env::temp_dir().join(format!("candela_assets_gltf_glass_{}", std::process::id()));
    std::fs::create_dir_all(&dir)?;
    // One triangle (positions only, 36 bytes) in a data URI, two materials.
    let floats: Vec<u8> = [0.0f32, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]
        .iter()
        .flat_map(|f| f.to_le_bytes())
        .collect();
    let data = base64::encode(&floats);
    let json = format!(
        r#"{{"asset":{{"version":"2.0"}},
        "extensionsUsed":["KHR_materials_transmission","KHR_materials_ior","KHR_materials_volume","KHR_materials_emissive_strength"],
        "buffers":[{{"byteLength":36,"uri":"data:application/octet-stream;base64,{data}"}}],
        "bufferViews":[{{"buffer":0,"byteLength":36}}],
        "accessors":[{{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}}],
        "materials":[
          {{"name":"glass","pbrMetallicRoughness":{{"baseColorFactor":[0.9,1,0.8,1],"metallicFactor":0,"roughnessFactor":0.1}},
            "extensions":{{"KHR_materials_transmission":{{"transmissionFactor":1}},"KHR_materials_ior":{{"ior":1.33}},
              "KHR_materials_volume":{{"attenuationColor":[0.5,0.6,0.7],"attenuationDistance":2.0,"thicknessFactor":0.1}}}}}},
          {{"name":"half","pbrMetallicRoughness":{{"metallicFactor":0.2}},"emissiveFactor":[1,0.5,0],
            "extensions":{{"KHR_materials_transmission":{{"transmissionFactor":0.5}},"KHR_materials_emissive_strength":{{"emissiveStrength":3}}}}}}],
        "meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}},"material":0}},{{"attributes":{{"POSITION":0}},"material":1}},{{"attributes":{{"POSITION":0}}}}]}}],
        "nodes":[{{"mesh":0,"translation":[1,2,3]}}],"scenes":[{{"nodes":[0]}}],"scene":0}}"#
    );
    std::fs::write(dir.join("glass.gltf"), json)?;
    let model = load_model_file(&dir.join("glass.gltf"))?;
    let glass = material(&model, "glass")?;
    assert_eq!(glass.kind, MaterialKind::Dielectric);
    assert_eq!(
        (glass.ior, glass.roughness, glass.base_color),
        (1.33, 0.1, Vec3::new(0.9, 1.0, 0.8))
    );
    assert_eq!(
        (glass.attenuation_color, glass.attenuation_distance),
        (Vec3::new(0.5, 0.6, 0.7), 2.0)
    );
    let half = material(&model, "half")?;
    assert_eq!(
        (half.kind, half.transmission, half.metallic),
        (MaterialKind::MetalRough, 0.5, 0.2)
    );
    assert_eq!(half.emission, Vec3::new(3.0, 1.5, 0.0));
    assert_eq!(
        model.materials.len(),
        3,
        "the glTF default material is appended"
    );
    let default = &model.materials[2];
    assert_eq!(
        (default.base_color, default.metallic, default.roughness),
        (Vec3::ONE, 1.0, 1.0)
    );
    assert_eq!(model.meshes[0].triangle_materials, vec![0, 1, 2]);
    assert_eq!(
        model.placements[0].model_from_mesh,
        Mat4::from_translation(Vec3::new(1.0, 2.0, 3.0))
    );
    std::fs::remove_dir_all(&dir)?;
    Ok(())
}
