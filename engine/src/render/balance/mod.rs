//! Several tracers on one frame: Brigade's workload balancing (Bikker & van Schijndel 2013,
//! §4.3, Figure 9, Table 1) and schemes of ours that beat it.
//!
//! A frame is cut into work units of [`UNIT_ROWS`] pixel rows. Before each frame a
//! [`Balancer`] turns what the last frame measured ([`FrameTimes`]: seconds per tracer and per
//! unit) into a [`Split`] (which tracer renders which unit). The paper's four schemes
//! ([`Equal`], [`RobinHood`], [`Perfect`], [`PerfectSmooth`]) and ours ([`CostModel`],
//! [`Interleaved`]) are small pure state machines; [`simulate`] replays recorded per-unit costs
//! ([`CostTrace`], recorded by [`record_unit_costs`]) on simulated tracers of given speeds, so
//! the same scheme code is measured here and would drive a real pool.
//!
//! [`CpuPool`] is the real thing for CPU tracers: several tracers of chosen thread counts render
//! the disjoint units of one frame at once into one film. [`PoolTracer`] wraps it, with the GPU
//! tracer as one more member when asked, as a `Tracer` the render thread runs
//! (`TracerChoice::Pool`): the balanced frame is then converged, scaled and presented like any
//! other.

mod apportion;
mod cost_model;
mod costs;
mod deal;
mod error;
mod measure;
mod paper;
mod pool;
mod pool_tracer;
mod record;
mod scheme;
mod simulate;
mod speeds;
mod split;

pub use apportion::apportion;
pub use cost_model::{COST_BLEND, CostModel, Interleaved};
pub use costs::CostTrace;
pub use deal::{deal_interleaved, fill_contiguous};
pub use error::BalanceError;
pub use measure::FrameTimes;
pub use paper::{Equal, Perfect, PerfectSmooth, RobinHood};
pub use pool::{CpuPool, PartTimes};
pub use pool_tracer::{PoolSpec, PoolTracer};
pub use record::{UnitCost, record_unit_costs};
pub use scheme::{Balancer, SchemeKind};
pub use simulate::{FrameOutcome, SimReport, idle_share, simulate};
pub use speeds::SpeedEstimate;
pub use split::{Split, UNIT_ROWS, unit_count, unit_rows};
