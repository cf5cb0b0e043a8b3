//! An X virtual framebuffer for window tests: start `Xvfb` on a free display, point this
//! process at it, and send a window the window manager's close request.
//!
//! Owns: the Xvfb child process (killed on drop) and the process environment of a window test
//! (`DISPLAY`, `XDG_RUNTIME_DIR`, no Wayland). Must not: be used by tests that share their
//! process with other tests (winit allows one event loop per process; the environment is global).

use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// An Xvfb server, killed when dropped.
pub struct Xvfb {
    child: Child,
    /// The display name, e.g. `:93`.
    pub display: String,
}

impl Drop for Xvfb {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Starts Xvfb (1280×720×24) on the first free display in :90..:190.
pub fn start_xvfb() -> Xvfb {
    for n in 90..190 {
        if Path::new(&format!("/tmp/.X11-unix/X{n}")).exists()
            || Path::new(&format!("/tmp/.X{n}-lock")).exists()
        {
            continue;
        }
        let display = format!(":{n}");
        let spawned = Command::new("Xvfb")
            .args([&display, "-screen", "0", "1280x720x24", "-nolisten", "tcp"])
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn();
        let mut child = match spawned {
            Ok(child) => child,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => panic!(
                "Xvfb is not installed: `cargo xtask test` installs it (Debian package xvfb)"
            ),
            Err(e) => panic!("cannot start Xvfb: {e}"),
        };
        let started = Instant::now();
        while started.elapsed() < Duration::from_secs(10) {
            if Path::new(&format!("/tmp/.X11-unix/X{n}")).exists() {
                return Xvfb { child, display };
            }
            if let Ok(Some(_)) = child.try_wait() {
                break; // the display was taken meanwhile: try the next one
            }
            std::thread::sleep(Duration::from_millis(50));
        }
        let _ = child.kill();
        let _ = child.wait();
    }
    panic!("no free X display number in :90..:190");
}

/// Points this process at `display`, with a private runtime folder under `scratch`.
pub fn set_environment(display: &str, scratch: &Path) {
    let runtime = scratch.join("xdg");
    std::fs::create_dir_all(&runtime).expect("runtime dir");
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(&runtime, std::fs::Permissions::from_mode(0o700))
            .expect("runtime dir mode");
    }
    // SAFETY: this test binary holds only this test; no other thread reads the environment yet.
    unsafe {
        std::env::set_var("DISPLAY", display);
        std::env::remove_var("WAYLAND_DISPLAY");
        std::env::set_var("XDG_RUNTIME_DIR", &runtime);
        if std::env::var_os("WGPU_BACKEND").is_none() {
            std::env::set_var("WGPU_BACKEND", "vulkan");
        }
    }
}

/// Asks every top-level window on `display` to close, as a window manager's close button does
/// (a `WM_PROTOCOLS` / `WM_DELETE_WINDOW` client message). Returns how many windows were asked.
pub fn close_windows(display: &str) -> Result<usize, Box<dyn std::error::Error>> {
    use x11rb::connection::Connection;
    use x11rb::protocol::xproto::{ClientMessageEvent, ConnectionExt, EventMask};
    let (conn, screen) = x11rb::connect(Some(display))?;
    let root = conn.setup().roots[screen].root;
    let protocols = conn.intern_atom(false, b"WM_PROTOCOLS")?.reply()?.atom;
    let delete = conn.intern_atom(false, b"WM_DELETE_WINDOW")?.reply()?.atom;
    let children = conn.query_tree(root)?.reply()?.children;
    for &window in &children {
        let event = ClientMessageEvent::new(32, window, protocols, [delete, 0, 0, 0, 0]);
        conn.send_event(false, window, EventMask::NO_EVENT, event)?;
    }
    conn.flush()?;
    Ok(children.len())
}
