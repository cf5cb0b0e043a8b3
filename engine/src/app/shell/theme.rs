//! The shell's one look for menus and the HUD, unlike the debug overlay's default egui style:
//! large type, a warm amber accent on near-black translucent panels, wide buttons with generous
//! padding, rounded corners, and a UI scale that follows the window's height (720 px = 1).
//!
//! Owns: the colours, sizes and the egui `Style` built from them, and small builders every
//! screen uses (the panel frame, menu buttons, headings). Main thread. Must not: hold state.

use egui::{Color32, CornerRadius, FontFamily, FontId, Margin, Stroke, TextStyle, Vec2};

/// The accent: titles, the selected or hovered button, the crosshair's centre.
pub const ACCENT: Color32 = Color32::from_rgb(255, 183, 77);
/// Body text.
pub const TEXT: Color32 = Color32::from_rgb(236, 232, 222);
/// Secondary text.
pub const MUTED: Color32 = Color32::from_rgb(160, 156, 148);
/// Warnings (a replaced file, a key bound twice).
pub const WARN: Color32 = Color32::from_rgb(255, 110, 90);
/// Menu panels: near black, mostly opaque.
pub const PANEL: Color32 = Color32::from_rgba_premultiplied(10, 11, 16, 232);
/// HUD boxes: lighter, so the picture shows through.
pub const HUD_BOX: Color32 = Color32::from_rgba_premultiplied(6, 7, 10, 150);
/// Over the picture behind a menu (pause, settings in play).
pub const DIM: Color32 = Color32::from_rgba_premultiplied(0, 0, 0, 130);
/// Buttons at rest.
const BUTTON: Color32 = Color32::from_rgb(34, 36, 44);
const BUTTON_HOVER: Color32 = Color32::from_rgb(64, 52, 30);

/// Width of the menu column at UI scale 1, points.
pub const MENU_WIDTH: f32 = 360.0;
/// Window height, physical pixels, at which the UI scale is 1.
const REFERENCE_HEIGHT: f32 = 720.0;

/// The shell's egui style.
pub fn style() -> egui::Style {
    let mut style = egui::Style {
        visuals: egui::Visuals::dark(),
        ..Default::default()
    };
    style.text_styles = [
        (
            TextStyle::Heading,
            FontId::new(30.0, FontFamily::Proportional),
        ),
        (TextStyle::Body, FontId::new(19.0, FontFamily::Proportional)),
        (
            TextStyle::Button,
            FontId::new(21.0, FontFamily::Proportional),
        ),
        (
            TextStyle::Small,
            FontId::new(15.0, FontFamily::Proportional),
        ),
        (
            TextStyle::Monospace,
            FontId::new(17.0, FontFamily::Monospace),
        ),
    ]
    .into();
    let s = &mut style.spacing;
    s.item_spacing = Vec2::new(12.0, 10.0);
    s.button_padding = Vec2::new(18.0, 8.0);
    s.interact_size = Vec2::new(48.0, 30.0);
    s.slider_width = 220.0;
    s.slider_rail_height = 6.0;
    s.combo_width = 140.0;
    s.window_margin = Margin::same(24);
    let v = &mut style.visuals;
    v.override_text_color = Some(TEXT);
    v.panel_fill = PANEL;
    v.window_fill = PANEL;
    v.window_stroke = Stroke::new(1.0, ACCENT.gamma_multiply(0.5));
    v.window_corner_radius = CornerRadius::same(10);
    v.extreme_bg_color = Color32::from_rgb(22, 23, 30);
    v.selection.bg_fill = ACCENT.gamma_multiply(0.6);
    v.selection.stroke = Stroke::new(1.5, ACCENT);
    v.slider_trailing_fill = true;
    let w = &mut v.widgets;
    for (state, fill, stroke) in [
        (
            &mut w.inactive,
            BUTTON,
            Stroke::new(1.0, Color32::from_gray(70)),
        ),
        (&mut w.hovered, BUTTON_HOVER, Stroke::new(1.5, ACCENT)),
        (
            &mut w.active,
            ACCENT.gamma_multiply(0.7),
            Stroke::new(2.0, ACCENT),
        ),
        (&mut w.open, BUTTON_HOVER, Stroke::new(1.0, ACCENT)),
    ] {
        state.bg_fill = fill;
        state.weak_bg_fill = fill;
        state.bg_stroke = stroke;
        state.corner_radius = CornerRadius::same(6);
        state.fg_stroke = Stroke::new(1.5, TEXT);
        state.expansion = 0.0;
    }
    w.noninteractive.fg_stroke = Stroke::new(1.0, TEXT);
    w.noninteractive.bg_stroke = Stroke::new(1.0, Color32::from_gray(60));
    w.noninteractive.corner_radius = CornerRadius::same(6);
    style
}

/// Applies the style (once) and the UI scale for this frame's window height.
pub fn apply(ctx: &egui::Context, styled: &mut bool) {
    if !*styled {
        ctx.set_style_of(egui::Theme::Dark, style());
        ctx.set_style_of(egui::Theme::Light, style());
        *styled = true;
    }
    let physical_height = ctx.content_rect().height() * ctx.pixels_per_point();
    let native = ctx.pixels_per_point() / ctx.zoom_factor();
    let zoom = (physical_height / REFERENCE_HEIGHT / native).clamp(0.5, 3.0);
    if (zoom - ctx.zoom_factor()).abs() > 0.01 {
        ctx.set_zoom_factor(zoom);
    }
}

/// The frame of a menu panel.
pub fn panel() -> egui::Frame {
    egui::Frame::new()
        .fill(PANEL)
        .stroke(Stroke::new(1.0, ACCENT.gamma_multiply(0.45)))
        .corner_radius(CornerRadius::same(12))
        .inner_margin(Margin::symmetric(32, 26))
        .shadow(egui::Shadow {
            offset: [0, 6],
            blur: 24,
            spread: 0,
            color: Color32::from_black_alpha(160),
        })
}

/// The frame of a HUD box.
pub fn hud_box() -> egui::Frame {
    egui::Frame::new()
        .fill(HUD_BOX)
        .corner_radius(CornerRadius::same(8))
        .inner_margin(Margin::symmetric(14, 8))
}

/// A large title (the game's name).
pub fn title(text: &str) -> egui::RichText {
    egui::RichText::new(text).size(58.0).color(ACCENT).strong()
}

/// A screen's heading ("Paused", "Settings").
pub fn heading(text: &str) -> egui::RichText {
    egui::RichText::new(text).size(36.0).color(ACCENT).strong()
}

/// A section heading inside a panel.
pub fn section(text: &str) -> egui::RichText {
    egui::RichText::new(text.to_uppercase())
        .size(15.0)
        .color(ACCENT.gamma_multiply(0.85))
        .strong()
}

/// A full-width menu button; returns whether it was clicked.
pub fn menu_button(ui: &mut egui::Ui, text: &str) -> bool {
    let button = egui::Button::new(egui::RichText::new(text).size(22.0))
        .min_size(Vec2::new(MENU_WIDTH, 44.0));
    ui.add(button).clicked()
}

/// Darkens the whole screen behind a menu.
pub fn dim(ctx: &egui::Context) {
    let painter = ctx.layer_painter(egui::LayerId::background());
    painter.rect_filled(ctx.content_rect(), CornerRadius::ZERO, DIM);
}

/// Shades the top of the screen (dark at the top edge, clear at `fraction` of the height) so
/// a title reads on any picture.
pub fn top_shade(ctx: &egui::Context, fraction: f32) {
    let rect = ctx.content_rect();
    let bottom = rect.top() + rect.height() * fraction;
    let mut mesh = egui::Mesh::default();
    let top = Color32::from_black_alpha(190);
    let clear = Color32::TRANSPARENT;
    mesh.colored_vertex(rect.left_top(), top);
    mesh.colored_vertex(rect.right_top(), top);
    mesh.colored_vertex(egui::pos2(rect.right(), bottom), clear);
    mesh.colored_vertex(egui::pos2(rect.left(), bottom), clear);
    mesh.add_triangle(0, 1, 2);
    mesh.add_triangle(0, 2, 3);
    ctx.layer_painter(egui::LayerId::background())
        .add(egui::Shape::mesh(mesh));
}

/// A centred menu area.
pub fn centred(ctx: &egui::Context, id: &str, add: impl FnOnce(&mut egui::Ui)) {
    egui::Area::new(egui::Id::unique(id))
        .anchor(egui::Align2::CENTER_CENTER, Vec2::ZERO)
        .order(egui::Order::Foreground)
        .show(ctx, |ui| {
            panel().show(ui, add);
        });
}
