//! Writing a [`Document`] as level RON in the style of the hand-written level files, with the
//! file's comments back at their anchors ([`render_document`]).
//!
//! Layout: `Level(`, one top-level field per line indented four spaces, each list's items one
//! per line (lists of plain values such as `lights_off: [2]` on one line), `gameplay` with
//! its own fields one per line, every value compact (`layout`), broken only past 100 columns.
//! Fields come in the order the file wrote them (then the others in the level type's order);
//! a field the file wrote is written even if it holds its default value, others only when
//! they differ from it. Main thread. Must not: write files (see `save`).

use serde::Serialize;
use serde::de::DeserializeOwned;

use crate::assets::{GameplayEntry, Level};

use super::comments::{Anchored, Comments};
use super::document::Document;
use super::layout::{layout, minimal};

/// The level's fields in the type's order.
const LEVEL_FIELDS: [&str; 15] = [
    "models",
    "materials",
    "grids",
    "boxes",
    "terrains",
    "cities",
    "instances",
    "camera",
    "sun",
    "sky",
    "render",
    "render_areas",
    "needs",
    "gameplay",
    "characters",
];

/// The gameplay section's fields in the type's order.
const GAMEPLAY_FIELDS: [&str; 13] = [
    "sounds",
    "music",
    "emitters",
    "animations",
    "autoplay",
    "lights_off",
    "volumes",
    "lasers",
    "rules",
    "events",
    "usables",
    "counters",
    "breakables",
];

/// A field's value, ready to write.
enum Value {
    /// One value (compact RON).
    One(String),
    /// A list's items (compact RON each).
    List(Vec<String>),
    /// The gameplay section's fields.
    Struct(Vec<(&'static str, Value, bool)>),
}

type Res<T> = Result<T, ron::Error>;

fn list<T: Serialize + DeserializeOwned + PartialEq>(items: &[T]) -> Res<(Value, bool)> {
    let texts = items.iter().map(minimal).collect::<Res<Vec<_>>>()?;
    Ok((Value::List(texts), items.is_empty()))
}

fn one<T: Serialize + DeserializeOwned + PartialEq>(
    value: &T,
    default: bool,
) -> Res<(Value, bool)> {
    Ok((Value::One(minimal(value)?), default))
}

/// A top-level field's value and whether it is the value the field has when left out.
fn level_field(level: &Level, name: &str) -> Res<(Value, bool)> {
    match name {
        "models" => list(&level.models),
        "materials" => list(&level.materials),
        "grids" => list(&level.grids),
        "boxes" => list(&level.boxes),
        "terrains" => list(&level.terrains),
        "cities" => list(&level.cities),
        "instances" => list(&level.instances),
        "camera" => one(&level.camera, false),
        "sun" => one(&level.sun, level.sun.is_none()),
        "sky" => one(&level.sky, level.sky == Default::default()),
        "render" => one(&level.render, level.render == Default::default()),
        "render_areas" => list(&level.render_areas),
        "needs" => one(&level.needs, level.needs.is_none()),
        "characters" => list(&level.characters),
        _ => gameplay(&level.gameplay),
    }
}

fn gameplay_field(g: &GameplayEntry, name: &str) -> Res<(Value, bool)> {
    match name {
        "sounds" => list(&g.sounds),
        "music" => one(&g.music, g.music.is_none()),
        "emitters" => list(&g.emitters),
        "animations" => list(&g.animations),
        "autoplay" => list(&g.autoplay),
        "lights_off" => list(&g.lights_off),
        "volumes" => list(&g.volumes),
        "lasers" => list(&g.lasers),
        "rules" => list(&g.rules),
        "events" => list(&g.events),
        "usables" => list(&g.usables),
        "counters" => list(&g.counters),
        _ => list(&g.breakables),
    }
}

fn gameplay(g: &GameplayEntry) -> Res<(Value, bool)> {
    let fields = GAMEPLAY_FIELDS
        .iter()
        .map(|&name| gameplay_field(g, name).map(|(v, d)| (name, v, d)))
        .collect::<Res<Vec<_>>>()?;
    Ok((Value::Struct(fields), g.is_empty()))
}

/// `names` in the file's order (`order`, paths under `path`), then the rest in theirs.
fn ordered(names: &[&'static str], order: &[String], path: &str) -> Vec<&'static str> {
    let prefix = if path.is_empty() {
        String::new()
    } else {
        format!("{path}.")
    };
    let mut out: Vec<&'static str> = order
        .iter()
        .filter_map(|p| p.strip_prefix(prefix.as_str()))
        .filter_map(|n| names.iter().find(|&&k| k == n).copied())
        .collect();
    out.dedup();
    out.extend(
        names
            .iter()
            .filter(|n| !out.contains(n))
            .copied()
            .collect::<Vec<_>>(),
    );
    out
}

struct Writer<'a> {
    out: String,
    comments: &'a Comments,
}

impl Writer<'_> {
    fn lines(&mut self, lines: &[String], depth: usize) {
        for line in lines {
            self.out.push_str(&"    ".repeat(depth));
            self.out.push_str(line);
            self.out.push('\n');
        }
    }

    /// `text` at `depth` (the line already indented), then `suffix`, the trailing comment and
    /// a new line; the trailing comment ends the first line.
    fn value(&mut self, text: &str, suffix: &str, trailing: Option<&String>) {
        let (first, rest) = text.split_once('\n').unwrap_or((text, ""));
        let end = |out: &mut String| {
            if let Some(t) = trailing {
                out.push(' ');
                out.push_str(t);
            }
        };
        self.out.push_str(first);
        if rest.is_empty() {
            self.out.push_str(suffix);
            end(&mut self.out);
        } else {
            end(&mut self.out);
            self.out.push('\n');
            self.out.push_str(rest);
            self.out.push_str(suffix);
        }
        self.out.push('\n');
    }

    fn fields(
        &mut self,
        path: &str,
        fields: Vec<(&'static str, Value, bool)>,
        names: &[&'static str],
        depth: usize,
    ) {
        let order = ordered(names, &self.comments.order, path);
        let comments = self.comments;
        let mut fields: Vec<Option<(&'static str, Value, bool)>> =
            fields.into_iter().map(Some).collect();
        for name in order {
            let Some((_, value, default)) = fields
                .iter_mut()
                .find(|f| f.as_ref().is_some_and(|(n, _, _)| *n == name))
                .and_then(Option::take)
            else {
                continue;
            };
            let key = if path.is_empty() {
                name.to_string()
            } else {
                format!("{path}.{name}")
            };
            let anchored = comments.field(&key).cloned().unwrap_or_default();
            let written = comments.order.contains(&key);
            if default && !written && anchored.is_empty() {
                continue;
            }
            self.lines(&anchored.before, depth);
            let pad = "    ".repeat(depth);
            self.out.push_str(&pad);
            let head = format!("{name}: ");
            match value {
                Value::One(text) => {
                    self.out.push_str(&head);
                    let text = layout(&text, pad.len() + head.len(), pad.len());
                    self.value(&text, ",", anchored.trailing.as_ref());
                }
                Value::List(items) => self.list(&key, &head, items, &anchored, depth),
                Value::Struct(inner) => {
                    self.value(&format!("{head}("), "", anchored.trailing.as_ref());
                    self.fields(&key, inner, &GAMEPLAY_FIELDS, depth + 1);
                    self.close(&key, "),", depth);
                }
            }
        }
    }

    fn list(
        &mut self,
        key: &str,
        head: &str,
        items: Vec<String>,
        anchored: &Anchored,
        depth: usize,
    ) {
        let pad = "    ".repeat(depth);
        let item_comments = self.comments.items.get(key);
        let inline = format!("{head}[{}]", items.join(", "));
        let plain = items.iter().all(|i| !i.contains(['(', '[']));
        if item_comments.is_none()
            && self.comments.end(key).is_none()
            && (items.is_empty() || plain)
            && pad.len() + inline.len() < super::layout::WIDTH
        {
            self.value(&inline, ",", anchored.trailing.as_ref());
            return;
        }
        self.value(&format!("{head}["), "", anchored.trailing.as_ref());
        let inner = "    ".repeat(depth + 1);
        let none = Anchored::default();
        let count = items.len().max(item_comments.map_or(0, Vec::len));
        for i in 0..count {
            let c = item_comments.and_then(|l| l.get(i)).unwrap_or(&none);
            self.lines(&c.before, depth + 1);
            match items.get(i) {
                Some(item) => {
                    self.out.push_str(&inner);
                    let text = layout(item, inner.len(), inner.len());
                    self.value(&text, ",", c.trailing.as_ref());
                }
                // Comments of items no longer there (a list the editor shortened): kept.
                None => self.lines(&c.trailing.iter().cloned().collect::<Vec<_>>(), depth + 1),
            }
        }
        self.close(key, "],", depth);
    }

    /// The comments before a closing bracket, the bracket line at `depth` and its comment.
    fn close(&mut self, key: &str, bracket: &str, depth: usize) {
        let end = self.comments.end(key).cloned().unwrap_or_default();
        self.lines(&end.before, depth + 1);
        self.out.push_str(&"    ".repeat(depth));
        self.value(bracket, "", end.trailing.as_ref());
    }
}

/// The document as level RON text with its comments (see the module doc for the layout).
pub fn render_document(doc: &Document) -> Result<String, ron::Error> {
    let comments = &doc.comments;
    let mut w = Writer {
        out: String::new(),
        comments,
    };
    w.lines(&comments.header, 0);
    w.lines(&comments.attributes, 0);
    w.value("Level(", "", comments.opening.as_ref());
    let fields = LEVEL_FIELDS
        .iter()
        .map(|&name| level_field(&doc.level, name).map(|(v, d)| (name, v, d)))
        .collect::<Res<Vec<_>>>()?;
    w.fields("", fields, &LEVEL_FIELDS, 1);
    let end = comments.end("").cloned().unwrap_or_default();
    w.lines(&end.before, 1);
    w.value(")", "", end.trailing.as_ref());
    w.lines(&comments.footer, 0);
    Ok(w.out)
}
