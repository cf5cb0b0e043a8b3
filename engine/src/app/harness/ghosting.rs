//! Ghosting under fast motion (Brigade §4.5): how much error a converging policy leaves on a
//! fast-moving object and on the trail it leaves behind.
//!
//! Owns: the standard ghosting scene — a bright emissive square (radiance [`GhostSetup::
//! object_radiance`], two-sided, facing the camera) sweeping across a dark diffuse backdrop it
//! alone lights — running it through the headless [`Engine`] on the CPU tracer with a given
//! [`ConvergePolicy`], and the error of the last frame's converged film against a fresh,
//! non-accumulated render of the same scene state with many samples. Regions: the object's
//! pixels now, the trail (pixels it covered in the previous [`GhostSetup::trail_frames`]
//! frames but not now) and the rest of the image. Errors are RMS over a region of the
//! per-pixel mean of R, G, B, divided by the object's radiance (dimensionless).
//! Main thread (the engine's render thread renders). Must not: change any policy; it measures.
//!
//! Geometry: camera at (0, 0, `camera_distance`) looking down −Z (right-handed, Y up, metres);
//! the square moves along +X in the plane z = 0; the backdrop is the plane z = −0.5.

use glam::{Mat4, Vec3};

use crate::app::runner::{Engine, EngineError, Environment};
use crate::assets::{
    CameraDesc, Material, MaterialKind, Mesh, Model, Placement, RenderSettings, SkyDesc,
};
use crate::commit::Motion;
use crate::ecs::{Renderable, Static, Transform};
use crate::render::cpu::CpuTracer;
use crate::render::film::{Converge, ConvergePolicy, Film};
use crate::render::{
    FrameSettings, RenderConfig, RenderError, Tracer, TracerChoice, frame_uniforms,
};

/// The scene and workload of a ghosting measurement.
#[derive(Clone, Copy, Debug)]
pub struct GhostSetup {
    /// Film size, pixels.
    pub width: u32,
    pub height: u32,
    /// Samples per pixel per frame.
    pub spp: u32,
    /// Frames run; the last one is measured.
    pub frames: u32,
    /// Samples per pixel of the reference render.
    pub reference_spp: u32,
    /// Side of the square, metres.
    pub object_size: f32,
    /// Emitted radiance of the square (W·sr⁻¹·m⁻², grey).
    pub object_radiance: f32,
    /// Metres the square moves per frame.
    pub metres_per_frame: f32,
    /// Frames behind the square that count as its trail.
    pub trail_frames: u32,
    pub camera_distance: f32,
    pub seed: u32,
}

impl Default for GhostSetup {
    /// 48 × 32 pixels, 2 spp per frame, 24 frames; a 0.8 m square moving 0.25 m per frame
    /// (15 m/s at 60 Hz, about two pixels per frame; it crosses the view in the run).
    fn default() -> Self {
        Self {
            width: 48,
            height: 32,
            spp: 2,
            frames: 24,
            reference_spp: 256,
            object_size: 0.8,
            object_radiance: 4.0,
            metres_per_frame: 0.25,
            trail_frames: 8,
            camera_distance: 6.0,
            seed: 7,
        }
    }
}

/// Errors of one policy (RMS, relative to the object's radiance) and the regions' sizes.
#[derive(Clone, Copy, Debug)]
pub struct GhostError {
    pub policy: ConvergePolicy,
    /// The object's pixels in the measured frame.
    pub object: f64,
    /// Pixels the object left during the last `trail_frames` frames.
    pub trail: f64,
    /// Object and trail together: the error of the moving content.
    pub moving: f64,
    /// Everything else (where accumulation only removes noise).
    pub rest: f64,
    pub object_pixels: usize,
    pub trail_pixels: usize,
    /// What an ideal running blend with this policy's blend factors leaves on the moving
    /// content (object + trail) without any noise: each pixel's noise-free history (1 where the
    /// square covers its centre, 0 elsewhere) blended frame by frame, minus its value now.
    pub predicted_ghost: f64,
    /// √Σ wᵢ² over the blend weights wᵢ of each frame in the final film: the factor by which
    /// blending scales one fresh frame's noise (1 for reset on motion).
    pub noise_factor: f64,
}

/// A square of side `size` metres in the xy plane, facing +Z.
fn square(size: f32, material: Material) -> Model {
    let h = size / 2.0;
    Model {
        name: "square".into(),
        meshes: vec![Mesh {
            name: "square".into(),
            positions: vec![
                Vec3::new(-h, -h, 0.0),
                Vec3::new(h, -h, 0.0),
                Vec3::new(h, h, 0.0),
                Vec3::new(-h, h, 0.0),
            ],
            triangles: vec![[0, 1, 2], [0, 2, 3]],
            triangle_materials: vec![0, 0],
            ..Default::default()
        }],
        materials: vec![material],
        placements: vec![Placement {
            mesh: 0,
            model_from_mesh: Mat4::IDENTITY,
        }],
        ..Default::default()
    }
}

impl GhostSetup {
    fn camera(&self) -> CameraDesc {
        CameraDesc {
            position: [0.0, 0.0, self.camera_distance],
            look_at: [0.0, 0.0, 0.0],
            up: [0.0, 1.0, 0.0],
            vertical_fov_deg: 40.0,
            aperture_radius: 0.0,
            focus_distance: None,
        }
    }

    fn environment(&self) -> Environment {
        Environment {
            sun: None,
            sky: SkyDesc::Constant([0.0; 3]),
            render: RenderSettings {
                max_bounces: 2,
                roulette_start: 2,
                ..Default::default()
            },
            default_camera: self.camera(),
        }
    }

    /// x of the square's centre at `frame` (metres, world space): it moves along +X and is 1 m
    /// right of the view's centre at the measured (last) frame.
    pub fn object_x(&self, frame: u32) -> f32 {
        (frame as f32 - (self.frames as f32 - 1.0)) * self.metres_per_frame + 1.0
    }

    /// Whether pixel (`px`, `py`)'s centre sees the square at `frame` (py downward; the camera
    /// mapping of `render::camera`).
    fn covers(&self, px: u32, py: u32, frame: u32) -> bool {
        let tan_half = (40.0f32.to_radians() * 0.5).tan();
        let aspect = self.width as f32 / self.height as f32;
        let sx = 2.0 * (px as f32 + 0.5) / self.width as f32 - 1.0;
        let sy = 1.0 - 2.0 * (py as f32 + 0.5) / self.height as f32;
        let x = sx * tan_half * aspect * self.camera_distance;
        let y = sy * tan_half * self.camera_distance;
        let h = self.object_size / 2.0;
        (x - self.object_x(frame)).abs() < h && y.abs() < h
    }
}

/// Runs the scene with `policy` and returns the last frame's converged film and the game-side
/// scene of that frame (what the render thread rendered it from).
fn run_policy(
    setup: &GhostSetup,
    policy: ConvergePolicy,
) -> Result<(Film, crate::scene::RenderScene), EngineError> {
    let config = RenderConfig {
        tracer: TracerChoice::Cpu,
        width: setup.width,
        height: setup.height,
        spp: setup.spp,
        seed: setup.seed,
        converge: policy,
        scaling: None,
        denoise: false,
        light_sampling: None,
        indirect_every: None,
        first_hit_guides: false,
        atrous_kernel: Default::default(),
        sky_rebuild: crate::scene::SkyRebuild::Blocking,
        temporal_upscale: None,
    };
    let mut engine = Engine::new(config, setup.environment())?;
    let backdrop_material = Material {
        kind: MaterialKind::Diffuse,
        base_color: Vec3::splat(0.5),
        ..Default::default()
    };
    let backdrop = engine.add_model(&square(40.0, backdrop_material));
    let lamp = engine.add_model(&square(
        setup.object_size,
        Material {
            emission: Vec3::splat(setup.object_radiance),
            two_sided_emission: true,
            base_color: Vec3::ZERO,
            ..Default::default()
        },
    ));
    engine.world_mut().spawn((
        Transform::from_translation(Vec3::Z * -0.5),
        Renderable {
            model: backdrop,
            material_override: None,
        },
        Static,
    ));
    let mover = engine.world_mut().spawn((
        Transform::from_translation(Vec3::X * setup.object_x(0)),
        Renderable {
            model: lamp,
            material_override: None,
        },
    ));
    let mut film = None;
    for frame in 0..setup.frames {
        if let Ok(mut t) = engine.world_mut().get::<&mut Transform>(mover) {
            t.translation.x = setup.object_x(frame);
        }
        if frame + 1 == setup.frames {
            engine.capture_next();
        }
        engine.frame(1.0 / 60.0, &mut |_: &mut crate::app::runner::Step<'_>| {})?;
        // Lock step: the game side's scene is then the one the render thread rendered.
        if let Some(rendered) = engine.wait_rendered() {
            film = rendered?.film.or(film);
        }
    }
    let scene = engine.scene().clone();
    let _ = engine.shutdown();
    let film = film.ok_or_else(|| RenderError::Device("no film came back".into()))?;
    Ok((film, scene))
}

/// A fresh render of `scene` with `setup.reference_spp` samples per pixel and no history.
fn reference(setup: &GhostSetup, scene: &crate::scene::RenderScene) -> Result<Film, RenderError> {
    let environment = setup.environment();
    let mut tracer = CpuTracer::new();
    let mut settings = FrameSettings::new(
        setup.width,
        setup.height,
        setup.reference_spp,
        setup.seed ^ 0x5eed,
        &environment.render,
    );
    settings.film_blend = 1.0;
    let uniforms = frame_uniforms(
        &environment.default_camera,
        None,
        &environment.sky,
        &settings,
        &scene.header(),
    );
    tracer.render(scene, &uniforms)?;
    tracer.film()
}

/// The blend factor of every frame as the render thread's [`Converge`] picks them: the first
/// frame is a cut, and the square moves in every frame.
fn blend_factors(setup: &GhostSetup, policy: ConvergePolicy) -> Vec<f32> {
    let mut converge = Converge::new(policy);
    (0..setup.frames)
        .map(|k| {
            converge.blend(&Motion {
                cut: k == 0,
                camera: 0.0,
                objects: true,
                lighting: 0.0,
            })
        })
        .collect()
}

/// `(predicted_ghost, noise_factor)` of [`GhostError`] for `policy`.
fn predict(setup: &GhostSetup, policy: ConvergePolicy) -> (f64, f64) {
    let factors = blend_factors(setup, policy);
    let last = setup.frames.saturating_sub(1);
    let (mut sum, mut n) = (0.0f64, 0usize);
    for py in 0..setup.height {
        for px in 0..setup.width {
            let moving = (0..=setup.trail_frames.min(last)).any(|k| setup.covers(px, py, last - k));
            if !moving {
                continue;
            }
            let mut v = 0.0f64;
            for (k, &f) in factors.iter().enumerate() {
                let c = setup.covers(px, py, k as u32) as u32 as f64;
                v += f as f64 * (c - v);
            }
            let now = setup.covers(px, py, last) as u32 as f64;
            sum += (v - now).powi(2);
            n += 1;
        }
    }
    let mut weights = 0.0f64;
    let mut later = 1.0f64;
    for &f in factors.iter().rev() {
        weights += (f as f64 * later).powi(2);
        later *= 1.0 - f as f64;
    }
    ((sum / n.max(1) as f64).sqrt(), weights.sqrt())
}

/// Measures every policy on the same scene; the reference is rendered once (every run ends in
/// the same scene state).
pub fn measure_ghosting(
    setup: &GhostSetup,
    policies: &[ConvergePolicy],
) -> Result<Vec<GhostError>, EngineError> {
    let mut out = Vec::with_capacity(policies.len());
    let mut reference_film: Option<Film> = None;
    let last = setup.frames.saturating_sub(1);
    for &policy in policies {
        let (film, scene) = run_policy(setup, policy)?;
        let reference_film = match &reference_film {
            Some(r) => r,
            None => reference_film.insert(reference(setup, &scene)?),
        };
        let mut sums = [(0.0f64, 0usize); 3];
        for py in 0..setup.height {
            for px in 0..setup.width {
                let i = (py * setup.width + px) as usize;
                let (Some(a), Some(b)) = (film.mean.get(i), reference_film.mean.get(i)) else {
                    continue;
                };
                let d = ((*a - *b).element_sum() / 3.0) as f64 / setup.object_radiance as f64;
                let region = if setup.covers(px, py, last) {
                    0
                } else if (1..=setup.trail_frames.min(last)).any(|k| setup.covers(px, py, last - k))
                {
                    1
                } else {
                    2
                };
                sums[region].0 += d * d;
                sums[region].1 += 1;
            }
        }
        let rms = |(s, n): (f64, usize)| (s / n.max(1) as f64).sqrt();
        let (predicted_ghost, noise_factor) = predict(setup, policy);
        out.push(GhostError {
            predicted_ghost,
            noise_factor,
            policy,
            object: rms(sums[0]),
            trail: rms(sums[1]),
            moving: rms((sums[0].0 + sums[1].0, sums[0].1 + sums[1].1)),
            rest: rms(sums[2]),
            object_pixels: sums[0].1,
            trail_pixels: sums[1].1,
        });
    }
    Ok(out)
}
