//! Helpers shared by the cross-crate tests: where the external test data lives.

use std::path::PathBuf;

/// `../shared/external` beside the repository (test data made by others; never copied in).
pub fn external() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../shared/external")
}

/// The repository root.
pub fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}
