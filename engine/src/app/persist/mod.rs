//! What the game keeps in the player's folders: the folders themselves ([`UserDirs`]), RON
//! files loaded with a warning and the bad file kept aside, saved atomically ([`load_or_default`],
//! [`save_ron`]), the player's settings ([`Settings`]) with their rebinding of actions
//! ([`Bindings`]), and progress saves ([`Progress`]). Atomic writes themselves live in
//! `crate::assets::atomic_file` (the editor, below `app`, saves levels with them too); `app`
//! re-exports them.
//!
//! One file per job: `user_dirs`, `stored` (load, check, keep aside, save), `bindings`,
//! `settings`, `saves`. Main thread. Must not: apply settings (the runner and the shell do),
//! read devices, or know the engine or a game.

mod bindings;
mod saves;
mod settings;
mod stored;
mod user_dirs;

pub use bindings::{BindingProblem, Bindings, BindingsError};
pub use saves::Progress;
pub use settings::Settings;
pub use stored::{LoadWarning, Loaded, StoreError, load_or_default, parse_checked, save_ron};
pub use user_dirs::{UserDirs, UserDirsError};
