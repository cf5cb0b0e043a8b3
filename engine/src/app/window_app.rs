//! The window runner's event handling (winit 0.30 `ApplicationHandler`): open the window and
//! the engine on `resumed`, turn window and device events into [`InputState`] changes, run one
//! engine frame per redraw (game frame hook → overlay → present request → `Engine::frame` →
//! collect render results), react to the runner's own actions, and end cleanly: the render
//! thread is joined before the event loop exits, whether the window closed, Ctrl-C set the
//! stop flag, the frame count was reached or a render failed.
//!
//! Owns: the per-run state (window, engine, input, overlay, limiter, stats). Main thread.
//! Must not: render, or block on anything but the hand-off and, at the end, the last results.

use std::sync::Arc;
use std::sync::atomic::Ordering;
use std::time::{Duration, Instant};

use winit::application::ApplicationHandler;
use winit::event::{DeviceEvent, DeviceId, MouseScrollDelta, WindowEvent};
use winit::event_loop::ActiveEventLoop;
use winit::keyboard::PhysicalKey;
use winit::window::{CursorGrabMode, Fullscreen, Window, WindowId};

use super::engine::{Engine, Environment};
use super::frame_limiter::FrameLimiter;
use super::game::Game;
use super::input::{InputState, actions};
use super::stats::FrameStats;
use super::stats_overlay::StatsOverlay;
use super::window::{WindowConfig, WindowEnd, WindowError, WindowReport};
use crate::commit::PresentRequest;
use crate::render::present::PresentTarget;
use crate::render::{RenderConfig, RenderError, Rendered, TracerChoice};

/// Pixels of a touchpad scroll that count as one wheel line.
const PIXELS_PER_LINE: f64 = 40.0;

struct Running {
    window: Arc<Window>,
    engine: Engine,
    overlay: StatsOverlay,
    limiter: FrameLimiter,
    stats: FrameStats,
    last_frame: Instant,
    captured: bool,
    vsync: bool,
    frames: u64,
    /// After the last frame: close at this time.
    hold_until: Option<Instant>,
}

impl Running {
    fn set_captured(&mut self, captured: bool) {
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
}

pub(super) struct WindowApp<'g> {
    config: WindowConfig,
    render: RenderConfig,
    environment: Option<Environment>,
    game: &'g mut dyn Game,
    running: Option<Running>,
    started: Instant,
    error: Option<WindowError>,
    report: Option<WindowReport>,
    screenshot: Option<std::path::PathBuf>,
}

impl<'g> WindowApp<'g> {
    pub(super) fn new(
        config: WindowConfig,
        render: RenderConfig,
        environment: Environment,
        game: &'g mut dyn Game,
    ) -> Self {
        Self {
            config,
            render,
            environment: Some(environment),
            game,
            running: None,
            started: Instant::now(),
            error: None,
            report: None,
            screenshot: None,
        }
    }

    pub(super) fn into_outcome(self) -> Result<WindowReport, WindowError> {
        match (self.error, self.report) {
            (Some(e), _) => Err(e),
            (None, Some(report)) => Ok(report),
            (None, None) => Err(WindowError::Window(
                "the event loop ended before the window opened".into(),
            )),
        }
    }

    fn start(&mut self, event_loop: &ActiveEventLoop) -> Result<Running, WindowError> {
        let (width, height) = self.config.size;
        let mut attributes = Window::default_attributes()
            .with_title(self.config.title.clone())
            .with_inner_size(winit::dpi::PhysicalSize::new(width.max(1), height.max(1)));
        if self.config.fullscreen {
            attributes = attributes.with_fullscreen(Some(Fullscreen::Borderless(None)));
        }
        let window = Arc::new(
            event_loop
                .create_window(attributes)
                .map_err(|e| WindowError::Window(format!("cannot open a window: {e}")))?,
        );
        let size = window.inner_size();
        let mut render = self.render;
        render.width = size.width.max(1);
        render.height = size.height.max(1);
        let target = PresentTarget {
            window: Arc::clone(&window),
            display: event_loop.owned_display_handle(),
        };
        let environment = self
            .environment
            .take()
            .ok_or_else(|| WindowError::Window("the window was opened twice".into()))?;
        let mut engine = Engine::new_windowed(render, environment, target)?;
        *engine.input_mut() = InputState::new(&self.config.input);
        self.game.setup(&mut engine).map_err(WindowError::Game)?;
        let stats = FrameStats {
            tracer: match render.tracer {
                TracerChoice::Auto => "auto".into(),
                TracerChoice::Gpu => "gpu (wgpu)".into(),
                TracerChoice::Cpu => format!("cpu ({} threads)", rayon::current_num_threads()),
            },
            ..Default::default()
        };
        Ok(Running {
            overlay: StatsOverlay::new(&window, self.config.show_stats),
            window,
            engine,
            limiter: FrameLimiter::new(self.config.max_fps),
            stats,
            last_frame: Instant::now(),
            captured: false,
            vsync: self.config.vsync,
            frames: 0,
            hold_until: None,
        })
    }

    /// Counts a render result; saves the screenshot it carries. A render error ends the run.
    fn take(&mut self, result: Result<Rendered, RenderError>) {
        match result {
            Ok(rendered) => {
                if let Some(running) = self.running.as_mut() {
                    running.stats.observe_rendered(&rendered);
                }
                if let (Some(shot), Some(path)) = (&rendered.screenshot, &self.config.screenshot) {
                    match shot.save_png(path) {
                        Ok(()) => self.screenshot = Some(path.clone()),
                        Err(e) => self.fail(e.into()),
                    }
                }
            }
            Err(e) => self.fail(e.into()),
        }
    }

    fn fail(&mut self, error: WindowError) {
        log::error!("{error}");
        if self.error.is_none() {
            self.error = Some(error);
        }
    }

    /// Releases the mouse, joins the render thread (taking its last results) and leaves.
    fn end(&mut self, event_loop: &ActiveEventLoop, ended_by: WindowEnd) {
        if let Some(mut running) = self.running.take() {
            running.set_captured(false);
            let inner_position = running.window.inner_position().ok().map(|p| (p.x, p.y));
            let size = running.window.inner_size();
            let frames = running.frames;
            let mut stats = std::mem::take(&mut running.stats);
            let results = running.engine.shutdown();
            for result in results {
                if let Ok(rendered) = &result {
                    stats.observe_rendered(rendered);
                }
                self.take(result);
            }
            self.report = Some(WindowReport {
                frames,
                seconds: self.started.elapsed().as_secs_f64(),
                ended_by,
                screenshot: self.screenshot.clone(),
                inner_position,
                inner_size: (size.width, size.height),
                stats,
            });
        }
        event_loop.exit();
    }

    /// The runner's own actions: overlay, fullscreen, vsync, mouse capture, leaving.
    fn runner_actions(&mut self, event_loop: &ActiveEventLoop) {
        let Some(running) = self.running.as_mut() else {
            return;
        };
        let input = running.engine.input();
        if input.pressed_this_frame(actions::TOGGLE_STATS) {
            running.overlay.visible = !running.overlay.visible;
        }
        if input.pressed_this_frame(actions::TOGGLE_VSYNC) {
            running.vsync = !running.vsync;
            log::info!("vsync {}", if running.vsync { "on" } else { "off" });
        }
        if input.pressed_this_frame(actions::TOGGLE_FULLSCREEN) {
            let next = match running.window.fullscreen() {
                Some(_) => None,
                None => Some(Fullscreen::Borderless(None)),
            };
            running.window.set_fullscreen(next);
        }
        let capture = input.pressed_this_frame(actions::CAPTURE_MOUSE);
        let release = input.pressed_this_frame(actions::RELEASE_MOUSE);
        if capture && !running.captured && !running.overlay.wants_pointer() {
            running.set_captured(true);
        } else if release {
            if running.captured {
                running.set_captured(false);
            } else {
                self.end(event_loop, WindowEnd::Closed);
            }
        }
    }

    /// One frame: hooks, overlay, present request, `Engine::frame`, results.
    fn redraw(&mut self, event_loop: &ActiveEventLoop) {
        let Some(running) = self.running.as_mut() else {
            return;
        };
        if let Some(until) = running.hold_until {
            if Instant::now() >= until {
                self.end(event_loop, WindowEnd::Frames);
            } else {
                std::thread::sleep(Duration::from_millis(10));
            }
            return;
        }
        let now = Instant::now();
        let frame_seconds = (now - running.last_frame).as_secs_f64();
        running.last_frame = now;
        self.runner_actions(event_loop);
        let Some(running) = self.running.as_mut() else {
            return;
        };
        let Running {
            window,
            engine,
            overlay,
            stats,
            ..
        } = running;
        let size = window.inner_size();
        stats.output_size = (size.width, size.height);
        let last = self.config.frames.is_some_and(|n| running.frames + 1 >= n);
        engine.present_next(PresentRequest {
            surface_size: (size.width, size.height),
            tonemap: self.config.tonemap,
            vsync: running.vsync,
            overlay: if self.game.has_ui() {
                let game = &mut *self.game;
                overlay.build(window, stats, Some(&mut |ctx| game.ui(ctx)))
            } else {
                overlay.build(window, stats, None)
            },
            screenshot: last && self.config.screenshot.is_some(),
        });
        let frame = engine.frame(frame_seconds, &mut *self.game);
        let report = match frame {
            Ok(report) => report,
            Err(e) => {
                // The render thread stopped: its error is among the results.
                let pending = running.engine.rendered();
                self.fail(e.into());
                pending.into_iter().for_each(|r| self.take(r));
                self.end(event_loop, WindowEnd::Closed);
                return;
            }
        };
        running.stats.observe_frame(&report, frame_seconds);
        running.frames += 1;
        let mut results = running.engine.rendered();
        if last {
            // Wait for the last frame (and its screenshot) before holding or leaving.
            while !results
                .iter()
                .any(|r| r.as_ref().map_or(true, |r| r.frame == report.frame))
            {
                match running.engine.wait_rendered() {
                    Some(result) => results.push(result),
                    None => break,
                }
            }
        }
        let hold = self.config.hold_seconds;
        let limiter_wait = !last;
        if let Some(running) = self.running.as_mut() {
            if last && hold > 0.0 {
                running.hold_until = Some(Instant::now() + Duration::from_secs_f64(hold));
            }
            if limiter_wait {
                running.limiter.wait();
            }
        }
        results.into_iter().for_each(|r| self.take(r));
        if self.error.is_some() || (last && hold <= 0.0) {
            let ended_by = if self.error.is_some() {
                WindowEnd::Closed
            } else {
                WindowEnd::Frames
            };
            self.end(event_loop, ended_by);
        }
    }
}

impl ApplicationHandler for WindowApp<'_> {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.running.is_some() || self.report.is_some() || self.error.is_some() {
            return;
        }
        match self.start(event_loop) {
            Ok(running) => {
                running.window.request_redraw();
                self.running = Some(running);
            }
            Err(e) => {
                self.fail(e);
                event_loop.exit();
            }
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _: WindowId, event: WindowEvent) {
        let Some(running) = self.running.as_mut() else {
            return;
        };
        let egui_used =
            running
                .overlay
                .on_window_event(&running.window, &event, self.game.has_ui());
        match event {
            WindowEvent::CloseRequested => self.end(event_loop, WindowEnd::Closed),
            WindowEvent::Focused(false) => {
                running.engine.input_mut().release_all();
                running.set_captured(false);
            }
            WindowEvent::KeyboardInput { event, .. } => {
                // Releases always count (a press egui took was never seen as held).
                if let PhysicalKey::Code(code) = event.physical_key
                    && (!egui_used || !event.state.is_pressed())
                {
                    running
                        .engine
                        .input_mut()
                        .key(code, event.state.is_pressed());
                }
            }
            WindowEvent::MouseInput { state, button, .. } => {
                if !egui_used || !state.is_pressed() {
                    running
                        .engine
                        .input_mut()
                        .mouse_button(button, state.is_pressed());
                }
            }
            WindowEvent::MouseWheel { delta, .. } if !egui_used => {
                let lines = match delta {
                    MouseScrollDelta::LineDelta(_, y) => y as f64,
                    MouseScrollDelta::PixelDelta(p) => p.y / PIXELS_PER_LINE,
                };
                running.engine.input_mut().wheel(lines as f32);
            }
            WindowEvent::RedrawRequested => self.redraw(event_loop),
            _ => {}
        }
    }

    fn device_event(&mut self, _: &ActiveEventLoop, _: DeviceId, event: DeviceEvent) {
        if let (Some(running), DeviceEvent::MouseMotion { delta }) = (self.running.as_mut(), event)
            && running.captured
        {
            running
                .engine
                .input_mut()
                .mouse_motion(delta.0 as f32, delta.1 as f32);
        }
    }

    fn about_to_wait(&mut self, event_loop: &ActiveEventLoop) {
        if self.config.stop.load(Ordering::Relaxed) {
            self.end(event_loop, WindowEnd::Stopped);
        } else if let Some(running) = &self.running {
            running.window.request_redraw();
        }
    }

    fn exiting(&mut self, event_loop: &ActiveEventLoop) {
        if self.running.is_some() {
            self.end(event_loop, WindowEnd::Closed);
        }
    }
}
