//! The asset root: the one folder a level and everything it references must stay inside.
//!
//! Owns: turning a path written in a level or a model (relative, `/`-separated) into a real
//! path, refusing any that leaves the root (`..` past the root, absolute paths, symlinks out).
//! Must not: read file contents.

use std::path::{Component, Path, PathBuf};

use super::error::{AssetError, AssetResult};

/// A folder that confines every path resolved through it.
#[derive(Clone, Debug)]
pub struct AssetRoot {
    root: PathBuf,
}

impl AssetRoot {
    /// Opens `root`, which must be an existing directory.
    pub fn new(root: impl AsRef<Path>) -> AssetResult<Self> {
        let given = root.as_ref();
        let root = given
            .canonicalize()
            .map_err(|source| AssetError::io(given, source))?;
        Ok(Self { root })
    }

    /// The root folder (canonical).
    pub fn path(&self) -> &Path {
        &self.root
    }

    /// Resolves `requested` (relative to `base`, a folder inside the root, or to the root when
    /// `base` is `None`) and checks that the result stays inside the root. `referrer` is the
    /// file that names the path, for the error message. The target must exist.
    pub fn resolve(
        &self,
        referrer: &Path,
        base: Option<&Path>,
        requested: &str,
    ) -> AssetResult<PathBuf> {
        let outside = || AssetError::OutsideRoot {
            path: referrer.to_path_buf(),
            requested: requested.to_string(),
            root: self.root.clone(),
        };
        let requested_path = Path::new(requested);
        let start = base.unwrap_or(&self.root);
        // Lexical check first, so that a path which leaves the root is refused even when the
        // file it names does not exist.
        let Some(lexical) = lexical_join(start, &self.root, requested_path) else {
            return Err(outside());
        };
        // Then the real check, which also catches symbolic links that point out of the root.
        let real = lexical
            .canonicalize()
            .map_err(|source| AssetError::io(&lexical, source))?;
        if !real.starts_with(&self.root) {
            return Err(outside());
        }
        Ok(real)
    }
}

/// `start` joined with `requested` by components alone (`.` skipped, `..` removes one; no file
/// system access), or `None` when the result leaves `root` or `requested` is absolute. The
/// disk root ([`AssetRoot::resolve`]) and in-memory loads (`context`) both confine paths
/// with it.
pub(crate) fn lexical_join(start: &Path, root: &Path, requested: &Path) -> Option<PathBuf> {
    if requested.is_absolute() || requested.has_root() {
        return None;
    }
    let mut lexical = start.to_path_buf();
    for component in requested.components() {
        match component {
            Component::Normal(part) => lexical.push(part),
            Component::CurDir => {}
            Component::ParentDir => {
                if !lexical.pop() {
                    return None;
                }
            }
            Component::RootDir | Component::Prefix(_) => return None,
        }
    }
    lexical.starts_with(root).then_some(lexical)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refuses_paths_that_leave_the_root() -> Result<(), Box<dyn std::error::Error>> {
        let dir = std::env::temp_dir().join(format!("candela_root_{}", std::process::id()));
        std::fs::create_dir_all(dir.join("inner"))?;
        std::fs::write(dir.join("inner/a.obj"), "")?;
        let root = AssetRoot::new(dir.join("inner"))?;
        let referrer = Path::new("level.ron");
        assert!(root.resolve(referrer, None, "a.obj").is_ok());
        assert!(root.resolve(referrer, None, "./x/../a.obj").is_ok()); // lexical: x need not exist
        for bad in [
            "../a.obj",
            "../../etc/passwd",
            "/etc/passwd",
            "x/../../a.obj",
        ] {
            match root.resolve(referrer, None, bad) {
                Err(AssetError::OutsideRoot { requested, .. }) => assert_eq!(requested, bad),
                other => panic!("{bad}: expected OutsideRoot, got {other:?}"),
            }
        }
        std::fs::remove_dir_all(&dir)?;
        Ok(())
    }
}
