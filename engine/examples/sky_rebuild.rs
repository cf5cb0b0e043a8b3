//! Development aid: what a moving sun costs the render side's sky tables (issue 34 item 5).
//! Times, each the median of `rounds` runs: the full build of every table for a new atmosphere
//! on one thread (transmittance, the scattering orders and the sky-view table, serially), the
//! full build on the rayon pool (a new atmosphere), the
//! sky-view table alone on kept tables (the sun crossed an elevation step, built on the spot),
//! the same in twilight, the same when the table was built ahead (the sun moving steadily), and an update that keeps
//! everything (the sun moved within a step).
//! `cargo run --release -p candela --example sky_rebuild -- [rounds]`
use std::time::Instant;

use candela::sky::{PhysicalSky, SkyBaker, SkyTables};

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn time(rounds: usize, mut f: impl FnMut(usize)) -> f64 {
    median(
        (0..rounds)
            .map(|i| {
                let t = Instant::now();
                f(i);
                t.elapsed().as_secs_f64() * 1000.0
            })
            .collect(),
    )
}

fn main() {
    let rounds: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(5);
    let sky = |elevation: f32| PhysicalSky {
        sun_elevation_deg: elevation,
        ..PhysicalSky::default()
    };
    // A new atmosphere each round (the scattering orders are cached per atmosphere).
    let hazy = |elevation: f32, haze: f32| PhysicalSky {
        haze,
        ..sky(elevation)
    };
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("a one-thread pool");
    let serial = time(rounds, |i| {
        one.install(|| {
            SkyTables::build(&hazy(20.0 + i as f32, 1.1 + 0.01 * i as f32)).expect("sky")
        });
    });
    let full = time(rounds, |i| {
        SkyTables::build(&hazy(20.0 + i as f32, 2.1 + 0.01 * i as f32)).expect("sky");
    });
    let mut baker = SkyBaker::default();
    baker.update(&sky(10.0)).expect("sky");
    let view = time(rounds, |i| {
        baker
            .update(&sky(10.0 + 0.2 * (i + 1) as f32))
            .expect("sky");
    });
    let view_serial = time(rounds, |i| {
        one.install(|| {
            baker
                .update(&sky(30.0 + 0.2 * (i + 1) as f32))
                .expect("sky")
        });
    });
    let twilight = time(rounds, |i| {
        baker.update(&sky(4.0 - 0.2 * (i + 1) as f32)).expect("sky");
    });
    // The sun moving steadily, the next step's table done ahead (given a second to finish).
    let ahead = median(
        (0..rounds)
            .map(|i| {
                std::thread::sleep(std::time::Duration::from_secs(1));
                let t = Instant::now();
                baker.update(&sky(50.0 + 0.1 * i as f32)).expect("sky");
                t.elapsed().as_secs_f64() * 1000.0
            })
            .collect(),
    );
    let kept = time(rounds, |i| {
        baker
            .update(&sky(30.0 + 0.2 * rounds as f32 + 0.001 * i as f32))
            .expect("sky");
    });
    println!("rayon threads {}", rayon::current_num_threads());
    println!("full build, one thread (before)   {serial:8.1} ms");
    println!("full build, rayon (new atmosphere) {full:8.1} ms");
    println!("sky-view only, rayon (sun moved)   {view:8.1} ms");
    println!("sky-view only, one thread          {view_serial:8.1} ms");
    println!(
        "sky-view only, rayon, twilight     {twilight:8.1} ms (the orders table read at every step)"
    );
    println!("sky-view built ahead, taken        {ahead:8.3} ms (the first round builds)");
    println!("kept (sun within a 0.1 deg step)   {kept:8.4} ms");
}
