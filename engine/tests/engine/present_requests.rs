//! Present requests on a headless engine (no display, no surface; CPU tracer): the render
//! thread opens no device, presents nothing and returns no screenshot, yet follows the
//! request's surface size as it would a window's — the film is re-created at the new size and
//! converging restarts — and the overlay's bytes are counted in the frame report. Shutdown
//! returns every result and joins the thread.

use candela::app::{Engine, Environment, Step};
use candela::assets::{CameraDesc, RenderSettings, SkyDesc};
use candela::commit::{Overlay, PresentRequest};
use candela::render::RenderConfig;
use candela::render::film::TonemapSettings;

fn engine() -> Engine {
    let config = RenderConfig {
        seed: 3,
        ..RenderConfig::cpu(32, 16)
    };
    let environment = Environment {
        sun: None,
        sky: SkyDesc::Constant([0.3, 0.3, 0.3]),
        render: RenderSettings {
            max_bounces: 2,
            roulette_start: 1,
            ..Default::default()
        },
        default_camera: CameraDesc {
            position: [0.0, 1.0, 3.0],
            look_at: [0.0, 0.0, 0.0],
            up: [0.0, 1.0, 0.0],
            vertical_fov_deg: 50.0,
            aperture_radius: 0.0,
            focus_distance: None,
        },
    };
    Engine::new(config, environment).expect("engine starts")
}

fn request(size: (u32, u32), overlay: Option<Overlay>) -> PresentRequest {
    PresentRequest {
        surface_size: size,
        tonemap: TonemapSettings::default(),
        vsync: true,
        overlay,
        screenshot: true,
        scaling: None,
    }
}

/// An overlay of one small triangle.
fn overlay() -> Overlay {
    let mut mesh = egui::epaint::Mesh::default();
    mesh.colored_vertex(egui::pos2(0.0, 0.0), egui::Color32::RED);
    mesh.colored_vertex(egui::pos2(8.0, 0.0), egui::Color32::RED);
    mesh.colored_vertex(egui::pos2(0.0, 8.0), egui::Color32::RED);
    mesh.add_triangle(0, 1, 2);
    Overlay {
        primitives: vec![egui::ClippedPrimitive {
            clip_rect: egui::Rect::EVERYTHING,
            primitive: egui::epaint::Primitive::Mesh(mesh),
        }],
        textures_delta: Default::default(),
        pixels_per_point: 1.0,
    }
}

#[test]
fn headless_engines_follow_the_surface_size_and_present_nothing() {
    let mut engine = engine();
    let mut reports = Vec::new();
    for frame in 0..6u32 {
        let size = if frame < 3 { (32, 16) } else { (20, 10) };
        engine.present_next(request(size, (frame == 1).then(overlay)));
        reports.push(
            engine
                .frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})
                .expect("frame"),
        );
    }
    assert_eq!(reports[0].overlay_bytes, 0);
    assert_eq!(
        reports[1].overlay_bytes,
        3 * size_of::<egui::epaint::Vertex>() + 3 * 4,
        "three vertices and three u32 indices"
    );
    let mut rendered = Vec::new();
    while rendered.len() < 6 {
        rendered.push(
            engine
                .wait_rendered()
                .expect("a result")
                .expect("render ok"),
        );
    }
    for r in &rendered {
        assert!(r.screenshot.is_none(), "nothing is presented headless");
        assert_eq!(r.present_seconds, 0.0);
        let want = if r.frame < 3 { (32, 16) } else { (20, 10) };
        assert_eq!(r.film_size, want, "frame {}", r.frame);
    }
    assert_eq!(rendered[2].blend, 1.0 / 3.0, "still frames converge");
    assert_eq!(rendered[3].blend, 1.0, "a resize restarts the film");
    assert_eq!(rendered[4].blend, 0.5);
    assert!(engine.shutdown().is_empty(), "every result was taken");
}
