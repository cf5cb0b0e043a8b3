//! [`apportion`]: whole unit counts from fractional shares (largest remainder, at least one
//! unit per tracer).
//!
//! Owns: rounding only. Must not: know where the shares came from.

/// Splits `units` whole units in proportion to `shares` (any non-negative weights; all zero or
/// non-finite counts as equal). Every tracer gets at least one unit, so no tracer is starved
/// and every tracer keeps being measured; the counts sum to `units`. Needs
/// `units >= shares.len()`; with fewer units it hands out one unit to as many as it can.
pub fn apportion(shares: &[f64], units: usize) -> Vec<usize> {
    let n = shares.len();
    if n == 0 {
        return Vec::new();
    }
    let clean: Vec<f64> = shares
        .iter()
        .map(|&s| if s.is_finite() && s > 0.0 { s } else { 0.0 })
        .collect();
    let total: f64 = clean.iter().sum();
    let ideal: Vec<f64> = if total > 0.0 {
        clean.iter().map(|s| s / total * units as f64).collect()
    } else {
        vec![units as f64 / n as f64; n]
    };
    let mut counts: Vec<usize> = ideal.iter().map(|q| (q.floor() as usize).max(1)).collect();
    let mut sum: usize = counts.iter().sum();
    while sum < units {
        // The tracer furthest below its ideal share takes the next unit.
        let w = (0..n)
            .max_by(|&a, &b| {
                (ideal[a] - counts[a] as f64)
                    .total_cmp(&(ideal[b] - counts[b] as f64))
                    .then(b.cmp(&a))
            })
            .unwrap_or(0);
        counts[w] += 1;
        sum += 1;
    }
    while sum > units {
        // The tracer furthest above its ideal share gives one back, never its last.
        let Some(w) = (0..n).filter(|&w| counts[w] > 1).max_by(|&a, &b| {
            (counts[a] as f64 - ideal[a])
                .total_cmp(&(counts[b] as f64 - ideal[b]))
                .then(a.cmp(&b))
        }) else {
            break;
        };
        counts[w] -= 1;
        sum -= 1;
    }
    counts
}
