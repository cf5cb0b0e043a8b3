//! Replays every fuzz corpus and crash input through its target, and a few hundred
//! deterministic mutations of each seed except the campaigns' minimised corpus
//! (`fuzz/corpus/<target>/afl/`, replayed once each: afl mutated it already): none may panic (see `fuzz_targets`' module doc for what
//! counts as a bug). Seeds come from `fuzz/corpus/<target>/`, `fuzz/crashes/<target>/`, the
//! repository's own assets and `../shared/external`. Each target must accept at least one of
//! its seeds, so a harness that refuses everything (a wrong scratch path, say) fails here.
//! The long coverage-guided campaigns are `cargo xtask fuzz` (see docs/RELIABILITY.md).

use std::collections::BTreeMap;
use std::panic::{AssertUnwindSafe, catch_unwind};

use fuzz_targets::seeds::{campaign_corpus, mutable_seeds};
use fuzz_targets::{Outcome, Target, mutate::mutate, run};

/// Mutations run per seed (the seeds per target are capped in `seeds`, so the test stays fast).
const MUTATIONS_PER_SEED: u64 = 300;
#[test]
fn no_input_of_any_target_panics() {
    // Silence the default hook's backtraces: each panic is reported below with its input.
    std::panic::set_hook(Box::new(|_| {}));
    let mut crashes = Vec::new();
    let mut accepted: BTreeMap<&str, usize> = BTreeMap::new();
    let mut runs = 0_u64;
    for target in Target::ALL {
        let seeds = mutable_seeds(target);
        assert!(!seeds.is_empty(), "target {} has no seeds", target.name());
        // The campaigns' minimised corpus: replayed as it is (mutation 0 only).
        let corpus = campaign_corpus(target);
        let inputs = seeds.iter().map(|s| (s, MUTATIONS_PER_SEED));
        for ((name, seed), mutations) in inputs.chain(corpus.iter().map(|s| (s, 0))) {
            for n in 0..=mutations {
                let input = if n == 0 {
                    seed.clone()
                } else {
                    mutate(seed, n, target.is_text())
                };
                runs += 1;
                match catch_unwind(AssertUnwindSafe(|| run(target, &input))) {
                    Ok(Outcome::Accepted) if n == 0 => {
                        *accepted.entry(target.name()).or_default() += 1
                    }
                    Ok(_) => {}
                    Err(payload) => {
                        let message = payload
                            .downcast_ref::<String>()
                            .cloned()
                            .or_else(|| payload.downcast_ref::<&str>().map(|s| s.to_string()))
                            .unwrap_or_default();
                        crashes.push(format!("{}: {name} mutation {n}: {message}", target.name()));
                    }
                }
            }
        }
    }
    let _ = std::panic::take_hook();
    assert!(
        crashes.is_empty(),
        "{} of {runs} inputs crashed (save each under fuzz/crashes/<target>/ once fixed):\n{}",
        crashes.len(),
        crashes.join("\n")
    );
    let never: Vec<&str> = Target::ALL
        .iter()
        .map(|t| t.name())
        .filter(|n| !accepted.contains_key(n))
        .collect();
    assert!(
        never.is_empty(),
        "targets that accepted none of their seeds (is the harness broken?): {never:?}"
    );
    eprintln!("{runs} inputs, no crash; seeds accepted per target: {accepted:?}");
}
