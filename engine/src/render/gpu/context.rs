//! The wgpu device the GPU tracer and the presenter run on (render thread only).
//!
//! Owns: creating the instance, adapter and device — headless, or for a window's surface (the
//! adapter must be able to present to it) — with the adapter's own limits (wgpu's defaults are
//! lower than what lavapipe offers: 128 MiB per storage binding), and routing uncaptured wgpu
//! errors to the log instead of a panic, and noticing when the device is lost (a driver reset,
//! an unplugged or hung GPU: [`GpuContext::lost`]; [`GpuContext::destroy_device`] loses it on
//! purpose, for fault tests). Without a GPU, Mesa's lavapipe (software Vulkan) runs
//! the same WGSL on the CPU.
//! Must not: know scenes or shaders.

use std::sync::{Arc, Mutex};

use crate::render::tracer::RenderError;

/// A device and its queue.
pub struct GpuContext {
    pub adapter: wgpu::Adapter,
    pub device: wgpu::Device,
    pub queue: wgpu::Queue,
    pub info: wgpu::AdapterInfo,
    pub limits: wgpu::Limits,
    /// Why the device was lost, once wgpu has said so (its device-lost callback).
    lost: Arc<Mutex<Option<String>>>,
}

impl GpuContext {
    /// Opens the best adapter without any window or display. Honours `WGPU_BACKEND` and the
    /// other wgpu environment variables.
    pub fn headless() -> Result<Arc<Self>, RenderError> {
        let instance =
            wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
        Self::open(&instance, None)
    }

    /// The adapter [`GpuContext::headless`] would open, without opening a device (`None`: no
    /// adapter at all). For choosing a tracer.
    pub fn probe() -> Option<wgpu::AdapterInfo> {
        let instance =
            wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
        pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::HighPerformance,
            ..Default::default()
        }))
        .ok()
        .map(|adapter| adapter.get_info())
    }

    /// Opens the best adapter that can present to `surface`, made by `instance` (which must
    /// have been created with the window system's display handle).
    pub fn for_surface(
        instance: &wgpu::Instance,
        surface: &wgpu::Surface<'_>,
    ) -> Result<Arc<Self>, RenderError> {
        Self::open(instance, Some(surface))
    }

    fn open(
        instance: &wgpu::Instance,
        surface: Option<&wgpu::Surface<'_>>,
    ) -> Result<Arc<Self>, RenderError> {
        let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::HighPerformance,
            compatible_surface: surface,
            ..Default::default()
        }))
        .map_err(|_| RenderError::NoAdapter)?;
        let info = adapter.get_info();
        let limits = adapter.limits();
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("candela"),
            required_features: wgpu::Features::empty(),
            required_limits: limits.clone(),
            ..Default::default()
        }))
        .map_err(|e| RenderError::Device(e.to_string()))?;
        device.on_uncaptured_error(Arc::new(|error: wgpu::Error| {
            log::error!("wgpu: {error}");
        }));
        let lost = Arc::new(Mutex::new(None));
        let lost_in_callback = Arc::clone(&lost);
        device.set_device_lost_callback(move |reason, message| {
            let text = if message.is_empty() {
                format!("{reason:?}")
            } else {
                format!("{reason:?}: {message}")
            };
            if let Ok(mut lost) = lost_in_callback.lock() {
                lost.get_or_insert(text);
            }
        });
        log::info!(
            "GPU adapter: {} ({:?}, {:?}, driver {} {})",
            info.name,
            info.device_type,
            info.backend,
            info.driver,
            info.driver_info
        );
        Ok(Arc::new(Self {
            adapter,
            device,
            queue,
            info,
            limits,
            lost,
        }))
    }

    /// Why the device was lost, if it was (wgpu reports it from any later call that touches
    /// the device, a `poll` at the latest). Once lost, a device never comes back.
    pub fn lost(&self) -> Option<String> {
        self.lost.lock().ok().and_then(|lost| lost.clone())
    }

    /// `Err(RenderError::DeviceLost)` once the device is lost.
    pub fn check_alive(&self) -> Result<(), RenderError> {
        match self.lost() {
            Some(reason) => Err(RenderError::DeviceLost(reason)),
            None => Ok(()),
        }
    }

    /// Fault injection: destroys the device, which wgpu then treats exactly as a lost device
    /// (every later use fails, the device-lost callback runs). For tests of what the render
    /// thread does when the GPU goes away mid-run.
    pub fn destroy_device(&self) {
        self.device.destroy();
        // Let wgpu run the device-lost callback now rather than at the next use.
        let _ = self.device.poll(wgpu::PollType::Poll);
    }

    /// "name (type, backend)" for reports.
    pub fn describe(&self) -> String {
        format!(
            "{} ({:?}, {:?})",
            self.info.name, self.info.device_type, self.info.backend
        )
    }
}

/// Maps `buffer` (MAP_READ, its copy already submitted) for reading and waits until it is.
pub fn map_for_reading(device: &wgpu::Device, buffer: &wgpu::Buffer) -> Result<(), RenderError> {
    let (sender, receiver) = std::sync::mpsc::channel();
    buffer.map_async(wgpu::MapMode::Read, .., move |result| {
        let _ = sender.send(result);
    });
    device
        .poll(wgpu::PollType::Wait {
            submission_index: None,
            timeout: None,
        })
        .map_err(|e| RenderError::Device(e.to_string()))?;
    receiver
        .recv()
        .map_err(|e| RenderError::Device(e.to_string()))?
        .map_err(|e| RenderError::Device(e.to_string()))
}
