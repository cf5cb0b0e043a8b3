//! The engine's integration tests, linked into one test binary (`engine`) so that
//! the workspace links one executable instead of seventy: each file is a module named
//! `<subsystem>_<topic>` (nextest: `-E 'test(/^editor_/)'` runs the editor's), and the
//! `*_common` folders hold the helpers that several of them share. nextest runs every
//! test in its own process, so a test that sets environment variables or process-wide
//! state still starts clean.
//!
//! A new engine test goes in a new file here, declared below in alphabetical order.

mod app_common;
mod balance_common;
mod common;
mod denoise_common;
mod editor_common;
mod physics_common;
mod pipeline_common;

mod accel_structure;
mod anim_bad_input;
mod anim_engine;
mod anim_player;
mod anim_reference;
mod anim_robustness;
mod anim_skin;
mod anim_state_machine;
mod app_bindings;
mod app_full_disk;
mod app_game_api;
mod app_monkey;
mod app_replay;
mod app_replay_engine;
mod app_replay_format;
mod app_saves;
mod app_settings;
mod app_shell_run;
mod app_shell_states;
mod assets_bad_input;
mod assets_gltf;
mod assets_obj;
mod assets_robustness;
mod assets_tga;
mod audio_decode;
mod audio_device;
mod audio_mix;
mod audio_pause;
mod audio_spatial;
mod balance_parts;
mod balance_pool;
mod balance_pool_tracer;
mod balance_schemes;
mod balance_simulate;
mod blas_params_scene;
mod denoise_gpu_matches_cpu;
mod denoise_kernels;
mod denoise_quality;
mod denoise_reproject;
mod denoise_robustness;
mod editor_full_disk;
mod editor_kill;
mod editor_mode;
mod editor_mode_box;
mod editor_pick;
mod editor_problem_select;
mod editor_recovery;
mod editor_save;
mod editor_ui;
mod editor_undo;
mod editor_world;
mod faults_asset_root;
mod faults_audio_device;
mod faults_gpu_lost;
mod faults_resource_limits;
mod gameplay_bad_input;
mod gameplay_laser_beams;
mod gameplay_plate_door;
mod gameplay_rules;
mod ghosting;
mod level_bad_input;
mod level_character;
mod level_validate;
mod physics_character;
mod physics_determinism;
mod physics_engine;
mod physics_interaction;
mod physics_level;
mod physics_ride;
mod physics_stability;
mod pipeline;
mod pipeline_denoise;
mod player_bad_input;
mod player_first_person;
mod player_third_person;
mod present_requests;
mod refit_degradation;
mod scene_light_tree;
mod script_determinism;
mod script_format;
mod sky_energy;
mod sky_ephemeris;
mod sky_gpu_fallback;
mod sky_level;
mod sky_reference;
mod structure_layers;
mod trace_agreement;
mod upkeep_camera_motion;
mod upkeep_equivalence;
mod work_report;
