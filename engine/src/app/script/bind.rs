//! Binding a checked [`Script`] to a loaded level: every motion's instance name (or `prefix*`)
//! becomes the list of level instances it moves, every light switch's group is checked to exist,
//! time-of-day keys need a physical sky with a time.
//!
//! Owns: [`BoundScript`] and the errors for names the level lacks (unknown instance, a pattern
//! that matches nothing, a static instance asked to move, an unused light group). Also loading
//! the level a script names. Main thread. Must not: run anything.

use std::collections::HashSet;
use std::path::{Path, PathBuf};

use super::desc::{Script, ScriptError};
use crate::assets::{AssetRoot, SceneDesc};
use crate::level::{PlayableLevel, load_level};

/// Level instances (indices into `SceneDesc::instances`, level order) of each motion entry.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BoundScript {
    pub motion_targets: Vec<Vec<usize>>,
}

/// Whether `name` is matched by `pattern` (an exact name, or a prefix ending in `*`).
pub fn matches(pattern: &str, name: &str) -> bool {
    match pattern.strip_suffix('*') {
        Some(prefix) => name.starts_with(prefix),
        None => name == pattern,
    }
}

impl Script {
    /// Checks every name against `desc` and lists the instances each motion moves.
    pub fn bind(&self, desc: &SceneDesc) -> Result<BoundScript, ScriptError> {
        let mut motion_targets = Vec::with_capacity(self.motions.len());
        for (i, entry) in self.motions.iter().enumerate() {
            let item = format!("motions[{i}]");
            let targets: Vec<usize> = desc
                .instances
                .iter()
                .enumerate()
                .filter(|(_, inst)| {
                    inst.name
                        .as_deref()
                        .is_some_and(|n| matches(&entry.instance, n))
                })
                .map(|(k, _)| k)
                .collect();
            if targets.is_empty() {
                return Err(ScriptError::UnknownInstance {
                    path: self.source.clone(),
                    item,
                    name: entry.instance.clone(),
                });
            }
            if let Some(&k) = targets.iter().find(|&&k| !desc.instances[k].dynamic) {
                return Err(ScriptError::StaticInstance {
                    path: self.source.clone(),
                    item,
                    name: desc.instances[k].name.clone().unwrap_or_default(),
                });
            }
            motion_targets.push(targets);
        }
        let groups: HashSet<u32> = desc
            .instances
            .iter()
            .filter_map(|i| i.light_group)
            .collect();
        for (i, s) in self.lights.iter().enumerate() {
            if !groups.contains(&s.group) {
                return Err(ScriptError::UnknownLightGroup {
                    path: self.source.clone(),
                    item: format!("lights[{i}]"),
                    group: s.group,
                });
            }
        }
        let timed = matches!(&desc.sky, crate::assets::SkyDesc::Physical(p) if p.time.is_some());
        if !self.times.is_empty() && !timed {
            return Err(ScriptError::Invalid {
                path: self.source.clone(),
                item: "times[0]".into(),
                message: "the level's sky must be Physical with a `time` to set the time of day"
                    .into(),
            });
        }
        Ok(BoundScript { motion_targets })
    }

    /// The folder relative paths of the script start from.
    fn folder(&self) -> PathBuf {
        self.source
            .parent()
            .filter(|p| !p.as_os_str().is_empty())
            .map(Path::to_path_buf)
            .unwrap_or_else(|| PathBuf::from("."))
    }

    /// Loads the level the script names (paths relative to the script's folder; the asset
    /// root defaults to the level's folder).
    pub fn load_level(&self) -> Result<PlayableLevel, ScriptError> {
        let Some(level) = &self.level else {
            return Err(ScriptError::NoLevel {
                path: self.source.clone(),
            });
        };
        let level_path = self.folder().join(&level.path);
        let root_dir = match &level.asset_root {
            Some(r) => self.folder().join(r),
            None => level_path
                .parent()
                .map(Path::to_path_buf)
                .unwrap_or_else(|| PathBuf::from(".")),
        };
        let wrap = |source| ScriptError::Level {
            path: self.source.clone(),
            source,
        };
        let root = AssetRoot::new(&root_dir).map_err(wrap)?;
        load_level(&level_path, &root).map_err(wrap)
    }
}
