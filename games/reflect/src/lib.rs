//! Reflect: the first-person mirror-and-laser puzzle game (design: `../shared/games/REFLECT.md`),
//! a thin crate over the engine's game API (`candela::app::Game`, the first-person player, the
//! shell). Its chambers are level files under `assets/reflect/levels/` merged into one world;
//! its art and sounds are made by `tools/assetgen`.
//!
//! Modules: `chambers` (the game file), `world` (loading the world), `game` (the rules),
//! `mirror_gun`, `hazard` (lasers that send the player back), `replays`, `harness` (Reflect as
//! the engine's game harness runs it), `headless`, `bench`, `soak`, `capture` (what Reflect
//! reads of and asks of the harness's modes), `cli`, `bot` (the scripted player that records
//! the committed replays).
//! Main thread throughout. Must not: reach into the renderer.

pub mod bench;
pub mod bench_editor;
pub mod bot;
pub mod bot_tasks;
pub mod capture;
pub mod chambers;
pub mod cli;
pub mod game;
pub mod harness;
pub mod hazard;
pub mod headless;
pub mod mirror_gun;
pub mod replays;
pub mod soak;
pub mod world;
