//! Reading the comments of a level file's text and anchoring them ([`scan`] →
//! [`Comments`]): a character scanner that knows RON's strings, raw strings, line and (nested)
//! block comments and brackets, and tracks where it is in the level's structure — the
//! level's fields, the `gameplay` section's fields, the items of their lists — without
//! parsing any value.
//!
//! Main thread. Must not: fail: text it does not understand only anchors less precisely
//! (serde reports real syntax errors).

use super::comments::{Anchored, Comments};

/// What a comment is anchored to.
#[derive(Clone, Debug, PartialEq)]
enum Key {
    Field(String),
    Item(String, usize),
    End(String),
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    /// The level or its gameplay section: fields by name.
    Struct,
    /// A list field: items by index.
    List,
    /// Brackets inside a value: comments go to the value's anchor.
    Opaque,
}

#[derive(Clone, Debug, PartialEq)]
enum Expect {
    /// A field name (structs) or an item (lists).
    Start,
    /// The value of this field.
    Value(String),
    /// The rest of a value or item, up to the next comma.
    Rest,
}

struct Frame {
    kind: Kind,
    path: String,
    expect: Expect,
    items: usize,
    /// Opaque frames: what their comments belong to.
    anchor: Option<Key>,
}

fn join(path: &str, field: &str) -> String {
    if path.is_empty() {
        field.to_string()
    } else {
        format!("{path}.{field}")
    }
}

fn is_ident(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

struct Scanner {
    out: Comments,
    frames: Vec<Frame>,
    pending: Vec<String>,
    last: Option<Key>,
    opened: bool,
}

impl Scanner {
    fn anchored(&mut self, key: &Key) -> &mut Anchored {
        match key {
            Key::Field(p) => self.out.fields.entry(p.clone()).or_default(),
            Key::Item(p, i) => self.out.item_mut(p, *i),
            Key::End(p) => self.out.ends.entry(p.clone()).or_default(),
        }
    }

    /// Gives the comments waiting for the next thing in the text to `key`.
    fn settle(&mut self, key: Key) {
        let pending = std::mem::take(&mut self.pending);
        self.anchored(&key).before.extend(pending);
        self.last = Some(key);
    }

    fn comment(&mut self, text: String, own_line: bool) {
        let Some(frame) = self.frames.last() else {
            if self.opened {
                self.out.footer.push(text);
            } else {
                self.out.header.push(text);
            }
            return;
        };
        if !own_line {
            match self.last.clone() {
                Some(key) => self.anchored(&key).add_trailing(text),
                None if self.out.opening.is_none() => self.out.opening = Some(text),
                None => self.pending.push(text),
            }
        } else if let (Kind::Opaque, Some(key)) = (frame.kind, frame.anchor.clone()) {
            self.anchored(&key).before.push(text);
        } else {
            self.pending.push(text);
        }
    }

    /// Something that is not whitespace or a comment, at the start of a token.
    fn code(&mut self, c: char, word: &str) {
        let Some(frame) = self.frames.last_mut() else {
            if c == '(' && !self.opened {
                self.opened = true;
                let pending = std::mem::take(&mut self.pending);
                self.out.header.extend(pending);
                self.push(Kind::Struct, String::new(), None);
            }
            return;
        };
        let (kind, path) = (frame.kind, frame.path.clone());
        match (c, kind, frame.expect.clone()) {
            (')' | ']' | '}', _, _) => {
                self.frames.pop();
                if kind != Kind::Opaque {
                    self.settle(Key::End(path));
                }
            }
            (',', Kind::Struct | Kind::List, _) => frame.expect = Expect::Start,
            (_, Kind::Struct, Expect::Start) if is_ident(c) => {
                frame.expect = Expect::Value(word.to_string());
                self.out.order.push(join(&path, word));
                self.settle(Key::Field(join(&path, word)));
            }
            (_, Kind::Struct, Expect::Value(field)) if c != ':' => {
                frame.expect = Expect::Rest;
                let key = Key::Field(join(&path, &field));
                match c {
                    '[' => self.push(Kind::List, join(&path, &field), None),
                    '(' if path.is_empty() && field == "gameplay" => {
                        self.push(Kind::Struct, field, None)
                    }
                    '(' | '{' => self.push(Kind::Opaque, String::new(), Some(key)),
                    _ => {}
                }
            }
            (_, Kind::List, Expect::Start) => {
                frame.expect = Expect::Rest;
                let key = Key::Item(path, frame.items);
                frame.items += 1;
                self.settle(key.clone());
                if matches!(c, '(' | '[' | '{') {
                    self.push(Kind::Opaque, String::new(), Some(key));
                }
            }
            ('(' | '[' | '{', _, _) => {
                let anchor = match kind {
                    Kind::Opaque => frame.anchor.clone(),
                    _ => self.last.clone(),
                };
                self.push(Kind::Opaque, String::new(), anchor);
            }
            _ => {}
        }
    }

    fn push(&mut self, kind: Kind, path: String, anchor: Option<Key>) {
        self.frames.push(Frame {
            kind,
            path,
            expect: Expect::Start,
            items: 0,
            anchor,
        });
    }
}

/// The comments of a level file's `text`, anchored.
pub(super) fn scan(text: &str) -> Comments {
    let chars: Vec<char> = text.chars().collect();
    let mut s = Scanner {
        out: Comments::default(),
        frames: Vec::new(),
        pending: Vec::new(),
        last: None,
        opened: false,
    };
    let mut line_has_code = false;
    let mut i = 0;
    let collect = |from: usize, to: usize| chars[from..to].iter().collect::<String>();
    while i < chars.len() {
        let c = chars[i];
        let next = chars.get(i + 1).copied();
        if c == '\n' {
            line_has_code = false;
            i += 1;
        } else if c.is_whitespace() {
            i += 1;
        } else if c == '/' && next == Some('/') {
            let end = (i..chars.len())
                .find(|&k| chars[k] == '\n')
                .unwrap_or(chars.len());
            s.comment(collect(i, end).trim_end().to_string(), !line_has_code);
            i = end;
        } else if c == '/' && next == Some('*') {
            let (mut depth, mut k) = (0u32, i);
            while k < chars.len() {
                if chars[k] == '/' && chars.get(k + 1) == Some(&'*') {
                    depth += 1;
                    k += 2;
                } else if chars[k] == '*' && chars.get(k + 1) == Some(&'/') {
                    depth -= 1;
                    k += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    k += 1;
                }
            }
            s.comment(collect(i, k.min(chars.len())), !line_has_code);
            i = k;
        } else if c == '#' && s.frames.is_empty() && !s.opened {
            // `#![enable(…)]`: up to its closing bracket.
            let end = (i..chars.len())
                .find(|&k| chars[k] == ']')
                .map_or(chars.len(), |k| k + 1);
            s.out.attributes.push(collect(i, end));
            line_has_code = true;
            i = end;
        } else if c == '"' || (c == 'r' && matches!(next, Some('"' | '#'))) {
            i = skip_string(&chars, i);
            s.code('"', "");
            line_has_code = true;
        } else if is_ident(c) {
            let end = (i..chars.len())
                .find(|&k| !is_ident(chars[k]))
                .unwrap_or(chars.len());
            let word = collect(i, end);
            s.code(c, &word);
            line_has_code = true;
            i = end;
        } else {
            s.code(c, "");
            line_has_code = true;
            i += 1;
        }
    }
    let rest = std::mem::take(&mut s.pending);
    if s.frames.is_empty() && s.opened {
        s.out.footer.extend(rest);
    } else {
        s.out.header.extend(rest);
    }
    s.out.tidy_all();
    s.out
}

/// The index after the string starting at `i` (`"…"` with escapes, or `r#"…"#`).
fn skip_string(chars: &[char], i: usize) -> usize {
    if chars[i] == 'r' {
        let hashes = chars[i + 1..].iter().take_while(|&&c| c == '#').count();
        let mut k = i + 1 + hashes + 1;
        while k < chars.len() {
            if chars[k] == '"'
                && chars[k + 1..]
                    .iter()
                    .take(hashes)
                    .filter(|&&c| c == '#')
                    .count()
                    == hashes
            {
                return k + 1 + hashes;
            }
            k += 1;
        }
        return chars.len();
    }
    let mut k = i + 1;
    while k < chars.len() {
        match chars[k] {
            '\\' => k += 2,
            '"' => return k + 1,
            _ => k += 1,
        }
    }
    chars.len()
}
