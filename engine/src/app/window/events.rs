//! The window runner's winit `ApplicationHandler`: opening the window on `resumed`, window
//! and device events turned into [`InputState`](crate::app::input::InputState) changes (and, under
//! the shell, presses for rebinding, focus lost and recapturing clicks), a redraw per frame,
//! the stop flag, and ending cleanly on `exiting`.
//!
//! Main thread. Must not: run the frame itself (`WindowApp::redraw` does).

use std::sync::atomic::Ordering;

use winit::application::ApplicationHandler;
use winit::event::{DeviceEvent, DeviceId, MouseScrollDelta, WindowEvent};
use winit::event_loop::ActiveEventLoop;
use winit::keyboard::PhysicalKey;
use winit::window::WindowId;

use super::app::WindowApp;
use super::config::WindowEnd;
use super::running::Running;
use crate::app::input::Binding;
use crate::app::shell::ShellRun;

/// Pixels of a touchpad scroll that count as one wheel line.
const PIXELS_PER_LINE: f64 = 40.0;

/// What the shell hears of a window event: every key and mouse press (rebinding), focus lost
/// (pause), and a click in the playing window while the mouse is free (recapture).
fn forward_to_shell(
    shell: &mut ShellRun,
    running: &mut Running,
    event: &WindowEvent,
    egui_used: bool,
) {
    match event {
        WindowEvent::KeyboardInput { event, .. } if event.state.is_pressed() && !event.repeat => {
            if let PhysicalKey::Code(code) = event.physical_key {
                shell.pressed(Binding::Key(code));
            }
        }
        WindowEvent::MouseInput { state, button, .. } if state.is_pressed() => {
            shell.pressed(Binding::Mouse(*button));
            let playing = shell.screen() == crate::app::shell::Screen::Playing;
            if playing && !running.captured && !egui_used {
                running.set_captured(true);
            }
        }
        WindowEvent::Focused(false) => shell.push(crate::app::shell::ShellInput::FocusLost),
        _ => {}
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
        let editing = self.editing || self.edit.as_ref().is_some_and(|e| e.active());
        let egui_used = running.overlay.on_window_event(
            &running.window,
            &event,
            self.game.has_ui() || self.shell.is_some() || editing,
        );
        if self.shell.is_none()
            && let WindowEvent::KeyboardInput { event: key, .. } = &event
            && key.state.is_pressed()
            && !key.repeat
            && key.physical_key == PhysicalKey::Code(winit::keyboard::KeyCode::F1)
        {
            self.edit_toggle = true;
        }
        if let Some(shell) = self.shell.as_mut() {
            forward_to_shell(shell, running, &event, egui_used);
        }
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
            WindowEvent::MouseInput { state, button, .. } if !egui_used || !state.is_pressed() => {
                running
                    .engine
                    .input_mut()
                    .mouse_button(button, state.is_pressed());
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
