//! The commit buffer: everything the render thread learns about a frame, sealed once per frame
//! on the main thread, and the hand-off between the two threads.

mod handoff;
mod present;
mod sealed;

pub use handoff::{CommitReceiver, CommitSender, commit_channel};
pub use present::{Overlay, PresentRequest, ScalingRequest, TonemapSettings};
pub use sealed::{Commit, Motion};
