//! Which render areas (`render_areas` in the level, `candela::assets::RenderArea`) the camera
//! stands in along a replay's camera path (`headless::RunSummary::camera_path`): the table
//! `its_about_time --replay FILE --headless --camera-path OUT.csv` writes, and the share of
//! frames spent inside an area the replay tests check.
//!
//! Owns: [`areas_at`], [`path_csv`], [`share_inside`]. Any thread, pure. Must not: change the
//! level or the engine's sampling (the upkeep samples from the camera itself).
//!
//! Units: metres, world space (right-handed, Y up).

use candela::assets::RenderArea;

/// The names of the areas whose box holds `camera` (metres, world space), in the level's order.
pub fn areas_at(areas: &[RenderArea], camera: [f32; 3]) -> Vec<&str> {
    (areas.iter())
        .filter(|a| a.contains(camera))
        .map(|a| a.name.as_str())
        .collect()
}

/// The camera path as CSV: `frame,x,y,z,areas` (areas joined by `+`, `-` outside every area).
pub fn path_csv(areas: &[RenderArea], path: &[[f32; 3]]) -> String {
    let mut out = String::from("frame,x,y,z,areas\n");
    for (i, p) in path.iter().enumerate() {
        let inside = areas_at(areas, *p);
        let names = if inside.is_empty() {
            "-".to_string()
        } else {
            inside.join("+")
        };
        out += &format!("{i},{:.2},{:.2},{:.2},{names}\n", p[0], p[1], p[2]);
    }
    out
}

/// The share (0 to 1) of the points of `path` inside the area named `name`; 0 for an empty
/// path or an unknown name.
pub fn share_inside(areas: &[RenderArea], path: &[[f32; 3]], name: &str) -> f64 {
    let Some(area) = areas.iter().find(|a| a.name == name) else {
        return 0.0;
    };
    if path.is_empty() {
        return 0.0;
    }
    path.iter().filter(|p| area.contains(**p)).count() as f64 / path.len() as f64
}

/// One line per area: the share of `path`'s frames inside it, and outside every area.
pub fn shares_line(areas: &[RenderArea], path: &[[f32; 3]]) -> String {
    let mut parts: Vec<String> = (areas.iter())
        .map(|a| a.name.as_str())
        .map(|n| (n, share_inside(areas, path, n)))
        .filter(|(_, s)| *s > 0.0)
        .map(|(n, s)| format!("{n} {:.0} %", 100.0 * s))
        .collect();
    let outside = path
        .iter()
        .filter(|p| areas_at(areas, **p).is_empty())
        .count();
    let total = path.len().max(1) as f64;
    parts.push(format!("outside {:.0} %", 100.0 * outside as f64 / total));
    format!("camera in areas: {}", parts.join(", "))
}
