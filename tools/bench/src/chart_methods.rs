//! The curves `bench chart` measures: estimator settings, bounce caps and BVH builds, and which
//! panel of a scene's figure each one is drawn in.
//!
//! Owns: [`Method`] (one curve's settings), [`METHODS`] (the full set), [`Panel`], [`Layout`]
//! (the BLAS build variants) and [`Config`], the settings a render actually runs with, so that
//! two curves with the same effective settings (the default, and "max 7 bounces" on a 7-bounce
//! level) are measured once. Pure data. Must not: render or draw.

use candela::accel::{BlasParams, BuildQuality};
use candela::assets::RenderSettings;
use candela::layout::{METHOD_DEFAULT, METHOD_LIGHTS_BY_POWER, METHOD_MIS, METHOD_NEE};

/// The panels of one scene × tracer figure.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Panel {
    /// Estimators (BSDF sampling, NEE, MIS, light selection) and roulette settings.
    Estimators,
    /// The default estimator with every bounce cap from 1 to 8 (one past Mitsuba's `max_depth
    /// 8`, i.e. 7 bounces, of the external references).
    Bounces,
    /// The default estimator over each BLAS build ([`Layout`]).
    Layouts,
}

impl Panel {
    pub const ALL: [Panel; 3] = [Panel::Estimators, Panel::Bounces, Panel::Layouts];

    /// The name used on the command line (`--panels`) and in file names.
    pub fn key(self) -> &'static str {
        match self {
            Panel::Estimators => "estimators",
            Panel::Bounces => "bounces",
            Panel::Layouts => "layouts",
        }
    }

    /// The panel's title in charts and tables.
    pub fn title(self) -> &'static str {
        match self {
            Panel::Estimators => "estimators and roulette",
            Panel::Bounces => "max bounces (default estimator)",
            Panel::Layouts => "BVH build (default estimator)",
        }
    }
}

/// BLAS build variants. The traversal layout is the same for all (8-wide SoA nodes and
/// four-triangle blocks, `engine/src/accel/mod.rs`); the builds differ in tree quality and leaf
/// size, hence in traversal speed only: the images are the same.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Layout {
    /// The engine's default: binned SAH, leaves of up to four blocks.
    Default,
    /// obvhs PLOC, fastest preset (radius 1, no reinsertion), leaves of up to four blocks.
    PlocFastest,
    /// Binned SAH with one block (four triangles) per leaf: the layout before leaves grew.
    OneBlockPerLeaf,
}

impl Layout {
    pub const ALL: [Layout; 3] = [
        Layout::Default,
        Layout::PlocFastest,
        Layout::OneBlockPerLeaf,
    ];

    /// How the engine builds each BLAS for this variant.
    pub fn params(self) -> BlasParams {
        match self {
            Layout::Default => BlasParams::default(),
            Layout::PlocFastest => BlasParams {
                quality: BuildQuality::Fastest,
                ..BlasParams::default()
            },
            Layout::OneBlockPerLeaf => BlasParams {
                max_leaf_blocks: 1,
                ..BlasParams::default()
            },
        }
    }
}

/// One curve: an estimator configuration on one BLAS build.
#[derive(Clone, Copy, Debug)]
pub struct Method {
    pub name: &'static str,
    /// The panels it is drawn in.
    pub panels: &'static [Panel],
    /// `layout::METHOD_*` bits.
    pub method: u32,
    /// `None`: the level's max bounces.
    pub max_bounces: Option<u32>,
    /// `None`: the level's roulette start.
    pub roulette_start: Option<u32>,
    /// Multiplies the roulette survival probability (1 = the engine's).
    pub roulette_scale: f32,
    pub layout: Layout,
}

/// The default estimator at the level's settings on the default build: the name the readings
/// compare every other curve with.
pub const DEFAULT_NAME: &str = "NEE+MIS, lights by power (default)";

const fn estimator(name: &'static str, method: u32) -> Method {
    Method {
        name,
        panels: &[Panel::Estimators],
        method,
        max_bounces: None,
        roulette_start: None,
        roulette_scale: 1.0,
        layout: Layout::Default,
    }
}

const fn bounces(name: &'static str, max_bounces: u32) -> Method {
    Method {
        panels: &[Panel::Bounces],
        max_bounces: Some(max_bounces),
        ..estimator(name, METHOD_DEFAULT)
    }
}

const fn layout(name: &'static str, layout: Layout) -> Method {
    Method {
        panels: &[Panel::Layouts],
        layout,
        ..estimator(name, METHOD_DEFAULT)
    }
}

/// Every curve, in legend order per panel.
pub const METHODS: &[Method] = &[
    estimator("BSDF sampling only", 0),
    estimator("NEE, no MIS", METHOD_NEE),
    estimator("NEE+MIS, uniform lights", METHOD_NEE | METHOD_MIS),
    Method {
        panels: &[Panel::Estimators, Panel::Layouts],
        ..estimator(
            DEFAULT_NAME,
            METHOD_NEE | METHOD_MIS | METHOD_LIGHTS_BY_POWER,
        )
    },
    Method {
        roulette_start: Some(1),
        ..estimator("default, roulette from bounce 1", METHOD_DEFAULT)
    },
    Method {
        roulette_scale: 0.5,
        ..estimator("default, roulette scale 0.5", METHOD_DEFAULT)
    },
    bounces("max 1 bounce", 1),
    bounces("max 2 bounces", 2),
    bounces("max 3 bounces", 3),
    bounces("max 4 bounces", 4),
    bounces("max 5 bounces", 5),
    bounces("max 6 bounces", 6),
    bounces("max 7 bounces", 7),
    bounces("max 8 bounces", 8),
    layout("BVH: PLOC fastest", Layout::PlocFastest),
    layout("BVH: 1 block per leaf", Layout::OneBlockPerLeaf),
];

/// The settings a curve's renders run with on a level: equal configs give equal images and
/// equal timings (up to noise), so each is measured once.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Config {
    pub method: u32,
    pub max_bounces: u32,
    pub roulette_start: u32,
    /// `f32::to_bits` of the roulette scale.
    pub roulette_scale_bits: u32,
    pub layout: Layout,
}

impl Method {
    /// This curve's effective settings on a level whose render settings are `level`.
    pub fn config(&self, level: &RenderSettings) -> Config {
        Config {
            method: self.method,
            max_bounces: self.max_bounces.unwrap_or(level.max_bounces),
            roulette_start: self.roulette_start.unwrap_or(level.roulette_start),
            roulette_scale_bits: self.roulette_scale.to_bits(),
            layout: self.layout,
        }
    }

    /// Whether the curve is drawn in any of `panels`.
    pub fn in_any(&self, panels: &[Panel]) -> bool {
        self.panels.iter().any(|p| panels.contains(p))
    }
}

/// The methods drawn in `panel`, in legend order.
pub fn in_panel(panel: Panel) -> impl Iterator<Item = &'static Method> {
    METHODS.iter().filter(move |m| m.panels.contains(&panel))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bounce_panel_spans_one_to_eight() {
        let caps: Vec<u32> = in_panel(Panel::Bounces)
            .map(|m| m.max_bounces.unwrap_or(0))
            .collect();
        assert_eq!(caps, (1..=8).collect::<Vec<_>>());
        for m in in_panel(Panel::Bounces) {
            assert_eq!(m.method, METHOD_DEFAULT);
            assert_eq!((m.roulette_start, m.roulette_scale), (None, 1.0));
            assert_eq!(m.layout, Layout::Default);
        }
    }

    #[test]
    fn names_are_unique_and_csv_safe() {
        for (i, a) in METHODS.iter().enumerate() {
            assert!(!a.panels.is_empty(), "{} is in no panel", a.name);
            for b in &METHODS[i + 1..] {
                assert_ne!(a.name, b.name);
            }
        }
        assert!(METHODS.iter().any(|m| m.name == DEFAULT_NAME));
    }

    #[test]
    fn the_level_cap_curve_shares_the_default_config() {
        let level = RenderSettings {
            max_bounces: 7,
            roulette_start: 4,
            ..Default::default()
        };
        let default = METHODS
            .iter()
            .find(|m| m.name == DEFAULT_NAME)
            .map(|m| m.config(&level));
        let same: Vec<&str> = METHODS
            .iter()
            .filter(|m| Some(m.config(&level)) == default)
            .map(|m| m.name)
            .collect();
        assert_eq!(same, [DEFAULT_NAME, "max 7 bounces"]);
        // Every other curve has settings of its own.
        let unique: std::collections::HashSet<Config> =
            METHODS.iter().map(|m| m.config(&level)).collect();
        assert_eq!(unique.len(), METHODS.len() - 1);
    }

    #[test]
    fn the_layout_panel_compares_every_build_with_the_default() {
        let layouts: Vec<Layout> = in_panel(Panel::Layouts).map(|m| m.layout).collect();
        assert_eq!(layouts, Layout::ALL);
        assert_eq!(Layout::Default.params(), BlasParams::default());
        assert_eq!(Layout::OneBlockPerLeaf.params().max_leaf_blocks, 1);
        assert_eq!(Layout::PlocFastest.params().quality, BuildQuality::Fastest);
    }
}
