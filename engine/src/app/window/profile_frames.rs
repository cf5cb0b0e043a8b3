//! [`ProfileRecorder`]: the profiler's recording side. It turns puffin's scopes on or off
//! (`puffin::set_scopes_on`: off, every `puffin::profile_scope!` in the engine costs one relaxed
//! atomic load), keeps the recent frames puffin collects (a `puffin::GlobalFrameView` sink), and
//! reads a frame's per-thread byte streams into plain nested bars ([`ProfileFrame`]) for the
//! view (`profiler_view.rs`) and for tests.
//!
//! Where the scopes are: `Engine::frame` opens a `"frame"` scope on the main thread with one
//! scope per `app::Phase` (named by `Phase::name`) and the main systems inside them; the render
//! thread opens a `"render frame"` scope per commit (apply, trace, guides, denoise, present,
//! compose, overlay). `Engine::frame` also ends puffin's frame (`GlobalProfiler::new_frame`)
//! while scopes are on. A puffin frame holds the main thread's engine frame and whatever the
//! render thread finished meanwhile (it renders the previous commit).
//!
//! Owns: the sink and the conversion. Any thread (the window runner's main thread in a game).
//! Must not: open scopes itself, or keep frames while the scopes are off (the sink stays, but
//! puffin sends it nothing).

use std::sync::Arc;

/// One recorded frame's length, for the frame-time bars.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrameTime {
    /// Puffin's frame index (counts `new_frame` calls since start-up).
    pub index: u64,
    /// Milliseconds from the first scope's start to the last scope's end, all threads.
    pub duration_ms: f64,
}

/// One scope as a bar: where it starts and how long it lasts, within its frame.
#[derive(Clone, Debug, PartialEq)]
pub struct ScopeBar {
    /// The scope's name, as given to `puffin::profile_scope!`.
    pub name: String,
    /// The scope's extra data (for example a step index); often empty.
    pub data: String,
    /// 0 for a thread's top scopes, 1 for their children, …
    pub depth: usize,
    /// The index in [`ThreadScopes::scopes`] of the enclosing scope (`None` at the top).
    pub parent: Option<usize>,
    /// Milliseconds from the frame's start ([`ProfileFrame`]'s first scope) to the scope's.
    pub start_ms: f64,
    /// The scope's length in milliseconds.
    pub duration_ms: f64,
}

/// The scopes one thread recorded in a frame, parents before their children.
#[derive(Clone, Debug, PartialEq)]
pub struct ThreadScopes {
    /// The thread's name (`candela-render` for the render thread).
    pub name: String,
    pub scopes: Vec<ScopeBar>,
}

impl ThreadScopes {
    /// The first scope called `name`, with its index.
    pub fn find(&self, name: &str) -> Option<(usize, &ScopeBar)> {
        self.scopes.iter().enumerate().find(|(_, s)| s.name == name)
    }

    /// Whether some scope called `child` lies (at any depth) inside one called `ancestor`.
    pub fn nests(&self, ancestor: &str, child: &str) -> bool {
        self.scopes.iter().filter(|s| s.name == child).any(|s| {
            let mut up = s.parent;
            while let Some(i) = up {
                if self.scopes[i].name == ancestor {
                    return true;
                }
                up = self.scopes[i].parent;
            }
            false
        })
    }

    /// The deepest nesting plus one (0 without scopes).
    pub fn rows(&self) -> usize {
        self.scopes.iter().map(|s| s.depth + 1).max().unwrap_or(0)
    }
}

/// One recorded frame: every thread's scopes.
#[derive(Clone, Debug, PartialEq)]
pub struct ProfileFrame {
    pub index: u64,
    pub duration_ms: f64,
    /// Threads in puffin's order (by the time they first recorded).
    pub threads: Vec<ThreadScopes>,
}

impl ProfileFrame {
    /// The thread called `name`.
    pub fn thread(&self, name: &str) -> Option<&ThreadScopes> {
        self.threads.iter().find(|t| t.name == name)
    }

    /// The thread holding a scope called `scope`.
    pub fn thread_with(&self, scope: &str) -> Option<&ThreadScopes> {
        self.threads.iter().find(|t| t.find(scope).is_some())
    }
}

/// The profiler's recording side (see the module doc).
#[derive(Default)]
pub struct ProfileRecorder {
    /// Opened the first time scopes are turned on.
    view: Option<puffin::GlobalFrameView>,
}

impl ProfileRecorder {
    /// Turns the engine's scopes on (keeping the frames puffin collects from then on) or off.
    /// The switch is process-wide: puffin's scopes are global.
    pub fn set_on(&mut self, on: bool) {
        if on && self.view.is_none() {
            let view = puffin::GlobalFrameView::default();
            // A few seconds of frames at 60 fps is plenty to pick one from.
            view.lock().set_max_recent(600);
            self.view = Some(view);
        }
        puffin::set_scopes_on(on);
    }

    /// Whether the engine's scopes are on (process-wide).
    pub fn is_on(&self) -> bool {
        puffin::are_scopes_on()
    }

    /// The lengths of the last `n` recorded frames, oldest first.
    pub fn recent(&self, n: usize) -> Vec<FrameTime> {
        let Some(view) = &self.view else {
            return Vec::new();
        };
        let view = view.lock();
        view.latest_frames(n)
            .map(|f| FrameTime {
                index: f.frame_index(),
                duration_ms: f.duration_ns() as f64 * 1e-6,
            })
            .collect()
    }

    /// The recorded frame `index`, or the latest with `None`; `None` when it is no longer kept
    /// (or nothing was recorded). A stream puffin cannot read is logged and left out.
    pub fn frame(&self, index: Option<u64>) -> Option<ProfileFrame> {
        let view = self.view.as_ref()?.lock();
        let data = match index {
            Some(i) => view.recent_frames().find(|f| f.frame_index() == i).cloned(),
            None => view.latest_frame(),
        }?;
        Some(read_frame(&data, view.scope_collection()))
    }
}

/// Reads `data`'s per-thread streams into bars, names from `names`.
fn read_frame(data: &Arc<puffin::FrameData>, names: &puffin::ScopeCollection) -> ProfileFrame {
    let start_ns = data.range_ns().0;
    let mut threads = Vec::new();
    // Without puffin's `packing` feature a frame is always unpacked: this cannot fail.
    let Ok(unpacked) = data.unpacked();
    for (info, stream) in &unpacked.thread_streams {
        let mut thread = ThreadScopes {
            name: info.name.clone(),
            scopes: Vec::new(),
        };
        let reader = puffin::Reader::from_start(&stream.stream);
        let read = read_scopes(
            reader,
            &stream.stream,
            names,
            start_ns,
            None,
            0,
            &mut thread,
        );
        if let Err(e) = read {
            log::warn!("profiler: thread {:?}'s frame stream: {e:?}", info.name);
        }
        threads.push(thread);
    }
    ProfileFrame {
        index: data.frame_index(),
        duration_ms: data.duration_ns() as f64 * 1e-6,
        threads,
    }
}

/// Reads the sibling scopes of `reader` (and their children, depth first) into `thread`.
fn read_scopes(
    reader: puffin::Reader<'_>,
    stream: &puffin::Stream,
    names: &puffin::ScopeCollection,
    start_ns: i64,
    parent: Option<usize>,
    depth: usize,
    thread: &mut ThreadScopes,
) -> puffin::Result<()> {
    for scope in reader {
        let scope = scope?;
        let name = names
            .fetch_by_id(&scope.id)
            .map_or_else(|| format!("scope {}", scope.id.0), |d| d.name().to_string());
        let index = thread.scopes.len();
        thread.scopes.push(ScopeBar {
            name,
            data: scope.record.data.to_string(),
            depth,
            parent,
            start_ms: (scope.record.start_ns - start_ns) as f64 * 1e-6,
            duration_ms: scope.record.duration_ns as f64 * 1e-6,
        });
        let children = puffin::Reader::with_offset(stream, scope.child_begin_position)?;
        read_scopes(
            children,
            stream,
            names,
            start_ns,
            Some(index),
            depth + 1,
            thread,
        )?;
    }
    Ok(())
}
