//! The hand-off: the one synchronisation point between the main thread and the render thread.
//!
//! Owns: a channel of capacity one. The main thread seals commit N+1 while the render thread
//! renders N; sending N+1 blocks only if the render thread has not yet taken N (one frame of
//! latency, as in Brigade). Dropping the sender is the shutdown signal.
//! Must not: carry anything but sealed commits.

use std::sync::mpsc::{Receiver, RecvError, SendError, SyncSender, sync_channel};

use super::sealed::Commit;

/// The main thread's end.
pub struct CommitSender(SyncSender<Commit>);

/// The render thread's end.
pub struct CommitReceiver(Receiver<Commit>);

/// A connected pair.
pub fn commit_channel() -> (CommitSender, CommitReceiver) {
    let (tx, rx) = sync_channel(1);
    (CommitSender(tx), CommitReceiver(rx))
}

impl CommitSender {
    /// Hands a sealed commit over; fails only when the render thread has stopped.
    pub fn send(&self, commit: Commit) -> Result<(), SendError<Commit>> {
        self.0.send(commit)
    }
}

impl CommitReceiver {
    /// The next commit; `Err` when the main thread has shut down.
    pub fn recv(&self) -> Result<Commit, RecvError> {
        self.0.recv()
    }
}
