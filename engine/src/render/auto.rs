//! The `auto` tracer choice: the GPU tracer on a real GPU, the CPU tracer when the only adapter
//! is a software one (Mesa's lavapipe/llvmpipe, SwiftShader, WARP) or there is none. On the
//! project's 2-core machines lavapipe runs the WGSL on the CPU about 45× slower than the CPU
//! tracer (98 s against ~2 s for the README's 64-spp Cornell box), so a software adapter is
//! never worth it.
//!
//! Owns: [`resolve`] and the one log line saying which tracer was picked and why. Render
//! thread (when it opens its tracer) or a tool's main thread. Must not: open a device.

use super::gpu::GpuContext;
use super::thread::TracerChoice;

/// Why `auto` picked the tracer it picked.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct AutoPick {
    /// [`TracerChoice::Gpu`] or [`TracerChoice::Cpu`], never `Auto`.
    pub choice: TracerChoice,
    /// One sentence for the log and the stats overlay.
    pub reason: String,
}

/// Whether an adapter of this type runs on the CPU.
pub fn is_software(device_type: wgpu::DeviceType) -> bool {
    device_type == wgpu::DeviceType::Cpu
}

/// What `auto` means given the adapter wgpu would use (`None`: no adapter at all).
pub fn pick(adapter: Option<&wgpu::AdapterInfo>) -> AutoPick {
    match adapter {
        None => AutoPick {
            choice: TracerChoice::Cpu,
            reason: "tracer auto: cpu (no GPU adapter)".into(),
        },
        Some(info) if is_software(info.device_type) => AutoPick {
            choice: TracerChoice::Cpu,
            reason: format!(
                "tracer auto: cpu (the only GPU adapter, {}, is software: it runs the WGSL on \
                 the CPU, much slower than the CPU tracer; --tracer gpu forces it)",
                info.name
            ),
        },
        Some(info) => AutoPick {
            choice: TracerChoice::Gpu,
            reason: format!("tracer auto: gpu ({}, {:?})", info.name, info.device_type),
        },
    }
}

/// Resolves `choice`: `Auto` becomes GPU or CPU by the adapter `context` has (a window's) or,
/// headless, by the adapter wgpu would pick; logs the reason once. Other choices stay.
pub fn resolve(choice: TracerChoice, context: Option<&GpuContext>) -> TracerChoice {
    if choice != TracerChoice::Auto {
        return choice;
    }
    let picked = match context {
        Some(context) => pick(Some(&context.info)),
        None => pick(GpuContext::probe().as_ref()),
    };
    log::info!("{}", picked.reason);
    picked.choice
}

#[cfg(test)]
mod tests {
    use super::*;

    fn info(name: &str, device_type: wgpu::DeviceType) -> wgpu::AdapterInfo {
        wgpu::AdapterInfo {
            name: name.into(),
            ..wgpu::AdapterInfo::new(device_type, wgpu::Backend::Vulkan)
        }
    }

    #[test]
    fn software_adapters_and_none_pick_the_cpu_tracer() {
        assert_eq!(pick(None).choice, TracerChoice::Cpu);
        let lavapipe = pick(Some(&info(
            "llvmpipe (LLVM 15.0.6, 256 bits)",
            wgpu::DeviceType::Cpu,
        )));
        assert_eq!(lavapipe.choice, TracerChoice::Cpu);
        assert!(lavapipe.reason.contains("llvmpipe"), "{}", lavapipe.reason);
        for real in [
            wgpu::DeviceType::DiscreteGpu,
            wgpu::DeviceType::IntegratedGpu,
            wgpu::DeviceType::VirtualGpu,
        ] {
            assert_eq!(
                pick(Some(&info("gpu", real))).choice,
                TracerChoice::Gpu,
                "{real:?}"
            );
        }
    }

    #[test]
    fn explicit_choices_are_kept() {
        assert_eq!(resolve(TracerChoice::Cpu, None), TracerChoice::Cpu);
        assert_eq!(resolve(TracerChoice::Gpu, None), TracerChoice::Gpu);
        assert_ne!(resolve(TracerChoice::Auto, None), TracerChoice::Auto);
    }
}
