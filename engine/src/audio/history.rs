//! A bounded, append-only history that stays one contiguous slice.
//!
//! Owns: [`Capped`], used for the `played` log and the silent recorder's samples so that a game
//! running for hours holds bounded memory. Appending is amortised O(1): once `2 × keep` items are
//! held, the oldest are dropped in one move down to `keep`. Must not: know what it stores.

/// Keeps at least the latest `keep` items appended (all of them while fewer were appended) and at
/// most `2 × keep`.
#[derive(Clone, Debug)]
pub struct Capped<T> {
    items: Vec<T>,
    keep: usize,
    /// Items dropped from the front so far: the index, in everything ever appended, of
    /// `items[0]`.
    dropped: u64,
}

impl<T: Clone> Capped<T> {
    pub fn new(keep: usize) -> Self {
        Self {
            items: Vec::new(),
            keep,
            dropped: 0,
        }
    }

    /// An empty history whose first item will be item `start` of everything (as if `start`
    /// items had been appended and dropped already).
    pub fn starting_at(keep: usize, start: u64) -> Self {
        Self {
            items: Vec::new(),
            keep,
            dropped: start,
        }
    }

    pub fn push(&mut self, item: T) {
        self.extend_from_slice(std::slice::from_ref(&item));
    }

    pub fn extend_from_slice(&mut self, new: &[T]) {
        if self.keep == 0 {
            self.dropped += new.len() as u64;
            return;
        }
        // Appending more than `keep` at once: only the tail can survive.
        let skip = new.len().saturating_sub(self.keep);
        if skip > 0 {
            self.dropped += (self.items.len() + skip) as u64;
            self.items.clear();
        }
        self.items.extend_from_slice(&new[skip..]);
        if self.items.len() >= 2 * self.keep {
            let excess = self.items.len() - self.keep;
            self.items.drain(..excess);
            self.dropped += excess as u64;
        }
    }

    pub fn as_slice(&self) -> &[T] {
        &self.items
    }

    /// How many items were dropped from the front so far.
    pub fn dropped(&self) -> u64 {
        self.dropped
    }
}
