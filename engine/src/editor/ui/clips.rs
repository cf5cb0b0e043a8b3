//! The clip inspector: one clip's duration (seconds: its last key's time; a new duration
//! scales every key's and event's time), whether it plays from the start and how (once, loop, ping-pong:
//! `gameplay.autoplay`), and each track's keys (time in seconds and value: metres for
//! translation, a quaternion for rotation, factors for scale). A change edits a copy of the
//! clip and asks for it whole (`ListEdit::Clip`, merged within a drag).
//!
//! Main thread, inside an egui pass. Must not: change the document (it only asks, `Pending`).

use crate::assets::{AuthoredClip, AutoplayEntry, PlayMode};

use super::super::command::{Edit, ListEdit};
use super::super::state::EditorState;
use super::Pending;

/// The clip's duration, seconds: its latest key.
pub fn duration_seconds(clip: &AuthoredClip) -> f32 {
    (clip.tracks.iter())
        .flat_map(|t| t.keys.iter().map(|k| k.time_seconds))
        .fold(0.0, f32::max)
}

/// `gameplay.animations[index]`'s widgets.
pub(super) fn show(ui: &mut egui::Ui, state: &EditorState, index: usize, p: &mut Pending) {
    let g = &state.doc.level.gameplay;
    let Some(clip) = g.animations.get(index) else {
        return;
    };
    let replace = |p: &mut Pending, clip: AuthoredClip| {
        p.edits.push(Edit::List(ListEdit::Clip {
            index,
            clip: Box::new(clip),
        }))
    };
    ui.label(egui::RichText::new(format!("Clip {:?}", clip.name)).strong());
    let duration = duration_seconds(clip);
    ui.horizontal(|ui| {
        ui.label("duration (s)");
        let mut d = duration;
        let changed = ui
            .add(
                egui::DragValue::new(&mut d)
                    .speed(0.01)
                    .range(0.01..=3600.0),
            )
            .changed();
        if changed && duration > 0.0 {
            let scale = d / duration;
            let mut copy = clip.clone();
            for key in copy.tracks.iter_mut().flat_map(|t| t.keys.iter_mut()) {
                key.time_seconds *= scale;
            }
            for event in &mut copy.events {
                event.time_seconds *= f64::from(scale);
            }
            replace(p, copy);
        }
    });
    autoplay(ui, state, &clip.name, p);
    for (t, track) in clip.tracks.iter().enumerate() {
        ui.label(format!(
            "{} {:?} ({:?})",
            track.target, track.property, track.interpolation
        ));
        for (k, key) in track.keys.iter().enumerate() {
            let mut copy = key.clone();
            let changed = ui
                .horizontal(|ui| {
                    let mut changed = ui
                        .add(
                            egui::DragValue::new(&mut copy.time_seconds)
                                .speed(0.01)
                                .range(0.0..=3600.0)
                                .suffix(" s"),
                        )
                        .changed();
                    for v in &mut copy.value {
                        changed |= ui.add(egui::DragValue::new(v).speed(0.01)).changed();
                    }
                    changed
                })
                .inner;
            if changed {
                let mut edited = clip.clone();
                edited.tracks[t].keys[k] = copy;
                replace(p, edited);
            }
        }
    }
}

/// Whether the clip named `name` plays from the start, and in which mode.
fn autoplay(ui: &mut egui::Ui, state: &EditorState, name: &str, p: &mut Pending) {
    let list = &state.doc.level.gameplay.autoplay;
    let current = list.iter().find(|a| a.clip == name).map(|a| a.mode);
    let label = |m: Option<PlayMode>| match m {
        None => "no (a rule starts it)".to_string(),
        Some(m) => format!("{m:?}"),
    };
    egui::ComboBox::from_label("plays from the start")
        .selected_text(label(current))
        .show_ui(ui, |ui| {
            for mode in [
                None,
                Some(PlayMode::Once),
                Some(PlayMode::Loop),
                Some(PlayMode::PingPong),
            ] {
                if ui.selectable_label(mode == current, label(mode)).clicked() && mode != current {
                    let mut edited: Vec<AutoplayEntry> =
                        list.iter().filter(|a| a.clip != name).cloned().collect();
                    if let Some(mode) = mode {
                        let at = list.iter().position(|a| a.clip == name);
                        let entry = AutoplayEntry {
                            clip: name.to_string(),
                            mode,
                        };
                        edited.insert(at.unwrap_or(edited.len()), entry);
                    }
                    p.edits.push(Edit::List(ListEdit::Autoplay(edited)));
                }
            }
        });
}
