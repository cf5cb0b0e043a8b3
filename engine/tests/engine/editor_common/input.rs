//! Synthetic input for the editor's panels (issue 33): the panels run in a headless
//! `egui::Context` for as many passes as a gesture needs, fed real `egui::Event`s (pointer
//! moves, presses and releases at a widget's place, keys, typed text). Widgets are found by the
//! text the previous pass painted (its shapes, [`Painted`]): a label, a combo box's selected
//! text, a list entry, a number in a field. So a test breaks when a panel stops answering its
//! input, not when a widget moves, and it never calls into `EditorState::apply`.

#![allow(dead_code)]

use candela::editor::EditorState;
use candela::editor::ui::{PanelOutput, panels};
use egui::epaint::{ClippedShape, Shape};
use egui::{Event, Key, Modifiers, Pos2, Rect};

/// The screen the panels are drawn on, points.
pub const SCREEN: egui::Vec2 = egui::vec2(1280.0, 720.0);

/// The text pieces one pass painted, in paint order, with their screen rects.
#[derive(Clone, Debug, Default)]
pub struct Painted(pub Vec<(String, Rect)>);

impl Painted {
    /// The texts of `out`'s shapes.
    pub fn of(out: &egui::FullOutput) -> Self {
        let mut texts = Vec::new();
        for ClippedShape { shape, .. } in &out.shapes {
            collect_text(shape, &mut texts);
        }
        Self(texts)
    }

    /// The rect of the last painted text equal to `text` (the topmost: popups paint last).
    pub fn find(&self, text: &str) -> anyhow::Result<Rect> {
        self.find_where(|t, _| t == text)
            .ok_or_else(|| anyhow::anyhow!("no {text:?} painted; painted: {:?}", self.texts()))
    }

    /// The rect of the last painted text for which `keep` holds.
    pub fn find_where(&self, keep: impl Fn(&str, Rect) -> bool) -> Option<Rect> {
        (self.0.iter().rev())
            .find(|(t, r)| keep(t, *r))
            .map(|(_, r)| *r)
    }

    /// Whether some painted text starts with `prefix`.
    pub fn has_prefix(&self, prefix: &str) -> bool {
        self.0.iter().any(|(t, _)| t.starts_with(prefix))
    }

    /// The numbers painted right of `label` on its row, left to right (a row of fields).
    pub fn numbers_right_of(&self, label: Rect) -> Vec<Rect> {
        let mut out: Vec<Rect> = (self.0.iter())
            .filter(|(t, r)| {
                t.trim_end_matches(" s").parse::<f32>().is_ok()
                    && r.left() > label.right()
                    && (r.center().y - label.center().y).abs() < 4.0
            })
            .map(|(_, r)| *r)
            .collect();
        out.sort_by(|a, b| a.left().total_cmp(&b.left()));
        out
    }

    /// The number painted nearest left of `label` on its row (a slider's value field).
    pub fn number_left_of(&self, label: Rect) -> Option<Rect> {
        (self.0.iter())
            .filter(|(t, r)| {
                t.parse::<f32>().is_ok()
                    && r.right() <= label.left()
                    && (r.center().y - label.center().y).abs() < 4.0
            })
            .map(|(_, r)| *r)
            .max_by(|a, b| a.right().total_cmp(&b.right()))
    }

    pub fn texts(&self) -> Vec<&str> {
        self.0.iter().map(|(t, _)| t.as_str()).collect()
    }
}

fn collect_text(shape: &Shape, out: &mut Vec<(String, Rect)>) {
    match shape {
        Shape::Text(t) => out.push((t.galley.text().to_string(), t.visual_bounding_rect())),
        Shape::Vec(shapes) => shapes.iter().for_each(|s| collect_text(s, out)),
        _ => {}
    }
}

/// A move to `at`, a press and a release of the primary button there (egui sees a click).
pub fn click(at: Pos2) -> Vec<Event> {
    let button = |pressed| Event::PointerButton {
        pos: at,
        button: egui::PointerButton::Primary,
        pressed,
        modifiers: Modifiers::NONE,
    };
    vec![Event::PointerMoved(at), button(true), button(false)]
}

pub fn key(key: Key, modifiers: Modifiers) -> Event {
    Event::Key {
        key,
        physical_key: None,
        pressed: true,
        repeat: false,
        modifiers,
    }
}

/// Select all, type `text`, Enter: what a designer does in a field that has the keyboard.
pub fn replace_text(text: &str) -> Vec<Event> {
    vec![
        key(Key::A, Modifiers::COMMAND),
        Event::Text(text.into()),
        key(Key::Enter, Modifiers::NONE),
    ]
}

/// The editor's panels over `state` in a headless context.
pub struct Panels {
    pub ctx: egui::Context,
    pub state: EditorState,
    /// What the last pass painted (where the next gesture aims).
    pub painted: Painted,
    /// What the panels reported, every pass since the harness began, in order.
    pub outputs: Vec<PanelOutput>,
}

impl Panels {
    /// The panels over `state`, after two passes (windows settle their sizes).
    pub fn new(state: EditorState) -> Self {
        let mut panels = Self {
            ctx: egui::Context::default(),
            state,
            painted: Painted::default(),
            outputs: Vec::new(),
        };
        panels.pass(Vec::new());
        panels.pass(Vec::new());
        panels
    }

    /// One pass with `events`; what it painted is kept in `painted`.
    pub fn pass(&mut self, events: Vec<Event>) -> &Painted {
        let input = egui::RawInput {
            screen_rect: Some(Rect::from_min_size(Pos2::ZERO, SCREEN)),
            events,
            ..Default::default()
        };
        let mut report = PanelOutput::default();
        let state = &mut self.state;
        let out = self.ctx.run_pass(input, |ctx| report = panels(ctx, state));
        self.outputs.push(report);
        self.painted = Painted::of(&out);
        &self.painted
    }

    /// Clicks the centre of `rect`, then lets a pass settle.
    pub fn click_at(&mut self, rect: Rect) {
        self.pass(click(rect.center()));
        self.pass(Vec::new());
    }

    /// Clicks the last painted text equal to `text`.
    pub fn click_text(&mut self, text: &str) -> anyhow::Result<()> {
        let rect = self.painted.find(text)?;
        self.click_at(rect);
        Ok(())
    }

    /// Clicks the text `choice` painted below `combo` (a combo box's open list), after
    /// clicking `combo` (its selected text) to open it.
    pub fn choose(&mut self, combo: &str, choice: &str) -> anyhow::Result<()> {
        let at = self.painted.find(combo)?;
        self.click_at(at);
        let item = (self.painted)
            .find_where(|t, r| t == choice && r.top() > at.bottom() - 1.0)
            .ok_or_else(|| anyhow::anyhow!("{combo:?} did not list {choice:?}"))?;
        self.click_at(item);
        Ok(())
    }

    /// Types `text` into the field painted at `field` (a drag value turns into a text field
    /// on a click): click, select all, type, Enter.
    pub fn type_into(&mut self, field: Rect, text: &str) -> anyhow::Result<()> {
        self.click_at(field);
        anyhow::ensure!(
            self.ctx.egui_wants_keyboard_input(),
            "the field at {field:?} did not take the keyboard"
        );
        self.pass(replace_text(text));
        self.pass(Vec::new());
        Ok(())
    }

    /// Types `text` into the `nth` number field right of the label `label`.
    pub fn type_beside(&mut self, label: &str, nth: usize, text: &str) -> anyhow::Result<()> {
        let at = self.painted.find(label)?;
        let field = *(self.painted.numbers_right_of(at).get(nth))
            .ok_or_else(|| anyhow::anyhow!("no field {nth} right of {label:?}"))?;
        self.type_into(field, text)
    }
}
