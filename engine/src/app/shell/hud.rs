//! The HUD while playing: a crosshair at the centre (white with a dark outline and an amber
//! dot, readable on any picture), the objective top left, counters top right, the
//! interaction prompt under the crosshair, the outline of where a held body will land, the
//! messages of what just happened centred near the top and a flash over the whole picture —
//! all from the game's [`HudInfo`].
//!
//! Draws with egui. Main thread. Must not: read the world (the game fills `HudInfo`).

use egui::{Align2, Color32, Pos2, RichText, Stroke, Vec2};

use super::theme;
use crate::app::runner::HudInfo;

/// The crosshair's arm length and its gap from the centre, points.
pub const ARM: f32 = 10.0;
pub const GAP: f32 = 5.0;

/// Draws the HUD.
pub fn show(ctx: &egui::Context, hud: &HudInfo) {
    let screen = ctx.content_rect();
    if hud.flash > 0.0 {
        // Under every HUD box (they are foreground areas), over the picture.
        let painter = ctx.layer_painter(egui::LayerId::background());
        let alpha = (hud.flash.clamp(0.0, 1.0) * 150.0) as u8;
        painter.rect_filled(
            screen,
            0.0,
            Color32::from_rgba_unmultiplied(255, 70, 40, alpha),
        );
    }
    if hud.crosshair {
        let painter = ctx.layer_painter(egui::LayerId::background());
        let c = screen.center();
        let arms = [
            (Vec2::new(-1.0, 0.0)),
            (Vec2::new(1.0, 0.0)),
            (Vec2::new(0.0, -1.0)),
            (Vec2::new(0.0, 1.0)),
        ];
        for (width, colour) in [
            (5.0, Color32::from_black_alpha(170)),
            (2.5, Color32::from_rgb(250, 250, 250)),
        ] {
            for d in arms {
                let a: Pos2 = c + d * GAP;
                let b: Pos2 = c + d * (GAP + ARM);
                painter.line_segment([a, b], Stroke::new(width, colour));
            }
        }
        painter.circle_filled(c, 2.5, theme::ACCENT);
    }
    if !hud.outline.is_empty() {
        // The drop preview: a dark underlay and a light line, readable on any picture.
        let painter = ctx.layer_painter(egui::LayerId::background());
        let c = screen.center();
        let scale = screen.height() * 0.5;
        let at = |p: [f32; 2]| c + Vec2::new(p[0], -p[1]) * scale;
        for (width, colour) in [
            (3.5, Color32::from_black_alpha(120)),
            (1.5, Color32::from_rgba_unmultiplied(180, 235, 255, 200)),
        ] {
            for [a, b] in &hud.outline {
                painter.line_segment([at(*a), at(*b)], Stroke::new(width, colour));
            }
        }
    }
    if let Some(objective) = &hud.objective {
        egui::Area::new(egui::Id::unique("shell_hud_objective"))
            .anchor(Align2::LEFT_TOP, Vec2::new(20.0, 20.0))
            .interactable(false)
            .show(ctx, |ui| {
                theme::hud_box().show(ui, |ui| {
                    ui.label(theme::section("Objective"));
                    ui.label(RichText::new(objective).size(20.0));
                });
            });
    }
    if !hud.counters.is_empty() {
        egui::Area::new(egui::Id::unique("shell_hud_counters"))
            .anchor(Align2::RIGHT_TOP, Vec2::new(-20.0, 20.0))
            .interactable(false)
            .show(ctx, |ui| {
                theme::hud_box().show(ui, |ui| {
                    egui::Grid::new("shell_hud_counter_grid")
                        .num_columns(2)
                        .spacing([16.0, 4.0])
                        .show(ui, |ui| {
                            for (label, value) in &hud.counters {
                                ui.label(RichText::new(label).color(theme::MUTED));
                                ui.label(
                                    RichText::new(value)
                                        .size(22.0)
                                        .color(theme::ACCENT)
                                        .strong(),
                                );
                                ui.end_row();
                            }
                        });
                });
            });
    }
    if !hud.messages.is_empty() {
        egui::Area::new(egui::Id::unique("shell_hud_messages"))
            .anchor(Align2::CENTER_TOP, Vec2::new(0.0, 90.0))
            .interactable(false)
            .show(ctx, |ui| {
                theme::hud_box().show(ui, |ui| {
                    for message in &hud.messages {
                        ui.label(RichText::new(message).size(22.0).strong());
                    }
                });
            });
    }
    if let Some(prompt) = &hud.prompt {
        egui::Area::new(egui::Id::unique("shell_hud_prompt"))
            .anchor(Align2::CENTER_CENTER, Vec2::new(0.0, 70.0))
            .interactable(false)
            .show(ctx, |ui| {
                theme::hud_box().show(ui, |ui| {
                    ui.label(RichText::new(prompt).size(20.0));
                });
            });
    }
}
