//! Saves that change only what was edited ([`splice_level`]): the level file's old text is
//! kept, and only the items the edit changed are rewritten in it, so that a designer's diff
//! shows the edit and nothing else.
//!
//! How: the old text is read as a level (serde) and as spans (`ron_tree`). Each top-level
//! field of the level and of its `gameplay` section is compared with the edited level as
//! values; an equal field keeps its bytes. A changed list is aligned item by item (values
//! again, `splice::align`): kept items keep their bytes, exactly (layout, field order, omitted
//! defaults, comments); a changed item is merged (`splice::merge`): only the atoms and fields
//! that differ are replaced, so a one-line instance stays one line and a moved one changes
//! only its translation; it is checked by parsing it as its type, and if the merge does not
//! read back as the new value, the item is written whole ([`layout::minimal`], on one line when
//! it was on one line). A removed item is cut with its line and the comment lines just above
//! it (the document anchors those to it, and an undo brings them back); an added item goes
//! after its predecessor in the style of its neighbour, with the document's comments for it
//! (an undone delete) above it. A field the file did not write is added after its last field,
//! as the full writer (`write`) lays it out.
//!
//! Last, the spliced text is parsed and must be exactly the edited level; anything else (the
//! old file does not parse, a list does not match its spans, splices overlap, the result
//! differs) is a [`SpliceError`], and the save writes the whole file with `write` instead and
//! says why. Main thread. Must not: write files (`save` does).

use serde::Serialize;
use serde::de::DeserializeOwned;

use crate::assets::{GameplayEntry, Level};

use super::comments::Comments;
use super::document::Document;
use super::layout::{layout, minimal, options};
use super::ron_tree::{self, Group, Node};
use super::splice::{Splice, Step, align, apply, cut, indent_at, insert, merge, one_line};
use super::write::render_document;

/// Why only the edited items could not be rewritten (the save rewrites the whole file).
#[derive(Debug, thiserror::Error)]
pub enum SpliceError {
    /// The old file does not read as a level.
    #[error("the file on disk does not read as a level: {0}")]
    OldLevel(String),
    /// The old file's text is not RON this writer can follow.
    #[error("the file on disk is RON this writer cannot follow")]
    Unreadable,
    /// A field's text does not match its value (`gameplay.rules` has 3 items, the text 2).
    #[error("`{0}` in the file on disk does not match its value")]
    Shape(String),
    /// A value could not be serialised.
    #[error("cannot write a value as RON: {0}")]
    Format(#[from] ron::Error),
    /// Two changes overlap in the text.
    #[error("two changes overlap in the text")]
    Overlap,
    /// The spliced text does not read back as the edited level.
    #[error("the spliced text does not read back as the edited level")]
    Mismatch,
}

type Res<T = ()> = Result<T, SpliceError>;

struct Ctx<'a> {
    old: &'a str,
    /// The edited level written whole by `write` (the text of fields the file lacks).
    fresh: &'a str,
    comments: &'a Comments,
    out: Vec<Splice>,
}

/// The entry `key` of `g`.
fn entry<'g>(g: &'g Group, key: &str) -> Option<&'g super::ron_tree::Entry> {
    g.entries.iter().find(|e| e.key.as_deref() == Some(key))
}

impl Ctx<'_> {
    /// Adds field `name` (the fresh text's) after the last field of `g`.
    fn add_field(&mut self, g: &Group, fresh: Option<&Group>, path: &str, name: &str) -> Res {
        let e = fresh
            .and_then(|f| entry(f, name))
            .ok_or_else(|| SpliceError::Shape(path.into()))?;
        let text = self.fresh[e.start..e.value.end].to_string();
        insert(
            self.old,
            g,
            g.entries.len().checked_sub(1),
            |_| text.clone(),
            &mut self.out,
        );
        Ok(())
    }

    /// One changed value at `node`: merged, else written whole (see the module doc).
    fn item<T: Serialize + DeserializeOwned + PartialEq>(&mut self, node: &Node, new: &T) -> Res {
        let text = minimal(new)?;
        let tree = ron_tree::parse(&text).ok_or(SpliceError::Unreadable)?;
        let piece = &self.old[node.start..node.end];
        for keep_absent in [true, false] {
            let mut splices = Vec::new();
            merge(self.old, node, &text, &tree, keep_absent, &mut splices);
            let inside = splices
                .iter()
                .all(|s| s.start >= node.start && s.end <= node.end);
            let local: Vec<Splice> = splices
                .iter()
                .map(|s| Splice {
                    start: s.start.saturating_sub(node.start),
                    end: s.end.saturating_sub(node.start),
                    text: s.text.clone(),
                })
                .collect();
            let back = apply(piece, &local).and_then(|t| options().from_str::<T>(&t).ok());
            if inside && back.as_ref() == Some(new) {
                self.out.extend(splices);
                return Ok(());
            }
        }
        let pad = indent_at(self.old, node.start).len();
        let whole = if one_line(self.old, node.start, node.end) {
            text
        } else {
            layout(&text, pad, pad)
        };
        self.out.push(Splice {
            start: node.start,
            end: node.end,
            text: whole,
        });
        Ok(())
    }

    /// Field `name` of `g` holding one value.
    fn one<T: Serialize + DeserializeOwned + PartialEq>(
        &mut self,
        (g, fresh, path): (&Group, Option<&Group>, &str),
        name: &str,
        old: &T,
        new: &T,
    ) -> Res {
        if old == new {
            return Ok(());
        }
        match entry(g, name) {
            Some(e) => self.item(&e.value.clone(), new),
            None => self.add_field(g, fresh, path, name),
        }
    }

    /// List field `name` of `g`.
    fn list<T: Serialize + DeserializeOwned + PartialEq>(
        &mut self,
        (g, fresh, path): (&Group, Option<&Group>, &str),
        name: &str,
        old: &[T],
        new: &[T],
    ) -> Res {
        if old == new {
            return Ok(());
        }
        let key = if path.is_empty() {
            name.to_string()
        } else {
            format!("{path}.{name}")
        };
        let Some(e) = entry(g, name) else {
            return self.add_field(g, fresh, path, name);
        };
        let shape = || SpliceError::Shape(key.clone());
        let list = e.value.group.as_ref().ok_or_else(shape)?;
        if list.open != b'[' || list.entries.len() != old.len() {
            return Err(shape());
        }
        if old.is_empty() {
            let f = fresh.and_then(|f| entry(f, name)).ok_or_else(shape)?;
            self.out.push(Splice {
                start: e.value.start,
                end: e.value.end,
                text: self.fresh[f.value.start..f.value.end].to_string(),
            });
            return Ok(());
        }
        for step in align(old.len(), new.len(), |i, j| old[i] == new[j]) {
            match step {
                Step::Keep(..) => {}
                Step::Change(i, j) => self.item(&list.entries[i].value, &new[j])?,
                Step::Remove(i) => cut(self.old, list, i, &mut self.out),
                Step::Insert(j, after) => {
                    let near = &list.entries[after.unwrap_or(0)].value;
                    let single = one_line(self.old, near.start, near.end);
                    let text = minimal(&new[j])?;
                    // Only instance comments follow their items through edits (`comments`).
                    let comments = (key == "instances")
                        .then(|| self.comments.item(&key, j).cloned())
                        .flatten()
                        .unwrap_or_default();
                    let lines: Vec<String> = comments
                        .before
                        .into_iter()
                        .chain(comments.trailing)
                        .collect();
                    let item = |pad: &str| {
                        let body = if single || pad.is_empty() {
                            text.clone()
                        } else {
                            layout(&text, pad.len(), pad.len())
                        };
                        if pad.is_empty() {
                            return body;
                        }
                        lines
                            .iter()
                            .map(|c| format!("{c}\n{pad}"))
                            .collect::<String>()
                            + &body
                    };
                    insert(self.old, list, after, item, &mut self.out);
                }
            }
        }
        Ok(())
    }

    fn level(&mut self, g: &Group, fresh: Option<&Group>, old: &Level, new: &Level) -> Res {
        let at = (g, fresh, "");
        self.list(at, "models", &old.models, &new.models)?;
        self.list(at, "materials", &old.materials, &new.materials)?;
        self.list(at, "grids", &old.grids, &new.grids)?;
        self.list(at, "boxes", &old.boxes, &new.boxes)?;
        self.list(at, "terrains", &old.terrains, &new.terrains)?;
        self.list(at, "cities", &old.cities, &new.cities)?;
        self.list(at, "instances", &old.instances, &new.instances)?;
        self.one(at, "camera", &old.camera, &new.camera)?;
        self.one(at, "sun", &old.sun, &new.sun)?;
        self.one(at, "sky", &old.sky, &new.sky)?;
        self.one(at, "render", &old.render, &new.render)?;
        self.list(at, "render_areas", &old.render_areas, &new.render_areas)?;
        self.one(at, "needs", &old.needs, &new.needs)?;
        self.list(at, "characters", &old.characters, &new.characters)?;
        if old.gameplay == new.gameplay {
            return Ok(());
        }
        let Some(e) = entry(g, "gameplay") else {
            return self.add_field(g, fresh, "", "gameplay");
        };
        let inner = e
            .value
            .group
            .as_ref()
            .filter(|h| h.open == b'(' && h.keyed());
        let inner = inner.ok_or_else(|| SpliceError::Shape("gameplay".into()))?;
        let fresh_inner = fresh
            .and_then(|f| entry(f, "gameplay"))
            .and_then(|f| f.value.group.as_ref());
        self.gameplay(inner, fresh_inner, &old.gameplay, &new.gameplay)
    }

    fn gameplay(
        &mut self,
        g: &Group,
        fresh: Option<&Group>,
        o: &GameplayEntry,
        n: &GameplayEntry,
    ) -> Res {
        let at = (g, fresh, "gameplay");
        self.list(at, "sounds", &o.sounds, &n.sounds)?;
        self.one(at, "music", &o.music, &n.music)?;
        self.list(at, "emitters", &o.emitters, &n.emitters)?;
        self.list(at, "animations", &o.animations, &n.animations)?;
        self.list(at, "autoplay", &o.autoplay, &n.autoplay)?;
        self.list(at, "lights_off", &o.lights_off, &n.lights_off)?;
        self.list(at, "volumes", &o.volumes, &n.volumes)?;
        self.list(at, "lasers", &o.lasers, &n.lasers)?;
        self.list(at, "rules", &o.rules, &n.rules)?;
        self.list(at, "events", &o.events, &n.events)?;
        self.list(at, "usables", &o.usables, &n.usables)?;
        self.list(at, "counters", &o.counters, &n.counters)?;
        self.list(at, "breakables", &o.breakables, &n.breakables)
    }
}

/// The level file's `old` text with only what `doc.level` changed rewritten (see the module
/// doc); checked to read back as exactly `doc.level`.
pub(super) fn splice_level(old: &str, doc: &Document) -> Result<String, SpliceError> {
    let old_level = options()
        .from_str::<Level>(old)
        .map_err(|e| SpliceError::OldLevel(e.to_string()))?;
    if old_level == doc.level {
        return Ok(old.to_string());
    }
    let tree = ron_tree::parse(old).ok_or(SpliceError::Unreadable)?;
    let root = tree
        .group
        .as_ref()
        .filter(|g| g.open == b'(' && g.keyed())
        .ok_or(SpliceError::Unreadable)?;
    let fresh = render_document(&Document::new(doc.level.clone()))?;
    let fresh_tree = ron_tree::parse(&fresh);
    let mut ctx = Ctx {
        old,
        fresh: &fresh,
        comments: &doc.comments,
        out: Vec::new(),
    };
    let fresh_root = fresh_tree.as_ref().and_then(|t| t.group.as_ref());
    ctx.level(root, fresh_root, &old_level, &doc.level)?;
    let text = apply(old, &ctx.out).ok_or(SpliceError::Overlap)?;
    match options().from_str::<Level>(&text) {
        Ok(back) if back == doc.level => Ok(text),
        _ => Err(SpliceError::Mismatch),
    }
}
