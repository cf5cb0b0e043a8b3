//! The shader registry: WGSL has no `#include`, so passes are composed here from the shared
//! pieces in `shaders/shared/` (in dependency order) and the pass file.
//!
//! Owns: the list of WGSL sources (compiled into the binary with `include_str!`) and their
//! composition. Must not: create pipelines.

/// A named WGSL source.
#[derive(Clone, Copy, Debug)]
pub struct ShaderSource {
    pub name: &'static str,
    pub text: &'static str,
}

macro_rules! shader {
    ($path:literal) => {
        ShaderSource {
            name: $path,
            text: include_str!(concat!("../../../../shaders/", $path)),
        }
    };
}

/// The shared pieces, in the order they must appear.
pub const SHARED: &[ShaderSource] = &[
    shader!("shared/types.wgsl"),
    shader!("shared/bindings.wgsl"),
    shader!("shared/rng.wgsl"),
    shader!("shared/sampling.wgsl"),
    shader!("shared/light_tree.wgsl"),
    shader!("shared/microfacet.wgsl"),
    shader!("shared/bsdf.wgsl"),
    shader!("shared/texture.wgsl"),
    shader!("shared/traverse.wgsl"),
    shader!("shared/surface.wgsl"),
    shader!("shared/lines.wgsl"),
    shader!("shared/sky_view.wgsl"),
    shader!("shared/night.wgsl"),
    shader!("shared/clouds.wgsl"),
    shader!("shared/interleave.wgsl"),
];

/// The path tracing pass (entry point `trace_main`). Compose it with [`compose_trace`]: it
/// needs [`DIRECT`] beside the shared pieces.
pub const TRACE: ShaderSource = shader!("trace.wgsl");

/// Next-event estimation for the trace pass (twin of `render/cpu/direct.rs`).
pub const DIRECT: ShaderSource = shader!("direct.wgsl");

/// Batch ray tracing (entry point `ray_batch_main`).
pub const RAY_BATCH: ShaderSource = shader!("ray_batch.wgsl");

/// Tonemapping the film into the window's frame (entry points `present_vs`, `present_fs`).
/// It needs only the struct twins: compose it with [`compose_with`]`(PRESENT_SHARED, PRESENT)`.
pub const PRESENT: ShaderSource = shader!("present.wgsl");

/// The shared pieces the present pass needs (the tracing bindings would clash with its own).
pub const PRESENT_SHARED: &[ShaderSource] = &[shader!("shared/types.wgsl")];

/// The shared pieces of the denoiser's passes: the struct twins and the SVGF arithmetic (its
/// bindings 0–2: uniforms, guides, albedo). Compose with [`compose_with`]`(DENOISE_SHARED, …)`.
pub const DENOISE_SHARED: &[ShaderSource] =
    &[shader!("shared/types.wgsl"), shader!("shared/denoise.wgsl")];

/// The denoiser's per-pixel reprojection of its history (entry point `denoise_reproject`).
pub const DENOISE_REPROJECT: ShaderSource = shader!("denoise_reproject.wgsl");

/// SVGF's temporal stage (entry point `denoise_temporal`).
pub const DENOISE_TEMPORAL: ShaderSource = shader!("denoise_temporal.wgsl");

/// SVGF's variance estimate (entry point `denoise_variance`).
pub const DENOISE_VARIANCE: ShaderSource = shader!("denoise_variance.wgsl");

/// One variance-guided à-trous pass (entry point `denoise_atrous`).
pub const DENOISE_ATROUS: ShaderSource = shader!("denoise_atrous.wgsl");

/// The shared pieces followed by `pass`, as one WGSL module.
pub fn compose(pass: ShaderSource) -> String {
    compose_with(SHARED, pass)
}

/// The trace pass as one WGSL module: the shared pieces, [`DIRECT`], then [`TRACE`].
pub fn compose_trace() -> String {
    compose_with(SHARED, DIRECT) + &compose_with(&[], TRACE)
}

/// `shared` (in order) followed by `pass`, as one WGSL module.
pub fn compose_with(shared: &[ShaderSource], pass: ShaderSource) -> String {
    let mut text = String::new();
    for part in shared.iter().chain(std::iter::once(&pass)) {
        text.push_str(&format!("// ---- {} ----\n", part.name));
        text.push_str(part.text);
        text.push('\n');
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The composed pass parses and validates with naga (the same front end wgpu uses), so a
    /// WGSL error fails `cargo test` before any GPU is involved.
    #[test]
    fn trace_pass_validates() {
        validates(compose_trace());
    }

    #[test]
    fn ray_batch_pass_validates() {
        validates(compose(RAY_BATCH));
    }

    #[test]
    fn present_pass_validates() {
        validates(compose_with(PRESENT_SHARED, PRESENT));
    }

    #[test]
    fn denoise_passes_validate() {
        for pass in [
            DENOISE_REPROJECT,
            DENOISE_TEMPORAL,
            DENOISE_VARIANCE,
            DENOISE_ATROUS,
        ] {
            validates(compose_with(DENOISE_SHARED, pass));
        }
    }

    fn validates(source: String) {
        let module = match naga::front::wgsl::parse_str(&source) {
            Ok(m) => m,
            Err(e) => panic!("{}", e.emit_to_string(&source)),
        };
        let mut validator = naga::valid::Validator::new(
            naga::valid::ValidationFlags::all(),
            naga::valid::Capabilities::default(),
        );
        if let Err(e) = validator.validate(&module) {
            panic!("{}", e.emit_to_string(&source));
        }
    }
}
