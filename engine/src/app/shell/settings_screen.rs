//! The settings screen: picture (resolution scale, target frame rate, vsync, fullscreen), sound
//! (master, effects, music), controls (mouse sensitivity, invert Y) and key bindings (click an
//! action, press a key, mouse button or gamepad button; a key bound twice is marked), with Reset to defaults
//! and Back. Every change goes into the [`SettingsEditor`]'s draft, which the runner applies at
//! once and saves.
//!
//! Draws with egui, returns the choice. Main thread. Must not: apply or save settings itself.

use egui::{RichText, Vec2};

use super::settings_edit::{FRAME_RATES, SettingsEditor, action_label, binding_label};
use super::state::ShellInput;
use super::theme;

fn rate_label(rate: Option<f32>) -> String {
    match rate {
        Some(fps) => format!("{fps:.0} fps"),
        None => "Unlimited".into(),
    }
}

/// One labelled row of the settings grid.
fn row(ui: &mut egui::Ui, label: &str, add: impl FnOnce(&mut egui::Ui)) {
    ui.label(label);
    add(ui);
    ui.end_row();
}

/// Draws the settings screen; `workload` is what workload scaling settled on (shown under the
/// target frame rate); `dim` darkens the picture first (opened from the pause menu).
pub fn show(
    ctx: &egui::Context,
    editor: &mut SettingsEditor,
    workload: Option<&str>,
    dim: bool,
) -> Option<ShellInput> {
    if dim {
        theme::dim(ctx);
    }
    let mut choice = None;
    let max_height = ctx.content_rect().height() - 60.0;
    theme::centred(ctx, "shell_settings", |ui| {
        ui.set_max_height(max_height);
        ui.vertical_centered(|ui| ui.label(theme::heading("Settings")));
        ui.add_space(4.0);
        egui::ScrollArea::vertical()
            .max_height(max_height - 120.0)
            .show(ui, |ui| {
                ui.columns(2, |cols| {
                    general(&mut cols[0], editor, workload);
                    bindings(&mut cols[1], editor);
                });
            });
        ui.add_space(8.0);
        ui.horizontal(|ui| {
            if ui
                .add(egui::Button::new("Reset to defaults").min_size(Vec2::new(200.0, 40.0)))
                .clicked()
            {
                editor.reset_all();
            }
            ui.add_space(ui.available_width() - 200.0);
            if ui
                .add(
                    egui::Button::new(RichText::new("Back").strong())
                        .min_size(Vec2::new(200.0, 40.0)),
                )
                .clicked()
            {
                choice = Some(ShellInput::CloseSettings);
            }
        });
    });
    choice
}

/// Picture, sound and controls, in one grid so that every widget lines up.
fn general(ui: &mut egui::Ui, editor: &mut SettingsEditor, workload: Option<&str>) {
    let s = &mut editor.draft;
    let percent = |v: f64, _: std::ops::RangeInclusive<usize>| format!("{:.0} %", v * 100.0);
    egui::Grid::new("shell_settings_general")
        .num_columns(2)
        .spacing([18.0, 7.0])
        .show(ui, |ui| {
            section_row(ui, "Picture");
            row(ui, "Resolution scale", |ui| {
                ui.add(
                    egui::Slider::new(&mut s.resolution_scale, 0.25..=1.0)
                        .step_by(0.05)
                        .custom_formatter(percent),
                );
            });
            row(ui, "Target frame rate", |ui| {
                egui::ComboBox::from_id_salt("shell_settings_fps")
                    .selected_text(rate_label(s.target_fps))
                    .show_ui(ui, |ui| {
                        for rate in FRAME_RATES {
                            ui.selectable_value(&mut s.target_fps, rate, rate_label(rate));
                        }
                    });
            });
            if let Some(workload) = workload {
                row(ui, "Holding now", |ui| {
                    ui.label(workload)
                        .on_hover_text("What workload scaling settled on to hold the target");
                });
            }
            row(ui, "Vsync", |ui| {
                ui.checkbox(&mut s.vsync, "");
            });
            row(ui, "Fullscreen", |ui| {
                ui.checkbox(&mut s.fullscreen, "");
            });
            section_row(ui, "Sound");
            for (label, value) in [
                ("Master volume", &mut s.master_volume),
                ("Effects volume", &mut s.effects_volume),
                ("Music volume", &mut s.music_volume),
            ] {
                row(ui, label, |ui| {
                    ui.add(egui::Slider::new(value, 0.0..=1.0).custom_formatter(percent));
                });
            }
            section_row(ui, "Controls");
            row(ui, "Mouse sensitivity", |ui| {
                ui.add(
                    egui::Slider::new(&mut s.mouse_sensitivity, 0.1..=5.0)
                        .logarithmic(true)
                        .max_decimals(2),
                );
            });
            row(ui, "Invert Y", |ui| {
                ui.checkbox(&mut s.invert_y, "");
            });
        });
}

/// A section heading as a grid row.
fn section_row(ui: &mut egui::Ui, text: &str) {
    ui.label(theme::section(text));
    ui.label("");
    ui.end_row();
}

/// The key bindings list.
fn bindings(ui: &mut egui::Ui, editor: &mut SettingsEditor) {
    ui.label(theme::section("Key bindings"));
    let capturing = editor.capturing().map(str::to_string);
    let mut rebind = None;
    egui::Grid::new("shell_settings_bindings")
        .num_columns(2)
        .spacing([18.0, 6.0])
        .show(ui, |ui| {
            for action in editor.rebindable() {
                let conflict = editor.in_conflict(&action);
                let label = RichText::new(action_label(&action));
                ui.label(if conflict {
                    label.color(theme::WARN)
                } else {
                    label
                });
                let text = if capturing.as_deref() == Some(action.as_str()) {
                    RichText::new("press a key or button…").color(theme::ACCENT)
                } else {
                    let shown: Vec<String> = editor
                        .bindings_of(&action)
                        .iter()
                        .map(binding_label)
                        .collect();
                    let text = if shown.is_empty() {
                        "—".to_string()
                    } else {
                        shown.join(" / ")
                    };
                    let text = RichText::new(text).size(17.0);
                    if conflict {
                        text.color(theme::WARN)
                    } else {
                        text
                    }
                };
                if ui
                    .add(egui::Button::new(text).min_size(Vec2::new(190.0, 28.0)))
                    .clicked()
                {
                    rebind = Some(action.clone());
                }
                ui.end_row();
            }
        });
    if let Some(action) = rebind {
        editor.start_rebind(&action);
    }
    let conflicts = editor.conflicts();
    if !conflicts.is_empty() {
        ui.add_space(6.0);
        for c in conflicts {
            let names: Vec<String> = c.actions.iter().map(|a| action_label(a)).collect();
            ui.label(
                RichText::new(format!(
                    "⚠ {} is bound to {}",
                    binding_label(&c.binding),
                    names.join(" and ")
                ))
                .small()
                .color(theme::WARN),
            );
        }
    }
}
