//! The ruins' glyphs: four Aztec-like signs (sun, step fret, eye, serpent) as masks over the
//! square `[-1, 1]²` (x to the right, y up). The carved-stone texture raises them in relief
//! and the glowing glyph tile builds its emissive inlay from the same mask, so the two agree.
//! Must not: draw images or build meshes (the callers do).

/// How many glyphs there are.
pub const GLYPH_COUNT: usize = 4;

/// The step fret (a square spiral), 12 × 12 cells, top row first.
const FRET: [&str; 12] = [
    "############",
    "#..........#",
    "#.########.#",
    "#.#......#.#",
    "#.#.####.#.#",
    "#.#.#..#.#.#",
    "#.#.#.##.#.#",
    "#.#.#....#.#",
    "#.#.######.#",
    "#.#........#",
    "#.##########",
    "#...........",
];

fn fret(x: f32, y: f32) -> bool {
    let col = (((x + 1.0) * 6.0).floor() as i64).clamp(0, 11) as usize;
    let row = (((1.0 - y) * 6.0).floor() as i64).clamp(0, 11) as usize;
    FRET[row].as_bytes()[col] == b'#'
}

fn sun(x: f32, y: f32) -> bool {
    let r = (x * x + y * y).sqrt();
    let ray = (0.58..0.95).contains(&r)
        && (x.abs() < 0.09 || y.abs() < 0.09 || (x - y).abs() < 0.12 || (x + y).abs() < 0.12);
    r < 0.2 || (0.33..0.47).contains(&r) || ray
}

fn eye(x: f32, y: f32) -> bool {
    let square = x.abs().max(y.abs());
    let diamond = x.abs() + y.abs();
    let r = (x * x + y * y).sqrt();
    (0.78..0.95).contains(&square) || (0.42..0.58).contains(&diamond) || r < 0.17
}

fn serpent(x: f32, y: f32) -> bool {
    // A zigzag body (a triangle wave of period 0.8), a head at the right, two rows of scales.
    let phase = ((x + 1.0) / 0.8).fract();
    let wave = 0.4 * ((phase * 2.0 - 1.0).abs() * 2.0 - 1.0);
    let body = (y - wave).abs() < 0.14 && x < 0.7;
    let head = (x - 0.78).abs() < 0.18 && (y - 0.4).abs() < 0.2;
    let scale = |cy: f32| {
        let cx = ((x + 1.0) / 0.4).floor() * 0.4 - 0.8;
        (x - cx).abs() < 0.07 && (y - cy).abs() < 0.07
    };
    body || head || scale(0.82) || scale(-0.82)
}

/// Whether glyph `index` (mod [`GLYPH_COUNT`]) covers `(x, y)` ∈ `[-1, 1]²`.
pub fn covers(index: usize, x: f32, y: f32) -> bool {
    if x.abs() > 1.0 || y.abs() > 1.0 {
        return false;
    }
    match index % GLYPH_COUNT {
        0 => sun(x, y),
        1 => fret(x, y),
        2 => eye(x, y),
        _ => serpent(x, y),
    }
}
