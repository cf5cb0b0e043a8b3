//! An X virtual framebuffer for window tests: start `Xvfb` on a free display, point this
//! process at it, and send a window the window manager's close request.
//!
//! Owns: the Xvfb child process (killed on drop) and the process environment of a window test
//! (`DISPLAY`, `XDG_RUNTIME_DIR`, `XDG_CACHE_HOME`, no Wayland). Must not: be used by tests that share their
//! process with other tests (winit allows one event loop per process; the environment is global).

use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::Duration;

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

/// Starts Xvfb (1280×720×24) on a display it picks itself (`-displayfd`: the server takes the
/// first free number atomically and reports it once it accepts connections, so window tests
/// running side by side never share a server).
pub fn start_xvfb() -> Xvfb {
    use std::io::{BufRead, BufReader};
    let spawned = Command::new("Xvfb")
        .args([
            "-displayfd",
            "1",
            "-screen",
            "0",
            "1280x720x24",
            "-nolisten",
            "tcp",
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn();
    let mut child = match spawned {
        Ok(child) => child,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            panic!("Xvfb is not installed: `cargo xtask test` installs it (Debian package xvfb)")
        }
        Err(e) => panic!("cannot start Xvfb: {e}"),
    };
    let stdout = child.stdout.take().expect("Xvfb's stdout is piped");
    let (sender, receiver) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let mut line = String::new();
        let _ = BufReader::new(stdout).read_line(&mut line);
        let _ = sender.send(line);
    });
    match receiver.recv_timeout(Duration::from_secs(30)) {
        Ok(line) if line.trim().parse::<u32>().is_ok() => Xvfb {
            child,
            display: format!(":{}", line.trim()),
        },
        other => {
            let _ = child.kill();
            let _ = child.wait();
            panic!("Xvfb did not report a display within 30 s: {other:?}");
        }
    }
}

/// Points this process at `display`, with a private runtime folder and cache folder (the
/// editor's thumbnails) under `scratch`.
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
        std::env::set_var("XDG_CACHE_HOME", scratch.join("cache"));
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
