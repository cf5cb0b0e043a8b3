//! Lasers that block the way: a beam that crosses the player sends them back to the start of
//! the chamber they are in (what they carried drops where they were).
//!
//! Owns: [`beam_crosses`] and [`send_back`]. Main thread, Reflect's fixed step, after the
//! level's logic traced the beams of the last step. Must not: touch beams or the renderer.

use candela::ecs::Transform;
use candela::player::FirstPersonPlayer;
use candela::sim::physics::{Carrier, CarryRequest, PhysicsWorld};
use candela::sim::triggers::LaserPath;
use glam::{Quat, Vec3};
use hecs::World;

/// Whether any laser's beam, as traced in the last step, passes through the player's body.
pub fn beam_crosses(world: &World, physics: &PhysicsWorld, player: &FirstPersonPlayer) -> bool {
    world.query::<&LaserPath>().iter().any(|path| {
        path.segments()
            .any(|(a, b)| physics.segment_touches(player.body, a, b))
    })
}

/// Puts the player's feet at `feet` looking along `yaw` (radians, 0 along −Z), level, and
/// drops what they carried.
pub fn send_back(
    world: &mut World,
    physics: &mut PhysicsWorld,
    player: &mut FirstPersonPlayer,
    feet: Vec3,
    yaw: f32,
) {
    if player.held(world).is_some()
        && let Ok(mut c) = world.get::<&mut Carrier>(player.camera)
    {
        c.request = Some(CarryRequest::Drop);
    }
    let centre = feet + (player.position(world) - player.feet(world));
    physics.set_pose(player.body, centre, Quat::IDENTITY);
    if let Ok(mut t) = world.get::<&mut Transform>(player.body) {
        t.translation = centre;
    }
    player.yaw = yaw;
    player.pitch = 0.0;
}
