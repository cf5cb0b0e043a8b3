//! A small deterministic mutator for the corpus tests: from a seed file and a number it makes
//! the same variant every time (bit flips, byte overwrites with boundary values, insertions,
//! deletions, duplicated ranges, syntax tokens for text formats). It is no substitute for afl's
//! coverage-guided search (the campaigns in `fuzz/`); it keeps shallow crashes out of CI.
//!
//! Pure functions; any thread.

/// Tokens spliced into text formats: brackets, separators, numbers at the edges of their types.
const TOKENS: &[&str] = &[
    "(",
    ")",
    "[",
    "]",
    "{",
    "}",
    ",",
    ":",
    "\"",
    "'",
    "\\",
    "\n",
    "-",
    "0",
    "1e39",
    "-1e39",
    "NaN",
    "inf",
    "-inf",
    "1e309",
    "4294967295",
    "4294967296",
    "-2147483649",
    "18446744073709551616",
    "0.0",
    "-0.0",
    "true",
    "Some(",
    "None",
    "//",
    "/*",
    "..",
    "../",
    "/",
    "#",
    "\u{0}",
    "é",
    "\u{202e}",
];

/// Values written over bytes: the edges of u8, i8, u16 and u32.
const BOUNDARY: &[&[u8]] = &[
    &[0],
    &[0xff],
    &[0x7f],
    &[0x80],
    &[0xff, 0xff],
    &[0xff, 0xff, 0xff, 0x7f],
    &[0xff, 0xff, 0xff, 0xff],
    &[0, 0, 0, 0x80],
];

/// SplitMix64: a tiny, well-mixed generator; the same seed gives the same sequence.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// A number in `0..n` (`n` > 0).
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
}

/// Variant number `n` of `seed`: 1 to 4 stacked mutations. `text` adds token splices.
pub fn mutate(seed: &[u8], n: u64, text: bool) -> Vec<u8> {
    let mut rng = Rng(n.wrapping_mul(0x2545_f491_4f6c_dd1d) ^ seed.len() as u64);
    let mut out = seed.to_vec();
    let rounds = 1 + rng.below(4);
    for _ in 0..rounds {
        let kinds = if text { 7 } else { 6 };
        match rng.below(kinds) {
            0 if !out.is_empty() => {
                let i = rng.below(out.len());
                out[i] ^= 1 << rng.below(8);
            }
            1 if !out.is_empty() => {
                let value = BOUNDARY[rng.below(BOUNDARY.len())];
                let i = rng.below(out.len());
                for (k, &b) in value.iter().enumerate() {
                    if let Some(slot) = out.get_mut(i + k) {
                        *slot = b;
                    }
                }
            }
            2 => {
                let i = rng.below(out.len() + 1);
                let count = 1 + rng.below(8);
                let bytes: Vec<u8> = (0..count).map(|_| rng.next() as u8).collect();
                out.splice(i..i, bytes);
            }
            3 if !out.is_empty() => {
                let i = rng.below(out.len());
                let len = 1 + rng.below((out.len() - i).min(64));
                out.drain(i..i + len);
            }
            4 if !out.is_empty() => {
                let i = rng.below(out.len());
                let len = 1 + rng.below((out.len() - i).min(256));
                let copy = out[i..i + len].to_vec();
                let at = rng.below(out.len() + 1);
                out.splice(at..at, copy);
            }
            5 if !out.is_empty() => {
                // Truncate: the most common corruption of a file cut short.
                let keep = rng.below(out.len());
                out.truncate(keep);
            }
            6 => {
                let token = TOKENS[rng.below(TOKENS.len())].as_bytes();
                let i = rng.below(out.len() + 1);
                out.splice(i..i, token.iter().copied());
            }
            _ => out.push(rng.next() as u8),
        }
    }
    out
}
