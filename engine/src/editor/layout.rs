//! RON text in the level files' style, for the writer: one value serialised compactly
//! (`(model: "lift", transform: (translation: (0, 0.1, -2)))`), without the fields that only
//! repeat their default, whole numbers without `.0`, and broken over lines only where a line
//! would pass [`WIDTH`] columns (each part of the outermost brackets on its own line,
//! recursively).
//!
//! Main thread. Must not: know the level's types (serde does; defaults are found by parsing).

use ron::extensions::Extensions;
use ron::ser::PrettyConfig;
use serde::Serialize;
use serde::de::DeserializeOwned;

/// Lines longer than this many columns are broken.
pub(super) const WIDTH: usize = 100;

/// The options level files are read with (`Level::parse`): `Option` values need no `Some(…)`.
pub(super) fn options() -> ron::Options {
    ron::Options::default().with_default_extension(Extensions::IMPLICIT_SOME)
}

/// `value` on one line, `name: value` separated by `, `.
pub(super) fn compact<T: Serialize>(value: &T) -> Result<String, ron::Error> {
    options().to_string_pretty(value, PrettyConfig::new().depth_limit(0))
}

/// [`compact`] without the fields of a struct value whose absence reads back the same value
/// (defaults), with whole numbers written without `.0`.
pub(super) fn minimal<T: Serialize + DeserializeOwned + PartialEq>(
    value: &T,
) -> Result<String, ron::Error> {
    let text = compact(value)?;
    let Some(inner) = text.strip_prefix('(').and_then(|t| t.strip_suffix(')')) else {
        return Ok(whole_numbers(&text));
    };
    let mut parts = split_top(inner);
    if parts.is_empty() || !parts.iter().all(|p| is_field(p)) {
        return Ok(whole_numbers(&text));
    }
    let mut i = 0;
    while i < parts.len() {
        let mut trial = parts.clone();
        trial.remove(i);
        let candidate = format!("({})", trial.join(", "));
        if options().from_str::<T>(&candidate).ok().as_ref() == Some(value) {
            parts = trial;
        } else {
            i += 1;
        }
    }
    Ok(whole_numbers(&format!("({})", parts.join(", "))))
}

/// Whether `part` is `identifier: value`.
fn is_field(part: &str) -> bool {
    let name: String = part
        .chars()
        .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
        .collect();
    !name.is_empty() && part[name.len()..].trim_start().starts_with(':')
}

/// The parts of `inner` (the text between a pair of brackets) separated by commas outside any
/// nested bracket or string, trimmed; a trailing comma makes no empty part.
pub(super) fn split_top(inner: &str) -> Vec<String> {
    let mut parts = Vec::new();
    let mut depth = 0i32;
    let mut start = 0;
    let mut in_string = false;
    let mut escaped = false;
    for (k, c) in inner.char_indices() {
        if in_string {
            match (escaped, c) {
                (true, _) => escaped = false,
                (false, '\\') => escaped = true,
                (false, '"') => in_string = false,
                _ => {}
            }
            continue;
        }
        match c {
            '"' => in_string = true,
            '(' | '[' | '{' => depth += 1,
            ')' | ']' | '}' => depth -= 1,
            ',' if depth == 0 => {
                parts.push(inner[start..k].trim().to_string());
                start = k + 1;
            }
            _ => {}
        }
    }
    let last = inner[start..].trim();
    if !last.is_empty() {
        parts.push(last.to_string());
    }
    parts
}

/// `text` with every number token `N.0` written `N` (outside strings; `-0.0` is kept, so
/// that the sign of zero survives).
pub(super) fn whole_numbers(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    let mut in_string = false;
    while i < chars.len() {
        let c = chars[i];
        if in_string {
            out.push(c);
            if c == '\\' && i + 1 < chars.len() {
                out.push(chars[i + 1]);
                i += 1;
            } else if c == '"' {
                in_string = false;
            }
            i += 1;
            continue;
        }
        let starts_number = c.is_ascii_digit()
            && (i == 0 || !(chars[i - 1].is_ascii_alphanumeric() || chars[i - 1] == '_'));
        if !starts_number {
            in_string = c == '"';
            out.push(c);
            i += 1;
            continue;
        }
        let end = (i..chars.len())
            .find(|&k| !(chars[k].is_ascii_digit() || chars[k] == '.'))
            .unwrap_or(chars.len());
        let token: String = chars[i..end].iter().collect();
        let negative_zero = token == "0.0" && i > 0 && chars[i - 1] == '-';
        match token.strip_suffix(".0") {
            Some(whole) if !negative_zero && !whole.contains('.') => out.push_str(whole),
            _ => out.push_str(&token),
        }
        i = end;
    }
    out
}

/// `text` (one line) laid out for a line that starts at column `column` with continuation
/// lines indented by `indent` + 4 spaces: unchanged if it fits in [`WIDTH`], otherwise its
/// outermost brackets are opened with one part per line (each laid out the same way) and the
/// closing bracket at `indent`.
pub(super) fn layout(text: &str, column: usize, indent: usize) -> String {
    if column + text.chars().count() < WIDTH {
        return text.to_string();
    }
    let Some((prefix, open, inner, close)) = outer_brackets(text) else {
        return text.to_string();
    };
    let parts = split_top(inner);
    if parts.is_empty() {
        return text.to_string();
    }
    let pad = " ".repeat(indent + 4);
    let mut out = format!("{prefix}{open}\n");
    for part in parts {
        out.push_str(&pad);
        out.push_str(&layout(&part, indent + 4, indent + 4));
        out.push_str(",\n");
    }
    out.push_str(&" ".repeat(indent));
    out.push(close);
    out
}

/// `prefix`, the first bracket outside strings, what it encloses and its closing bracket, if
/// that bracket closes at the very end of `text`.
fn outer_brackets(text: &str) -> Option<(&str, char, &str, char)> {
    let mut in_string = false;
    let mut escaped = false;
    let mut open_at = None;
    let mut depth = 0;
    for (k, c) in text.char_indices() {
        if in_string {
            match (escaped, c) {
                (true, _) => escaped = false,
                (false, '\\') => escaped = true,
                (false, '"') => in_string = false,
                _ => {}
            }
            continue;
        }
        match c {
            '"' => in_string = true,
            '(' | '[' | '{' => {
                if depth == 0 && open_at.is_none() {
                    open_at = Some((k, c));
                }
                depth += 1;
            }
            ')' | ']' | '}' => {
                depth -= 1;
                if depth == 0 {
                    let (at, open) = open_at?;
                    // The first bracket must close at the end, or the text is not one value.
                    return (k + c.len_utf8() == text.len())
                        .then(|| (&text[..at], open, &text[at + 1..k], c));
                }
            }
            _ => {}
        }
    }
    None
}
