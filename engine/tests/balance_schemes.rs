//! Workload balancing schemes (render/balance, Brigade §4.3): every scheme covers every row of
//! every frame exactly once and gives every tracer work, for any tracer speeds; Robin Hood moves
//! exactly one unit per frame; Perfect reaches the equal-time split in one frame on a static,
//! even cost field; Perfect Smooth converges to it; our schemes reach the best split a unit
//! size allows on a static uneven field, and the pieces they stand on (rounding, band placement,
//! dealing, speed estimate) do what they say.

use candela::render::balance::{
    Balancer, CostModel, FrameTimes, Perfect, PerfectSmooth, RobinHood, SchemeKind, SpeedEstimate,
    Split, apportion, deal_interleaved, fill_contiguous, idle_share, unit_count,
};

/// A deterministic stream of numbers in [0, 1) (xorshift).
struct Noise(u64);

impl Noise {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// What a pool of tracers of `speeds` reports after rendering `costs` (seconds on a speed-one
/// tracer per unit) with `split`.
fn measure(split: &Split, costs: &[f64], speeds: &[f64]) -> FrameTimes {
    let unit_seconds: Vec<f64> = (0..split.units())
        .map(|u| costs[u] / speeds[split.owner(u)])
        .collect();
    let mut tracer_seconds = vec![0.0; speeds.len()];
    for (u, t) in unit_seconds.iter().enumerate() {
        tracer_seconds[split.owner(u)] += t;
    }
    FrameTimes {
        split: split.clone(),
        tracer_seconds,
        unit_seconds,
    }
}

/// Runs `scheme` for `frames` frames over cost fields from `field(frame)`, checking every split
/// with `check`, and returns the frame times.
fn run(
    scheme: &mut dyn Balancer,
    speeds: &[f64],
    frames: usize,
    mut field: impl FnMut(usize) -> Vec<f64>,
    mut check: impl FnMut(&Split),
) -> Vec<FrameTimes> {
    let mut last: Option<FrameTimes> = None;
    let mut out = Vec::new();
    for f in 0..frames {
        let split = scheme.next(last.as_ref());
        check(&split);
        let m = measure(&split, &field(f), speeds);
        out.push(m.clone());
        last = Some(m);
    }
    out
}

/// A sky-over-city field: cheap top rows, expensive bottom rows, a bright band that drifts.
fn city_field(units: usize, frame: usize) -> Vec<f64> {
    (0..units)
        .map(|u| {
            let y = u as f64 / units as f64;
            let drift = ((y * 9.0 + frame as f64 * 0.3).sin() + 1.0) * 0.5;
            if y < 0.4 {
                0.05 + 0.02 * drift
            } else {
                1.0 + 2.0 * drift * y
            }
        })
        .collect()
}

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

/// The frame time of contiguous bands `counts` over `costs` on tracers of `speeds`.
fn band_time(counts: &[usize], costs: &[f64], speeds: &[f64]) -> f64 {
    let mut start = 0;
    let mut worst: f64 = 0.0;
    for (w, n) in counts.iter().enumerate() {
        worst = worst.max(costs[start..start + n].iter().sum::<f64>() / speeds[w]);
        start += n;
    }
    worst
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

#[test]
fn split_rejects_bad_owners_and_idle_tracers() {
    assert!(
        Split::from_owners(vec![0, 1, 2], 2).is_err(),
        "owner out of range"
    );
    assert!(
        Split::from_owners(vec![0, 0, 0], 2).is_err(),
        "tracer 1 without work"
    );
    assert!(Split::contiguous(&[3, 0, 2]).is_err());
    assert!(Split::equal(2, 3).is_err());
    let s = Split::from_owners(vec![1, 0, 1, 0, 0], 2).expect("valid");
    assert_eq!(s.counts(), vec![3, 2]);
    assert_eq!(s.units_of(1).collect::<Vec<_>>(), vec![0, 2]);
    assert_eq!(s.rows_of(1, 18), vec![0, 1, 2, 3, 8, 9, 10, 11]);
    assert_eq!(s.rows_of(0, 18), vec![4, 5, 6, 7, 12, 13, 14, 15, 16, 17]);
}

#[test]
fn apportion_rounds_to_the_total_and_keeps_one_unit_each() {
    assert_eq!(apportion(&[1.0, 1.0, 1.0], 10), vec![4, 3, 3]);
    assert_eq!(apportion(&[0.999, 0.001], 10), vec![9, 1]);
    assert_eq!(apportion(&[0.0, 0.0], 7), vec![4, 3]);
    assert_eq!(apportion(&[f64::NAN, 1.0], 7), vec![1, 6]);
    let mut noise = Noise(7);
    for _ in 0..500 {
        let n = 1 + (noise.next() * 6.0) as usize;
        let units = n + (noise.next() * 200.0) as usize;
        let shares: Vec<f64> = (0..n).map(|_| noise.next().powi(4)).collect();
        let counts = apportion(&shares, units);
        assert_eq!(counts.iter().sum::<usize>(), units);
        assert!(counts.iter().all(|&c| c >= 1));
        let total: f64 = shares.iter().sum();
        for (c, s) in counts.iter().zip(&shares) {
            // Within one unit of the ideal, except where the one-unit floor lifts it.
            let ideal = s / total * units as f64;
            assert!(
                (*c as f64 - ideal).abs() < n as f64 || *c == 1,
                "{counts:?} for {shares:?}"
            );
        }
    }
}

#[test]
fn fill_contiguous_finds_the_best_bands() {
    let mut noise = Noise(11);
    for _ in 0..200 {
        let units = 3 + (noise.next() * 14.0) as usize;
        let costs: Vec<f64> = (0..units).map(|_| noise.next() * 3.0).collect();
        let speeds = [0.5 + noise.next(), 0.5 + noise.next(), 0.5 + noise.next()];
        let time = |c: &[usize]| {
            let mut start = 0;
            let mut worst: f64 = 0.0;
            for (w, n) in c.iter().enumerate() {
                worst = worst.max(costs[start..start + n].iter().sum::<f64>() / speeds[w]);
                start += n;
            }
            worst
        };
        let mut brute = f64::MAX;
        for a in 1..units - 1 {
            for b in 1..units - a {
                brute = brute.min(time(&[a, b, units - a - b]));
            }
        }
        let counts = fill_contiguous(&costs, &speeds);
        assert_eq!(counts.iter().sum::<usize>(), units);
        assert!(counts.iter().all(|&c| c >= 1));
        assert!(
            (time(&counts) - brute).abs() < 1e-12,
            "{counts:?}: {} vs {brute}",
            time(&counts)
        );
    }
}

#[test]
fn dealt_units_interleave_and_balance_within_a_unit() {
    let units = 90;
    let costs = city_field(units, 3);
    let speeds = [1.0, 2.0, 0.7];
    let owners = deal_interleaved(&costs, &speeds);
    let mut load = [0.0; 3];
    for (u, &o) in owners.iter().enumerate() {
        load[o as usize] += costs[u];
    }
    let times: Vec<f64> = (0..3).map(|w| load[w] / speeds[w]).collect();
    let ideal = costs.iter().sum::<f64>() / speeds.iter().sum::<f64>();
    let max_unit = costs.iter().copied().fold(0.0, f64::max);
    let worst = times.iter().copied().fold(0.0, f64::max);
    assert!(
        worst <= ideal + max_unit / 0.7,
        "{times:?} vs ideal {ideal}"
    );
    // Interleaved: every tracer has units in the top and in the bottom half of the image.
    for w in 0..3u16 {
        assert!(
            owners[..units / 2].contains(&w) && owners[units / 2..].contains(&w),
            "{owners:?}"
        );
    }
}

#[test]
fn speed_estimate_recovers_relative_speeds() {
    let units = 80;
    let speeds = [1.0, 2.0, 0.5];
    let mut scheme = candela::render::balance::Interleaved::new(units, 3);
    let times = run(&mut scheme, &speeds, 20, |f| city_field(units, f), |_| {});
    let mut estimate = SpeedEstimate::new(3);
    for m in &times {
        estimate.observe(m);
    }
    let got = estimate.speeds();
    for w in 0..3 {
        let (ratio, truth) = (got[w] / got[0], speeds[w] / speeds[0]);
        assert!(
            (ratio / truth - 1.0).abs() < 0.05,
            "tracer {w}: {ratio} vs {truth} ({got:?})"
        );
    }
}

#[test]
fn idle_share_is_the_papers_measure() {
    assert_eq!(idle_share(&[2.0, 1.0]), 0.25);
    assert_eq!(idle_share(&[3.0, 3.0, 3.0]), 0.0);
    assert!((idle_share(&[3.0, 0.0, 0.0]) - 2.0 / 3.0).abs() < 1e-12);
    assert_eq!(idle_share(&[]), 0.0);
}
