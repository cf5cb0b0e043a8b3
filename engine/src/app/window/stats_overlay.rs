//! [`StatsOverlay`]: the egui stats window (F3) and the profiler view (F5,
//! `profiler_view.rs`), run on the main thread where the window's events are, tessellated
//! there, and handed to the render thread inside the commit.
//!
//! Owns: the egui context and its winit glue (pointer, keyboard, scale factor), the profiler
//! view. Produces an [`Overlay`] per frame while either is visible. Must not: touch the device (the render thread draws)
//! or the world. [`stats_window`] is the window's layout alone (`bench present` times the CPU
//! overlay drawing it).

use winit::window::Window;

use super::profiler_view::ProfilerView;
use crate::app::runner::FrameStats;
use crate::commit::Overlay;

/// The stats overlay.
pub struct StatsOverlay {
    context: egui::Context,
    state: egui_winit::State,
    pub visible: bool,
    /// The profiler view (F5), drawn in the same pass.
    pub profiler: ProfilerView,
}

impl StatsOverlay {
    pub fn new(window: &Window, visible: bool) -> Self {
        let context = egui::Context::default();
        let state = egui_winit::State::new(
            context.clone(),
            egui::ViewportId::ROOT,
            window,
            Some(window.scale_factor() as f32),
            window.theme(),
            None,
        );
        Self {
            context,
            state,
            visible,
            profiler: ProfilerView::default(),
        }
    }

    /// Feeds a window event to egui; returns whether egui used it (a click on the overlay
    /// should not also capture the mouse). Ignored while hidden, unless the game draws a UI.
    pub fn on_window_event(
        &mut self,
        window: &Window,
        event: &winit::event::WindowEvent,
        game_ui: bool,
    ) -> bool {
        (self.visible || self.profiler.visible() || game_ui)
            && self.state.on_window_event(window, event).consumed
    }

    /// Whether the pointer is over the overlay.
    pub fn wants_pointer(&self) -> bool {
        (self.visible || self.profiler.visible()) && self.context.egui_wants_pointer_input()
    }

    /// Runs egui for this frame: the game's `ui` (its HUD and menus) when `game_ui` is given,
    /// then the stats window and the profiler when they are shown; tessellates them all.
    /// `None` when there is nothing to draw.
    pub fn build(
        &mut self,
        window: &Window,
        stats: &FrameStats,
        mut game_ui: Option<&mut dyn FnMut(&egui::Context)>,
    ) -> Option<Overlay> {
        if !self.visible && !self.profiler.visible() && game_ui.is_none() {
            return None;
        }
        let input = self.state.take_egui_input(window);
        let visible = self.visible;
        let profiler = &mut self.profiler;
        let output = self.context.run_pass(input, |context| {
            if let Some(ui) = game_ui.as_mut() {
                ui(context);
            }
            if visible {
                stats_window(context, &stats.lines());
            }
            profiler.ui(context);
        });
        self.state
            .handle_platform_output(window, output.platform_output);
        let primitives = self
            .context
            .tessellate(output.shapes, output.pixels_per_point);
        Some(Overlay {
            primitives,
            textures_delta: output.textures_delta,
            pixels_per_point: output.pixels_per_point,
        })
    }
}

/// The stats window of `lines` (label, value) in `context`: bottom right, in a small fixed
/// font, clear of the games' HUD (objective top left, counters top right, crosshair in the
/// middle).
pub fn stats_window<L: AsRef<str>>(context: &egui::Context, lines: &[(L, String)]) {
    egui::Window::new("Candela stats (F3)")
        .anchor(egui::Align2::RIGHT_BOTTOM, [-8.0, -8.0])
        .resizable(false)
        .title_bar(false)
        .show(context, |ui| {
            ui.style_mut().override_font_id = Some(egui::FontId::proportional(11.0));
            ui.spacing_mut().interact_size.y = 13.0;
            ui.spacing_mut().item_spacing.y = 1.0;
            ui.label(egui::RichText::new("Candela stats (F3)").strong());
            egui::Grid::new("stats")
                .num_columns(2)
                .spacing([8.0, 1.0])
                .show(ui, |ui| {
                    for (label, value) in lines {
                        ui.label(label.as_ref());
                        ui.label(egui::RichText::new(value).monospace().size(11.0));
                        ui.end_row();
                    }
                });
        });
}
