//! The time-of-day dial the HUD shows (bottom right): a disc split into day (upper half,
//! warm) and night (lower half, deep blue), the sun's place on it by the local solar time
//! (noon at the top, midnight at the bottom, the morning on the left), and the clock under it.
//!
//! Main thread, in `Game::ui`. Must not: change the game.

use egui::{Align2, Color32, Pos2, Stroke, Vec2};

/// Radius of the dial, points.
const RADIUS: f32 = 34.0;

/// Where on a unit dial the sun stands at `hours` local time: noon up (0, −1 in screen
/// space, y down), midnight down, 06:00 left, 18:00 right.
pub fn hand(hours: f64) -> Vec2 {
    let angle = (hours / 24.0 * std::f64::consts::TAU) as f32;
    // 0 h → down (0, 1); 6 h → left (−1, 0); 12 h → up; 18 h → right.
    Vec2::new(-angle.sin(), angle.cos())
}

/// Draws the dial for `hours` local time with `label` under it, bottom right of the screen.
pub fn draw(ctx: &egui::Context, hours: f64, label: &str) {
    egui::Area::new(egui::Id::unique("iat_time_dial"))
        .anchor(Align2::RIGHT_BOTTOM, Vec2::new(-24.0, -24.0))
        .interactable(false)
        .show(ctx, |ui| {
            let (rect, _) = ui.allocate_exact_size(
                Vec2::new(2.0 * RADIUS + 8.0, 2.0 * RADIUS + 26.0),
                egui::Sense::hover(),
            );
            let centre = Pos2::new(rect.center().x, rect.top() + RADIUS + 4.0);
            let painter = ui.painter();
            painter.circle_filled(centre, RADIUS, Color32::from_rgb(22, 30, 62));
            // The day half: a fan of thin triangles over the upper semicircle.
            let day = Color32::from_rgb(214, 160, 84);
            let steps = 24;
            for i in 0..steps {
                let a0 = std::f32::consts::PI * i as f32 / steps as f32;
                let a1 = std::f32::consts::PI * (i + 1) as f32 / steps as f32;
                let p = |a: f32| centre + Vec2::new(-a.cos(), -a.sin()) * RADIUS;
                painter.add(egui::Shape::convex_polygon(
                    vec![centre, p(a0), p(a1)],
                    day,
                    Stroke::NONE,
                ));
            }
            painter.circle_stroke(
                centre,
                RADIUS,
                Stroke::new(2.0, Color32::from_rgb(60, 44, 30)),
            );
            let sun = centre + hand(hours) * (RADIUS - 8.0);
            painter.line_segment(
                [centre, sun],
                Stroke::new(2.0, Color32::from_rgb(60, 44, 30)),
            );
            painter.circle_filled(sun, 6.0, Color32::from_rgb(255, 236, 160));
            painter.text(
                Pos2::new(centre.x, rect.bottom() - 2.0),
                Align2::CENTER_BOTTOM,
                label,
                egui::FontId::proportional(15.0),
                Color32::WHITE,
            );
        });
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn noon_is_up_and_the_morning_is_left() {
        let close = |a: Vec2, b: Vec2| (a - b).length() < 1e-5;
        assert!(close(hand(12.0), Vec2::new(0.0, -1.0)));
        assert!(close(hand(0.0), Vec2::new(0.0, 1.0)));
        assert!(close(hand(6.0), Vec2::new(-1.0, 0.0)));
        assert!(close(hand(18.0), Vec2::new(1.0, 0.0)));
    }
}
