//! Workload balancing schemes (render/balance, Brigade §4.3): every scheme covers every row of
//! every frame exactly once and gives every tracer work, for any tracer speeds; Robin Hood moves
//! exactly one unit per frame; Perfect reaches the equal-time split in one frame on a static,
//! even cost field; Perfect Smooth converges to it; our schemes reach the best split a unit
//! size allows on a static uneven field where Perfect overcompensates.

use crate::balance_common;

use balance_common::{Noise, band_time, city_field, measure, run};
use candela::render::balance::Balancer;
use candela::render::balance::{
    CostModel, Perfect, PerfectSmooth, RobinHood, SchemeKind, Split, fill_contiguous, idle_share,
    unit_count,
};

#[test]
fn every_scheme_covers_every_row_once_and_starves_no_tracer() {
    let height = 250; // not a multiple of 4: the last unit has two rows
    let units = unit_count(height);
    assert_eq!(units, 63);
    let speed_sets: [&[f64]; 6] = [
        &[1.0, 1.0],
        &[1.0, 3.0],
        &[1.0, 1.0, 1.0],
        &[0.2, 1.0, 5.0],
        &[1000.0, 1.0],
        &[1.0, 1.0, 1.0, 1.0, 0.01],
    ];
    for speeds in speed_sets {
        for kind in SchemeKind::ALL {
            let mut scheme = kind.build(units, speeds.len());
            let mut noise = Noise(0x9e37_79b9_7f4a_7c15);
            let name = scheme.name();
            run(
                scheme.as_mut(),
                speeds,
                60,
                |_| {
                    (0..units)
                        .map(|_| 0.01 + noise.next() * noise.next() * 5.0)
                        .collect()
                },
                |split| {
                    assert_eq!(split.units(), units, "{name}");
                    let mut seen = vec![0u32; height as usize];
                    for w in 0..speeds.len() {
                        let rows = split.rows_of(w, height);
                        assert!(
                            !rows.is_empty(),
                            "{name} {speeds:?}: tracer {w} has no work"
                        );
                        for y in rows {
                            seen[y as usize] += 1;
                        }
                    }
                    assert!(
                        seen.iter().all(|&n| n == 1),
                        "{name} {speeds:?}: some row rendered {} times, some {} times",
                        seen.iter().max().unwrap_or(&0),
                        seen.iter().min().unwrap_or(&0)
                    );
                },
            );
        }
    }
}

#[test]
fn robin_hood_moves_one_unit_per_frame_from_the_last_to_the_first() {
    let (units, speeds) = (40, [1.0, 2.0, 4.0]);
    let mut scheme = RobinHood::new(units, speeds.len());
    let costs = vec![1.0; units];
    let mut counts_before: Option<(Vec<usize>, Vec<f64>)> = None;
    run(
        &mut scheme,
        &speeds,
        30,
        |_| costs.clone(),
        |split| {
            let counts = split.counts();
            if let Some((before, times)) = &counts_before {
                let slowest = (0..3)
                    .max_by(|&a, &b| times[a].total_cmp(&times[b]))
                    .unwrap_or(0);
                let fastest = (0..3)
                    .min_by(|&a, &b| times[a].total_cmp(&times[b]))
                    .unwrap_or(0);
                let moved: usize = counts.iter().zip(before).map(|(a, b)| a.abs_diff(*b)).sum();
                assert_eq!(
                    moved, 2,
                    "one unit leaves one tracer and joins another: {before:?} → {counts:?}"
                );
                assert_eq!(counts[slowest] + 1, before[slowest]);
                assert_eq!(counts[fastest], before[fastest] + 1);
            } else {
                assert_eq!(counts, vec![14, 13, 13], "starts equal");
            }
            let m = measure(split, &costs, &speeds);
            counts_before = Some((counts, m.tracer_seconds));
        },
    );
    // Equal times: nothing moves.
    let split = Split::contiguous(&[10, 20]).expect("valid");
    let m = measure(&split, &vec![1.0; 30], &[1.0, 2.0]);
    assert_eq!(RobinHood::new(30, 2).next(Some(&m)), split);
}

#[test]
fn perfect_reaches_the_equal_time_split_in_one_frame_on_an_even_static_field() {
    for (units, speeds, expected) in [
        (40, vec![1.0, 3.0], vec![10, 30]),
        (80, vec![1.0, 2.0, 5.0], vec![10, 20, 50]),
        (60, vec![2.0, 1.0, 1.0, 2.0], vec![20, 10, 10, 20]),
    ] {
        let costs = vec![0.25; units];
        let times = run(
            &mut Perfect::new(units, speeds.len()),
            &speeds,
            3,
            |_| costs.clone(),
            |_| {},
        );
        assert!(
            idle_share(&times[0].tracer_seconds) > 0.1,
            "the first, equal frame is unbalanced"
        );
        for m in &times[1..] {
            assert_eq!(m.split.counts(), expected, "speeds {speeds:?}");
            assert!(idle_share(&m.tracer_seconds) < 1e-12);
        }
    }
}

#[test]
fn perfect_smooth_converges_to_the_perfect_split() {
    let (units, speeds) = (40, [1.0, 3.0]);
    let costs = vec![1.0; units];
    let mut scheme = PerfectSmooth::new(units, 2, 0.5);
    let times = run(&mut scheme, &speeds, 12, |_| costs.clone(), |_| {});
    // α = 0.5: the share error halves per frame; from 20/20 to 10/30 it is within a unit after 5.
    assert_ne!(
        times[1].split.counts(),
        vec![10, 30],
        "smoothing takes more than one frame"
    );
    for m in &times[6..] {
        assert_eq!(m.split.counts(), vec![10, 30]);
    }
}

#[test]
fn our_schemes_reach_the_best_split_on_a_static_uneven_field() {
    let units = 60;
    let costs = city_field(units, 0);
    let max_unit = costs.iter().copied().fold(0.0, f64::max);
    for speeds in [
        vec![1.0, 1.0],
        vec![1.0, 2.5],
        vec![1.0, 1.0, 1.0],
        vec![3.0, 1.0, 0.5],
    ] {
        // The best contiguous bands on the true costs and speeds.
        let best_bands = band_time(&fill_contiguous(&costs, &speeds), &costs, &speeds);
        // Any split is at least the ideal; dealing gets within one unit of it.
        let ideal = costs.iter().sum::<f64>() / speeds.iter().sum::<f64>();
        let dealt_bound = ideal + max_unit / speeds.iter().copied().fold(f64::MAX, f64::min);
        for (kind, bound) in [
            // The speeds are estimated, so a unit changing hands may be mispredicted by the
            // estimate's error (a few per cent of one unit): 1 % of the frame covers it.
            (SchemeKind::CostModel, best_bands * 1.01),
            (SchemeKind::Interleaved, dealt_bound),
        ] {
            let mut scheme = kind.build(units, speeds.len());
            let times = run(scheme.as_mut(), &speeds, 12, |_| costs.clone(), |_| {});
            for m in &times[8..] {
                assert!(
                    m.frame_seconds() >= ideal * (1.0 - 1e-12) && m.frame_seconds() <= bound,
                    "{kind:?} {speeds:?}: frame {} s, ideal {ideal} s, bound {bound} s",
                    m.frame_seconds()
                );
            }
        }
    }
}

#[test]
fn cost_model_uses_per_unit_times_where_perfect_overcompensates() {
    // Two equal tracers, sky on top: Perfect hands the sky tracer the expensive rows next.
    let units = 60;
    let costs = city_field(units, 0);
    let speeds = [1.0, 1.0];
    let best = band_time(&fill_contiguous(&costs, &speeds), &costs, &speeds);
    let perfect = run(
        &mut Perfect::new(units, 2),
        &speeds,
        2,
        |_| costs.clone(),
        |_| {},
    );
    let ours = run(
        &mut CostModel::new(units, 2),
        &speeds,
        2,
        |_| costs.clone(),
        |_| {},
    );
    let p = idle_share(&perfect[1].tracer_seconds);
    assert!(p > 0.1, "Perfect's second frame idles {p}");
    assert!(
        ours[1].frame_seconds() <= best * 1.01,
        "the cost model's second frame takes {} s, the best bands {best} s",
        ours[1].frame_seconds()
    );
}
