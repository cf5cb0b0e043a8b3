//! The engine's top-level modules form layers without cycles: a module uses only the modules
//! `engine/src/lib.rs` declares before it. This test reads every `crate::` path (plain,
//! grouped as `crate::{a::…, b::…}`, and `super::` chains that climb to the crate root) in the
//! code of `engine/src`, comments left out, and fails naming the file, the line and the two
//! modules of every upward use. The sub-modules of `app` are checked the same way against the
//! order `engine/src/app/mod.rs` declares them.

use std::collections::BTreeSet;
use std::fs;
use std::path::{Path, PathBuf};

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

/// The top-level modules in the order `lib.rs` declares them (`pub mod x;` / `mod x;`).
fn layers() -> Vec<String> {
    declared(&src().join("lib.rs"))
}

/// The modules `file` declares (`pub mod x;` / `mod x;`), in order.
fn declared(file: &Path) -> Vec<String> {
    let text = fs::read_to_string(file).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
    text.lines()
        .map(str::trim)
        .filter_map(|l| {
            l.strip_prefix("pub mod ")
                .or_else(|| l.strip_prefix("mod "))
        })
        .filter_map(|l| l.strip_suffix(';'))
        .map(str::to_string)
        .collect()
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<_> = fs::read_dir(dir)
        .expect("readable source folder")
        .map(|e| e.expect("entry").path())
        .collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The code of `text` without comments (line comments, doc comments and block comments) and
/// without the contents of string literals, line by line.
fn code_lines(text: &str) -> Vec<String> {
    let mut lines = Vec::new();
    let mut in_block = 0u32;
    for line in text.lines() {
        let mut out = String::new();
        let chars: Vec<char> = line.chars().collect();
        let mut i = 0;
        let mut in_string = false;
        while i < chars.len() {
            let c = chars[i];
            let next = chars.get(i + 1).copied();
            if in_block > 0 {
                if c == '*' && next == Some('/') {
                    in_block -= 1;
                    i += 2;
                } else if c == '/' && next == Some('*') {
                    in_block += 1;
                    i += 2;
                } else {
                    i += 1;
                }
                continue;
            }
            if in_string {
                if c == '\\' {
                    i += 2;
                    continue;
                }
                if c == '"' {
                    in_string = false;
                    out.push('"');
                }
                i += 1;
                continue;
            }
            match (c, next) {
                ('/', Some('/')) => break,
                ('/', Some('*')) => {
                    in_block += 1;
                    i += 2;
                }
                ('"', _) => {
                    in_string = true;
                    out.push('"');
                    i += 1;
                }
                _ => {
                    out.push(c);
                    i += 1;
                }
            }
        }
        lines.push(out);
    }
    lines
}

fn is_ident(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// The identifier starting at `rest` (after any whitespace).
fn ident(rest: &str) -> String {
    rest.trim_start()
        .chars()
        .take_while(|&c| is_ident(c))
        .collect()
}

/// Top-level modules named by `crate::` paths in `code` (the whole file's code, so that a
/// grouped `use` over several lines is read whole), with the line each appears on.
fn crate_uses(code: &[String], file_depth: usize) -> Vec<(usize, String)> {
    // `super::super::x` from a file `file_depth` folders below the crate root.
    path_uses(code, "crate::", |supers| supers >= file_depth && supers > 0)
}

/// Sub-modules of `app` named in the code of a file `file_depth` folders below the crate root
/// (`app/input/map.rs` is 3, `app/input/mod.rs` 2): `crate::app::x` paths (plain or grouped as
/// `crate::app::{x::…, y::…}`) and `super::` chains that climb exactly to `app`.
fn app_uses(code: &[String], file_depth: usize) -> Vec<(usize, String)> {
    path_uses(code, "crate::app::", |supers| {
        supers > 0 && supers + 1 == file_depth
    })
}

/// The first identifier after each `prefix` path in `code` (each item of a grouped
/// `prefix{a::…, b::…}`), and after each `super::` chain of a length `climbs` accepts, with
/// the line each appears on.
fn path_uses(
    code: &[String],
    prefix: &str,
    climbs: impl Fn(usize) -> bool,
) -> Vec<(usize, String)> {
    let joined: String = code.iter().map(|l| format!("{l}\n")).collect();
    let line_of = |offset: usize| joined[..offset].matches('\n').count() + 1;
    let mut uses = Vec::new();
    let bytes = joined.as_bytes();
    let mut at = 0;
    while let Some(found) = joined[at..].find(prefix) {
        let start = at + found;
        at = start + prefix.len();
        if start > 0 && is_ident(bytes[start - 1] as char) {
            continue; // `mycrate::`
        }
        let rest = &joined[at..];
        if rest.trim_start().starts_with('{') {
            // prefix{a::x, b::{y, z}}: the first identifier of each top-level item.
            let open = at + rest.find('{').unwrap_or(0);
            let mut depth = 0;
            let mut item_start = true;
            for (k, c) in joined[open..].char_indices() {
                match c {
                    '{' => {
                        depth += 1;
                        if depth == 1 {
                            item_start = true;
                            continue;
                        }
                    }
                    '}' => {
                        depth -= 1;
                        if depth == 0 {
                            break;
                        }
                    }
                    ',' if depth == 1 => {
                        item_start = true;
                        continue;
                    }
                    _ => {}
                }
                if depth == 1 && item_start && is_ident(c) {
                    let name = ident(&joined[open + k..]);
                    uses.push((line_of(open + k), name));
                    item_start = false;
                }
            }
        } else {
            uses.push((line_of(start), ident(rest)));
        }
    }
    for (n, line) in code.iter().enumerate() {
        let mut from = 0;
        while let Some(found) = line[from..].find("super::") {
            let start = from + found;
            let mut supers = 0;
            let mut rest = &line[start..];
            while let Some(r) = rest.strip_prefix("super::") {
                supers += 1;
                rest = r;
            }
            from = line.len() - rest.len();
            if climbs(supers) {
                uses.push((n + 1, ident(rest)));
            }
        }
    }
    uses
}

/// What [`layer_problems`] checks: the modules under `dir` (below `src()`), whose layer is the
/// path part at `level` (0: `src/<layer>`, 1: `src/app/<layer>`), in `layers` order, declared by
/// `toc` (skipped: its re-exports name every layer).
struct Layering<'a> {
    dir: PathBuf,
    toc: &'a [&'a str],
    level: usize,
    layers: &'a [String],
    /// The declaring file, for messages.
    declared_in: &'a str,
    /// The layers a file uses, from its code lines and its module's depth below the crate.
    uses: fn(&[String], usize) -> Vec<(usize, String)>,
    /// Whether a used name that is not a layer is a problem (a re-export hiding its layer).
    unknown_is_a_problem: bool,
}

/// Every use of a later layer (and every undeclared layer, and unknown names when asked), and
/// the layer-to-layer uses seen.
fn layer_problems(l: &Layering<'_>) -> (Vec<String>, BTreeSet<(String, String)>) {
    let position = |m: &str| l.layers.iter().position(|x| x == m);
    let mut files = Vec::new();
    rust_files(&l.dir, &mut files);
    let mut problems = Vec::new();
    let mut edges = BTreeSet::new();
    for file in &files {
        let relative = file.strip_prefix(src()).expect("under src");
        let parts: Vec<&str> = relative
            .iter()
            .map(|p| p.to_str().expect("utf-8 path"))
            .collect();
        if parts == l.toc {
            continue;
        }
        let own_name = parts[l.level].trim_end_matches(".rs");
        let Some(own) = position(own_name) else {
            problems.push(format!(
                "{}: module `{own_name}` is not declared in {}",
                relative.display(),
                l.declared_in
            ));
            continue;
        };
        // Depth below the crate root of the module the file is: `a.rs` and `a/mod.rs` are
        // depth 1, `a/b.rs` depth 2 (a `super::` from `a/b.rs` is `a`).
        let is_mod = parts.last().is_some_and(|p| *p == "mod.rs");
        let depth = parts.len() - usize::from(is_mod);
        let text = fs::read_to_string(file).expect("readable source");
        for (line, used) in (l.uses)(&code_lines(&text), depth) {
            if used == own_name || used.is_empty() {
                continue;
            }
            let Some(theirs) = position(&used) else {
                if l.unknown_is_a_problem {
                    problems.push(format!(
                        "{}:{line}: `{own_name}` names `{used}`, a re-export at the root: name the module it lives in",
                        relative.display()
                    ));
                }
                continue;
            };
            edges.insert((own_name.to_string(), used.clone()));
            if theirs > own {
                problems.push(format!(
                    "{}:{line}: `{own_name}` uses `{used}`, which {} declares after it (a layer may use only the layers before it)",
                    relative.display(),
                    l.declared_in
                ));
            }
        }
    }
    (problems, edges)
}

#[test]
fn top_level_modules_only_use_the_layers_below_them() {
    let layers = layers();
    assert!(
        layers.len() >= 12,
        "lib.rs declares only {layers:?}: the layer list was not read"
    );
    // A crate::SomeReexport at the root (none today) or a macro path is not a layer.
    let (problems, edges) = layer_problems(&Layering {
        dir: src(),
        toc: &["lib.rs"],
        level: 0,
        layers: &layers,
        declared_in: "lib.rs",
        uses: crate_uses,
        unknown_is_a_problem: false,
    });
    assert!(
        edges.len() > 20,
        "only {} module-to-module uses found: the path reader is broken ({edges:?})",
        edges.len()
    );
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn the_path_reader_sees_every_form_of_use() {
    let code = code_lines(
        "use crate::{a::X,\n    b::{Y, Z}};\n// crate::c::Hidden\nlet s = \"crate::d\";\nfn f() { crate::e::g(); }\n/* crate::h */ super::super::k::L;",
    );
    let names: Vec<String> = crate_uses(&code, 2).into_iter().map(|(_, n)| n).collect();
    assert_eq!(names, ["a", "b", "e", "k"]);
}

/// The sub-modules of `app` form layers too: each uses only the ones `app/mod.rs` declares
/// before it. Read from `crate::app::<sub>` paths and `super::` chains that climb into `app`;
/// a file inside a sub-module that names a re-export at `app`'s root (`crate::app::Engine`)
/// fails too, since the re-export hides which layer it reaches.
#[test]
fn app_sub_modules_only_use_the_ones_declared_before_them() {
    let app = src().join("app");
    let layers = declared(&app.join("mod.rs"));
    assert!(
        layers.len() >= 8,
        "app/mod.rs declares only {layers:?}: the layer list was not read"
    );
    let (problems, edges) = layer_problems(&Layering {
        dir: app,
        toc: &["app", "mod.rs"],
        level: 1,
        layers: &layers,
        declared_in: "app/mod.rs",
        uses: app_uses,
        unknown_is_a_problem: true,
    });
    assert!(
        edges.len() > 10,
        "only {} sub-module-to-sub-module uses found in app: the path reader is broken ({edges:?})",
        edges.len()
    );
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn the_app_path_reader_sees_every_form_of_use() {
    let code = code_lines(
        "use crate::app::{input::X,\n    runner::{Y, Z}};\n// crate::app::hidden::H\nfn f() { crate::app::replay::g(); }\nuse super::super::shell::S;\nuse super::sibling::T;\nuse crate::assets::A;",
    );
    let names: Vec<String> = app_uses(&code, 3).into_iter().map(|(_, n)| n).collect();
    assert_eq!(names, ["input", "runner", "replay", "shell"]);
}
