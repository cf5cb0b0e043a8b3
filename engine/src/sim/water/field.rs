//! The water's height field: the damped wave equation on a regular grid (Müller-Fischer, GDC
//! 2008), in the grid's object space (metres, seconds, +Y up).
//!
//! Owns: the heights and vertical speeds per grid vertex, the waders' push of the last step,
//! one fixed step (push, then substeps of symplectic Euler), the discrete energy and the state
//! words for the engine's state hash. Main thread, inside the fixed steps. Must not: read the
//! ECS or the physics world (`water.rs` gathers the push), or deform meshes (the app's waves
//! system adds these heights to the swell).

use glam::Vec3;

use crate::assets::WaterSimDesc;

/// A regular grid of vertices, row by row (`x` fastest), as the engine's grid models are laid
/// out: vertex `(ix, iz)` is `ix + iz·columns`, at rest at `(x0 + ix·dx, y, z0 + iz·dz)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GridLayout {
    /// Vertices along x (divisions + 1), at least 3.
    pub columns: usize,
    /// Vertices along z (divisions + 1), at least 3.
    pub rows: usize,
    /// Spacing along x and z, metres, positive.
    pub dx: f32,
    pub dz: f32,
    /// Rest position of vertex 0 (object space, metres); `y` is the rest surface.
    pub origin: Vec3,
}

impl GridLayout {
    /// The layout of rest positions `base` if they form such a grid (flat, evenly spaced,
    /// at least 3 × 3 vertices); `None` otherwise.
    pub fn infer(base: &[Vec3]) -> Option<Self> {
        let origin = *base.first()?;
        let columns = base.iter().take_while(|p| p.z == origin.z).count();
        if columns < 3 || !base.len().is_multiple_of(columns) || base.len() / columns < 3 {
            return None;
        }
        let rows = base.len() / columns;
        let dx = base[1].x - origin.x;
        let dz = base[columns].z - origin.z;
        let layout = Self {
            columns,
            rows,
            dx,
            dz,
            origin,
        };
        let fits = base.iter().enumerate().all(|(i, p)| {
            let expected = layout.rest(i % columns, i / columns);
            (*p - expected).abs().max_element() <= 1e-4 * (1.0 + expected.abs().max_element())
        });
        (dx > 0.0 && dz > 0.0 && dx.is_finite() && dz.is_finite() && fits).then_some(layout)
    }

    /// Rest position of vertex `(ix, iz)`.
    pub fn rest(&self, ix: usize, iz: usize) -> Vec3 {
        self.origin + Vec3::new(ix as f32 * self.dx, 0.0, iz as f32 * self.dz)
    }

    pub fn len(&self) -> usize {
        self.columns * self.rows
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// Heights below which a surface counts as still, metres (0.1 mm).
pub const STILL_METRES: f32 = 1e-4;
/// Speeds below which a surface counts as still, metres per second.
pub const STILL_METRES_PER_SECOND: f32 = 1e-3;

/// Heights and vertical speeds on a [`GridLayout`], stepped by [`HeightField::step`].
#[derive(Clone, Debug, PartialEq)]
pub struct HeightField {
    pub layout: GridLayout,
    pub desc: WaterSimDesc,
    /// Metres above the rest surface, per vertex (edges stay 0).
    h: Vec<f32>,
    /// Metres per second, per vertex (edges stay 0).
    v: Vec<f32>,
    /// The waders' push of the last step (metres, ≥ 0 pushes down), per vertex.
    pushed: Vec<f32>,
    /// No step has run yet (see [`WaterSimDesc::start_at_rest`]).
    unstarted: bool,
    /// How many times the heights were changed (steps and raises): a mesh written at this
    /// count is still up to date.
    changes: u64,
}

impl HeightField {
    /// Still water on `layout`.
    pub fn new(layout: GridLayout, desc: WaterSimDesc) -> Self {
        let n = layout.len();
        Self {
            layout,
            desc,
            h: vec![0.0; n],
            v: vec![0.0; n],
            pushed: vec![0.0; n],
            unstarted: true,
            changes: 0,
        }
    }

    /// Heights above the rest surface, metres, per vertex.
    pub fn heights(&self) -> &[f32] {
        &self.h
    }

    /// The waders' push of the last step, metres, per vertex.
    pub fn pushed(&self) -> &[f32] {
        &self.pushed
    }

    /// True while the surface is still to the eye: every height under `STILL_METRES` and
    /// every speed under `STILL_METRES_PER_SECOND` (the mesh need not be rewritten).
    pub fn is_still(&self) -> bool {
        self.h.iter().all(|h| h.abs() < STILL_METRES)
            && self.v.iter().all(|v| v.abs() < STILL_METRES_PER_SECOND)
    }

    /// How many times the heights were changed ([`Self::step`], [`Self::raise`]) since
    /// [`Self::new`]: equal counts, equal heights.
    pub fn steps(&self) -> u64 {
        self.changes
    }

    /// Raises vertex `(ix, iz)` by `metres` (an interior vertex; edges stay 0).
    pub fn raise(&mut self, ix: usize, iz: usize, metres: f32) {
        self.changes += 1;
        let (c, r) = (self.layout.columns, self.layout.rows);
        if (1..c - 1).contains(&ix) && (1..r - 1).contains(&iz) {
            self.h[ix + iz * c] += metres;
        }
    }

    /// Substeps for a fixed step of `step_seconds`: the level's, or more when the step is
    /// longer than the 60 Hz the level was checked at and the level's would break the CFL
    /// limit (then each substep keeps the CFL number at 0.9).
    pub fn substeps(&self, step_seconds: f32) -> u32 {
        let asked = self.desc.substeps.max(1);
        let courant = (self.desc).courant(step_seconds, self.layout.dx, self.layout.dz);
        if courant < 1.0 || !courant.is_finite() {
            return asked;
        }
        (asked as f32 * courant / 0.9).ceil().min(1024.0) as u32
    }

    /// One fixed step of `step_seconds`: the surface gives way to `push` (this step's push of
    /// the waders, metres per vertex, or empty for none) by the change since the last step,
    /// then [`Self::substeps`] substeps of the damped wave equation. With
    /// [`WaterSimDesc::start_at_rest`], the first step's push is the rest state: remembered,
    /// the surface left where it is.
    pub fn step(&mut self, step_seconds: f32, push: &[f32]) {
        self.changes += 1;
        if std::mem::take(&mut self.unstarted) && self.desc.start_at_rest {
            self.rest_under(push);
        }
        self.give_way(push);
        let n = self.substeps(step_seconds);
        let dt = step_seconds / n as f32;
        for _ in 0..n {
            self.substep(dt);
        }
    }

    /// Takes `push` (metres per vertex) as what the waders pushed in the last step, so that
    /// only a later change of it makes waves.
    fn rest_under(&mut self, push: &[f32]) {
        let (c, r) = (self.layout.columns, self.layout.rows);
        for iz in 1..r - 1 {
            for ix in 1..c - 1 {
                let i = ix + iz * c;
                self.pushed[i] = push.get(i).copied().unwrap_or(0.0);
            }
        }
    }

    /// Lowers the surface by how much more the waders push than in the last step (a wader at
    /// rest pushes the same and makes no waves; one that moves or sinks does).
    fn give_way(&mut self, push: &[f32]) {
        let (c, r) = (self.layout.columns, self.layout.rows);
        let now = |i: usize| push.get(i).copied().unwrap_or(0.0);
        for iz in 1..r - 1 {
            for ix in 1..c - 1 {
                let i = ix + iz * c;
                let p = now(i);
                self.h[i] -= p - self.pushed[i];
                self.pushed[i] = p;
            }
        }
    }

    /// `v += c²·∇²h·dt; v *= exp(−damping·dt); h += v·dt` on the interior vertices.
    fn substep(&mut self, dt: f32) {
        let (c, r) = (self.layout.columns, self.layout.rows);
        let c2dt = self.desc.wave_speed * self.desc.wave_speed * dt;
        let decay = (-self.desc.damping * dt).exp();
        for iz in 1..r - 1 {
            for ix in 1..c - 1 {
                let i = ix + iz * c;
                let lap = self.laplacian(i);
                self.v[i] = (self.v[i] + c2dt * lap) * decay;
            }
        }
        for iz in 1..r - 1 {
            let row = iz * c;
            for i in row + 1..row + c - 1 {
                self.h[i] += self.v[i] * dt;
            }
        }
    }

    /// The discrete Laplacian of `h` at interior vertex `i`, 1/m.
    fn laplacian(&self, i: usize) -> f32 {
        let c = self.layout.columns;
        let (idx2, idz2) = (
            1.0 / (self.layout.dx * self.layout.dx),
            1.0 / (self.layout.dz * self.layout.dz),
        );
        let h = self.h[i];
        (self.h[i - 1] + self.h[i + 1] - 2.0 * h) * idx2
            + (self.h[i - c] + self.h[i + c] - 2.0 * h) * idz2
    }

    /// The energy the scheme keeps exactly without damping, per unit density and cell area
    /// (m⁴/s² summed over vertices): `½Σv² + ½c²Σ(∇h)² + ½·dt·c²·Σv·∇²h` with `dt` one substep
    /// of a `step_seconds` step (the last term is the symplectic Euler scheme's correction).
    pub fn energy(&self, step_seconds: f32) -> f64 {
        let (c, r) = (self.layout.columns, self.layout.rows);
        let dt = f64::from(step_seconds / self.substeps(step_seconds) as f32);
        let c2 = f64::from(self.desc.wave_speed).powi(2);
        let (dx, dz) = (f64::from(self.layout.dx), f64::from(self.layout.dz));
        let (mut kinetic, mut gradient, mut cross) = (0.0, 0.0, 0.0);
        for iz in 0..r {
            for ix in 0..c {
                let i = ix + iz * c;
                let h = f64::from(self.h[i]);
                if ix + 1 < c {
                    gradient += ((f64::from(self.h[i + 1]) - h) / dx).powi(2);
                }
                if iz + 1 < r {
                    gradient += ((f64::from(self.h[i + c]) - h) / dz).powi(2);
                }
                if (1..c - 1).contains(&ix) && (1..r - 1).contains(&iz) {
                    let v = f64::from(self.v[i]);
                    kinetic += v * v;
                    cross += v * f64::from(self.laplacian(i));
                }
            }
        }
        0.5 * kinetic + 0.5 * c2 * gradient + 0.5 * dt * c2 * cross
    }

    /// The state as 64-bit words for the engine's state hash: heights, speeds, last push
    /// (f32 bits, vertex order).
    pub fn state_words(&self) -> impl Iterator<Item = u64> + '_ {
        (self.h.iter().chain(&self.v).chain(&self.pushed)).map(|x| u64::from(x.to_bits()))
    }
}
