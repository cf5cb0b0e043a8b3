//! Splits of a predicted cost field: [`fill_contiguous`] (the best contiguous bands) and
//! [`deal_interleaved`] (units dealt out in turn, then evened up).
//!
//! Both take a predicted cost per unit (seconds on a tracer of speed one) and a relative speed
//! per tracer, and minimise the predicted frame time `max_w Σ_{u∈w} cost_u / speed_w`, giving
//! every tracer at least one unit. Owns: the two placements. Must not: predict.

/// Unit counts of contiguous bands (tracer 0 at the top) minimising the predicted frame time,
/// exactly (dynamic programming over band ends, `O(tracers · units²)`). Needs
/// `costs.len() >= speeds.len() >= 1`.
pub fn fill_contiguous(costs: &[f64], speeds: &[f64]) -> Vec<usize> {
    let (units, tracers) = (costs.len(), speeds.len());
    let mut prefix = vec![0.0; units + 1];
    for (u, c) in costs.iter().enumerate() {
        prefix[u + 1] = prefix[u] + c.max(0.0);
    }
    // best[w][k]: the least max time when tracers 0..=w render units 0..k, each at least one.
    let mut best = vec![vec![f64::INFINITY; units + 1]; tracers];
    let mut cut = vec![vec![0usize; units + 1]; tracers];
    for k in 1..=units {
        best[0][k] = prefix[k] / speeds[0];
    }
    for w in 1..tracers {
        for k in (w + 1)..=units {
            for j in w..k {
                let t = best[w - 1][j].max((prefix[k] - prefix[j]) / speeds[w]);
                if t < best[w][k] {
                    best[w][k] = t;
                    cut[w][k] = j;
                }
            }
        }
    }
    let mut counts = vec![0; tracers];
    let mut end = units;
    for w in (1..tracers).rev() {
        let start = cut[w][end];
        counts[w] = end - start;
        end = start;
    }
    counts[0] = end;
    counts
}

/// Owners of every unit, dealt top to bottom so each tracer's predicted time keeps pace with
/// its share of the frame so far (every tracer gets units from every part of the image, so a
/// change in one region is shared by all), then evened up by moving single units from the
/// slowest tracer to the fastest while that lowers their larger time. Needs
/// `costs.len() >= speeds.len() >= 1`.
pub fn deal_interleaved(costs: &[f64], speeds: &[f64]) -> Vec<u16> {
    let (units, tracers) = (costs.len(), speeds.len());
    let total_speed: f64 = speeds.iter().sum();
    let share: Vec<f64> = speeds.iter().map(|s| s / total_speed).collect();
    let mut load = vec![0.0; tracers];
    let mut count = vec![0usize; tracers];
    let mut owners = vec![0u16; units];
    let mut so_far = 0.0;
    for (u, &c) in costs.iter().enumerate() {
        let c = c.max(0.0);
        so_far += c;
        let left = units - u;
        let starving = count.iter().filter(|&&n| n == 0).count();
        // The tracer furthest behind its share; a tracer with no unit yet when only as many
        // units are left as such tracers must be chosen.
        let w = (0..tracers)
            .filter(|&w| left > starving || count[w] == 0)
            .max_by(|&a, &b| {
                let da = share[a] * so_far - load[a];
                let db = share[b] * so_far - load[b];
                da.total_cmp(&db).then(b.cmp(&a))
            })
            .unwrap_or(0);
        owners[u] = w as u16;
        load[w] += c;
        count[w] += 1;
    }
    even_up(costs, speeds, &mut owners, &mut load, &mut count);
    owners
}

/// Moves single units from the tracer with the largest predicted time to the one with the
/// smallest while the larger of their two times drops.
fn even_up(
    costs: &[f64],
    speeds: &[f64],
    owners: &mut [u16],
    load: &mut [f64],
    count: &mut [usize],
) {
    let tracers = speeds.len();
    for _ in 0..owners.len() {
        let time = |w: usize, load: &[f64]| load[w] / speeds[w];
        let Some(slow) = (0..tracers).max_by(|&a, &b| time(a, load).total_cmp(&time(b, load)))
        else {
            return;
        };
        let Some(fast) = (0..tracers).min_by(|&a, &b| time(a, load).total_cmp(&time(b, load)))
        else {
            return;
        };
        if slow == fast || count[slow] <= 1 {
            return;
        }
        let before = time(slow, load);
        let best = owners
            .iter()
            .enumerate()
            .filter(|(_, o)| **o as usize == slow)
            .map(|(u, _)| {
                let c = costs[u].max(0.0);
                let after = ((load[slow] - c) / speeds[slow]).max((load[fast] + c) / speeds[fast]);
                (u, after)
            })
            .min_by(|a, b| a.1.total_cmp(&b.1));
        match best {
            Some((u, after)) if after < before * (1.0 - 1e-9) => {
                let c = costs[u].max(0.0);
                owners[u] = fast as u16;
                load[slow] -= c;
                load[fast] += c;
                count[slow] -= 1;
                count[fast] += 1;
            }
            _ => return,
        }
    }
}
