//! The fly camera's action names (`view`, test levels): declared here,
//! below the camera that reads them (`app::play::fly_camera`), so that the default bindings
//! (`InputMap::fly_camera_defaults`) name them without input depending on the camera.
//!
//! Plain constants. Must not: hold state or read devices.

pub const FORWARD: &str = "forward";
pub const BACK: &str = "back";
pub const LEFT: &str = "left";
pub const RIGHT: &str = "right";
pub const UP: &str = "up";
pub const DOWN: &str = "down";
pub const FAST: &str = "fast";
pub const LOOK_X: &str = "look_x";
pub const LOOK_Y: &str = "look_y";
