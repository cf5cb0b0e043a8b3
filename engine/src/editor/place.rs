//! Placing new pieces: the palette's contents ([`Palette`]: the model files of the level's
//! asset folder, found once by [`model_files`], and the piece last chosen) and the one command
//! that places a piece at a point ([`place_edit`]: a new instance, plus a `models` entry when
//! the piece is a file the level does not list yet).
//!
//! Positions are world space, metres (right-handed, Y up). Main thread. Must not: touch the
//! world or pick (the runner finds the point: where the pick ray hits, else in front of the
//! camera; `app::edit::place`).

use std::path::Path;

use glam::Vec3;

use crate::assets::{InstanceEntry, Level, ModelEntry, TransformDesc};

use super::command::{Edit, ListEdit};
use super::comments::Anchored;
use super::snap::Snap;

/// Most folders deep [`model_files`] looks below the level's folder.
const MAX_DEPTH: usize = 4;
/// Most files [`model_files`] lists (a palette is for choosing, not for browsing a disk).
const MAX_FILES: usize = 500;

/// One piece the palette offers.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PaletteItem {
    /// A model the level names already (a model file, grid, box, terrain or city).
    Model(String),
    /// A model file, by its path relative to the asset root, that the level does not list.
    File(String),
}

/// What the palette offers beyond the level's own models, and the piece last chosen (which P
/// places under the pointer).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Palette {
    /// Model files (`.glb`, `.gltf`, `.obj`) of the level's asset folder, relative to the
    /// asset root with `/` separators, sorted.
    pub files: Vec<String>,
    pub current: Option<PaletteItem>,
}

/// The names every model of `level` can be placed by: model files, then grids, boxes, terrains
/// and cities (the model namespace, in the order the level lists them).
pub fn model_names(level: &Level) -> Vec<&str> {
    (level.models.iter().map(|m| m.name.as_str()))
        .chain(level.grids.iter().map(|g| g.name.as_str()))
        .chain(level.boxes.iter().map(|b| b.name.as_str()))
        .chain(level.terrains.iter().map(|t| t.name.as_str()))
        .chain(level.cities.iter().map(|c| c.name.as_str()))
        .collect()
}

/// The model files under `folder` (at most [`MAX_DEPTH`] folders down, [`MAX_FILES`] files),
/// as paths relative to `root` with `/` separators, sorted; files outside `root` and unreadable
/// folders are skipped.
pub fn model_files(root: &Path, folder: &Path) -> Vec<String> {
    let mut out = Vec::new();
    let mut stack = vec![(folder.to_path_buf(), 0)];
    while let Some((dir, depth)) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&dir) else {
            continue;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            if path.is_dir() {
                if depth < MAX_DEPTH {
                    stack.push((path, depth + 1));
                }
                continue;
            }
            let model = path.extension().and_then(|e| e.to_str()).is_some_and(|e| {
                ["glb", "gltf", "obj"]
                    .iter()
                    .any(|m| e.eq_ignore_ascii_case(m))
            });
            if model
                && out.len() < MAX_FILES
                && let Ok(relative) = path.strip_prefix(root)
            {
                let parts: Vec<String> = relative
                    .components()
                    .map(|c| c.as_os_str().to_string_lossy().into_owned())
                    .collect();
                out.push(parts.join("/"));
            }
        }
    }
    out.sort();
    out
}

/// The command that places `item` in `level` at `at` (the new instance's origin, snapped to the
/// grid when grid snapping is on): the instance goes at the end of the instance list, and a
/// file the level does not list yet is added to `models` under a name of its own (its file
/// stem, made unique) in the same command, so one undo takes both away.
pub fn place_edit(level: &Level, item: &PaletteItem, at: Vec3, snap: &Snap) -> Edit {
    let mut edits = Vec::new();
    let model = match item {
        PaletteItem::Model(name) => name.clone(),
        PaletteItem::File(path) => match level.models.iter().find(|m| &m.path == path) {
            Some(m) => m.name.clone(),
            None => {
                let name = fresh_model_name(level, path);
                edits.push(Edit::List(ListEdit::InsertModel {
                    index: level.models.len(),
                    entry: ModelEntry {
                        name: name.clone(),
                        path: path.clone(),
                    },
                }));
                name
            }
        },
    };
    let transform = Snap {
        grid: snap.grid,
        ..Snap::default()
    }
    .transform(TransformDesc {
        translation: at.to_array(),
        ..TransformDesc::default()
    });
    edits.push(Edit::InsertInstance {
        index: level.instances.len(),
        entry: Box::new(InstanceEntry {
            model,
            name: None,
            transform,
            material: None,
            dynamic: false,
            light_group: None,
            waves: None,
            body: None,
        }),
        comments: Anchored::default(),
    });
    Edit::Batch(edits)
}

/// The file stem of `path` (`kit/crate.glb` → `crate`), or `stem_2`, `stem_3`, … when a model
/// of `level` has that name.
fn fresh_model_name(level: &Level, path: &str) -> String {
    let stem = Path::new(path)
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "model".into());
    let names = model_names(level);
    std::iter::once(stem.clone())
        .chain((2u32..).map(|k| format!("{stem}_{k}")))
        .find(|n| !names.contains(&n.as_str()))
        .unwrap_or(stem)
}
