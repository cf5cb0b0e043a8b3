//! The window runner's per-run state ([`Running`]: the window, the engine, the overlay, the
//! limiter, stats, mouse capture) and the window changes it makes: capturing the mouse, and
//! following what the shell wants (capture, fullscreen, vsync, frame limiter).
//!
//! Main thread. Must not: run frames (`app.rs` does) or render.

use std::sync::Arc;
use std::time::Instant;

use winit::window::{CursorGrabMode, Fullscreen, Window};

use super::stats_overlay::StatsOverlay;
use crate::app::input::Gamepads;
use crate::app::runner::Engine;
use crate::app::runner::FrameLimiter;
use crate::app::runner::FrameStats;
use crate::app::shell::WindowWants;

pub(super) struct Running {
    pub(super) window: Arc<Window>,
    pub(super) engine: Engine,
    pub(super) overlay: StatsOverlay,
    /// The gamepads, polled once per frame into the engine's input.
    pub(super) gamepads: Gamepads,
    pub(super) limiter: FrameLimiter,
    pub(super) stats: FrameStats,
    pub(super) last_frame: Instant,
    pub(super) captured: bool,
    pub(super) vsync: bool,
    pub(super) frames: u64,
    /// After the last frame: close at this time.
    pub(super) hold_until: Option<Instant>,
    /// What the shell wanted last frame (changes are carried out once).
    pub(super) wants: Option<WindowWants>,
}

impl Running {
    pub(super) fn set_captured(&mut self, captured: bool) {
        if captured == self.captured {
            return;
        }
        if captured {
            let grabbed = self
                .window
                .set_cursor_grab(CursorGrabMode::Locked)
                .or_else(|_| self.window.set_cursor_grab(CursorGrabMode::Confined));
            if let Err(e) = grabbed {
                log::warn!("cannot capture the mouse: {e}");
                return;
            }
        } else if let Err(e) = self.window.set_cursor_grab(CursorGrabMode::None) {
            log::warn!("cannot release the mouse: {e}");
        }
        self.window.set_cursor_visible(!captured);
        self.captured = captured;
    }

    /// Makes the window what the shell wants, changing only what changed since last frame.
    pub(super) fn follow(&mut self, wants: WindowWants) {
        let before = self.wants.take();
        let changed =
            |f: fn(&WindowWants) -> bool| before.as_ref().is_none_or(|b| f(b) != f(&wants));
        if changed(|w| w.captured) {
            self.set_captured(wants.captured);
        }
        if changed(|w| w.fullscreen) && self.window.fullscreen().is_some() != wants.fullscreen {
            self.window
                .set_fullscreen(wants.fullscreen.then_some(Fullscreen::Borderless(None)));
        }
        if before.as_ref().is_none_or(|b| b.max_fps != wants.max_fps) {
            self.limiter = FrameLimiter::new(wants.max_fps);
        }
        self.vsync = wants.vsync;
        self.wants = Some(wants);
    }
}
