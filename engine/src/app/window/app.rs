//! The window runner's per-run work (winit 0.30; the `ApplicationHandler` is in
//! `events.rs`): open the window and the engine, run one engine frame per redraw (game frame hook → overlay → present request → `Engine::frame` →
//! collect render results), react to the runner's own actions, and end cleanly: the render
//! thread is joined before the event loop exits, whether the window closed, Ctrl-C set the
//! stop flag, the frame count was reached or a render failed.
//!
//! With the shell (`run_game`) each frame also goes through [`ShellRun`]: before the overlay
//! (menus' transitions, settings), its screens inside the overlay, after it, and after the
//! engine frame; the window follows what it wants (`running.rs`), key and mouse presses
//! reach it for rebinding, losing focus pauses, and cue screenshots are saved.
//!
//! Owns: the per-run state (`Running`, in `running.rs`). Main thread.
//! Must not: render, or block on anything but the hand-off and, at the end, the last results.

use std::sync::Arc;
use std::time::{Duration, Instant};

use winit::event_loop::ActiveEventLoop;
use winit::window::{Fullscreen, Window};

use super::config::{WindowConfig, WindowEnd, WindowError, WindowReport};
use super::running::Running;
use super::stats_overlay::StatsOverlay;
use crate::app::edit::EditMode;
use crate::app::input::Gamepads;
use crate::app::input::{Binding, InputState, actions};
use crate::app::runner::FrameLimiter;
use crate::app::runner::FrameStats;
use crate::app::runner::Game;
use crate::app::runner::{Engine, Environment};
use crate::app::shell::{ShellConfig, ShellRun};
use crate::commit::PresentRequest;
use crate::render::present::PresentTarget;
use crate::render::{RenderConfig, RenderError, Rendered, TracerChoice};

pub(super) struct WindowApp<'g> {
    pub(super) config: WindowConfig,
    pub(super) render: RenderConfig,
    pub(super) environment: Option<Environment>,
    pub(super) game: &'g mut dyn Game,
    pub(super) running: Option<Running>,
    pub(super) started: Instant,
    pub(super) error: Option<WindowError>,
    pub(super) report: Option<WindowReport>,
    pub(super) screenshot: Option<std::path::PathBuf>,
    pub(super) shell_config: Option<ShellConfig>,
    pub(super) shell: Option<ShellRun>,
    /// Screenshots the shell's cues asked for: (frame, where to write it).
    pub(super) shots: Vec<(u64, std::path::PathBuf)>,
    /// The editor (F1), opened the first time it is asked for (`edit.rs`).
    pub(super) edit: Option<EditMode>,
    /// Without the shell: F1 was pressed (the editor toggles at the next frame).
    pub(super) edit_toggle: bool,
    /// Without the shell: the editor is wanted on.
    pub(super) editing: bool,
    /// The game has no level to edit, or it did not open (asked once).
    pub(super) edit_unavailable: bool,
}

impl<'g> WindowApp<'g> {
    pub(super) fn new(
        config: WindowConfig,
        render: RenderConfig,
        environment: Environment,
        game: &'g mut dyn Game,
        shell_config: Option<ShellConfig>,
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
            shell_config,
            shell: None,
            shots: Vec::new(),
            edit: None,
            edit_toggle: false,
            editing: false,
            edit_unavailable: false,
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

    pub(super) fn start(&mut self, event_loop: &ActiveEventLoop) -> Result<Running, WindowError> {
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
        if let Some(shell) = self.shell_config.take() {
            self.shell = Some(ShellRun::new(
                shell,
                &mut engine,
                &mut *self.game,
                self.config.input.clone(),
            ));
        }
        let stats = FrameStats {
            tracer: match render.tracer {
                TracerChoice::Auto => "auto".into(),
                TracerChoice::Gpu => "gpu (wgpu)".into(),
                TracerChoice::Cpu => format!("cpu ({} threads)", rayon::current_num_threads()),
                TracerChoice::Pool(spec) => format!(
                    "pool ({}{} cpu × {} threads, {:?})",
                    if spec.gpu { "gpu + " } else { "" },
                    spec.cpu_tracers,
                    spec.cpu_threads,
                    spec.scheme
                ),
            },
            ..Default::default()
        };
        Ok(Running {
            overlay: StatsOverlay::new(&window, self.config.show_stats),
            gamepads: Gamepads::new(),
            window,
            engine,
            limiter: FrameLimiter::new(self.config.max_fps),
            stats,
            last_frame: Instant::now(),
            captured: false,
            vsync: self.config.vsync,
            frames: 0,
            hold_until: None,
            wants: None,
        })
    }

    /// Counts a render result; saves the screenshot it carries. A render error ends the run.
    pub(super) fn take(&mut self, result: Result<Rendered, RenderError>) {
        match result {
            Ok(rendered) => {
                if let Some(running) = self.running.as_mut() {
                    running.stats.observe_rendered(&rendered);
                }
                let cue = self.shots.iter().position(|(f, _)| *f == rendered.frame);
                let cue = cue.map(|i| self.shots.remove(i).1);
                if let Some(shot) = &rendered.screenshot {
                    match (cue, &self.config.screenshot) {
                        (Some(path), _) => match shot.save_png(&path) {
                            Ok(()) => log::info!("wrote {}", path.display()),
                            Err(e) => self.fail(e.into()),
                        },
                        (None, Some(path)) => match shot.save_png(path) {
                            Ok(()) => self.screenshot = Some(path.clone()),
                            Err(e) => self.fail(e.into()),
                        },
                        (None, None) => {}
                    }
                }
            }
            Err(e) => self.fail(e.into()),
        }
    }

    pub(super) fn fail(&mut self, error: WindowError) {
        log::error!("{error}");
        if self.error.is_none() {
            self.error = Some(error);
        }
    }

    /// Releases the mouse, joins the render thread (taking its last results) and leaves.
    pub(super) fn end(&mut self, event_loop: &ActiveEventLoop, ended_by: WindowEnd) {
        if let Some(shell) = self.shell.as_mut() {
            shell.finish();
        }
        if let Some(mut running) = self.running.take() {
            running.set_captured(false);
            let inner_position = running.window.inner_position().ok().map(|p| (p.x, p.y));
            let size = running.window.inner_size();
            let frames = running.frames;
            let mut stats = std::mem::take(&mut running.stats);
            // A recording (`--record`) holds every fixed step so far: write it before leaving.
            if let Err(e) = running.engine.finish_recording() {
                self.fail(WindowError::Recording(e));
            }
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
        if input.pressed_this_frame(actions::TOGGLE_PROFILER) {
            let shown = running.overlay.profiler.visible();
            running.overlay.profiler.set_visible(!shown);
        }
        if self.shell.is_some() {
            // Vsync, fullscreen and the mouse follow the shell (`Running::follow`).
            return;
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
        if self.edit.as_ref().is_some_and(EditMode::active) {
            // The editor has the mouse; Escape does not leave.
            return;
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
    pub(super) fn redraw(&mut self, event_loop: &ActiveEventLoop) {
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
        let pad_presses = running.gamepads.poll(running.engine.input_mut());
        if let Some(shell) = self.shell.as_mut() {
            for button in pad_presses {
                shell.pressed(Binding::Pad(button));
            }
        }
        self.runner_actions(event_loop);
        let Some(running) = self.running.as_mut() else {
            return;
        };
        if let Some(shell) = self.shell.as_mut() {
            shell.before_frame(&mut running.engine, &mut *self.game);
            let wants = shell.wants();
            if wants.exit {
                self.end(event_loop, WindowEnd::Quit);
                return;
            }
            running.follow(wants);
        }
        self.follow_edit_mode();
        let Some(running) = self.running.as_mut() else {
            return;
        };
        let editing = self.edit.as_ref().is_some_and(EditMode::active);
        let edit = &mut self.edit;
        let mut edit_frame = crate::app::edit::EditFrame::default();
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
        let game = &mut *self.game;
        let built = match self.shell.as_mut() {
            Some(shell) => {
                shell.set_workload(stats.workload_summary());
                let playing = shell.screen() == crate::app::shell::Screen::Playing;
                let overlay = overlay.build(
                    window,
                    stats,
                    Some(&mut |ctx| {
                        if playing && game.has_ui() {
                            game.ui(ctx);
                        }
                        shell.ui(ctx);
                        if editing && let Some(edit) = edit.as_mut() {
                            edit_frame = edit.ui(ctx, engine);
                        }
                    }),
                );
                shell.after_ui(engine, game);
                overlay
            }
            None if game.has_ui() || editing => overlay.build(
                window,
                stats,
                Some(&mut |ctx| {
                    if game.has_ui() && !editing {
                        game.ui(ctx);
                    }
                    if editing && let Some(edit) = edit.as_mut() {
                        edit_frame = edit.ui(ctx, engine);
                    }
                }),
            ),
            None => overlay.build(window, stats, None),
        };
        if edit_frame.respawned
            && let Some(edit) = self.edit.as_ref()
            && let Some(hooks) = game.editor()
        {
            hooks.level_respawned(engine, edit.world.spawned());
        }
        let shot = self.shell.as_mut().and_then(ShellRun::take_screenshot);
        if let Some(path) = shot.clone() {
            self.shots.push((engine.frames(), path));
        }
        let tonemap = self.config.tonemap_now(engine);
        engine.present_next(PresentRequest {
            surface_size: (size.width, size.height),
            tonemap,
            vsync: running.vsync,
            overlay: built,
            screenshot: shot.is_some() || (last && self.config.screenshot.is_some()),
            scaling: self.shell.as_ref().map(ShellRun::scaling_goal),
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
        if let Some(shell) = self.shell.as_mut() {
            shell.after_frame(&mut running.engine, &report);
        }
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
