//! The pieces the balancing schemes stand on (render/balance): splits refuse bad owners and idle
//! tracers, rounding shares keeps the total and one unit each, the contiguous placement is
//! optimal, dealt units interleave and balance within a unit, the speed estimate recovers
//! relative speeds from unit times alone, and the idle share is the paper's measure.

use crate::balance_common;

use balance_common::{Noise, city_field, run};
use candela::render::balance::{
    Interleaved, SpeedEstimate, Split, apportion, deal_interleaved, fill_contiguous, idle_share,
};

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
    let mut scheme = Interleaved::new(units, 3);
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
