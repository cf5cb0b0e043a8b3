//! The CPU tracer pool (render/balance/pool.rs): a frame split over several CPU tracers of
//! different thread counts, contiguous or interleaved, composes into the very film a single
//! `CpuTracer` renders, sample for sample (bit for bit), also when a second frame blends into
//! the first; and it reports a time for every tracer and every unit.

use std::path::Path;

use candela::assets::{AssetRoot, load_scene};
use candela::render::balance::{CpuPool, Split, deal_interleaved, unit_count};
use candela::render::cpu::CpuTracer;
use candela::render::film::Film;
use candela::render::{FrameSettings, Tracer, frame_uniforms};
use candela::scene::RenderScene;

#[test]
fn a_split_frame_equals_the_single_tracer_frame() -> anyhow::Result<()> {
    let assets = Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/test_scenes/script");
    let desc = load_scene(&assets.join("small.ron"), &AssetRoot::new(&assets)?)?;
    let scene = RenderScene::build(&desc);
    // 38 rows: 10 units, the last of two rows.
    let (width, height) = (40, 38);
    let units = unit_count(height);
    let uniforms = |frame: u32| {
        let s = FrameSettings::new(width, height, 2, 5, &desc.render).continuing(frame * 2);
        frame_uniforms(
            &desc.camera,
            desc.sun.as_ref(),
            &desc.sky,
            &s,
            &scene.header(),
        )
    };
    let mut single = CpuTracer::new();
    let mut single_films = Vec::new();
    for frame in 0..2 {
        single.render(&scene, &uniforms(frame))?;
        single_films.push(single.film()?);
    }
    let costs: Vec<f64> = (0..units).map(|u| 1.0 + (u % 3) as f64).collect();
    let splits = [
        (vec![1, 2], Split::contiguous(&[3, 7])?),
        (vec![1, 1, 1], Split::equal(units, 3)?),
        (
            vec![2, 1],
            Split::from_owners(deal_interleaved(&costs, &[1.0, 1.0]), 2)?,
        ),
    ];
    for (threads, split) in splits {
        let pool = CpuPool::new(&threads)?;
        let mut film = Film::new(0, 0);
        for (frame, expected) in single_films.iter().enumerate() {
            let times = pool.render(&scene, &uniforms(frame as u32), &split, &mut film)?;
            assert!(
                film.mean == expected.mean,
                "threads {threads:?}, split {:?}, frame {frame}: the composed film differs",
                split.owners()
            );
            assert_eq!(film.samples, expected.samples);
            assert!(times.tracer_seconds.iter().all(|t| *t > 0.0));
            assert_eq!(times.unit_seconds.len(), units);
            assert!(times.unit_seconds.iter().all(|t| *t >= 0.0));
        }
    }
    // A split that does not fit the pool or the frame is refused.
    let pool = CpuPool::new(&[1, 1])?;
    let mut film = Film::new(0, 0);
    assert!(
        pool.render(&scene, &uniforms(0), &Split::equal(units, 3)?, &mut film)
            .is_err()
    );
    assert!(
        pool.render(
            &scene,
            &uniforms(0),
            &Split::equal(units + 1, 2)?,
            &mut film
        )
        .is_err()
    );
    Ok(())
}
