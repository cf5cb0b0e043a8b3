//! The ruins' render settings (`render:` in `assets/its_about_time/ruins.ron`, written by
//! `games/its_about_time/layout/ruins_layout.py`): no Russian roulette within the paths'
//! bounces. From the first bounce (`roulette_start: 1`) roulette ended more than half the paths
//! off the shaded sandstone and scaled the rest up; their bounce onto sunlit sand showed as
//! orange dots on every shaded wall (5,894 of 31,200 pixels of the rolling stone's vault above
//! 3× the median at 1 spp, against 207 without roulette, the same mean: `docs/PERFORMANCE.md`,
//! "Render areas that are right"). With `roulette_start: 1` back in the layout this fails.

use its_about_time::world::RuinsWorld;

#[test]
fn the_ruins_paths_are_not_rouletted_within_their_bounces() -> anyhow::Result<()> {
    let world = RuinsWorld::open(None)?;
    let render = &world.level.scene.render;
    assert!(
        render.roulette_start >= render.max_bounces,
        "roulette_start {} < max_bounces {}: roulette would end paths within the bounces",
        render.roulette_start,
        render.max_bounces
    );
    Ok(())
}
