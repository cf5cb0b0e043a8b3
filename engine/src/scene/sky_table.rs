//! [`SkyTable`]: the physical sky's sky-view texels as the render side holds them — the CPU
//! tracer reads them in place, the GPU tracer uploads the same vector (binding 16, rewritten
//! when this table is rebuilt: `render/gpu/upload.rs`) and reads it with the WGSL twin of the
//! lookup (`shaders/shared/sky_view.wgsl`).
//!
//! Any thread (plain data). Updated whenever the sky's description changes ([`SkyTable::
//! update`] compares it), on the thread that owns the `RenderScene` copy (the render thread
//! when it applies a commit; the builder in `accel/flatten.rs`); a [`SkyBaker`] rebuilds only
//! what the change needs (nothing while the sun stays in the table's elevation step,
//! `sky::TABLE_ELEVATION_STEP_DEG`; the sky-view table alone when only the sun moved).
//!
//! Two ways to wait ([`SkyRebuild`]): `Blocking` (the default: the table always matches the
//! commit's sky, so captures and pictures repeat bit for bit) and `Background` (games in play:
//! a rebuild runs on a worker thread while frames go on with the table held, and the newest
//! finished table is installed at the next update — a sun turned fast at an altar costs the
//! render thread nothing, and the sky lags it by about one rebuild). Must not: compute the sky
//! (`crate::sky` does) or know about commits.

use std::sync::mpsc::{Receiver, TryRecvError, channel};
use std::sync::{Arc, Mutex};

use crate::assets::SkyDesc;
use crate::sky::{PhysicalSky, SkyBaker};

/// How [`SkyTable::update_with`] waits for a rebuild.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum SkyRebuild {
    /// Rebuild on the spot: the table always matches the sky asked for.
    #[default]
    Blocking,
    /// Rebuild on a worker thread, keeping the table held until the new one is done (the
    /// first table of a sky, or a new atmosphere, is still built on the spot).
    Background,
}

/// A rebuild under way on a worker thread: the sky it builds, and where the baker comes back.
struct Rebuilding {
    sky: PhysicalSky,
    done: Mutex<Receiver<SkyBaker>>,
}

/// The sky-view table of the current physical sky, or nothing for the other skies.
#[derive(Clone, Debug, Default)]
pub struct SkyTable {
    source: Option<PhysicalSky>,
    baker: SkyBaker,
    /// `sky::VIEW_WIDTH × sky::VIEW_HEIGHT` texels (layout in `sky::sky_view`); empty when the
    /// sky is not physical.
    pub texels: Arc<Vec<[f32; 4]>>,
    rebuilding: Option<Arc<Rebuilding>>,
    /// The cloud layer's optical depths (`sky::CloudLayer::bake`, `texels`² row-major), baked
    /// on the spot whenever the layer's description changes (not when the wind moves it);
    /// empty without clouds. The GPU tracer appends them to binding 16.
    pub clouds: Arc<Vec<f32>>,
    cloud_source: Option<crate::sky::CloudLayer>,
}

impl std::fmt::Debug for Rebuilding {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Rebuilding")
            .field("sky", &self.sky)
            .finish()
    }
}

impl SkyTable {
    /// Brings the texels up to `sky`, waiting for any rebuild ([`SkyRebuild::Blocking`]).
    pub fn update(&mut self, sky: &SkyDesc) {
        self.update_with(sky, SkyRebuild::Blocking);
    }

    /// Brings the texels up to `sky` when it is a physical sky other than the one held (about
    /// 0.3 s for a new atmosphere, less when only the sun moved, nothing while it stays in one
    /// `sky::TABLE_ELEVATION_STEP_DEG` step); clears them for the other skies. With
    /// [`SkyRebuild::Background`] a rebuild of the sky-view table runs on a worker thread and
    /// its result is installed by a later call. Returns whether the texels changed.
    /// A sky that fails its checks (the level loader refuses those first) leaves an empty
    /// table: the tracers then see a black sky.
    pub fn update_with(&mut self, sky: &SkyDesc, how: SkyRebuild) -> bool {
        let mut changed = self.collect();
        let layer = match sky {
            SkyDesc::Physical(p) => p.clouds,
            _ => None,
        };
        if layer != self.cloud_source {
            self.cloud_source = layer;
            self.clouds = Arc::new(layer.map(|l| l.bake()).unwrap_or_default());
            changed = true;
        }
        match sky {
            SkyDesc::Physical(p) => {
                if self.source.as_ref() == Some(p) {
                    return changed;
                }
                self.source = Some(*p);
                let background = how == SkyRebuild::Background
                    && !self.texels.is_empty()
                    && self.baker.holds_atmosphere_of(p);
                if !background {
                    self.rebuilding = None;
                    return self.build_here(p) || changed;
                }
                if !self.baker.needs_update(p) {
                    // The table held serves this sky: a rebuild for another sun that is
                    // still running is out of date.
                    self.rebuilding = None;
                } else if self.rebuilding.is_none() {
                    self.start(*p);
                }
            }
            _ => {
                self.rebuilding = None;
                if self.source.take().is_some() {
                    self.texels = Arc::default();
                    changed = true;
                }
            }
        }
        changed
    }

    /// Rebuilds for `p` on this thread; whether the texels changed.
    fn build_here(&mut self, p: &PhysicalSky) -> bool {
        let before = Arc::clone(&self.texels);
        match self.baker.update(p) {
            // A kept table keeps its `Arc`: the GPU upload compares pointers.
            Ok(_) => self.texels = self.baker.texels().clone(),
            Err(_) => {
                self.baker.clear();
                self.texels = Arc::default();
            }
        }
        !Arc::ptr_eq(&before, &self.texels)
    }

    /// Starts rebuilding for `sky` on a worker thread, from a copy of the baker.
    fn start(&mut self, sky: PhysicalSky) {
        let (send, done) = channel();
        let mut baker = self.baker.clone();
        let spawned = std::thread::Builder::new()
            .name("sky table".into())
            .spawn(move || {
                if baker.update(&sky).is_ok() {
                    // The table may have moved on (the receiver gone): nothing to do then.
                    let _ = send.send(baker);
                }
            });
        if spawned.is_ok() {
            self.rebuilding = Some(Arc::new(Rebuilding {
                sky,
                done: Mutex::new(done),
            }));
        } else {
            let _ = self.build_here(&sky);
        }
    }

    /// Installs a finished background rebuild, and starts the next one when the sky has moved
    /// on since; whether the texels changed.
    fn collect(&mut self) -> bool {
        let Some(rebuilding) = self.rebuilding.clone() else {
            return false;
        };
        let received = match rebuilding.done.lock() {
            Ok(done) => done.try_recv(),
            Err(_) => Err(TryRecvError::Disconnected),
        };
        match received {
            Ok(baker) => {
                self.baker = baker;
                self.texels = self.baker.texels().clone();
                self.rebuilding = None;
                if let Some(wanted) = self.source
                    && self.baker.needs_update(&wanted)
                {
                    self.start(wanted);
                }
                true
            }
            Err(TryRecvError::Empty) => false,
            Err(TryRecvError::Disconnected) => {
                self.rebuilding = None;
                false
            }
        }
    }

    /// The horizontal illuminance under `sky` over the table held (sky units;
    /// [`SkyBaker::horizontal_illuminance`]): while a background rebuild runs, the held
    /// table's sky with `sky`'s own sun and moon.
    pub fn horizontal_illuminance(&self, sky: &PhysicalSky) -> Result<f32, crate::sky::SkyError> {
        self.baker.horizontal_illuminance(sky)
    }

    /// Whether a background rebuild is under way (the texels lag the sky asked for).
    pub fn rebuilding(&self) -> bool {
        self.rebuilding.is_some()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sky_at(elevation_deg: f32) -> SkyDesc {
        SkyDesc::Physical(PhysicalSky {
            sun_elevation_deg: elevation_deg,
            ..PhysicalSky::default()
        })
    }

    #[test]
    fn a_background_rebuild_keeps_the_table_until_done_then_matches_a_blocking_one() {
        let how = SkyRebuild::Background;
        let mut table = SkyTable::default();
        // The first table of a sky is built on the spot.
        assert!(table.update_with(&sky_at(20.0), how));
        assert!(!table.texels.is_empty() && !table.rebuilding());
        let held = Arc::clone(&table.texels);
        // The sun moves to another step: the update returns at once with the table held.
        let moved = sky_at(35.0);
        assert!(!table.update_with(&moved, how));
        assert!(table.rebuilding() && Arc::ptr_eq(&held, &table.texels));
        // A later update installs the finished table (a bound on waiting, not on speed).
        let installed = (0..1200).any(|_| {
            std::thread::sleep(std::time::Duration::from_millis(50));
            table.update_with(&moved, how)
        });
        assert!(installed && !table.rebuilding(), "the rebuild never landed");
        let mut blocking = SkyTable::default();
        blocking.update(&moved);
        assert_eq!(
            *table.texels, *blocking.texels,
            "the same bits as a build on the spot"
        );
        // A sun within the same 0.1° step starts nothing.
        assert!(!table.update_with(&sky_at(35.02), how));
        assert!(!table.rebuilding());
    }
}
