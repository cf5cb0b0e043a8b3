//! Cross-crate tests (layout twins, accuracy against references, GPU against CPU,
//! windows under Xvfb, the committed assets), linked into one test binary (`cross`):
//! each file is a module (nextest: `-E 'test(/^accuracy::/)'`), the shared helpers are
//! the `candela_tests` library in `../support`. nextest runs every test in its own
//! process, so tests that start Xvfb or set environment variables still start clean.
//!
//! A new cross-crate test goes in a new file here, declared below in alphabetical order.

mod accuracy;
mod analytic;
mod beams;
mod beams_upscaled;
mod bvh;
mod capture_budget;
mod clouds;
mod demo;
mod editor_session;
mod editor_window;
mod far_from_origin;
mod first_hit_guides;
mod furnace;
mod gpu_matches_cpu;
mod headless;
mod hero;
mod hero_skin;
mod interleave;
mod layout;
mod many_lights;
mod mips;
mod present;
mod reflect_kit;
mod reflect_record;
mod reflect_window;
mod ruins_kit;
mod shell_screens;
mod single_pick;
mod sounds;
mod stability;
mod watertight;
mod window;
mod window_close;
