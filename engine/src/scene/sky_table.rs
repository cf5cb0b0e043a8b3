//! [`SkyTable`]: the physical sky's sky-view texels as the render side holds them — the CPU
//! tracer reads them in place, the GPU tracer uploads the same vector (binding 16, rewritten
//! when this table is rebuilt: `render/gpu/upload.rs`) and reads it with the WGSL twin of the
//! lookup (`shaders/shared/sky_view.wgsl`).
//!
//! Any thread (plain data). Updated whenever the sky's description changes ([`SkyTable::
//! update`] compares it), on the thread that owns the `RenderScene` copy (the render thread
//! when it applies a commit; the builder in `accel/flatten.rs`); a [`SkyBaker`] rebuilds only
//! what the change needs (nothing while the sun stays in the table's elevation step,
//! `sky::TABLE_ELEVATION_STEP_DEG`; the sky-view table alone when only the sun moved). Must not: compute
//! the sky (`crate::sky` does) or know about commits.

use std::sync::Arc;

use crate::assets::SkyDesc;
use crate::sky::{PhysicalSky, SkyBaker};

/// The sky-view table of the current physical sky, or nothing for the other skies.
#[derive(Clone, Debug, Default)]
pub struct SkyTable {
    source: Option<PhysicalSky>,
    baker: SkyBaker,
    /// `sky::VIEW_WIDTH × sky::VIEW_HEIGHT` texels (layout in `sky::sky_view`); empty when the
    /// sky is not physical.
    pub texels: Arc<Vec<[f32; 4]>>,
}

impl SkyTable {
    /// Brings the texels up to `sky` when it is a physical sky other than the one held (about
    /// 0.3 s for a new atmosphere, less when only the sun moved, nothing while it stays in one
    /// `sky::TABLE_ELEVATION_STEP_DEG` step); clears them for the other skies.
    /// A sky that fails its checks (the level loader refuses those first) leaves an empty
    /// table: the tracers then see a black sky.
    pub fn update(&mut self, sky: &SkyDesc) {
        match sky {
            SkyDesc::Physical(p) => {
                if self.source.as_ref() == Some(p) {
                    return;
                }
                self.source = Some(*p);
                match self.baker.update(p) {
                    // A kept table keeps its `Arc`: the GPU upload compares pointers.
                    Ok(_) => self.texels = self.baker.texels().clone(),
                    Err(_) => {
                        self.baker.clear();
                        self.texels = Arc::default();
                    }
                }
            }
            _ => {
                if self.source.take().is_some() {
                    self.texels = Arc::default();
                }
            }
        }
    }
}
