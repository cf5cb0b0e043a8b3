//! What a window asks of the render thread for one frame: [`PresentRequest`] (surface size,
//! tonemapping, vsync, a screenshot) and the stats [`Overlay`] drawn over the frame.
//!
//! Owns: [`TonemapSettings`] (applied by the render thread's film), the overlay as egui leaves it after tessellation on the main thread (clipped
//! primitives, texture changes, pixels per point) — plain data, so it travels inside the sealed
//! commit and the render thread, which owns the wgpu device, draws it after tonemapping.
//! Must not: reference the ECS, winit or the device (the render thread never sees game state).

/// An egui overlay, tessellated on the main thread, drawn by the render thread.
#[derive(Clone, Default)]
pub struct Overlay {
    /// Triangles in egui points, clipped per primitive.
    pub primitives: Vec<egui::ClippedPrimitive>,
    /// Font atlas and image changes to apply before drawing (and textures to free after).
    pub textures_delta: egui::TexturesDelta,
    /// Physical pixels per egui point (the window's scale factor).
    pub pixels_per_point: f32,
}

impl Overlay {
    /// Bytes of vertex, index and texture data this overlay carries.
    pub fn bytes(&self) -> usize {
        let mesh: usize = self
            .primitives
            .iter()
            .map(|p| match &p.primitive {
                egui::epaint::Primitive::Mesh(m) => {
                    m.vertices.len() * size_of::<egui::epaint::Vertex>() + m.indices.len() * 4
                }
                egui::epaint::Primitive::Callback(_) => 0,
            })
            .sum();
        let textures: usize = self
            .textures_delta
            .set
            .values()
            .flatten()
            .map(|d| d.image.width() * d.image.height() * 4)
            .sum();
        mesh + textures
    }
}

impl std::fmt::Debug for Overlay {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Overlay")
            .field("primitives", &self.primitives.len())
            .field("textures_set", &self.textures_delta.set.len())
            .field("textures_free", &self.textures_delta.free.len())
            .field("pixels_per_point", &self.pixels_per_point)
            .finish()
    }
}

/// How to show this frame in the window. A headless render thread presents nothing; only the
/// surface size applies (the render size follows it).
#[derive(Clone, Debug)]
pub struct PresentRequest {
    /// The window's inner size in physical pixels; the render size follows it (workload
    /// scaling may render smaller, the presenter upscales). A zero side (a minimised window)
    /// renders at the previous size and presents nothing.
    pub surface_size: (u32, u32),
    pub tonemap: TonemapSettings,
    /// Wait for the display's vertical blank (FIFO); otherwise present at once (immediate or
    /// mailbox, whichever the surface offers).
    pub vsync: bool,
    pub overlay: Option<Overlay>,
    /// Read the presented image back (the window's content, overlay included).
    pub screenshot: bool,
    /// A new goal for workload scaling (the player's target frame rate and resolution scale);
    /// `None` keeps the current one.
    pub scaling: Option<ScalingRequest>,
}

/// What workload scaling should hold from this frame on (the player's settings).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScalingRequest {
    /// Seconds per frame to hold by trading samples, roulette and resolution (`None`: a fixed
    /// workload).
    pub frame_seconds: Option<f32>,
    /// Highest render resolution, fraction of the window per axis, in [0.1, 1].
    pub max_resolution: f32,
}

/// How radiance becomes a displayed colour.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TonemapSettings {
    /// Exposure in stops (EV): radiance is multiplied by 2^exposure_ev.
    pub exposure_ev: f32,
    /// Apply a filmic-like curve (ACES fit by Narkowicz 2015) instead of clamping.
    pub filmic: bool,
}

impl Default for TonemapSettings {
    fn default() -> Self {
        Self {
            exposure_ev: 0.0,
            filmic: false,
        }
    }
}
