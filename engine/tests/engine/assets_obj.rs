//! OBJ + MTL loading: the two external reference scenes must load with exactly the materials
//! their `scene.md` describes, quads must split as Mitsuba splits them, and the MTL mapping
//! (illum modes, Ns, d, textures, bump maps) must give the documented engine materials.

use std::path::{Path, PathBuf};

use candela::assets::{AssetRoot, Material, MaterialKind, Model, load_model, load_model_file};
use glam::{Vec2, Vec3};

type TestResult = Result<(), Box<dyn std::error::Error>>;

use super::common::external;

/// A fresh temporary folder for one test.
fn temp_dir(name: &str) -> Result<PathBuf, std::io::Error> {
    let dir =
        std::env::temp_dir().join(format!("candela_assets_obj_{name}_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir)?;
    Ok(dir)
}

/// Triangles an OBJ file should give: a polygon of n corners makes n - 2 (counted from the text).
fn expected_triangles(path: &Path) -> Result<usize, std::io::Error> {
    Ok(std::fs::read_to_string(path)?
        .lines()
        .filter(|line| line.starts_with("f "))
        .map(|line| line.split_whitespace().count() - 3)
        .sum())
}

fn only_material(model: &Model) -> &Material {
    assert_eq!(
        model.materials.len(),
        1,
        "{}: materials {:?}",
        model.name,
        model.materials
    );
    &model.materials[0]
}

fn diffuse(albedo: Vec3) -> impl Fn(&Material) {
    move |m: &Material| {
        assert_eq!(m.kind, MaterialKind::Diffuse, "{}", m.name);
        assert_eq!(m.base_color, albedo, "{}", m.name);
        assert_eq!(m.emission, Vec3::ZERO, "{}", m.name);
        assert!(m.base_color_texture.is_none() && m.normal_texture.is_none());
    }
}

const WHITE: Vec3 = Vec3::new(0.725, 0.71, 0.68);
const RED: Vec3 = Vec3::new(0.63, 0.065, 0.05);
const GREEN: Vec3 = Vec3::new(0.14, 0.45, 0.091);

/// Checks one mesh file of a reference scene: one mesh, one identity placement, the triangle
/// count of its faces, flat shading unless it has `vn`, and the material.
fn check_reference_mesh(
    scene: &str,
    file: &str,
    check: &dyn Fn(&Material),
) -> Result<Model, Box<dyn std::error::Error>> {
    let path = external(&format!("reference/{scene}/meshes/{file}"));
    let model = load_model_file(&path)?;
    assert_eq!(model.meshes.len(), 1, "{file}");
    assert_eq!(model.placements.len(), 1, "{file}");
    assert_eq!(model.placements[0].model_from_mesh, glam::Mat4::IDENTITY);
    let mesh = &model.meshes[0];
    assert_eq!(mesh.triangles.len(), expected_triangles(&path)?, "{file}");
    assert!(mesh.triangle_materials.iter().all(|&m| m == 0));
    let has_vn = std::fs::read_to_string(&path)?
        .lines()
        .any(|l| l.starts_with("vn "));
    assert_eq!(mesh.normals.is_some(), has_vn, "{file}");
    if !has_vn {
        assert!(
            model.notes.iter().any(|n| n.contains("no normals")),
            "{file}: {:?}",
            model.notes
        );
    }
    check(only_material(&model));
    Ok(model)
}

#[test]
fn cornell_box_loads_with_the_materials_of_its_scene_md() -> TestResult {
    for file in [
        "floor.obj",
        "ceiling.obj",
        "backwall.obj",
        "short_block.obj",
        "tall_block.obj",
    ] {
        check_reference_mesh("cornell_box", file, &diffuse(WHITE))?;
    }
    check_reference_mesh("cornell_box", "leftwall.obj", &diffuse(RED))?;
    check_reference_mesh("cornell_box", "rightwall.obj", &diffuse(GREEN))?;
    let light = check_reference_mesh("cornell_box", "light.obj", &|m: &Material| {
        assert_eq!(m.kind, MaterialKind::Diffuse);
        assert_eq!(m.base_color, Vec3::ZERO);
        assert_eq!(m.emission, Vec3::new(17.0, 12.0, 4.0));
        assert!(!m.two_sided_emission, "the light is one-sided");
    })?;
    // One-sided towards -y: the geometric normal (v1 - v0) × (v2 - v0) of both triangles.
    let mesh = &light.meshes[0];
    for t in &mesh.triangles {
        let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
        let normal = (b - a).cross(c - a).normalize();
        assert!(
            normal.abs_diff_eq(Vec3::NEG_Y, 1e-6),
            "light normal {normal}"
        );
    }
    Ok(())
}

#[test]
fn quads_split_as_v0_v1_v2_and_v0_v2_v3() -> TestResult {
    let model = load_model_file(&external("reference/cornell_box/meshes/floor.obj"))?;
    let mesh = &model.meshes[0];
    // floor.obj: v (-1,0,-1) (-1,0,1) (1,0,1) (1,0,-1), "f 1 2 3 4".
    let corners = [
        Vec3::new(-1.0, 0.0, -1.0),
        Vec3::new(-1.0, 0.0, 1.0),
        Vec3::new(1.0, 0.0, 1.0),
        Vec3::new(1.0, 0.0, -1.0),
    ];
    let triangles: Vec<[Vec3; 3]> = mesh
        .triangles
        .iter()
        .map(|t| t.map(|i| mesh.positions[i as usize]))
        .collect();
    assert_eq!(
        triangles,
        vec![
            [corners[0], corners[1], corners[2]],
            [corners[0], corners[2], corners[3]]
        ]
    );
    Ok(())
}

#[test]
fn cornell_mirror_glass_loads_a_perfect_mirror_and_smooth_glass() -> TestResult {
    for file in ["floor.obj", "ceiling.obj", "backwall.obj"] {
        check_reference_mesh("cornell_mirror_glass", file, &diffuse(WHITE))?;
    }
    check_reference_mesh("cornell_mirror_glass", "leftwall.obj", &diffuse(RED))?;
    check_reference_mesh("cornell_mirror_glass", "rightwall.obj", &diffuse(GREEN))?;
    let sphere = check_reference_mesh(
        "cornell_mirror_glass",
        "mirror_sphere.obj",
        &|m: &Material| {
            assert_eq!(m.kind, MaterialKind::Conductor);
            assert_eq!(m.base_color, Vec3::ONE, "reflectance 1 for all channels");
            assert_eq!(m.roughness, 0.0, "a perfect mirror");
            assert_eq!(m.emission, Vec3::ZERO);
        },
    )?;
    let mesh = &sphere.meshes[0];
    assert_eq!(mesh.triangles.len(), 9024);
    let normals = mesh.normals.as_ref().ok_or("the sphere has vn")?;
    let centre = Vec3::new(-0.4, 0.4, -0.3);
    for (p, n) in mesh.positions.iter().zip(normals) {
        assert!(
            ((*p - centre) / 0.4).abs_diff_eq(*n, 1e-4),
            "normal {n} at {p}"
        );
    }
    check_reference_mesh("cornell_mirror_glass", "glass_cube.obj", &|m: &Material| {
        assert_eq!(m.kind, MaterialKind::Dielectric);
        assert_eq!(m.ior, 1.5);
        assert_eq!(m.roughness, 0.0, "smooth");
        assert_eq!(m.base_color, Vec3::ONE, "no tint");
        assert_eq!(m.attenuation_distance, f32::INFINITY, "no absorption");
        assert_eq!(m.emission, Vec3::ZERO);
    })?;
    check_reference_mesh("cornell_mirror_glass", "light.obj", &|m: &Material| {
        assert_eq!(
            (m.base_color, m.emission),
            (Vec3::ZERO, Vec3::new(17.0, 12.0, 4.0))
        );
        assert!(!m.two_sided_emission);
    })?;
    Ok(())
}

#[test]
fn the_whole_reference_scene_loads_through_one_asset_root() -> TestResult {
    let root = AssetRoot::new(external("reference/cornell_mirror_glass"))?;
    let model = load_model(&root, Path::new("scene.ron"), "meshes/glass_cube.obj")?;
    assert_eq!(model.name, "meshes/glass_cube.obj");
    assert_eq!(model.meshes[0].triangles.len(), 12);
    Ok(())
}

#[test]
fn groups_materials_uvs_and_polygons() -> TestResult {
    let dir = temp_dir("groups")?;
    std::fs::write(
        dir.join("m.mtl"),
        "newmtl a\nKd 1 0 0\nnewmtl b\nKd 0 0 1\nillum 2\nKs 0.5 0.5 0.5\nNs 100\n\
         newmtl c\nKd 0.5 0.5 0.5\nd 0.25\n",
    )?;
    std::fs::write(
        dir.join("m.obj"),
        "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 1.5 0\n\
         vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.25\n\
         g first\nusemtl a\nf 1/1 2/2 3/3\nusemtl b\nf 1/1 3/3 4/4\n\
         g second\nusemtl c\nf 1/1 2/2 3/3 5/5 4/4\n",
    )?;
    let model = load_model_file(&dir.join("m.obj"))?;
    assert_eq!(model.meshes.len(), 2, "one mesh per group");
    let [first, second] = [&model.meshes[0], &model.meshes[1]];
    assert_eq!(
        (first.name.as_str(), second.name.as_str()),
        ("first", "second")
    );
    assert_eq!(first.triangles.len(), 2);
    assert_eq!(
        second.triangles.len(),
        3,
        "a pentagon is a fan of 3 triangles"
    );
    let names = |mesh: &candela::assets::Mesh| -> Vec<String> {
        mesh.triangle_materials
            .iter()
            .map(|&m| model.materials[m as usize].name.clone())
            .collect()
    };
    assert_eq!(names(first), ["a", "b"]);
    assert_eq!(names(second), ["c", "c", "c"]);
    // vt (0.5, 0.25) becomes (0.5, 0.75): v down the image.
    let uvs = second.uvs.as_ref().ok_or("uvs")?;
    let apex = second
        .positions
        .iter()
        .position(|p| *p == Vec3::new(0.5, 1.5, 0.0))
        .ok_or("apex")?;
    assert_eq!(uvs[apex], Vec2::new(0.5, 0.75));
    let b = model.materials.iter().find(|m| m.name == "b").ok_or("b")?;
    assert_eq!(b.kind, MaterialKind::MetalRough);
    assert_eq!((b.base_color, b.metallic), (Vec3::new(0.0, 0.0, 1.0), 0.0));
    let expected = (2.0f32 / 102.0).sqrt().sqrt();
    assert!(
        (b.roughness - expected).abs() < 1e-6,
        "roughness {} from Ns 100",
        b.roughness
    );
    let c = model.materials.iter().find(|m| m.name == "c").ok_or("c")?;
    assert_eq!(
        (c.kind, c.transmission),
        (MaterialKind::MetalRough, 0.75),
        "d 0.25"
    );
    std::fs::remove_dir_all(&dir)?;
    Ok(())
}

#[test]
fn mcguire_glossy_sphere_and_walls_map_as_documented() -> TestResult {
    let model = load_model_file(&external("obj/mcguire_cornell_box/CornellBox-Glossy.obj"))?;
    let sphere = model
        .materials
        .iter()
        .find(|m| m.name == "sphere")
        .ok_or("sphere")?;
    assert_eq!(sphere.kind, MaterialKind::MetalRough, "illum 2 with Ks 0.7");
    assert_eq!(sphere.base_color, Vec3::new(0.486, 0.631, 0.663));
    assert!(
        (sphere.roughness - (2.0f32 / 34.0).sqrt().sqrt()).abs() < 1e-6,
        "Ns 32"
    );
    let light = model
        .materials
        .iter()
        .find(|m| m.name == "light")
        .ok_or("light")?;
    assert_eq!(light.emission, Vec3::splat(10.0), "Ke 10 10 10");
    let original = load_model_file(&external("obj/mcguire_cornell_box/CornellBox-Original.obj"))?;
    let light = original
        .materials
        .iter()
        .find(|m| m.name == "light")
        .ok_or("light")?;
    assert_eq!(
        (light.kind, light.emission),
        (MaterialKind::Diffuse, Vec3::new(17.0, 12.0, 4.0))
    );
    let mirror = load_model_file(&external("obj/mcguire_cornell_box/CornellBox-Mirror.obj"))?;
    let left = mirror
        .materials
        .iter()
        .find(|m| m.name == "leftWall")
        .ok_or("leftWall")?;
    assert_eq!(
        (left.kind, left.base_color),
        (MaterialKind::Diffuse, RED),
        "illum 2 but Ks 0"
    );
    Ok(())
}

#[test]
fn textures_decode_srgb_and_bump_height_maps_become_normal_maps() -> TestResult {
    let dir = temp_dir("textures")?;
    // A 2×1 colour texture with known sRGB bytes, and a greyscale height ramp.
    image::RgbaImage::from_raw(2, 1, vec![0, 128, 255, 255, 10, 200, 50, 128])
        .ok_or("image")?
        .save(dir.join("colour.png"))?;
    image::GrayImage::from_fn(4, 4, |x, _| image::Luma([(x * 60) as u8]))
        .save(dir.join("height.png"))?;
    std::fs::write(
        dir.join("t.mtl"),
        "newmtl t\nmap_Kd -clamp on colour.png\nbump -bm 0.5 height.png\nKe 1 2 3\n",
    )?;
    std::fs::write(
        dir.join("t.obj"),
        "mtllib t.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\nusemtl t\nf 1/1/1 2/2/1 3/3/1\n",
    )?;
    let model = load_model_file(&dir.join("t.obj"))?;
    let material = only_material(&model);
    assert_eq!(material.base_color, Vec3::ONE, "map_Kd without Kd");
    assert_eq!(material.emission, Vec3::new(1.0, 2.0, 3.0));
    assert_eq!(material.normal_scale, 0.5, "-bm");
    let colour = &model.textures[material.base_color_texture.ok_or("colour")?.0];
    assert_eq!(
        (colour.width, colour.height, colour.wrap_u),
        (2, 1, candela::assets::Wrap::Clamp)
    );
    let srgb = |byte: u8| {
        let c = f32::from(byte) / 255.0;
        if c <= 0.04045 {
            c / 12.92
        } else {
            ((c + 0.055) / 1.055).powf(2.4)
        }
    };
    for (texel, bytes) in colour
        .texels
        .iter()
        .zip([[0u8, 128, 255, 255], [10, 200, 50, 128]])
    {
        for channel in 0..3 {
            let expected = srgb(bytes[channel]);
            let got = texel[channel].to_f32();
            assert!(
                (got - expected).abs() <= expected * 1e-3 + 1e-6,
                "{got} vs {expected}"
            );
        }
        assert!(
            (texel[3].to_f32() - f32::from(bytes[3]) / 255.0).abs() < 1e-3,
            "alpha is linear"
        );
    }
    let normal = &model.textures[material.normal_texture.ok_or("normal")?.0];
    // Height rises along +u in the middle: the normal leans towards -x, y stays 0.
    let n = normal.texels[4 + 1].map(|c| c.to_f32() * 2.0 - 1.0);
    assert!(
        n[0] < -0.1 && n[1].abs() < 1e-2 && n[2] > 0.5,
        "normal {n:?}"
    );
    assert!(
        model.notes.iter().any(|n| n.contains("height map")),
        "{:?}",
        model.notes
    );
    let mesh = &model.meshes[0];
    assert!(mesh.tangents.is_some(), "normal-mapped mesh gets tangents");
    assert!(model.notes.iter().any(|n| n.contains("generated tangents")));
    std::fs::remove_dir_all(&dir)?;
    Ok(())
}
