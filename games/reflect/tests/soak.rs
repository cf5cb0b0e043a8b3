//! A short soak of every Reflect chamber in CI (the 100,000-frame soak is the same code with a
//! larger count, `reflect --soak 100000`): 1,500 frames of random input per chamber with no NaN
//! in any transform or in the film, nothing falling out of the world, and resident memory after
//! the warm-up not growing by more than a bound that a leak of one small allocation per frame
//! would already break (48 MiB over 1,350 frames is 36 KiB a frame). The monkey must have
//! reached the game's mechanics: somewhere it walked into a laser and was sent back, or made
//! a mirror, so a soak whose input never reached the game fails. (With seed 1 it made no
//! mirror in 1,500 frames per chamber and was sent back once, in chamber_4.)

use reflect::world::ReflectWorld;

#[test]
fn every_chamber_survives_random_input() -> anyhow::Result<()> {
    let (path, root) = reflect::cli::locate(None)?;
    let world = ReflectWorld::load(&path, &root)?;
    let chambers: Vec<usize> = (0..world.chambers.len()).collect();
    let results = reflect::soak::soak_chambers(&world, &chambers, 1500, 1)?;
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
    let acted: u32 = results.iter().map(|c| c.mirrors + c.sent_back).sum();
    assert!(
        acted > 0,
        "the monkey never made a mirror nor walked into a laser: its input did not reach the game\n{}",
        reflect::soak::table(&results, 1)
    );
    Ok(())
}
