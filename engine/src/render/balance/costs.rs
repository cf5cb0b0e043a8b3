//! [`CostTrace`]: recorded per-unit render costs of a sequence of frames, and its CSV file.
//!
//! File format (one line per frame and quantity, so a 128-frame recording stays small):
//! ```text
//! # any comment
//! # key=value lines: width, height, and free-form ones (camera, spp, ...)
//! frame,kind,u0,u1,...
//! 0,us,812.40,790.11,...      // microseconds of each unit on the recording thread
//! 0,rays,1520,1490,...        // rays traced in each unit
//! ```
//! Owns: the record and its file. Must not: record or simulate.

use std::fmt::Write as _;
use std::path::Path;

use super::error::BalanceError;
use super::split::unit_count;

/// Per-unit costs of consecutive frames, as one tracer thread measured them.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CostTrace {
    /// Image size the frames were rendered at, pixels.
    pub width: u32,
    pub height: u32,
    /// Free-form facts about the recording (camera, spp, scene), kept in the file header.
    pub notes: Vec<(String, String)>,
    /// Per frame, per unit: seconds on the recording thread (its CPU time).
    pub unit_seconds: Vec<Vec<f64>>,
    /// Per frame, per unit: rays traced (camera + bounce + shadow).
    pub unit_rays: Vec<Vec<u64>>,
}

impl CostTrace {
    /// Work units per frame.
    pub fn units(&self) -> usize {
        unit_count(self.height)
    }

    /// Frames recorded.
    pub fn frames(&self) -> usize {
        self.unit_seconds.len()
    }

    /// The file's text.
    pub fn to_csv(&self) -> String {
        let mut out = String::from("# candela per-unit render costs (render/balance/costs.rs)\n");
        let _ = writeln!(out, "# width={}", self.width);
        let _ = writeln!(out, "# height={}", self.height);
        for (k, v) in &self.notes {
            let _ = writeln!(out, "# {k}={v}");
        }
        out.push_str("frame,kind");
        for u in 0..self.units() {
            let _ = write!(out, ",u{u}");
        }
        out.push('\n');
        for (f, secs) in self.unit_seconds.iter().enumerate() {
            let _ = write!(out, "{f},us");
            for s in secs {
                let _ = write!(out, ",{:.2}", s * 1e6);
            }
            out.push('\n');
            if let Some(rays) = self.unit_rays.get(f) {
                let _ = write!(out, "{f},rays");
                for r in rays {
                    let _ = write!(out, ",{r}");
                }
                out.push('\n');
            }
        }
        out
    }

    /// Parses a file's text; `path` names it in errors.
    pub fn parse(path: &str, text: &str) -> Result<Self, BalanceError> {
        let bad = |line: usize, reason: String| BalanceError::CostFile {
            path: path.to_string(),
            line,
            reason,
        };
        let mut trace = CostTrace::default();
        let mut header_seen = false;
        for (i, line) in text.lines().enumerate() {
            let n = i + 1;
            let line = line.trim();
            if line.is_empty() {
                continue;
            }
            if let Some(comment) = line.strip_prefix('#') {
                if let Some((k, v)) = comment.trim().split_once('=') {
                    let (k, v) = (k.trim(), v.trim());
                    match k {
                        "width" => {
                            trace.width = v.parse().map_err(|e| bad(n, format!("width: {e}")))?
                        }
                        "height" => {
                            trace.height = v.parse().map_err(|e| bad(n, format!("height: {e}")))?
                        }
                        _ => trace.notes.push((k.to_string(), v.to_string())),
                    }
                }
                continue;
            }
            if !header_seen {
                if !line.starts_with("frame,kind") {
                    return Err(bad(
                        n,
                        "expected the column header `frame,kind,u0,...`".into(),
                    ));
                }
                header_seen = true;
                continue;
            }
            let mut fields = line.split(',');
            let frame: usize = fields
                .next()
                .unwrap_or("")
                .parse()
                .map_err(|e| bad(n, format!("frame number: {e}")))?;
            let kind = fields.next().unwrap_or("");
            let values: Vec<&str> = fields.collect();
            if values.len() != trace.units() || trace.units() == 0 {
                return Err(bad(
                    n,
                    format!("{} values, expected {} units", values.len(), trace.units()),
                ));
            }
            match kind {
                "us" => {
                    if frame != trace.unit_seconds.len() {
                        return Err(bad(n, format!("frame {frame} out of order")));
                    }
                    let secs = values
                        .iter()
                        .map(|v| match v.parse::<f64>() {
                            Ok(x) if x.is_finite() && x >= 0.0 => Ok(x * 1e-6),
                            Ok(x) => Err(bad(
                                n,
                                format!("unit time {x} is not a finite non-negative number"),
                            )),
                            Err(e) => Err(bad(n, format!("unit time {v:?}: {e}"))),
                        })
                        .collect::<Result<Vec<f64>, _>>()?;
                    trace.unit_seconds.push(secs);
                }
                "rays" => {
                    if frame != trace.unit_rays.len() {
                        return Err(bad(n, format!("frame {frame} out of order")));
                    }
                    let rays = values
                        .iter()
                        .map(|v| {
                            v.parse::<u64>()
                                .map_err(|e| bad(n, format!("ray count {v:?}: {e}")))
                        })
                        .collect::<Result<Vec<u64>, _>>()?;
                    trace.unit_rays.push(rays);
                }
                other => return Err(bad(n, format!("unknown kind {other:?} (us or rays)"))),
            }
        }
        if trace.unit_seconds.is_empty() {
            return Err(bad(0, "no frames".into()));
        }
        Ok(trace)
    }

    /// Reads a cost file.
    pub fn read(path: &Path) -> Result<Self, BalanceError> {
        let text = std::fs::read_to_string(path).map_err(|source| BalanceError::Io {
            path: path.display().to_string(),
            source,
        })?;
        Self::parse(&path.display().to_string(), &text)
    }

    /// Writes a cost file (atomically: the previous file stays whole if the write fails).
    pub fn write(&self, path: &Path) -> Result<(), BalanceError> {
        crate::assets::atomic_file::write_atomic(path, self.to_csv().as_bytes()).map_err(|e| {
            BalanceError::Io {
                path: path.display().to_string(),
                source: e.source,
            }
        })
    }

    /// The same frames with each unit's cost replaced by its ray count (seconds := rays), a
    /// noise-free stand-in for time.
    pub fn rays_as_cost(&self) -> Self {
        let mut out = self.clone();
        out.unit_seconds = self
            .unit_rays
            .iter()
            .map(|f| f.iter().map(|&r| r as f64).collect())
            .collect();
        out
    }
}
