//! [`Commands`]: the work a game's hooks queue for the engine (light groups, cuts, events for
//! the level's rules, checkpoints, level ends, unplaced sounds and loops, the time of day), carried out in order right
//! after the hook returns (`Engine::frame`, `app/runner/frame.rs`); and the
//! [`ProgressEvent`]s the checkpoints, ends and finishes become, for the shell to save.
//!
//! Kept apart from the `Game` trait so that the engine, which holds the queue, does not depend
//! on the trait that names the engine. Plain data, main thread. Must not: touch the world (the
//! runner applies each command).

use crate::sim::triggers::Outcome;
use crate::sky::SkyTime;

/// Work a hook asks of the engine, carried out in order right after the hook returns.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Commands {
    queue: Vec<Command>,
}

/// One queued [`Commands`] entry.
#[derive(Clone, Debug, PartialEq)]
pub enum Command {
    /// Switch a light group (its emitters leave or join the light distribution).
    Lights { group: u32, on: bool },
    /// Forget the converged image (a teleport, a level change).
    Cut,
    /// An event the level's rules see as `Event(name)` the next time they run (in the same
    /// step when sent from `fixed_step`, in the next from `level_event` or `frame`).
    Event(String),
    /// The player reached a checkpoint of the level being played (the shell saves it).
    Checkpoint(String),
    /// The game ends the level by its own rules (the shell shows the ending).
    EndLevel(Outcome),
    /// The player finished the level with this id without leaving play (a game of chambers
    /// in one world: the chamber behind the player counts as finished; the shell saves it).
    Finished(String),
    /// Play the level's sound `name` (from its `gameplay.sounds`) once, not placed, at linear
    /// volume `volume`: a cue for the HUD's messages. Not part of the simulation's state.
    Sound { name: String, volume: f32 },
    /// Keep the level's sound `name` looping, not placed, at linear volume `volume` (started
    /// the first time; 0 keeps it running silently): wind, a music pad, a sound held while a
    /// button is (`Audio::set_loop_volume`). Not part of the simulation's state.
    Loop { name: String, volume: f32 },
    /// Set or turn the physical sky's time of day (`app/runner/time_of_day.rs`).
    Time(TimeChange),
}

/// How a [`Command::Time`] changes the physical sky's time of day. Carried out right after the
/// hook that queued it returns, so the next fixed step sees the new sun and moon; a sky that
/// is not physical, or (but for `Set`) has no `time`, is left alone (logged).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TimeChange {
    /// Date, time, place and day rate all at once.
    Set(SkyTime),
    /// The same date and place at these hours UTC (0 ≤ h < 24).
    Hours(f64),
    /// Moved by these seconds of day (negative: backwards), across midnights.
    Advance(f64),
    /// The day flows at this many seconds of day per simulated second from now on (0..=1e6).
    Rate(f64),
}

impl Commands {
    /// Switches light group `group` on or off.
    pub fn set_light_group(&mut self, group: u32, on: bool) {
        self.queue.push(Command::Lights { group, on });
    }

    /// Marks a camera cut: the converged image restarts.
    pub fn cut(&mut self) {
        self.queue.push(Command::Cut);
    }

    /// Sends `name` to the level's rules: `Event(name)` conditions see it the next time the
    /// rules run (in the same step when sent from `fixed_step`, which runs before them). The
    /// level declares the names it expects in `gameplay.events`.
    pub fn send_event(&mut self, name: impl Into<String>) {
        self.queue.push(Command::Event(name.into()));
    }

    /// Reports that the player reached checkpoint `name` (saved in the progress file under the
    /// level being played; Continue starts from it).
    pub fn checkpoint(&mut self, name: impl Into<String>) {
        self.queue.push(Command::Checkpoint(name.into()));
    }

    /// Ends the level being played with `outcome` (won levels count as finished).
    pub fn end_level(&mut self, outcome: Outcome) {
        self.queue.push(Command::EndLevel(outcome));
    }

    /// Reports that the level with id `level` (a `LevelEntry::id`) is finished while play goes
    /// on (the next chamber of the same world); the shell saves it and offers it in its level
    /// select.
    pub fn finish_level(&mut self, level: impl Into<String>) {
        self.queue.push(Command::Finished(level.into()));
    }

    /// Plays the level's sound `name` once at `volume` (linear), not placed in the world (a
    /// sound the level does not have is logged and skipped).
    pub fn play_sound(&mut self, name: impl Into<String>, volume: f32) {
        self.queue.push(Command::Sound {
            name: name.into(),
            volume,
        });
    }

    /// Keeps the level's sound `name` looping, not placed, at `volume` (linear, `0.0..=1.0`):
    /// the first call starts it, later ones ramp its volume; queue it every step the volume
    /// should change (a sound the level does not have is logged and skipped).
    pub fn set_loop_volume(&mut self, name: impl Into<String>, volume: f32) {
        self.queue.push(Command::Loop {
            name: name.into(),
            volume,
        });
    }

    /// Sets the physical sky's whole time (date, UTC hours, place, day rate).
    pub fn set_sky_time(&mut self, time: SkyTime) {
        self.queue.push(Command::Time(TimeChange::Set(time)));
    }

    /// Sets the physical sky's time of day to `hours` UTC (0 ≤ h < 24), same date and place.
    pub fn set_time_of_day(&mut self, hours: f64) {
        self.queue.push(Command::Time(TimeChange::Hours(hours)));
    }

    /// Moves the physical sky's time by `seconds` of day (negative: backwards).
    pub fn advance_time(&mut self, seconds: f64) {
        self.queue.push(Command::Time(TimeChange::Advance(seconds)));
    }

    /// Lets the day flow at `rate` seconds of day per simulated second (0 stops it; 0..=1e6).
    pub fn set_time_rate(&mut self, rate: f64) {
        self.queue.push(Command::Time(TimeChange::Rate(rate)));
    }

    /// Takes the queued commands, oldest first.
    pub(in crate::app) fn drain(&mut self) -> std::vec::Drain<'_, Command> {
        self.queue.drain(..)
    }
}

/// Progress a game's hooks report (`Commands::checkpoint`, `Commands::end_level`) or the level's
/// rules reach (`LevelEvent::Ended`); the shell saves it (`Engine::take_progress_events`).
#[derive(Clone, Debug, PartialEq)]
pub enum ProgressEvent {
    /// The player reached this checkpoint of the level being played.
    Checkpoint(String),
    /// The level ended.
    Ended(Outcome),
    /// The level with this id was finished while play goes on (`Commands::finish_level`).
    Finished(String),
}
