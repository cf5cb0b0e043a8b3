//! The title screen: the game's name and subtitle, Continue / New game / each level (a tick on
//! finished ones), Settings, Quit, and a notice box when a settings or save file was corrupt
//! and replaced by defaults (naming the file, the problem and the kept backup).
//!
//! Draws with egui, returns the choice. Main thread. Must not: change state itself.

use egui::{Align2, RichText, Vec2};

use super::files::Notice;
use super::state::ShellInput;
use super::theme;
use crate::app::persist::Progress;
use crate::app::runner::{LevelStart, ShellInfo};

/// Where Continue starts: the first unfinished level, from its checkpoint (`None` when every
/// level is finished or nothing was played yet).
pub fn continue_point(info: &ShellInfo, progress: &Progress) -> Option<LevelStart> {
    let played = !progress.finished.is_empty() || !progress.checkpoints.is_empty();
    if !played {
        return None;
    }
    info.levels
        .iter()
        .find(|l| !progress.is_finished(&l.id))
        .map(|l| LevelStart {
            level: l.id.clone(),
            checkpoint: progress.checkpoint(&l.id).map(str::to_string),
        })
}

/// The Continue button's text: the level's name, and the checkpoint's when it is another
/// place (a level's id names that level; any other id is shown with spaces for underscores).
pub fn continue_label(info: &ShellInfo, start: &LevelStart) -> String {
    let named = |id: &str| {
        info.levels
            .iter()
            .find(|l| l.id == id)
            .map(|l| l.name.clone())
    };
    let level = named(&start.level).unwrap_or_else(|| start.level.replace('_', " "));
    let place = match start.checkpoint.as_deref() {
        None => level,
        Some(cp) if cp == start.level => level,
        Some(cp) => named(cp).unwrap_or_else(|| format!("{level}  ·  {}", cp.replace('_', " "))),
    };
    format!("Continue  ·  {place}")
}

/// Draws the title screen; `notices` can be dismissed here.
pub fn show(
    ctx: &egui::Context,
    info: &ShellInfo,
    progress: &Progress,
    notices: &mut Vec<Notice>,
) -> Option<ShellInput> {
    let mut choice = None;
    theme::top_shade(ctx, 0.45);
    let name = egui::Area::new(egui::Id::unique("shell_title_name"))
        .anchor(Align2::CENTER_TOP, Vec2::new(0.0, 70.0))
        .show(ctx, |ui| {
            ui.vertical_centered(|ui| {
                ui.label(theme::title(&info.title));
                if !info.subtitle.is_empty() {
                    ui.label(RichText::new(&info.subtitle).size(22.0).color(theme::MUTED));
                }
            });
        });
    // The menu sits centred in the window, but never higher than just under the subtitle (a
    // long level list grew up over it).
    // Its height is last frame's (egui lays an area out once a frame), 0 on the first.
    let menu_id = egui::Id::unique("shell_title_menu_height");
    let height: f32 = ctx.data(|d| d.get_temp(menu_id)).unwrap_or(0.0);
    let below_name = name.response.rect.bottom() + 24.0;
    let centred = ctx.content_rect().center().y + 60.0 - 0.5 * height;
    let menu = egui::Area::new(egui::Id::unique("shell_title_menu"))
        .anchor(Align2::CENTER_TOP, Vec2::new(0.0, centred.max(below_name)))
        .show(ctx, |ui| {
            theme::panel().show(ui, |ui| {
                ui.vertical_centered(|ui| {
                    if let Some(start) = continue_point(info, progress) {
                        if theme::menu_button(ui, &continue_label(info, &start)) {
                            choice = Some(ShellInput::Start(start));
                        }
                    }
                    if let Some(first) = info.levels.first()
                        && theme::menu_button(ui, "New game")
                    {
                        choice = Some(ShellInput::Start(LevelStart {
                            level: first.id.clone(),
                            checkpoint: None,
                        }));
                    }
                    let offered: Vec<_> = info
                        .levels
                        .iter()
                        .filter(|l| !info.finished_only || progress.is_finished(&l.id))
                        .collect();
                    if offered.len() > 1 || (info.finished_only && !offered.is_empty()) {
                        ui.add_space(6.0);
                        ui.label(theme::section("Levels"));
                        for level in offered {
                            // A list of finished levels only needs no mark. The mark is
                            // plain text: egui's default fonts have no check-mark glyph (a
                            // "✔" drew as an empty box).
                            let mark = match progress.is_finished(&level.id) {
                                true if !info.finished_only => " · solved",
                                _ => "",
                            };
                            if theme::menu_button(ui, &format!("{}{mark}", level.name)) {
                                choice = Some(ShellInput::Start(LevelStart {
                                    level: level.id.clone(),
                                    checkpoint: None,
                                }));
                            }
                        }
                        ui.add_space(6.0);
                    }
                    if theme::menu_button(ui, "Settings") {
                        choice = Some(ShellInput::OpenSettings);
                    }
                    if theme::menu_button(ui, "Quit") {
                        choice = Some(ShellInput::Quit);
                    }
                });
            });
        });
    let height = menu.response.rect.height();
    ctx.data_mut(|d| d.insert_temp(menu_id, height));
    if !notices.is_empty() {
        show_notices(ctx, notices);
    }
    choice
}

/// The notice box, bottom centre.
fn show_notices(ctx: &egui::Context, notices: &mut Vec<Notice>) {
    egui::Area::new(egui::Id::unique("shell_notices"))
        .anchor(Align2::CENTER_BOTTOM, Vec2::new(0.0, -24.0))
        .show(ctx, |ui| {
            theme::panel()
                .stroke(egui::Stroke::new(1.5, theme::WARN))
                .show(ui, |ui| {
                    ui.set_max_width(760.0);
                    for notice in notices.iter() {
                        ui.label(
                            RichText::new(format!("⚠  {}", notice.title))
                                .color(theme::WARN)
                                .strong(),
                        );
                        ui.label(RichText::new(&notice.detail).small().color(theme::TEXT));
                    }
                    if ui.button("Dismiss").clicked() {
                        notices.clear();
                    }
                });
        });
}
