//! The screenshot runs a game binary offers in a window (`--screenshots DIR`), as shell cues
//! ([`Cue`]): a level started as the title menu would ([`start_cue`]), the title and then a
//! moment of play, each shot, then quit ([`play_shots`]); the title and then every level in
//! turn from its start ([`tour_shots`]).
//!
//! Plain data for the shell (`ShellConfig::cues`), main thread. Must not: run anything (the
//! shell plays the cues frame by frame).

use std::path::Path;

use crate::app::shell::{Cue, LevelStart, ShellInput};

/// Starts level `id` two frames in (the shell's Start, as the menu would).
pub fn start_cue(id: &str) -> Cue {
    Cue::input(
        2,
        ShellInput::Start(LevelStart {
            level: id.to_string(),
            checkpoint: None,
        }),
    )
}

/// `title.png` after `title_frames` frames, then level `id` played for `play_frames` frames
/// and shot as `play.png`, then quit.
pub fn play_shots(dir: &Path, id: &str, title_frames: u32, play_frames: u32) -> Vec<Cue> {
    vec![
        Cue::screenshot(title_frames, dir.join("title.png")),
        start_cue(id),
        Cue::screenshot(play_frames, dir.join("play.png")),
        Cue::input(2, ShellInput::Quit),
    ]
}

/// `title.png` after `title_frames` frames, then each level of `ids` from its start, shot as
/// `<id>.png` after `play_frames` frames and left through the pause menu; then quit.
pub fn tour_shots(dir: &Path, ids: &[String], title_frames: u32, play_frames: u32) -> Vec<Cue> {
    let mut cues = vec![Cue::screenshot(title_frames, dir.join("title.png"))];
    for id in ids {
        cues.push(start_cue(id));
        cues.push(Cue::screenshot(play_frames, dir.join(format!("{id}.png"))));
        cues.push(Cue::input(2, ShellInput::Pause));
        cues.push(Cue::input(2, ShellInput::QuitToTitle));
    }
    cues.push(Cue::input(2, ShellInput::Quit));
    cues
}
