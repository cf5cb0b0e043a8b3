//! A first pass over OBJ text, before `tobj` parses it: validates every face index and
//! removes the statements the engine does not load.
//!
//! Why: `tobj` 4 computes relative and zero indices with unchecked arithmetic (a debug build
//! panics on `f 0 …` or on a negative index past the start, a release build wraps), and it
//! turns `l` polylines with three or more points into triangles. This pass refuses bad
//! indices with the line number, blanks out `l` (lines) and `p` (points) statements, and
//! ignores normal and texture indices in a file that has no `vn` or `vt` at all (as `tobj`
//! does), and collects the `usemtl` names so that unknown materials can be reported.
//! Input: the OBJ text. Output: [`Scan`] with the text `tobj` should parse.
//! Must not: build geometry (that is `tobj`'s job, then `obj`'s).

/// What the scan found.
pub(crate) struct Scan {
    /// The text for `tobj`: the input with `l` and `p` statements blanked.
    pub text: String,
    /// How many `l` and `p` statements were removed.
    pub skipped_lines_and_points: usize,
    /// How many `f` statements had fewer than three vertices (dropped by `tobj`).
    pub short_faces: usize,
    /// How many face corners name a normal or texture coordinate in a file that has none.
    pub dangling_indices: usize,
    /// The material names given to `usemtl`, in order of first use.
    pub used_materials: Vec<String>,
}

/// Scans `text`; an error is "line N: problem".
pub(crate) fn scan_obj(text: &str) -> Result<Scan, String> {
    // Totals first: OBJ allows a face to use a vertex written later in the file, and `tobj`
    // checks positive indices against the final arrays.
    let (mut total_v, mut total_vt, mut total_vn) = (0usize, 0usize, 0usize);
    for line in text.lines() {
        match line.split_whitespace().next() {
            Some("v") => total_v += 1,
            Some("vt") => total_vt += 1,
            Some("vn") => total_vn += 1,
            _ => {}
        }
    }
    let mut scan = Scan {
        text: String::with_capacity(text.len()),
        skipped_lines_and_points: 0,
        short_faces: 0,
        dangling_indices: 0,
        used_materials: Vec::new(),
    };
    let (mut seen_v, mut seen_vt, mut seen_vn) = (0usize, 0usize, 0usize);
    for (number, line) in text.lines().enumerate() {
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => seen_v += 1,
            Some("vt") => seen_vt += 1,
            Some("vn") => seen_vn += 1,
            Some("l") | Some("p") => {
                scan.skipped_lines_and_points += 1;
                scan.text.push('\n');
                continue;
            }
            Some("f") => {
                let mut corners = 0;
                for corner in words {
                    corners += 1;
                    let parts = corner.split('/');
                    for (slot, part) in parts.enumerate() {
                        let (seen, total, what) = match slot {
                            0 => (seen_v, total_v, "vertex"),
                            1 => (seen_vt, total_vt, "texture coordinate"),
                            2 => (seen_vn, total_vn, "normal"),
                            _ => {
                                return Err(format!(
                                    "line {}: face corner {corner:?} has more than three indices",
                                    number + 1
                                ));
                            }
                        };
                        // `tobj` ignores normal and texture indices when the file has none
                        // of that kind; so does the engine (with a note).
                        if part.is_empty() || (slot > 0 && total == 0) {
                            if !part.is_empty() {
                                scan.dangling_indices += 1;
                            }
                            continue;
                        }
                        check_index(part, seen, total, what)
                            .map_err(|problem| format!("line {}: {problem}", number + 1))?;
                    }
                }
                if corners < 3 {
                    scan.short_faces += 1;
                }
            }
            Some("usemtl") => {
                let name = line.trim_start()["usemtl".len()..].trim().to_string();
                if !name.is_empty() && !scan.used_materials.contains(&name) {
                    scan.used_materials.push(name);
                }
            }
            _ => {}
        }
        scan.text.push_str(line);
        scan.text.push('\n');
    }
    Ok(scan)
}

/// Checks one face index: 1-based, or negative (relative to the `seen` elements so far).
fn check_index(text: &str, seen: usize, total: usize, what: &str) -> Result<(), String> {
    let index: i64 = text
        .parse()
        .map_err(|_| format!("{what} index {text:?} is not a whole number"))?;
    let valid = if index > 0 {
        index as u64 <= total as u64
    } else if index < 0 {
        index.unsigned_abs() <= seen as u64
    } else {
        false
    };
    if valid {
        Ok(())
    } else {
        Err(format!(
            "{what} index {index} is out of range ({seen} defined so far, {total} in the file)"
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refuses_zero_and_out_of_range_indices_and_drops_lines() -> Result<(), String> {
        let good = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf -3/1 -2/-1 3\nl 1 2 3\np 1\nusemtl a b\n";
        let scan = scan_obj(good)?;
        assert_eq!(scan.skipped_lines_and_points, 2);
        assert!(!scan.text.contains("l 1 2 3"));
        assert_eq!(scan.used_materials, vec!["a b".to_string()]);
        for bad in [
            "v 0 0 0\nf 0 1 1",
            "v 0 0 0\nf -2 1 1",
            "v 0 0 0\nvt 0 0\nf 1/2 1 1",
            "f 1 2 3",
        ] {
            assert!(scan_obj(bad).is_err(), "{bad:?} was accepted");
        }
        Ok(())
    }
}
