//! Text edits on a RON file that keep everything they do not touch, for saves that change only
//! what was edited (`save_diff`): a [`Splice`] replaces a byte range; [`merge`] turns an old
//! value into a new one by replacing only the atoms and entries that differ (keeping the old
//! layout, field order, comments and fields the new text leaves out); [`cut`] removes an
//! entry with its line, and [`insert`] adds one in the style of its neighbour (on a line of
//! its own at the neighbour's indentation, or inline after `, `). [`align`] pairs the items of
//! an old and a new list.
//!
//! Main thread. Must not: know the level's types (`save_diff` checks every result by parsing).

use super::ron_tree::{Entry, Group, Node, same};

/// Replace `start..end` of the old text with `text` (an insertion when `start == end`).
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Splice {
    pub start: usize,
    pub end: usize,
    pub text: String,
}

impl Splice {
    fn new(start: usize, end: usize, text: impl Into<String>) -> Self {
        Self {
            start,
            end,
            text: text.into(),
        }
    }
}

/// `text` with `splices` applied (in order of position; an insertion before a replacement at
/// the same place), or `None` when two overlap.
pub(super) fn apply(text: &str, splices: &[Splice]) -> Option<String> {
    let mut order: Vec<&Splice> = splices.iter().collect();
    order.sort_by_key(|s| (s.start, s.end));
    let mut out = String::with_capacity(text.len());
    let mut at = 0;
    for s in order {
        if s.start < at || s.end < s.start || s.end > text.len() {
            return None;
        }
        out.push_str(text.get(at..s.start)?);
        out.push_str(&s.text);
        at = s.end;
    }
    out.push_str(text.get(at..)?);
    Some(out)
}

/// Where the line holding byte `at` starts.
pub(super) fn line_start(text: &str, at: usize) -> usize {
    text[..at].rfind('\n').map_or(0, |k| k + 1)
}

/// The indentation of the line holding byte `at`.
pub(super) fn indent_at(text: &str, at: usize) -> &str {
    let start = line_start(text, at);
    let line = &text[start..];
    &line[..line.len() - line.trim_start_matches([' ', '\t']).len()]
}

/// Whether `start..end` is one line.
pub(super) fn one_line(text: &str, start: usize, end: usize) -> bool {
    !text[start..end].contains('\n')
}

/// Whether only whitespace comes before `at` on its line.
fn opens_line(text: &str, at: usize) -> bool {
    text[line_start(text, at)..at].trim().is_empty()
}

/// After `at`: the index of the line's `\n` (or the text's end) when only whitespace and a
/// comment follow on the line.
fn line_rest(text: &str, at: usize) -> Option<usize> {
    let end = text[at..].find('\n').map_or(text.len(), |k| at + k);
    let rest = text[at..end].trim();
    (rest.is_empty() || rest.starts_with("//") || (rest.starts_with("/*") && rest.ends_with("*/")))
        .then_some(end)
}

/// Whether the entry stands on lines of its own (nothing else of the group on them).
fn own_lines(text: &str, e: &Entry) -> bool {
    opens_line(text, e.start) && line_rest(text, e.end()).is_some()
}

/// Removes entry `k` of `g`: with its lines (and the comment lines just above it, which the
/// document anchors to it) when it stands on lines of its own, else with one separator.
pub(super) fn cut(text: &str, g: &Group, k: usize, out: &mut Vec<Splice>) {
    let e = &g.entries[k];
    if own_lines(text, e) {
        let mut start = line_start(text, e.start);
        while start > 0 {
            let above = line_start(text, start - 1);
            let line = text[above..start].trim();
            let comment =
                line.starts_with("//") || (line.starts_with("/*") && line.ends_with("*/"));
            if !comment {
                break;
            }
            start = above;
        }
        let end = line_rest(text, e.end()).unwrap_or(e.end());
        out.push(Splice::new(start, (end + 1).min(text.len()), ""));
    } else if let Some(next) = g.entries.get(k + 1) {
        out.push(Splice::new(e.start, next.start, ""));
    } else if let Some(prev) = k.checked_sub(1).map(|p| &g.entries[p]) {
        out.push(Splice::new(prev.value.end, e.value.end, ""));
    } else {
        out.push(Splice::new(e.start, e.end(), ""));
    }
}

/// Inserts entry `item` (its text, e.g. `name: value` or a value, already laid out for
/// `indent` when it spans lines) after entry `after` of `g` (`None`: first), in the style of
/// the neighbour. `indent` is called with the indentation a line of its own would get.
pub(super) fn insert(
    text: &str,
    g: &Group,
    after: Option<usize>,
    item: impl Fn(&str) -> String,
    out: &mut Vec<Splice>,
) {
    let neighbour = match after {
        Some(k) => g.entries.get(k),
        None => g.entries.first(),
    };
    let Some(e) = neighbour else {
        // An empty group: the item alone inside its brackets.
        let at = g.open_at + 1;
        let close = text[at..]
            .find(|c: char| !c.is_whitespace())
            .map_or(at, |k| at + k);
        out.push(Splice::new(at, close, item("")));
        return;
    };
    let lines = own_lines(text, e);
    match (after, lines) {
        (Some(_), true) => {
            let pad = indent_at(text, e.start);
            if e.comma.is_none() {
                out.push(Splice::new(e.value.end, e.value.end, ","));
            }
            let end = line_rest(text, e.end()).unwrap_or(e.end());
            out.push(Splice::new(end, end, format!("\n{pad}{},", item(pad))));
        }
        (Some(_), false) => {
            out.push(Splice::new(
                e.value.end,
                e.value.end,
                format!(", {}", item("")),
            ));
        }
        (None, true) => {
            let pad = indent_at(text, e.start);
            let at = line_start(text, e.start);
            out.push(Splice::new(at, at, format!("{pad}{},\n", item(pad))));
        }
        (None, false) => out.push(Splice::new(e.start, e.start, format!("{}, ", item("")))),
    }
}

/// How an old list's items map to a new one's.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Step {
    /// Old item `.0` is new item `.1`, unchanged.
    Keep(usize, usize),
    /// Old item `.0` became new item `.1`.
    Change(usize, usize),
    /// Old item removed.
    Remove(usize),
    /// New item `.0`, after old item `.1` (`None`: before the first).
    Insert(usize, Option<usize>),
}

/// The longest run of kept items (after the common start and end), the items between kept
/// ones paired in order as changed, the rest removed or inserted. `same(i, j)`: old item `i`
/// equals new item `j`. Lists with more than `LIMIT` items left after trimming are paired in
/// order without a search.
pub(super) fn align(old: usize, new: usize, same: impl Fn(usize, usize) -> bool) -> Vec<Step> {
    const LIMIT: usize = 2000;
    let head = (0..old.min(new)).take_while(|&i| same(i, i)).count();
    let tail = (0..old.min(new) - head)
        .take_while(|&k| same(old - 1 - k, new - 1 - k))
        .count();
    let (n, m) = (old - head - tail, new - head - tail);
    // Kept pairs in the middle, by a longest common subsequence.
    let mut kept: Vec<(usize, usize)> = Vec::new();
    if n > 0 && m > 0 && n <= LIMIT && m <= LIMIT {
        let mut len = vec![0u32; (n + 1) * (m + 1)];
        let at = |i: usize, j: usize| i * (m + 1) + j;
        for i in (0..n).rev() {
            for j in (0..m).rev() {
                len[at(i, j)] = if same(head + i, head + j) {
                    len[at(i + 1, j + 1)] + 1
                } else {
                    len[at(i + 1, j)].max(len[at(i, j + 1)])
                };
            }
        }
        let (mut i, mut j) = (0, 0);
        while i < n && j < m {
            if same(head + i, head + j) {
                kept.push((head + i, head + j));
                (i, j) = (i + 1, j + 1);
            } else if len[at(i + 1, j)] >= len[at(i, j + 1)] {
                i += 1;
            } else {
                j += 1;
            }
        }
    }
    kept.extend((0..tail).map(|k| (old - tail + k, new - tail + k)));
    let mut steps: Vec<Step> = (0..head).map(|i| Step::Keep(i, i)).collect();
    let (mut i, mut j) = (head, head);
    for (ki, kj) in kept {
        pair_run(&mut steps, i..ki, j..kj);
        steps.push(Step::Keep(ki, kj));
        (i, j) = (ki + 1, kj + 1);
    }
    pair_run(&mut steps, i..old, j..new);
    steps
}

/// Old items `olds` and new items `news` between two kept pairs: paired in order.
fn pair_run(steps: &mut Vec<Step>, olds: std::ops::Range<usize>, news: std::ops::Range<usize>) {
    let mut last = olds.start.checked_sub(1);
    let mut news = news.peekable();
    for i in olds {
        match news.next() {
            Some(j) => steps.push(Step::Change(i, j)),
            None => steps.push(Step::Remove(i)),
        }
        last = Some(i);
    }
    for j in news {
        steps.push(Step::Insert(j, last));
    }
}

/// Splices that turn old value `o` (in `ot`) into new value `n` (in `nt`), keeping all that is
/// the same. `keep_absent`: keyed entries the new value leaves out stay as they were (fields
/// written at their default value); otherwise they are removed.
pub(super) fn merge(
    ot: &str,
    o: &Node,
    nt: &str,
    n: &Node,
    keep_absent: bool,
    out: &mut Vec<Splice>,
) {
    if same(ot, o, nt, n) {
        return;
    }
    let replace =
        |out: &mut Vec<Splice>| out.push(Splice::new(o.start, o.end, &nt[n.start..n.end]));
    let (Some(g), Some(h)) = (&o.group, &n.group) else {
        return replace(out);
    };
    if g.name != h.name || g.open != h.open {
        return replace(out);
    }
    let text_of = |e: &Entry| nt[e.start..e.value.end].to_string();
    if g.keyed() && h.keyed() && !g.entries.is_empty() {
        let mut last = None;
        for (k, e) in g.entries.iter().enumerate() {
            match h.entries.iter().find(|f| f.key == e.key) {
                Some(f) => merge(ot, &e.value, nt, &f.value, keep_absent, out),
                None if keep_absent => {}
                None => cut(ot, g, k, out),
            }
            if keep_absent || h.entries.iter().any(|f| f.key == e.key) {
                last = Some(k);
            }
        }
        for f in h
            .entries
            .iter()
            .filter(|f| !g.entries.iter().any(|e| e.key == f.key))
        {
            let item = text_of(f);
            insert(ot, g, last, |_| item.clone(), out);
        }
        return;
    }
    if g.keyed() != h.keyed() && !g.entries.is_empty() && !h.entries.is_empty() {
        return replace(out);
    }
    let steps = align(g.entries.len(), h.entries.len(), |i, j| {
        same(ot, &g.entries[i].value, nt, &h.entries[j].value)
    });
    for step in steps {
        match step {
            Step::Keep(..) => {}
            Step::Change(i, j) => merge(
                ot,
                &g.entries[i].value,
                nt,
                &h.entries[j].value,
                keep_absent,
                out,
            ),
            Step::Remove(i) => cut(ot, g, i, out),
            Step::Insert(j, after) => {
                let item = text_of(&h.entries[j]);
                insert(ot, g, after, |_| item.clone(), out);
            }
        }
    }
}
