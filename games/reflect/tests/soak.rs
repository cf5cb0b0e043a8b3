//! A short soak of every Reflect chamber in CI (the 100,000-frame soak is the same code with a
//! larger count, `reflect --soak 100000`): 1,500 frames of random input per chamber with no NaN
//! in any transform or in the film, nothing falling out of the world, and resident memory after
//! the warm-up not growing by more than a bound that a leak of one small allocation per frame
//! would already break (48 MiB over 1,350 frames is 36 KiB a frame). The monkey's input must
//! have reached the game in every chamber: the player walked there, at least [`MIN_FOOTSTEPS`]
//! footsteps (the game's `footstep` event, one every 0.75 m walked; measured 52 to 53 per
//! chamber with seed 1), so a soak whose input reaches one chamber only fails; and somewhere
//! it walked into a laser and was sent back, or made a mirror. (With seed 1 it made no mirror in 1,500 frames per chamber and
//! was sent back once, in chamber_4; where a laser sends the player is `tests/hazard.rs`.)

use candela::app::harness::soak_levels;
use reflect::game::{ReflectEvent, ReflectGame};
use reflect::soak::ChamberSoak;
use reflect::world::ReflectWorld;

/// Footsteps the player must take in each chamber's 1,500 frames (measured 52 to 53 with
/// seed 1; a player who never moves takes none).
const MIN_FOOTSTEPS: usize = 20;

#[test]
fn every_chamber_survives_random_input() -> anyhow::Result<()> {
    let (path, root) = reflect::cli::locate(None)?;
    let world = ReflectWorld::load(&path, &root)?;
    let chambers: Vec<usize> = (0..world.chambers.len()).collect();
    // `reflect::soak::soak_chambers`, with the footsteps counted from the game's log.
    let soaks = soak_levels(&world, &chambers, 1500, 1, |game: &ReflectGame| {
        let footsteps = game
            .log()
            .iter()
            .filter(|(_, e)| matches!(e, ReflectEvent::Rule { name, rising: true } if name == "footstep"))
            .count();
        let note = (game.gun().made, game.sent_back(), game.log().len());
        (note, footsteps)
    })?;
    let footsteps: Vec<usize> = soaks.iter().map(|s| s.note.1).collect();
    let results: Vec<ChamberSoak> = soaks
        .into_iter()
        .map(|s| ChamberSoak {
            id: s.id,
            report: s.report,
            mirrors: s.note.0.0,
            sent_back: s.note.0.1,
            events: s.note.0.2,
        })
        .collect();
    assert_eq!(results.len(), world.chambers.len());
    for c in &results {
        assert_eq!(c.report.frames, 1500, "{}", c.id);
        assert_eq!(
            c.report.film_checks, 3,
            "{}: a film check every 500 frames",
            c.id
        );
        assert!(c.report.rss_warm > 0, "resident memory was not read");
        assert!(
            c.report.growth() < 48 << 20,
            "{}: resident memory grew by {} MiB after the warm-up",
            c.id,
            c.report.growth() >> 20
        );
    }
    for (c, &steps) in results.iter().zip(&footsteps) {
        println!("{}: {steps} footsteps", c.id);
        assert!(
            steps >= MIN_FOOTSTEPS,
            "{}: the player took {steps} footsteps in 1,500 frames (at least {MIN_FOOTSTEPS}): the monkey's input did not reach the game there\n{}",
            c.id,
            reflect::soak::table(&results, 1)
        );
    }
    let acted: u32 = results.iter().map(|c| c.mirrors + c.sent_back).sum();
    assert!(
        acted > 0,
        "the monkey never made a mirror nor walked into a laser: its input did not reach the game\n{}",
        reflect::soak::table(&results, 1)
    );
    Ok(())
}
