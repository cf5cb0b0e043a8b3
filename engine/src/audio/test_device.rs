//! [`TestDevice`]: a stand-in sound card for fault tests. It opens like a device (or refuses
//! to, as a machine without a sound card does), mixes like one (the frames due each tick are
//! mixed and thrown away, as a device's thread would play them), and can be unplugged
//! mid-run, after which it reports its loss the way kira's cpal backend reports a device that
//! went away.
//!
//! Owns: the shared switch between the test and the backend. Any thread (the switch is
//! atomic). Must not: record what it mixes (the silent recorder does that).

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

/// A sound device a test controls; clones share one device.
#[derive(Clone, Debug, Default)]
pub struct TestDevice {
    state: Arc<State>,
}

#[derive(Debug, Default)]
struct State {
    /// Never there: opening it fails.
    absent: AtomicBool,
    /// Pulled out: opening fails, and an open one reports its loss.
    unplugged: AtomicBool,
}

impl TestDevice {
    /// A device that is there (until [`TestDevice::unplug`]).
    pub fn new() -> Self {
        Self::default()
    }

    /// A machine without a sound card: opening the device fails.
    pub fn absent() -> Self {
        let device = Self::default();
        device.state.absent.store(true, Ordering::SeqCst);
        device
    }

    /// Pulls the device out: the open one reports its loss on the next tick, and it cannot be
    /// opened again.
    pub fn unplug(&self) {
        self.state.unplugged.store(true, Ordering::SeqCst);
    }

    /// Why it cannot be opened now, if it cannot.
    pub(super) fn refusal(&self) -> Option<&'static str> {
        if self.state.absent.load(Ordering::SeqCst) {
            Some("no sound device (test device absent)")
        } else if self.is_unplugged() {
            Some("no sound device (test device unplugged)")
        } else {
            None
        }
    }

    pub(super) fn is_unplugged(&self) -> bool {
        self.state.unplugged.load(Ordering::SeqCst)
    }
}
