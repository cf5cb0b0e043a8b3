//! Gamepad controls by name, the engine's own: what bindings and settings files say
//! (`Pad(South)`, `PadAxis(LeftStickX)`), so that files do not depend on the gamepad crate's
//! serialisation and the input map does not know it. `gamepad.rs` translates gilrs's events.
//!
//! Conventions (those of gilrs and the SDL controller database): face buttons by position
//! (South is A on Xbox, Cross on PlayStation); stick axes in [−1, 1], X positive to the right,
//! Y positive **up**; triggers are buttons (`LeftTrigger2`, `RightTrigger2`). Data only; any
//! thread. Must not: read devices.

use serde::{Deserialize, Serialize};

/// A gamepad button by position.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum PadButton {
    South,
    East,
    North,
    West,
    /// Upper shoulder buttons (LB / L1, RB / R1).
    LeftTrigger,
    RightTrigger,
    /// Lower triggers (LT / L2, RT / R2), pressed past the driver's threshold.
    LeftTrigger2,
    RightTrigger2,
    Select,
    Start,
    /// The logo button.
    Mode,
    /// Pressing a stick in.
    LeftThumb,
    RightThumb,
    DPadUp,
    DPadDown,
    DPadLeft,
    DPadRight,
}

/// A gamepad axis; values in [−1, 1] after the dead zone.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum PadAxis {
    /// Left stick, positive to the right.
    LeftStickX,
    /// Left stick, positive up (away from the player).
    LeftStickY,
    /// Right stick, positive to the right.
    RightStickX,
    /// Right stick, positive up.
    RightStickY,
}
