//! The scenes of `bench chart`: which levels, at which image sizes, against which reference.
//!
//! Owns: [`SCENES`] (two external reference scenes with Mitsuba 3 references, and test scenes
//! of the repo measured against the engine's own converged image), loading a scene's level and
//! building it once per BLAS build. Must not: render, measure or draw.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use candela::assets::{AssetRoot, SceneDesc, load_scene};
use candela::scene::RenderScene;

use super::chart_methods::Layout;

/// Where a scene's reference image comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RefKind {
    /// Mitsuba 3 (`<external>/reference/<name>/reference.exr` and its standard-error image):
    /// error is bias plus variance against an independent renderer.
    Mitsuba,
    /// The engine's own CPU render at a high sample count (`chart_self_ref.rs`): error is
    /// convergence to the engine's own answer, not bias against an independent renderer.
    SelfConverged,
}

/// One scene of the chart.
#[derive(Clone, Copy, Debug)]
pub struct SceneSpec {
    /// Label in charts, tables, the CSV and `--scenes`.
    pub name: &'static str,
    /// Level file, relative to the repository root.
    pub level: &'static str,
    /// Asset root: under `--external` for the reference scenes, else relative to the repository.
    pub root: Root,
    pub reference: RefKind,
    /// Image edge of the CPU curves (pixels); self-references are rendered at this size.
    pub cpu_size: u32,
    /// Image edge of the GPU curves (lavapipe is slow): the reference is box-averaged to it.
    pub gpu_size: u32,
}

/// A scene's asset root.
#[derive(Clone, Copy, Debug)]
pub enum Root {
    /// A folder under `--external` (`shared/external`).
    External(&'static str),
    /// A folder of the repository.
    Repo(&'static str),
}

pub const SCENES: &[SceneSpec] = &[
    SceneSpec {
        name: "cornell_box",
        level: "assets/test_scenes/reference/cornell_box.ron",
        root: Root::External("reference/cornell_box"),
        reference: RefKind::Mitsuba,
        cpu_size: 256,
        gpu_size: 64,
    },
    SceneSpec {
        name: "cornell_mirror_glass",
        level: "assets/test_scenes/reference/cornell_mirror_glass.ron",
        root: Root::External("reference/cornell_mirror_glass"),
        reference: RefKind::Mitsuba,
        cpu_size: 256,
        gpu_size: 64,
    },
    // The README's level: Candela's own Cornell box (diffuse, one area light).
    SceneSpec {
        name: "candela_cornell",
        level: "assets/test_scenes/cornell_box.ron",
        root: Root::Repo("assets/test_scenes"),
        reference: RefKind::SelfConverged,
        cpu_size: 128,
        gpu_size: 64,
    },
    // The capture-script level: sun, gradient sky, two lamps, a glass pool, 3 bounces.
    SceneSpec {
        name: "script_small",
        level: "assets/test_scenes/script/small.ron",
        root: Root::Repo("assets/test_scenes/script"),
        reference: RefKind::SelfConverged,
        cpu_size: 128,
        gpu_size: 64,
    },
];

impl SceneSpec {
    /// Loads the scene's level.
    pub fn load(&self, external: &Path) -> anyhow::Result<SceneDesc> {
        let root = match self.root {
            Root::External(dir) => external.join(dir),
            Root::Repo(dir) => PathBuf::from(dir),
        };
        Ok(load_scene(Path::new(self.level), &AssetRoot::new(&root)?)?)
    }

    /// The folder holding Mitsuba's `reference.exr` and `reference_stderr.exr`, if it has one.
    pub fn mitsuba_dir(&self, external: &Path) -> Option<PathBuf> {
        (self.reference == RefKind::Mitsuba).then(|| external.join("reference").join(self.name))
    }
}

/// The scenes named in `names` (all when empty), in [`SCENES`] order; an unknown name is an
/// error that lists the known ones.
pub fn select(names: &[String]) -> anyhow::Result<Vec<&'static SceneSpec>> {
    for n in names {
        if !SCENES.iter().any(|s| s.name == n) {
            let known: Vec<&str> = SCENES.iter().map(|s| s.name).collect();
            anyhow::bail!("unknown scene {n:?}; known: {}", known.join(", "));
        }
    }
    Ok(SCENES
        .iter()
        .filter(|s| names.is_empty() || names.iter().any(|n| n == s.name))
        .collect())
}

/// `desc` built once per BLAS build in `layouts`.
pub fn build_layouts(desc: &SceneDesc, layouts: &[Layout]) -> HashMap<Layout, RenderScene> {
    layouts
        .iter()
        .map(|&l| (l, RenderScene::build_with_blas_params(desc, l.params())))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn selecting_scenes_keeps_order_and_rejects_unknown_names() {
        assert_eq!(select(&[]).map(|s| s.len()).ok(), Some(SCENES.len()));
        let picked = select(&["script_small".into(), "cornell_box".into()]).ok();
        let names: Option<Vec<&str>> = picked.map(|v| v.iter().map(|s| s.name).collect());
        assert_eq!(names, Some(vec!["cornell_box", "script_small"]));
        let err = select(&["nope".into()]).err().map(|e| e.to_string());
        assert!(err.is_some_and(|e| e.contains("candela_cornell")));
    }

    #[test]
    fn the_test_scenes_load_and_reference_sizes_divide() -> anyhow::Result<()> {
        // Tests run in tools/bench: levels are relative to the repository root.
        let repo = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        for spec in SCENES {
            assert_eq!(spec.cpu_size % spec.gpu_size, 0, "{}", spec.name);
            if let Root::Repo(dir) = spec.root {
                let root = AssetRoot::new(repo.join(dir))?;
                let desc = load_scene(&repo.join(spec.level), &root)?;
                let scene = RenderScene::build(&desc);
                assert!(!scene.triangles.is_empty(), "{}", spec.name);
            }
        }
        Ok(())
    }
}
