//! The one-shot flattening of a [`SceneDesc`] into a [`RenderScene`] (tools, tests, captures):
//! the very [`Upkeep`] path a running game takes frame by frame, so a one-shot build and an
//! incremental one agree.
//!
//! Owns: `RenderScene::build` and its variants (an inherent `impl` of the scene module's type,
//! kept here because building is this layer's job). Any thread. Must not: keep state.

use glam::Vec3;

use super::{BlasParams, Upkeep};
use crate::assets::SceneDesc;
use crate::scene::{RenderScene, SceneStats, model_triangles};

impl RenderScene {
    /// Flattens `desc` in one go, through the same [`Upkeep`](crate::accel::Upkeep) path a
    /// running game uses frame by frame (so a one-shot build and an incremental one agree).
    /// Render space's origin is snapped near the camera (camera-relative rendering, see
    /// `accel::origin`).
    pub fn build(desc: &SceneDesc) -> RenderScene {
        let origin = super::origin::snap_origin(Vec3::from(desc.camera.position));
        Self::build_with_origin(desc, origin)
    }

    /// [`RenderScene::build`] with render space's origin at `origin` (world metres, snapped to
    /// `accel::origin::ORIGIN_GRID`); `Vec3::ZERO` renders in world space as it is.
    pub fn build_with_origin(desc: &SceneDesc, origin: Vec3) -> RenderScene {
        Self::build_from(desc, origin, BlasParams::default())
    }

    /// [`RenderScene::build`] with every BLAS built with `params` (a build preset or leaf size
    /// other than the default, for measurements such as `bench chart`). Both tracers read the
    /// result like any other scene: the image is the same, only the traversal speed differs.
    pub fn build_with_blas_params(desc: &SceneDesc, params: BlasParams) -> RenderScene {
        let origin = super::origin::snap_origin(Vec3::from(desc.camera.position));
        Self::build_from(desc, origin, params)
    }

    fn build_from(desc: &SceneDesc, origin: Vec3, params: BlasParams) -> RenderScene {
        let started = std::time::Instant::now();
        let mut upkeep = Upkeep::with_blas_params(params);
        upkeep.set_origin(origin);
        upkeep.add_level_materials(&desc.level_materials);
        let handles: Vec<_> = desc.models.iter().map(|m| upkeep.add_model(m)).collect();
        let blas_build_seconds = started.elapsed().as_secs_f64();
        let mut ids = hecs::World::new();
        for instance in &desc.instances {
            let Some(&model) = handles.get(instance.model) else {
                continue;
            };
            let entity = ids.spawn(());
            let material_override = instance.material_override.map(|m| m as u32);
            upkeep.set_instance(
                entity,
                model,
                instance.world_from_model,
                material_override,
                None,
            );
        }
        let started = std::time::Instant::now();
        upkeep.finish_frame();
        let tlas_build_seconds = started.elapsed().as_secs_f64();
        let mut scene = upkeep.into_scene();
        scene.sky.update(&desc.sky);
        scene.stats = SceneStats {
            meshes: desc.models.iter().map(|m| m.meshes.len()).sum(),
            unique_triangles: desc
                .models
                .iter()
                .flat_map(|m| m.meshes.iter())
                .map(|m| m.triangles.len())
                .sum(),
            instanced_triangles: desc
                .instances
                .iter()
                .filter_map(|i| desc.models.get(i.model))
                .map(model_triangles)
                .sum(),
            instances: scene.instances.len(),
            lights: scene.lights.count as usize,
            blas_build_seconds,
            tlas_build_seconds,
        };
        scene
    }
}
