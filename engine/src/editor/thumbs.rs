//! Palette thumbnails: a small picture of each model file the palette offers, rendered by the
//! engine's CPU tracer ([`render_thumbnail`]: the model alone under a grey sky and a sun, seen
//! from the front and above, a few samples per pixel) and cached twice — on disk as a PNG named
//! by the model file's content hash (FNV-1a 64 of its bytes; written atomically, so a second
//! editor reuses it without rendering), and in memory as egui textures.
//!
//! [`Thumbnails`] runs the renders on one worker thread of its own, in the order asked, so the
//! editor never waits: the palette asks for what it shows ([`Thumbnails::shown`]) and takes
//! what is ready each pass ([`Thumbnails::poll`], main thread). A model that does not load
//! gets a placeholder and its error as the message. Must not: touch the document, the world
//! or the engine's renderer (the worker has its own CPU tracer).

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::mpsc::{Receiver, Sender, channel};

use glam::{Mat4, Vec3};

use crate::assets::atomic_file::write_atomic;
use crate::assets::{AssetRoot, CameraDesc, SceneDesc, SkyDesc, SunDesc, load_model};
use crate::render::cpu::CpuTracer;
use crate::render::film::{TonemapSettings, linear_to_srgb8};
use crate::render::{FrameSettings, Tracer, frame_uniforms};
use crate::scene::RenderScene;

/// Thumbnail edge in pixels.
pub const THUMB_PIXELS: u32 = 64;
/// Samples per pixel of a thumbnail render.
pub const THUMB_SPP: u32 = 8;

/// A thumbnail that could not be made: the model did not load or render.
#[derive(Debug, thiserror::Error)]
#[error("{0}")]
pub struct ThumbError(pub String);

/// A model file's thumbnail as the palette shows it.
#[derive(Clone)]
pub enum Shown {
    /// Asked for, not ready yet.
    Pending,
    Ready(egui::TextureHandle),
    /// No picture: why (the palette shows a placeholder and this on hover).
    Failed(String),
}

/// Where a finished thumbnail came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Source {
    Rendered,
    /// The disk cache had it.
    Disk,
}

type Done = (String, Result<(egui::ColorImage, Source), ThumbError>);

/// The palette's thumbnails: the worker, the disk cache folder and the textures made so far.
pub struct Thumbnails {
    jobs: Sender<String>,
    done: Receiver<Done>,
    shown: HashMap<String, Shown>,
    /// How many finished thumbnails were rendered and how many read from the disk cache.
    pub rendered: usize,
    pub from_disk: usize,
    /// Messages for thumbnails that failed, to show once (the palette's caller says them).
    pub messages: Vec<String>,
}

impl std::fmt::Debug for Thumbnails {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Thumbnails({} known)", self.shown.len())
    }
}

/// The user's cache folder for thumbnails: `$XDG_CACHE_HOME/candela/thumbnails`, else
/// `~/.cache/candela/thumbnails`, else one under the system's temporary folder.
pub fn user_cache_dir() -> PathBuf {
    let base = std::env::var_os("XDG_CACHE_HOME")
        .map(PathBuf::from)
        .filter(|p| p.is_absolute())
        .or_else(|| std::env::var_os("HOME").map(|h| PathBuf::from(h).join(".cache")))
        .unwrap_or_else(std::env::temp_dir);
    base.join("candela/thumbnails")
}

impl Thumbnails {
    /// Thumbnails of model files under `root` (paths relative to it), cached in `cache`.
    pub fn new(root: AssetRoot, cache: PathBuf) -> Self {
        let (jobs, inbox) = channel::<String>();
        let (outbox, done) = channel();
        let spawned = std::thread::Builder::new()
            .name("editor thumbnails".into())
            .spawn(move || {
                for rel in inbox {
                    let made = thumbnail(&root, &cache, &rel);
                    if outbox.send((rel, made)).is_err() {
                        return;
                    }
                }
            });
        if let Err(e) = spawned {
            log::warn!("editor: no thumbnail thread: {e}");
        }
        Self {
            jobs,
            done,
            shown: HashMap::new(),
            rendered: 0,
            from_disk: 0,
            messages: Vec::new(),
        }
    }

    /// The thumbnail of model file `rel` (relative to the asset root), asked for the first time
    /// it is wanted.
    pub fn shown(&mut self, rel: &str) -> Shown {
        if let Some(s) = self.shown.get(rel) {
            return s.clone();
        }
        let s = match self.jobs.send(rel.to_string()) {
            Ok(()) => Shown::Pending,
            Err(_) => Shown::Failed("the thumbnail thread is gone".into()),
        };
        self.shown.insert(rel.to_string(), s.clone());
        s
    }

    /// Takes the finished thumbnails as textures of `ctx` (main thread, inside a pass or not).
    pub fn poll(&mut self, ctx: &egui::Context) {
        while let Ok(done) = self.done.try_recv() {
            self.finish(ctx, done);
        }
    }

    /// Waits until every thumbnail asked for is finished (tools and tests; the editor polls).
    pub fn wait(&mut self, ctx: &egui::Context) {
        while self.shown.values().any(|s| matches!(s, Shown::Pending)) {
            match self.done.recv() {
                Ok(done) => self.finish(ctx, done),
                Err(_) => return,
            }
        }
    }

    fn finish(&mut self, ctx: &egui::Context, (rel, made): Done) {
        let shown = match made {
            Ok((image, source)) => {
                match source {
                    Source::Rendered => self.rendered += 1,
                    Source::Disk => self.from_disk += 1,
                }
                let name = format!("thumbnail {rel}");
                Shown::Ready(ctx.load_texture(name, image, egui::TextureOptions::LINEAR))
            }
            Err(e) => {
                self.messages.push(format!("no thumbnail for {rel}: {e}"));
                Shown::Failed(e.0)
            }
        };
        self.shown.insert(rel, shown);
    }
}

/// The thumbnail of `rel`: from the disk cache when it holds one for the file's bytes, else
/// rendered and cached.
fn thumbnail(
    root: &AssetRoot,
    cache: &Path,
    rel: &str,
) -> Result<(egui::ColorImage, Source), ThumbError> {
    let file = root.path().join(rel);
    let bytes = std::fs::read(&file).map_err(|e| ThumbError(format!("{}: {e}", file.display())))?;
    let cached = cache.join(format!("{:016x}-{THUMB_PIXELS}.png", content_hash(&bytes)));
    if let Ok(img) = image::open(&cached) {
        let img = img.to_rgba8();
        let size = [img.width() as usize, img.height() as usize];
        return Ok((
            egui::ColorImage::from_rgba_unmultiplied(size, img.as_raw()),
            Source::Disk,
        ));
    }
    let rgb = render_thumbnail(root, rel, THUMB_PIXELS, THUMB_SPP)?;
    let mut png = Vec::new();
    let encoded = image::RgbImage::from_raw(THUMB_PIXELS, THUMB_PIXELS, rgb.clone())
        .map(|img| img.write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png));
    match encoded {
        Some(Ok(())) => {
            let written = std::fs::create_dir_all(cache)
                .map_err(|e| e.to_string())
                .and_then(|()| write_atomic(&cached, &png).map_err(|e| e.to_string()));
            if let Err(e) = written {
                log::warn!("editor: thumbnail cache {}: {e}", cached.display());
            }
        }
        _ => log::warn!("editor: cannot encode the thumbnail of {rel}"),
    }
    let size = [THUMB_PIXELS as usize; 2];
    Ok((egui::ColorImage::from_rgb(size, &rgb), Source::Rendered))
}

/// Renders model file `rel` (relative to `root`) alone, `pixels` square with `spp` samples per
/// pixel: under a grey sky (radiance 0.6) and a sun from the upper left, seen from the front,
/// right and above so that its bounding sphere fills the view. Returns 8-bit sRGB, row-major
/// RGB.
pub fn render_thumbnail(
    root: &AssetRoot,
    rel: &str,
    pixels: u32,
    spp: u32,
) -> Result<Vec<u8>, ThumbError> {
    let referrer = root.path().join(rel);
    let model = load_model(root, &referrer, rel).map_err(|e| ThumbError(e.to_string()))?;
    let (mut lo, mut hi) = (Vec3::INFINITY, Vec3::NEG_INFINITY);
    for placement in &model.placements {
        let Some(mesh) = model.meshes.get(placement.mesh) else {
            continue;
        };
        for &p in &mesh.positions {
            let p = placement.model_from_mesh.transform_point3(p);
            lo = lo.min(p);
            hi = hi.max(p);
        }
    }
    if !(lo.x <= hi.x && lo.is_finite() && hi.is_finite()) {
        return Err(ThumbError(format!("{rel}: the model has no geometry")));
    }
    let centre = (lo + hi) * 0.5;
    let radius = ((hi - lo).length() * 0.5).max(1e-3);
    let fov_deg: f32 = 30.0;
    let distance = radius / (fov_deg.to_radians() * 0.5).sin() * 1.05;
    let eye = centre + Vec3::new(0.6, 0.45, 1.0).normalize() * distance;
    let camera = CameraDesc {
        position: eye.to_array(),
        look_at: centre.to_array(),
        up: [0.0, 1.0, 0.0],
        vertical_fov_deg: fov_deg,
        aperture_radius: 0.0,
        focus_distance: None,
    };
    let mut desc = SceneDesc::single(model, camera);
    desc.instances[0].world_from_model = Mat4::IDENTITY;
    desc.sky = SkyDesc::Constant([0.6, 0.6, 0.6]);
    desc.sun = Some(SunDesc {
        direction: [-0.5, 1.0, 0.7],
        irradiance: [2.0, 2.0, 2.0],
        angular_radius_deg: 0.27,
    });
    let scene = RenderScene::build(&desc);
    let mut tracer = CpuTracer::new();
    let settings = FrameSettings::new(pixels, pixels, spp, 1, &desc.render);
    let uniforms = frame_uniforms(
        &desc.camera,
        desc.sun.as_ref(),
        &desc.sky,
        &settings,
        &scene.header(),
    );
    let film = (tracer.render(&scene, &uniforms))
        .and_then(|_| tracer.film())
        .map_err(|e| ThumbError(format!("{rel}: {e}")))?;
    let tonemap = TonemapSettings::default();
    Ok(film
        .mean
        .iter()
        .flat_map(|&c| linear_to_srgb8(c, &tonemap))
        .collect())
}

/// FNV-1a, 64 bits, of `bytes`: the disk cache's key for a model file's content.
pub fn content_hash(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}
