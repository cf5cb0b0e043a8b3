//! The shape of a RON text with byte spans, for saves that change only what was edited
//! (`save_diff`): every value is an atom (number, string, identifier, character) or a group
//! (`Name(…)`, `(…)`, `[…]`, `{…}`) whose entries are values, each with its key when written
//! `key: value`. Whitespace and comments (`//`, nested `/* */`) are skipped; strings and raw
//! strings are read whole. It is not a RON parser: it does not know types, and serde reads the
//! values; it only says where each value lies in the text.
//!
//! Main thread. Must not: fail loudly: text it cannot read gives `None` (the save then
//! rewrites the whole file).

/// One value and where it lies: `text[start..end]`.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Node {
    pub start: usize,
    pub end: usize,
    pub group: Option<Group>,
}

/// A bracketed value: its name (empty when it has none), its bracket and its entries.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Group {
    pub name: String,
    pub open: u8,
    /// Byte index of the opening bracket (the closing one is at `Node::end - 1`).
    pub open_at: usize,
    pub entries: Vec<Entry>,
}

/// One entry of a group: `key: value` or a bare value, and the comma after it if any.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Entry {
    /// The key's text (`translation`, `"north"`), when the entry is `key: value`.
    pub key: Option<String>,
    /// Where the entry starts (its key, or its value).
    pub start: usize,
    pub value: Node,
    /// Byte index of the comma after it.
    pub comma: Option<usize>,
}

impl Entry {
    /// Where the entry ends, its comma included.
    pub fn end(&self) -> usize {
        self.comma.map_or(self.value.end, |c| c + 1)
    }
}

impl Group {
    /// Whether every entry is `key: value` (a struct, or a map).
    pub fn keyed(&self) -> bool {
        self.entries.iter().all(|e| e.key.is_some())
    }
}

struct Reader<'a> {
    b: &'a [u8],
    i: usize,
}

fn is_word(c: u8) -> bool {
    c.is_ascii_alphanumeric() || matches!(c, b'_' | b'.' | b'+' | b'-')
}

impl Reader<'_> {
    fn peek(&self) -> Option<u8> {
        self.b.get(self.i).copied()
    }

    /// Skips whitespace and comments.
    fn skip(&mut self) -> Option<()> {
        loop {
            match (self.peek(), self.b.get(self.i + 1).copied()) {
                (Some(c), _) if c.is_ascii_whitespace() => self.i += 1,
                (Some(b'/'), Some(b'/')) => {
                    while self.peek().is_some_and(|c| c != b'\n') {
                        self.i += 1;
                    }
                }
                (Some(b'/'), Some(b'*')) => {
                    let mut depth = 0u32;
                    loop {
                        match (self.peek()?, self.b.get(self.i + 1).copied()) {
                            (b'/', Some(b'*')) => {
                                depth += 1;
                                self.i += 2;
                            }
                            (b'*', Some(b'/')) => {
                                depth -= 1;
                                self.i += 2;
                                if depth == 0 {
                                    break;
                                }
                            }
                            _ => self.i += 1,
                        }
                    }
                }
                _ => return Some(()),
            }
        }
    }

    /// A string (`"…"` with escapes, `r#"…"#`) or character literal starting here.
    fn string(&mut self) -> Option<()> {
        let quote = self.peek()?;
        if quote == b'r' {
            self.i += 1;
            let hashes = self.b[self.i..].iter().take_while(|&&c| c == b'#').count();
            self.i += hashes + 1;
            let close: Vec<u8> = std::iter::once(b'"')
                .chain(std::iter::repeat_n(b'#', hashes))
                .collect();
            let at = self.b[self.i..]
                .windows(close.len())
                .position(|w| w == close.as_slice())?;
            self.i += at + close.len();
            return Some(());
        }
        self.i += 1;
        loop {
            match self.peek()? {
                b'\\' => self.i += 2,
                c if c == quote => {
                    self.i += 1;
                    return Some(());
                }
                _ => self.i += 1,
            }
        }
    }

    fn value(&mut self) -> Option<Node> {
        self.skip()?;
        let start = self.i;
        let c = self.peek()?;
        let mut name = String::new();
        if c == b'"'
            || c == b'\''
            || (c == b'r' && matches!(self.b.get(start + 1), Some(b'"' | b'#')))
        {
            self.string()?;
            return Some(Node {
                start,
                end: self.i,
                group: None,
            });
        }
        if is_word(c) {
            while self.peek().is_some_and(is_word) {
                self.i += 1;
            }
            let end = self.i;
            self.skip()?;
            if self.peek() != Some(b'(') {
                self.i = end;
                return Some(Node {
                    start,
                    end,
                    group: None,
                });
            }
            name = String::from_utf8_lossy(&self.b[start..end]).into_owned();
        }
        let open = self.peek()?;
        let close = match open {
            b'(' => b')',
            b'[' => b']',
            b'{' => b'}',
            _ => return None,
        };
        let open_at = self.i;
        self.i += 1;
        let mut entries = Vec::new();
        loop {
            self.skip()?;
            if self.peek()? == close {
                self.i += 1;
                break;
            }
            let first = self.value()?;
            self.skip()?;
            let (key, value) = if self.peek()? == b':' {
                self.i += 1;
                let key = String::from_utf8_lossy(&self.b[first.start..first.end]).into_owned();
                (Some(key), self.value()?)
            } else {
                (None, first.clone())
            };
            self.skip()?;
            let comma = (self.peek()? == b',').then_some(self.i);
            if comma.is_some() {
                self.i += 1;
            } else if self.peek()? != close {
                return None;
            }
            entries.push(Entry {
                key,
                start: first.start,
                value,
                comma,
            });
        }
        Some(Node {
            start,
            end: self.i,
            group: Some(Group {
                name,
                open,
                open_at,
                entries,
            }),
        })
    }
}

/// The one value of a whole file's `text` (after any `#![enable(…)]` lines), or `None` when
/// the text is not a value this reader understands.
pub(super) fn parse(text: &str) -> Option<Node> {
    let mut r = Reader {
        b: text.as_bytes(),
        i: 0,
    };
    r.skip()?;
    while r.peek() == Some(b'#') {
        while r.peek()? != b']' {
            r.i += 1;
        }
        r.i += 1;
        r.skip()?;
    }
    let node = r.value()?;
    r.skip()?;
    (r.i == text.len()).then_some(node)
}

/// Whether `a` (in text `at`) and `b` (in text `bt`) write the same value: the same atoms
/// (numbers compared by value: `1.0` is `1`), groups with the same name and bracket, and the
/// same entries (keyed ones in any order). Layout and comments do not count.
pub(super) fn same(at: &str, a: &Node, bt: &str, b: &Node) -> bool {
    match (&a.group, &b.group) {
        (None, None) => {
            let (x, y) = (&at[a.start..a.end], &bt[b.start..b.end]);
            x == y || matches!((x.parse::<f64>(), y.parse::<f64>()), (Ok(p), Ok(q)) if p == q)
        }
        (Some(g), Some(h)) => {
            g.name == h.name
                && g.open == h.open
                && g.entries.len() == h.entries.len()
                && if g.keyed() && h.keyed() {
                    g.entries.iter().all(|e| {
                        h.entries
                            .iter()
                            .find(|f| f.key == e.key)
                            .is_some_and(|f| same(at, &e.value, bt, &f.value))
                    })
                } else {
                    g.entries
                        .iter()
                        .zip(&h.entries)
                        .all(|(e, f)| e.key == f.key && same(at, &e.value, bt, &f.value))
                }
        }
        _ => false,
    }
}
