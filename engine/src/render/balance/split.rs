//! [`Split`]: which tracer renders which work unit of one frame.
//!
//! A work unit is [`UNIT_ROWS`] consecutive pixel rows (Brigade §4.3.2: "one work unit equals
//! four rows of pixels"); the last unit of a frame whose height is no multiple of four is
//! shorter. A split stores one owner per unit, so every row is rendered by exactly one tracer by
//! construction; constructors check that owners are in range and that no tracer is left
//! without work.
//! Must not: measure or decide (the schemes do).

use std::ops::Range;

use super::error::BalanceError;

/// Pixel rows per work unit (defined in `layout`: the GPU tracer's WGSL shares it).
pub use crate::layout::UNIT_ROWS;

/// Work units of an image `height` pixels tall.
pub fn unit_count(height: u32) -> usize {
    height.div_ceil(UNIT_ROWS) as usize
}

/// The pixel rows of `unit` in an image `height` pixels tall (empty past the bottom).
pub fn unit_rows(unit: usize, height: u32) -> Range<u32> {
    let y0 = (unit as u32).saturating_mul(UNIT_ROWS).min(height);
    y0..(y0 + UNIT_ROWS).min(height)
}

/// The owner of every work unit of one frame, for `tracers` tracers.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Split {
    owners: Vec<u16>,
    tracers: usize,
}

impl Split {
    /// A split from one owner per unit. Every tracer must own at least one unit.
    pub fn from_owners(owners: Vec<u16>, tracers: usize) -> Result<Self, BalanceError> {
        if tracers == 0 || owners.len() < tracers {
            return Err(BalanceError::TooFewUnits {
                units: owners.len(),
                tracers,
            });
        }
        let mut seen = vec![false; tracers];
        for (unit, &owner) in owners.iter().enumerate() {
            let owner = owner as usize;
            if owner >= tracers {
                return Err(BalanceError::BadOwner {
                    unit,
                    owner,
                    tracers,
                });
            }
            seen[owner] = true;
        }
        if seen.iter().any(|s| !s) {
            return Err(BalanceError::TooFewUnits {
                units: owners.len(),
                tracers,
            });
        }
        Ok(Self { owners, tracers })
    }

    /// Contiguous bands from the top: tracer 0 takes the first `counts[0]` units, and so on.
    /// Every count must be at least one.
    pub fn contiguous(counts: &[usize]) -> Result<Self, BalanceError> {
        let mut owners = Vec::with_capacity(counts.iter().sum());
        for (tracer, &n) in counts.iter().enumerate() {
            if n == 0 {
                return Err(BalanceError::TooFewUnits {
                    units: counts.iter().sum(),
                    tracers: counts.len(),
                });
            }
            owners.extend(std::iter::repeat_n(tracer as u16, n));
        }
        Self::from_owners(owners, counts.len())
    }

    /// `units` units split as evenly as contiguous bands allow (the first tracers take one more
    /// when the division leaves a remainder).
    pub fn equal(units: usize, tracers: usize) -> Result<Self, BalanceError> {
        if tracers == 0 || units < tracers {
            return Err(BalanceError::TooFewUnits { units, tracers });
        }
        let counts: Vec<usize> = (0..tracers)
            .map(|w| units / tracers + usize::from(w < units % tracers))
            .collect();
        Self::contiguous(&counts)
    }

    /// Units in the frame.
    pub fn units(&self) -> usize {
        self.owners.len()
    }

    /// Tracers the split is for.
    pub fn tracers(&self) -> usize {
        self.tracers
    }

    /// The tracer that renders `unit`.
    pub fn owner(&self, unit: usize) -> usize {
        self.owners[unit] as usize
    }

    /// One owner per unit, top to bottom.
    pub fn owners(&self) -> &[u16] {
        &self.owners
    }

    /// Units per tracer.
    pub fn counts(&self) -> Vec<usize> {
        let mut counts = vec![0; self.tracers];
        for &o in &self.owners {
            counts[o as usize] += 1;
        }
        counts
    }

    /// The units of `tracer`, top to bottom.
    pub fn units_of(&self, tracer: usize) -> impl Iterator<Item = usize> + '_ {
        self.owners
            .iter()
            .enumerate()
            .filter(move |(_, o)| **o as usize == tracer)
            .map(|(u, _)| u)
    }

    /// The pixel rows `tracer` renders in an image `height` pixels tall, top to bottom.
    pub fn rows_of(&self, tracer: usize, height: u32) -> Vec<u32> {
        self.units_of(tracer)
            .flat_map(|u| unit_rows(u, height))
            .collect()
    }
}
