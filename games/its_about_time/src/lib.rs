//! It's About Time: the third-person puzzle game across a day in Aztec ruins (design:
//! `../shared/games/ITS_ABOUT_TIME.md`, Brigade paper §6.2), a thin crate over the engine's
//! game API (`candela::app::Game`, the engine's third-person game, the shell). Its world is
//! one level file, `assets/its_about_time/ruins.ron`; its art is made by `tools/assetgen`.
//!
//! Modules: `world` (loading the ruins), `game` (the rules: artifacts, the sun altar that
//! turns time, the ending), `replays`, `harness` (the game as the engine's harness runs it),
//! `headless` (a replay's summary), `camera_areas` (the render areas along its camera path), `bot` (the scripted explorer that records the committed
//! replays) and `routes` (its ways through the ruins), `bench` (`--bench`), `cli`.
//! Main thread throughout. Must not: reach into the renderer.

pub mod bench;
pub mod bot;
pub mod camera_areas;
pub mod cli;
pub mod game;
pub mod harness;
pub mod headless;
pub mod replays;
pub mod routes;
pub mod world;
