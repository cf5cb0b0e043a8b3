//! The frame pipeline end to end, headless, on the CPU tracer: world → extract → upkeep →
//! commit → render thread. Checks that
//! * every submitted frame is rendered and shutdown is clean (all results returned, the thread
//!   joined, no deadlock) — also when the engine is dropped mid-run;
//! * ray queries made by game code during a frame see the scene of the previous commit while the
//!   render thread renders, and are exact;
//! * the overlap is real: with game update and rendering both loaded (the render load is
//!   measured and must have landed), the frames take less wall time than the update time plus
//!   the render thread's busy time, which serial execution could not (`bench pipeline` gives
//!   the ratio);
//! * once everything stops moving, the converged image equals a direct render of the final
//!   scene within noise, per channel, over the whole image and each of 4 × 4 regions.

use std::time::{Duration, Instant};

use candela::app::Step;
use candela::ecs::{GlobalTransform, Transform};
use candela::trace::Ray;
use glam::{Mat4, Vec3};

use crate::pipeline_common;

use pipeline_common::{direct_batches, environment, quad_model, scene};

#[test]
fn every_frame_renders_and_shutdown_is_clean() {
    let (mut engine, platforms) = scene(1, 16, 5);
    for frame in 0..30 {
        engine
            .frame(1.0 / 60.0, &mut |step: &mut Step<'_>| {
                let world = &mut *step.world;
                let dt = step.step_seconds;
                for (i, &p) in platforms.iter().enumerate() {
                    if let Ok(mut t) = world.get::<&mut Transform>(p) {
                        t.translation.y = 1.0 + (frame as f32 * dt as f32 + i as f32).sin();
                    }
                }
            })
            .expect("frame");
    }
    let results = engine.shutdown();
    let mut frames: Vec<u64> = Vec::new();
    for r in results {
        frames.push(r.expect("render ok").frame);
    }
    // Results that the main thread had not collected yet come back at shutdown; together
    // every frame is there exactly once, in order: the whole list.
    assert_eq!(frames, (0..30).collect::<Vec<u64>>());

    // Dropping a running engine joins its render thread (no deadlock, no panic).
    let (mut engine, _) = scene(1, 16, 3);
    for _ in 0..5 {
        engine
            .frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})
            .expect("frame");
    }
    drop(engine);
}

#[test]
fn queries_see_the_last_commit_while_the_render_thread_renders() {
    let (mut engine, platforms) = scene(4, 48, 3);
    let probe = platforms[1];
    let x = engine
        .world()
        .get::<&Transform>(probe)
        .expect("probe")
        .translation
        .x;
    let mut heights = Vec::new();
    for frame in 0..20 {
        let target = 0.5 + 0.1 * frame as f32;
        let mut seen = None;
        engine
            .frame(1.0 / 60.0, &mut |step: &mut Step<'_>| {
                let world = &mut *step.world;
                let queries = step.queries;
                // The ray down onto the probe platform sees last frame's height.
                let ray = Ray::new(Vec3::new(x, 3.5, 0.0), Vec3::NEG_Y); // below the lamp
                if let Some(hit) = queries.closest(&ray) {
                    seen = Some((hit.entity, hit.position.y, hit.geometric_normal));
                }
                if let Ok(mut t) = world.get::<&mut Transform>(probe) {
                    t.translation.y = target;
                }
            })
            .expect("frame");
        heights.push((seen, target));
    }
    for (frame, window) in heights.windows(2).enumerate() {
        let (seen, _) = window[1];
        let (_, previous_target) = window[0];
        let (entity, y, normal) = seen.expect("the probe is always below the ray");
        assert_eq!(entity, Some(probe), "frame {}", frame + 1);
        assert!(
            (y - previous_target).abs() < 1e-5,
            "frame {}: {y} vs {previous_target}",
            frame + 1
        );
        assert!((normal.abs() - Vec3::Y).length() < 1e-5);
    }
    engine.shutdown();
}

/// Samples per pixel at which a 96 × 96 frame of the overlap scene takes at least about
/// `seconds` to render (measured, rescaled up to four times).
fn calibrated_spp(seconds: f64) -> u32 {
    let mut spp = 1u32;
    for _ in 0..4 {
        let (mut engine, _) = scene(spp, 96, 20);
        let mut render = 0.0;
        for _ in 0..3 {
            engine
                .frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})
                .expect("frame");
            render = engine
                .wait_rendered()
                .expect("result")
                .expect("ok")
                .render_seconds;
        }
        engine.shutdown();
        if render >= seconds || spp >= 512 {
            break;
        }
        spp =
            ((f64::from(spp) * 1.2 * seconds / render.max(1e-4)).ceil() as u32).clamp(spp + 1, 512);
    }
    spp
}

#[test]
fn update_and_render_overlap() {
    // Serial execution takes at least (update time + render-thread busy time); overlapped it
    // can take less. Both are measured (the update by the game callback, the render thread's
    // apply + trace time by itself), so the check needs no assumed speed: only that the
    // render load landed, which is asserted first.
    let update = Duration::from_millis(80);
    let spp = calibrated_spp(update.as_secs_f64());
    let (mut engine, _) = scene(spp, 96, 20);
    for _ in 0..3 {
        engine
            .frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {
                std::thread::sleep(update)
            })
            .expect("frame");
    }
    let _ = engine.rendered();
    let started = Instant::now();
    let mut update_total = 0.0f64;
    let mut busy = Vec::new();
    for _ in 0..12 {
        engine
            .frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {
                let t = Instant::now();
                std::thread::sleep(update);
                update_total += t.elapsed().as_secs_f64();
            })
            .expect("frame");
        for r in engine.rendered() {
            let r = r.expect("ok");
            busy.push(r.apply_seconds + r.render_seconds);
        }
    }
    let elapsed = started.elapsed().as_secs_f64();
    // The first result may have been rendering before `started`: leave it out; every other
    // collected render ran entirely inside the timed window.
    let inside: f64 = busy.iter().skip(1).sum();
    eprintln!(
        "{spp} spp: {} renders inside, busy {inside:.3} s; updates {update_total:.3} s; wall {elapsed:.3} s",
        busy.len().saturating_sub(1)
    );
    assert!(
        busy.len() > 6 && inside >= 0.5 * update_total,
        "the render load did not land: {} renders collected, {inside:.3} s busy against {update_total:.3} s of updates",
        busy.len()
    );
    assert!(
        elapsed < update_total + inside,
        "not overlapped: {elapsed:.3} s of wall time for {update_total:.3} s of updates and {inside:.3} s of rendering"
    );
    engine.shutdown();
}

#[test]
fn still_scene_converges_to_a_direct_render() {
    use candela::assets::{SceneDesc, SceneInstance};
    let (mut engine, platforms) = scene(2, 24, 2);
    // Move for a while, then stop and let the image converge for 40 frames.
    for frame in 0..50 {
        let moving = frame < 10;
        if frame == 49 {
            engine.capture_next();
        }
        engine
            .frame(1.0 / 60.0, &mut |step: &mut Step<'_>| {
                let world = &mut *step.world;
                if moving {
                    for &p in &platforms {
                        if let Ok(mut t) = world.get::<&mut Transform>(p) {
                            t.translation.z += 0.2;
                        }
                    }
                }
            })
            .expect("frame");
    }
    let positions: Vec<Mat4> = platforms
        .iter()
        .map(|&p| engine.world().get::<&GlobalTransform>(p).expect("global").0)
        .collect();
    let results = engine.shutdown();
    let film = results
        .into_iter()
        .filter_map(|r| r.expect("ok").film)
        .next_back()
        .expect("captured film");
    // The same final scene, rendered directly with the same total samples (40 still frames × 2).
    let mut desc = SceneDesc::single(quad_model(20.0, 0.0), environment().default_camera);
    desc.models = vec![
        quad_model(20.0, 0.0),
        quad_model(2.0, 5.0),
        quad_model(0.5, 0.0),
    ];
    desc.sky = environment().sky;
    desc.render = environment().render;
    desc.instances = vec![
        SceneInstance::placed(0, Mat4::IDENTITY),
        SceneInstance::placed(1, Mat4::from_translation(Vec3::Y * 4.0)),
    ];
    for m in positions {
        desc.instances.push(SceneInstance::placed(2, m));
    }
    const SIZE: u32 = 24;
    let direct = direct_batches(&desc, SIZE, 80);
    assert_eq!(film.mean.len(), (SIZE * SIZE) as usize);
    assert!(film.mean.iter().all(|p| p.is_finite()), "non-finite pixel");
    // Two estimates of the same region means, each from 80 spp per pixel; the standard error
    // of the direct one comes from its batches' per-pixel spread, and the converged film has
    // as many samples, so their difference has √2 times that standard error. Regions: the
    // image and a 4 × 4 grid (6 × 6 pixels each), every channel: 51 comparisons at 4.5 σ.
    let cell = SIZE / 4;
    let mut failures = Vec::new();
    for region in 0..17u32 {
        let keep = |x: u32, y: u32| region == 16 || (x / cell + 4 * (y / cell)) == region;
        let (mean, std_error) = region_stat(&direct, SIZE, keep);
        let pixels: Vec<usize> = (0..SIZE * SIZE)
            .filter(|i| keep(i % SIZE, i / SIZE))
            .map(|i| i as usize)
            .collect();
        for c in 0..3 {
            let ours = pixels
                .iter()
                .map(|&i| f64::from(film.mean[i][c]))
                .sum::<f64>()
                / pixels.len() as f64;
            let tolerance = 4.5 * std_error[c] * std::f64::consts::SQRT_2;
            if !((ours - mean[c]).abs() <= tolerance) {
                failures.push(format!(
                    "region {region} channel {c}: converged {ours:.5} vs direct {:.5} ± {:.5}",
                    mean[c], std_error[c]
                ));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// A direct render of `desc`: `spp` per pixel in 8 independent batches, each batch's film.
/// `RenderConfig::denoise` on the render thread: the captured film is the denoiser's, finite,
/// closer to a direct many-sample render than the undenoised film of the same frames, and the
/// denoiser's time is reported (0 when it is off).

/// Mean of a region of the batches' overall image (per channel) and its standard error: each
/// pixel's variance of its overall mean from its batch spread (unbiased), summed over the
/// region (pixels are independent), so the estimate has (batches − 1) × pixels degrees of
/// freedom and 4.5 σ keeps its normal meaning.
fn region_stat(
    batches: &[Vec<Vec3>],
    size: u32,
    keep: impl Fn(u32, u32) -> bool,
) -> ([f64; 3], [f64; 3]) {
    let k = batches.len() as f64;
    let (mut mean, mut var, mut n) = ([0.0f64; 3], [0.0f64; 3], 0.0f64);
    for i in 0..(size * size) as usize {
        if !keep(i as u32 % size, i as u32 / size) {
            continue;
        }
        n += 1.0;
        for c in 0..3 {
            let m = batches.iter().map(|b| f64::from(b[i][c])).sum::<f64>() / k;
            let v = batches
                .iter()
                .map(|b| (f64::from(b[i][c]) - m).powi(2))
                .sum::<f64>()
                / (k - 1.0)
                / k;
            mean[c] += m;
            var[c] += v;
        }
    }
    (mean.map(|m| m / n), var.map(|v| (v / (n * n)).sqrt()))
}
