//! [`ProfilerView`]: the in-game profiler (F5), drawn with the workspace's egui (puffin_egui
//! 0.30 needs egui 0.33, so the view is our own): the last frames' lengths as bars (click one to
//! pick it, "pause" to hold still), then the picked frame as a flame graph, one block per thread
//! with a row per nesting depth, each scope a bar with its name and milliseconds, hover for
//! details. [`profiler_window`] is the layout alone, over plain data, for tests.
//!
//! Owns: the view's state and its [`ProfileRecorder`]; scopes are on exactly while the view is
//! shown and not paused (hidden, the engine's scopes cost one atomic load each). Main thread,
//! inside the stats overlay's egui pass. Must not: touch the world or the device.

use super::profile_frames::{FrameTime, ProfileFrame, ProfileRecorder, ThreadScopes};

/// How many recent frames the bar chart shows.
pub const FRAME_BARS: usize = 120;
/// Height of one flame-graph row, in points.
const ROW: f32 = 16.0;
/// The narrowest bar, in points, that gets its label written in it.
const LABELLED: f32 = 36.0;

/// What the window remembers between frames.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ProfilerState {
    /// Hold the frames shown (the scopes go off meanwhile).
    pub paused: bool,
    /// The picked frame's index; the latest with `None`.
    pub selected: Option<u64>,
}

/// The profiler view: its state and the recorder behind it.
#[derive(Default)]
pub struct ProfilerView {
    recorder: ProfileRecorder,
    state: ProfilerState,
    visible: bool,
}

impl ProfilerView {
    /// Whether the view is shown.
    pub fn visible(&self) -> bool {
        self.visible
    }

    /// Shows or hides the view; the engine's scopes follow (on while shown and not paused).
    pub fn set_visible(&mut self, visible: bool) {
        self.visible = visible;
        self.recorder.set_on(visible && !self.state.paused);
    }

    /// Draws the window in `context` when shown.
    pub fn ui(&mut self, context: &egui::Context) {
        if !self.visible {
            return;
        }
        let frames = self.recorder.recent(FRAME_BARS);
        let frame = self.recorder.frame(self.state.selected);
        let before = self.state.paused;
        profiler_window(context, &mut self.state, &frames, frame.as_ref());
        if self.state.paused != before {
            self.recorder.set_on(!self.state.paused);
            if !self.state.paused {
                self.state.selected = None;
            }
        }
    }
}

/// The profiler window in `context`: `frames` (oldest first) as bars, `frame` (the picked one)
/// as a flame graph; a click or the pause box changes `state`.
pub fn profiler_window(
    context: &egui::Context,
    state: &mut ProfilerState,
    frames: &[FrameTime],
    frame: Option<&ProfileFrame>,
) {
    // No title bar: the games' egui style draws titles in their large heading font. Below the
    // games' objective line (top left), clear of the F3 stats (bottom right).
    egui::Window::new("Profiler (F5)")
        .title_bar(false)
        .default_pos([8.0, 110.0])
        .default_width(760.0)
        .resizable(true)
        .show(context, |ui| {
            ui.style_mut().override_font_id = Some(egui::FontId::proportional(11.0));
            ui.label(egui::RichText::new("Profiler (F5)").strong());
            ui.horizontal(|ui| {
                ui.checkbox(&mut state.paused, "pause");
                match frame {
                    Some(f) => ui.label(format!(
                        "frame {}: {:.2} ms, {} threads",
                        f.index,
                        f.duration_ms,
                        f.threads.len()
                    )),
                    None => ui.label("no frame recorded yet"),
                };
                if state.selected.is_some() && ui.button("latest").clicked() {
                    state.selected = None;
                }
            });
            frame_bars(ui, state, frames, frame.map(|f| f.index));
            let Some(frame) = frame else {
                return;
            };
            egui::ScrollArea::vertical()
                .max_height(420.0)
                .show(ui, |ui| {
                    for thread in &frame.threads {
                        ui.label(egui::RichText::new(&thread.name).strong());
                        flame(ui, thread, frame.duration_ms);
                    }
                });
        });
}

/// The frame-time bars: taller is slower; the shown frame is highlighted; a click picks one
/// (and pauses, so it stays).
fn frame_bars(
    ui: &mut egui::Ui,
    state: &mut ProfilerState,
    frames: &[FrameTime],
    shown: Option<u64>,
) {
    let width = ui.available_width().max(120.0);
    let (rect, response) = ui.allocate_exact_size(egui::vec2(width, 40.0), egui::Sense::click());
    let painter = ui.painter_at(rect);
    painter.rect_filled(rect, 2.0, egui::Color32::from_black_alpha(120));
    let longest = frames.iter().map(|f| f.duration_ms).fold(1e-3, f64::max);
    let step = rect.width() / FRAME_BARS as f32;
    let bar_at = |x: f32| {
        let i = ((x - rect.left()) / step) as usize;
        frames.get(i)
    };
    for (i, f) in frames.iter().enumerate() {
        let h = (f.duration_ms / longest) as f32 * rect.height();
        let x = rect.left() + i as f32 * step;
        let bar = egui::Rect::from_min_max(
            egui::pos2(x, rect.bottom() - h),
            egui::pos2(x + (step - 1.0).max(1.0), rect.bottom()),
        );
        let colour = if Some(f.index) == shown {
            egui::Color32::from_rgb(255, 200, 60)
        } else {
            egui::Color32::from_rgb(90, 150, 230)
        };
        painter.rect_filled(bar, 0.0, colour);
    }
    painter.text(
        rect.left_top() + egui::vec2(4.0, 2.0),
        egui::Align2::LEFT_TOP,
        format!("longest {longest:.1} ms"),
        egui::FontId::monospace(10.0),
        egui::Color32::WHITE,
    );
    if let Some(f) = response.hover_pos().and_then(|p| bar_at(p.x)) {
        let (index, ms) = (f.index, f.duration_ms);
        if response.clicked() {
            state.selected = Some(index);
            state.paused = true;
        }
        response.on_hover_text_at_pointer(format!("frame {index}: {ms:.2} ms"));
    }
}

/// One thread's scopes as nested bars across the frame's `duration_ms`.
fn flame(ui: &mut egui::Ui, thread: &ThreadScopes, duration_ms: f64) {
    let rows = thread.rows().max(1);
    let width = ui.available_width().max(120.0);
    let size = egui::vec2(width, rows as f32 * ROW);
    let (rect, response) = ui.allocate_exact_size(size, egui::Sense::hover());
    let painter = ui.painter_at(rect);
    let per_ms = rect.width() / duration_ms.max(1e-6) as f32;
    let bar_rect = |s: &super::profile_frames::ScopeBar| {
        let x0 = rect.left() + s.start_ms as f32 * per_ms;
        let x1 = x0 + (s.duration_ms as f32 * per_ms).max(1.0);
        let y0 = rect.top() + s.depth as f32 * ROW;
        egui::Rect::from_min_max(egui::pos2(x0, y0), egui::pos2(x1, y0 + ROW - 1.0))
    };
    let font = egui::FontId::proportional(10.0);
    for scope in &thread.scopes {
        let bar = bar_rect(scope);
        painter.rect_filled(bar, 2.0, colour_of(&scope.name));
        if bar.width() >= LABELLED {
            let label = format!("{} {:.2} ms", scope.name, scope.duration_ms);
            painter.with_clip_rect(bar.intersect(rect)).text(
                bar.left_center() + egui::vec2(3.0, 0.0),
                egui::Align2::LEFT_CENTER,
                label,
                font.clone(),
                egui::Color32::BLACK,
            );
        }
    }
    let Some(pointer) = response.hover_pos() else {
        return;
    };
    // The deepest bar under the pointer.
    let hovered = thread
        .scopes
        .iter()
        .filter(|s| bar_rect(s).contains(pointer))
        .max_by_key(|s| s.depth);
    if let Some(s) = hovered {
        let mut text = format!(
            "{}\n{:.3} ms, from {:.3} ms\ndepth {}",
            s.name, s.duration_ms, s.start_ms, s.depth
        );
        if !s.data.is_empty() {
            text.push_str(&format!("\n{}", s.data));
        }
        response.on_hover_text_at_pointer(text);
    }
}

/// A stable colour per scope name, light enough for black text.
fn colour_of(name: &str) -> egui::Color32 {
    let hash = name.bytes().fold(2166136261u32, |h, b| {
        (h ^ u32::from(b)).wrapping_mul(16777619)
    });
    let hue = (hash % 360) as f32 / 360.0;
    egui::ecolor::Hsva::new(hue, 0.45, 0.95, 1.0).into()
}
