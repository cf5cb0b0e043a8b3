//! The input recording file (`--record FILE`, `--replay FILE`): a small binary format, one
//! [`ActionFrame`] per fixed step, run-length coded (a player standing still costs one run).
//!
//! Layout, version 2; all integers little-endian; `str` = `u32` byte length + UTF-8 bytes:
//!
//! | field | type | meaning |
//! | --- | --- | --- |
//! | magic | 8 bytes | `CDLAREC\0` |
//! | version | u32 | [`FORMAT_VERSION`] |
//! | game | str | the game's name |
//! | level id | str | the level the recording starts on |
//! | level hash | u64 | [`fnv1a64`] of the level file's bytes |
//! | step rate | f64 | fixed steps per second (compared bit for bit) |
//! | look sensitivity | f32 | the mouse sensitivity the steps were played with ([`RecordedLook`]) |
//! | invert Y | u8 | 1 when vertical look was inverted, else 0 |
//! | steps | u64 | number of fixed steps recorded |
//! | actions | u16 | number of actions `A`; then `A` × (kind `u8`: 0 button, 1 axis, 2 motion; name `str`), ids in that order |
//! | runs | … | until `steps` are covered: run length `u32` (≥ 1), `held` u64, `pressed` u64 (bit `i` = action `i`), then an `i32` per axis or motion action in id order (buttons have none) |
//! | checksum | u64 | [`fnv1a64`] of every byte before it |
//!
//! Version 1 files (no look fields) are read as recorded with sensitivity 1 and Y not inverted,
//! the defaults their recorders ran with. Fixed point as in `action_frame.rs`. Owns: encoding and decoding, with errors that name
//! the file. Any thread. Must not: check a recording against a game (`replay.rs` does).

use std::path::Path;

use super::error::ReplayError;
use crate::app::input::ActionFrame;
use crate::app::input::{ActionKind, MAX_ACTIONS};
use crate::assets::atomic_file::write_atomic;

/// The file's first eight bytes.
pub const MAGIC: [u8; 8] = *b"CDLAREC\0";
/// The format version this build writes and reads.
pub const FORMAT_VERSION: u32 = 2;
/// The oldest version this build still reads.
pub const OLDEST_VERSION: u32 = 1;

/// FNV-1a, 64 bits: the level content hash and the file checksum (stable across builds and
/// platforms; not a defence against tampering).
pub fn fnv1a64(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ b as u64).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

/// The content hash of a level file, for [`RecordingHeader::level_hash`].
pub fn level_hash(level_file: &Path) -> Result<u64, ReplayError> {
    std::fs::read(level_file)
        .map(|b| fnv1a64(&b))
        .map_err(|source| ReplayError::Read {
            path: level_file.to_path_buf(),
            source,
        })
}

/// An action as the recording knows it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RecordedAction {
    pub name: String,
    pub kind: ActionKind,
}

/// The player's look settings a recording was played with: motion actions are recorded as the
/// devices gave them, so a replay turns the same only with the same sensitivity and sign.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RecordedLook {
    /// `Settings::mouse_sensitivity` (a factor on mouse and stick look).
    pub mouse_sensitivity: f32,
    /// `Settings::invert_y`.
    pub invert_y: bool,
}

impl Default for RecordedLook {
    fn default() -> Self {
        Self {
            mouse_sensitivity: 1.0,
            invert_y: false,
        }
    }
}

/// What a recording was made on.
#[derive(Clone, Debug, PartialEq)]
pub struct RecordingHeader {
    pub game: String,
    pub level_id: String,
    pub level_hash: u64,
    /// Fixed steps per second.
    pub step_hz: f64,
    /// The look settings the steps were played with.
    pub look: RecordedLook,
    /// The recorder's action set, in id order (frames are laid out by it).
    pub actions: Vec<RecordedAction>,
}

/// `steps` consecutive fixed steps with the same input.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Run {
    pub steps: u32,
    pub frame: ActionFrame,
}

/// A whole recording: the header and the frames as runs.
#[derive(Clone, Debug, PartialEq)]
pub struct Recording {
    pub header: RecordingHeader,
    pub runs: Vec<Run>,
}

fn kind_code(kind: ActionKind) -> u8 {
    match kind {
        ActionKind::Button => 0,
        ActionKind::Axis => 1,
        ActionKind::Motion => 2,
    }
}

fn put_str(out: &mut Vec<u8>, s: &str) {
    out.extend_from_slice(&(s.len() as u32).to_le_bytes());
    out.extend_from_slice(s.as_bytes());
}

/// A cursor over the file's bytes; `None` at the end.
struct Cursor<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl<'a> Cursor<'a> {
    fn take(&mut self, n: usize) -> Option<&'a [u8]> {
        let end = self.at.checked_add(n).filter(|&e| e <= self.bytes.len())?;
        let s = &self.bytes[self.at..end];
        self.at = end;
        Some(s)
    }
    fn array<const N: usize>(&mut self) -> Option<[u8; N]> {
        self.take(N).and_then(|s| s.try_into().ok())
    }
    fn u8(&mut self) -> Option<u8> {
        self.array::<1>().map(|a| a[0])
    }
    fn u16(&mut self) -> Option<u16> {
        self.array().map(u16::from_le_bytes)
    }
    fn u32(&mut self) -> Option<u32> {
        self.array().map(u32::from_le_bytes)
    }
    fn i32(&mut self) -> Option<i32> {
        self.array().map(i32::from_le_bytes)
    }
    fn u64(&mut self) -> Option<u64> {
        self.array().map(u64::from_le_bytes)
    }
    fn f64(&mut self) -> Option<f64> {
        self.array().map(f64::from_le_bytes)
    }
    /// `Ok(None)`: truncated; `Err`: not UTF-8.
    fn str(&mut self) -> Result<Option<String>, String> {
        let Some(len) = self.u32() else {
            return Ok(None);
        };
        let Some(bytes) = self.take(len as usize) else {
            return Ok(None);
        };
        String::from_utf8(bytes.to_vec())
            .map(Some)
            .map_err(|e| format!("a name is not UTF-8 ({e})"))
    }
}

impl Recording {
    /// Number of fixed steps recorded.
    pub fn steps(&self) -> u64 {
        self.runs.iter().map(|r| r.steps as u64).sum()
    }

    /// Every step's frame, in order.
    pub fn frames(&self) -> impl Iterator<Item = &ActionFrame> + '_ {
        self.runs
            .iter()
            .flat_map(|r| std::iter::repeat_n(&r.frame, r.steps as usize))
    }

    /// The file's bytes (see the module doc for the layout).
    pub fn encode(&self) -> Vec<u8> {
        let h = &self.header;
        let mut out = Vec::new();
        out.extend_from_slice(&MAGIC);
        out.extend_from_slice(&FORMAT_VERSION.to_le_bytes());
        put_str(&mut out, &h.game);
        put_str(&mut out, &h.level_id);
        out.extend_from_slice(&h.level_hash.to_le_bytes());
        out.extend_from_slice(&h.step_hz.to_le_bytes());
        out.extend_from_slice(&h.look.mouse_sensitivity.to_le_bytes());
        out.push(u8::from(h.look.invert_y));
        out.extend_from_slice(&self.steps().to_le_bytes());
        out.extend_from_slice(&(h.actions.len() as u16).to_le_bytes());
        for a in &h.actions {
            out.push(kind_code(a.kind));
            put_str(&mut out, &a.name);
        }
        for run in self.runs.iter().filter(|r| r.steps > 0) {
            out.extend_from_slice(&run.steps.to_le_bytes());
            out.extend_from_slice(&run.frame.held.to_le_bytes());
            out.extend_from_slice(&run.frame.pressed.to_le_bytes());
            for (i, a) in h.actions.iter().enumerate() {
                if a.kind != ActionKind::Button {
                    let v = run.frame.values.get(i).copied().unwrap_or(0);
                    out.extend_from_slice(&v.to_le_bytes());
                }
            }
        }
        let sum = fnv1a64(&out);
        out.extend_from_slice(&sum.to_le_bytes());
        out
    }

    /// Reads the bytes of a recording; `path` names the file in errors.
    pub fn decode(path: &Path, bytes: &[u8]) -> Result<Recording, ReplayError> {
        let path_buf = || path.to_path_buf();
        let truncated = |at: String| ReplayError::Truncated {
            path: path_buf(),
            at,
        };
        let corrupt = |message: String| ReplayError::Corrupt {
            path: path_buf(),
            message,
        };
        let mut c = Cursor { bytes, at: 0 };
        match c.array::<8>() {
            Some(m) if m == MAGIC => {}
            _ => return Err(ReplayError::NotARecording { path: path_buf() }),
        }
        let in_header = || truncated("inside the header".into());
        let version = c.u32().ok_or_else(in_header)?;
        if !(OLDEST_VERSION..=FORMAT_VERSION).contains(&version) {
            return Err(ReplayError::Version {
                path: path_buf(),
                found: version,
                supported: FORMAT_VERSION,
            });
        }
        let game = c.str().map_err(corrupt)?.ok_or_else(in_header)?;
        let level_id = c.str().map_err(corrupt)?.ok_or_else(in_header)?;
        let level_hash = c.u64().ok_or_else(in_header)?;
        let step_hz = c.f64().ok_or_else(in_header)?;
        let mut look = RecordedLook::default();
        if version >= 2 {
            look.mouse_sensitivity = f32::from_le_bytes(c.array::<4>().ok_or_else(in_header)?);
            if !look.mouse_sensitivity.is_finite() {
                return Err(corrupt(format!(
                    "look sensitivity {} (a finite number expected)",
                    look.mouse_sensitivity
                )));
            }
            look.invert_y = match c.u8().ok_or_else(in_header)? {
                0 => false,
                1 => true,
                b => return Err(corrupt(format!("invert Y {b} (0 or 1 expected)"))),
            };
        }
        let steps = c.u64().ok_or_else(in_header)?;
        let count = c.u16().ok_or_else(in_header)?;
        if count as usize > MAX_ACTIONS {
            return Err(corrupt(format!("{count} actions (at most {MAX_ACTIONS})")));
        }
        let mut actions: Vec<RecordedAction> = Vec::with_capacity(count as usize);
        for _ in 0..count {
            let kind = match c.u8().ok_or_else(in_header)? {
                0 => ActionKind::Button,
                1 => ActionKind::Axis,
                2 => ActionKind::Motion,
                k => return Err(corrupt(format!("action kind {k} (0, 1 or 2 expected)"))),
            };
            let name = c.str().map_err(corrupt)?.ok_or_else(in_header)?;
            if actions.iter().any(|a| a.name == name) {
                return Err(corrupt(format!("action `{name}` is listed twice")));
            }
            actions.push(RecordedAction { name, kind });
        }
        let header = RecordingHeader {
            game,
            level_id,
            level_hash,
            step_hz,
            look,
            actions,
        };
        let mut runs = Vec::new();
        let mut covered = 0u64;
        while covered < steps {
            let at = || truncated(format!("in step {} of {steps}", covered + 1));
            let len = c.u32().ok_or_else(at)?;
            if len == 0 || covered + len as u64 > steps {
                return Err(corrupt(format!(
                    "a run of {len} steps at step {} of {steps}",
                    covered + 1
                )));
            }
            let held = c.u64().ok_or_else(at)?;
            let pressed = c.u64().ok_or_else(at)?;
            let mut values = vec![0; header.actions.len()];
            for (i, a) in header.actions.iter().enumerate() {
                if a.kind != ActionKind::Button {
                    values[i] = c.i32().ok_or_else(at)?;
                }
            }
            runs.push(Run {
                steps: len,
                frame: ActionFrame {
                    held,
                    pressed,
                    values,
                },
            });
            covered += len as u64;
        }
        let body_end = c.at;
        let sum = c
            .u64()
            .ok_or_else(|| truncated("before its checksum".into()))?;
        if sum != fnv1a64(&bytes[..body_end]) {
            return Err(corrupt("the checksum does not match the content".into()));
        }
        if c.at != bytes.len() {
            return Err(corrupt(format!(
                "{} bytes after the checksum",
                bytes.len() - c.at
            )));
        }
        Ok(Recording { header, runs })
    }

    /// Reads a recording file.
    pub fn read(path: &Path) -> Result<Recording, ReplayError> {
        let bytes = std::fs::read(path).map_err(|source| ReplayError::Read {
            path: path.to_path_buf(),
            source,
        })?;
        Self::decode(path, &bytes)
    }

    /// Writes the recording file atomically.
    pub fn write(&self, path: &Path) -> Result<(), ReplayError> {
        write_atomic(path, &self.encode())?;
        Ok(())
    }
}
