//! Tests that change process-wide state (a resource limit, a signal disposition, environment
//! variables, winit's one event loop per process) must run alone in their process. nextest
//! runs every test in a process of its own; plain `cargo test` runs a binary's tests as threads
//! of one process. [`alone_in_process`] makes such a test safe under both: under a runner that
//! shares processes it runs the test again in a child process of the same test binary,
//! filtered to that one test, and checks that exactly that test ran and passed.
//!
//! Test-only (shared by `candela_tests` and, by `#[path]`, the engine's test binary). Must
//! not: change any state itself.

use std::process::Command;

/// Set in the child this starts, so the child runs the test body.
const CHILD: &str = "CANDELA_TEST_ALONE";

/// Whether the calling test (`test`: its name as the test binary lists it, e.g.
/// `"editor_full_disk::saving_onto_a_full_disk_reports_it_and_keeps_the_old_level"`) runs alone
/// in its process and should go on. If not, it is run in a child process here, this panics if
/// the child did not run exactly that test or the test failed, and `false` is returned: the
/// caller returns at once.
pub fn alone_in_process(test: &str) -> bool {
    if std::env::var_os("NEXTEST").is_some() || std::env::var_os(CHILD).is_some() {
        return true;
    }
    let exe = std::env::current_exe().expect("the test binary's path");
    let output = Command::new(exe)
        .args([test, "--exact", "--nocapture", "--test-threads=1"])
        .env(CHILD, "1")
        .output()
        .expect("the test binary runs again");
    let stdout = String::from_utf8_lossy(&output.stdout);
    let stderr = String::from_utf8_lossy(&output.stderr);
    print!("{stdout}");
    eprint!("{stderr}");
    assert!(
        output.status.success(),
        "{test} failed in its own process ({})",
        output.status
    );
    assert!(
        stdout.contains("1 passed"),
        "the child process did not run {test} (no test of that exact name?)"
    );
    false
}
