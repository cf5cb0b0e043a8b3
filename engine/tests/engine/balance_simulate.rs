//! The device simulator and the cost files (render/balance/simulate.rs, costs.rs): a replay
//! gives each simulated tracer the sum of its units' costs over its speed and the paper's idle
//! share per frame; cost files round-trip and bad ones are refused with the line at fault.

use candela::render::balance::{CostTrace, Equal, SchemeKind, idle_share, simulate};

fn trace(frames: Vec<Vec<f64>>, height: u32) -> CostTrace {
    let rays = frames
        .iter()
        .map(|f| f.iter().map(|c| (c * 1000.0) as u64).collect())
        .collect();
    CostTrace {
        width: 8,
        height,
        notes: vec![("camera".into(), "test".into())],
        unit_seconds: frames,
        unit_rays: rays,
    }
}

#[test]
fn a_replay_times_each_tracer_by_its_units_and_speed() {
    // 4 units (16 rows); top half cheap.
    let t = trace(vec![vec![1e-3, 1e-3, 3e-3, 3e-3]; 3], 16);
    let report = simulate(&t, &[1.0, 2.0], &mut Equal::new(4, 2));
    assert_eq!(report.frames.len(), 3);
    for f in &report.frames {
        assert_eq!(f.counts, vec![2, 2]);
        // Tracer 0: 2 ms at speed 1; tracer 1: 6 ms at speed 2 = 3 ms.
        assert!((f.tracer_seconds[0] - 2e-3).abs() < 1e-15);
        assert!((f.tracer_seconds[1] - 3e-3).abs() < 1e-15);
        assert!((f.idle_share - idle_share(&[2e-3, 3e-3])).abs() < 1e-15);
    }
    assert!((report.mean_idle() - 1.0 / 6.0).abs() < 1e-12);
    assert!((report.total_seconds() - 9e-3).abs() < 1e-15);
}

#[test]
fn balancing_schemes_beat_no_balancing_on_a_steady_uneven_field() {
    let frame: Vec<f64> = (0..30).map(|u| if u < 12 { 1e-4 } else { 1e-3 }).collect();
    let t = trace(vec![frame; 40], 120);
    let none = simulate(&t, &[1.0, 1.0], SchemeKind::Equal.build(30, 2).as_mut()).mean_idle();
    assert!(none > 0.2, "{none}");
    for kind in SchemeKind::ALL
        .into_iter()
        .filter(|k| *k != SchemeKind::Equal)
    {
        let idle = simulate(&t, &[1.0, 1.0], kind.build(30, 2).as_mut()).mean_idle();
        assert!(idle < none, "{kind:?}: {idle} vs none {none}");
    }
}

#[test]
fn cost_files_round_trip() -> anyhow::Result<()> {
    let t = trace(vec![vec![1.5e-3, 2.25e-4, 0.0], vec![1e-6, 2e-6, 3e-6]], 10);
    let back = CostTrace::parse("test.csv", &t.to_csv())?;
    assert_eq!(back.width, 8);
    assert_eq!(back.height, 10);
    assert_eq!(back.notes, t.notes);
    assert_eq!(back.unit_rays, t.unit_rays);
    for (a, b) in back
        .unit_seconds
        .iter()
        .flatten()
        .zip(t.unit_seconds.iter().flatten())
    {
        // Written in microseconds with two decimals.
        assert!((a - b).abs() <= 0.5e-8, "{a} vs {b}");
    }
    Ok(())
}

#[test]
fn bad_cost_files_name_the_line() {
    let head = "# width=8\n# height=8\nframe,kind,u0,u1\n";
    for (body, line, what) in [
        ("0,us,1.0\n", 4, "values"),
        ("0,us,1.0,x\n", 4, "unit time"),
        ("0,us,1.0,-2\n", 4, "non-negative"),
        ("0,us,1,1\n2,us,1,1\n", 5, "out of order"),
        ("0,joules,1,1\n", 4, "unknown kind"),
        ("0,rays,1,1.5\n", 4, "ray count"),
    ] {
        let text = format!("{head}{body}");
        let err = CostTrace::parse("bad.csv", &text)
            .expect_err(body)
            .to_string();
        assert!(
            err.contains(&format!("line {line}")) && err.contains(what),
            "{body:?}: {err}"
        );
    }
    assert!(CostTrace::parse("bad.csv", "# width=8\n# height=8\n0,us,1,1\n").is_err());
    assert!(CostTrace::parse("bad.csv", "# width=8\n# height=8\nframe,kind,u0,u1\n").is_err());
}
