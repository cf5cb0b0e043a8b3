//! System packages the engine needs on Debian/Ubuntu, and installing the missing ones.
//!
//! Owns: the package lists and the apt call. Installs only when running as root; otherwise
//! prints the exact command and fails. On systems without `dpkg` it says what is needed and
//! goes on (the build will tell what is missing).

use std::process::Command;

/// What rendering needs: the Vulkan loader and Mesa's software Vulkan driver (lavapipe), so
/// that wgpu finds an adapter on a machine with no GPU; and, to build the engine at all, ALSA's
/// headers (kira's cpal backend links `libasound`; `alsa-sys` finds it with pkg-config) and
/// udev's (gilrs reads gamepads through `libudev`; `libudev-sys` finds it with pkg-config).
pub const RENDER: &[&str] = &[
    "libvulkan1",
    "mesa-vulkan-drivers",
    "pkg-config",
    "libasound2-dev",
    "libudev-dev",
];

/// Everything the tests need: rendering, a C toolchain and pkg-config for -sys crates, ALSA's
/// headers for kira's cpal backend (the audio tests themselves use the silent recorder), udev's
/// headers for gilrs (the gamepad tests run without a gamepad), and for
/// the window test an X virtual framebuffer (`Xvfb`), `xwd` to grab its root window and
/// ImageMagick to decode the grab.
pub const ALL: &[&str] = &[
    "libvulkan1",
    "mesa-vulkan-drivers",
    "build-essential",
    "pkg-config",
    "libasound2-dev",
    "libudev-dev",
    "xvfb",
    "x11-apps",
    "imagemagick",
];

fn installed(package: &str) -> bool {
    Command::new("dpkg-query")
        .args(["-W", "-f=${Status}", package])
        .output()
        .map(|o| {
            o.status.success()
                && String::from_utf8_lossy(&o.stdout).contains("install ok installed")
        })
        .unwrap_or(false)
}

fn is_root() -> bool {
    Command::new("id")
        .arg("-u")
        .output()
        .map(|o| String::from_utf8_lossy(&o.stdout).trim() == "0")
        .unwrap_or(false)
}

/// Makes sure `packages` are installed; returns the ones that were missing.
pub fn ensure(packages: &[&str]) -> Result<Vec<String>, String> {
    if Command::new("dpkg-query")
        .arg("--version")
        .output()
        .is_err()
    {
        eprintln!(
            "xtask: no dpkg here; make sure these (Debian names) are installed: {}",
            packages.join(" ")
        );
        return Ok(Vec::new());
    }
    let missing: Vec<String> = packages
        .iter()
        .filter(|p| !installed(p))
        .map(|p| p.to_string())
        .collect();
    if missing.is_empty() {
        return Ok(missing);
    }
    let apt = format!(
        "apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends {}",
        missing.join(" ")
    );
    if !is_root() {
        return Err(format!(
            "missing system packages: {}. Run as root:\n    sudo sh -c '{apt}'",
            missing.join(" ")
        ));
    }
    eprintln!("xtask: installing {}", missing.join(" "));
    let status = Command::new("sh")
        .args(["-c", &apt])
        .status()
        .map_err(|e| format!("cannot run apt-get: {e}"))?;
    if !status.success() {
        return Err(format!("`{apt}` failed with {status}"));
    }
    Ok(missing)
}
