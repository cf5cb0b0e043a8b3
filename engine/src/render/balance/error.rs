//! Errors of the workload balancer: bad splits, bad cost files.
//!
//! Owns: the error enum. Must not: decide anything.

/// What can go wrong building a split or reading recorded costs.
#[derive(Debug, thiserror::Error)]
pub enum BalanceError {
    #[error("unit {unit} is owned by tracer {owner}, but the split has {tracers} tracers")]
    BadOwner {
        unit: usize,
        owner: usize,
        tracers: usize,
    },
    #[error(
        "a split needs at least one tracer and at least one unit per tracer ({units} units, {tracers} tracers)"
    )]
    TooFewUnits { units: usize, tracers: usize },
    #[error("cost file {path}, line {line}: {reason}")]
    CostFile {
        path: String,
        line: usize,
        reason: String,
    },
    #[error(
        "a split of {units} units over {tracers} tracers does not fit a frame of {frame_units} units on {pool_tracers} tracers"
    )]
    SplitMismatch {
        units: usize,
        tracers: usize,
        frame_units: usize,
        pool_tracers: usize,
    },
    #[error("cannot start a tracer's thread pool: {0}")]
    Pool(String),
    #[error("cost file {path}: {source}")]
    Io {
        path: String,
        #[source]
        source: std::io::Error,
    },
}
