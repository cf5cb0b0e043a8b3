//! Chamber signs `sign_1` … `sign_5`: a 1 × 1 m dark metal plate (face at z = 0, y ∈ [0, 1])
//! whose face shows the chamber number ("01" … "05", from a built-in 5 × 7 bitmap font), a row
//! of five progress squares and a row of icons (cube, plate, laser, mirror, elevator; the ones
//! the chamber uses in orange). The digits and the filled squares glow: the face material's
//! emissive texture is white there and black elsewhere.
//!
//! Output: the pieces and their 128 × 128 textures `sign_N.png` (colour) and `sign_N_glow.png`
//! (emission). Must not: write files or read font files.

use glam::{Vec2, Vec3};
use image::{Rgb, RgbImage};

use super::Piece;
use super::materials as mat;
use super::mesh::{Builder, Uv};

/// Number of chamber signs.
pub const SIGN_COUNT: u32 = 5;

/// Side of the sign textures, texels.
const SIZE: u32 = 128;

/// The digits 0–9 of a 5 × 7 bitmap font: one row per byte, bit 4 the leftmost column.
const FONT: [[u8; 7]; 10] = [
    [0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E],
    [0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E],
    [0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F],
    [0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E],
    [0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02],
    [0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E],
    [0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E],
    [0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08],
    [0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E],
    [0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C],
];

/// Icons on every sign, in order.
#[derive(Clone, Copy, PartialEq, Debug)]
enum Icon {
    Cube,
    Plate,
    Laser,
    Mirror,
    Elevator,
}

const ICONS: [Icon; 5] = [
    Icon::Cube,
    Icon::Plate,
    Icon::Laser,
    Icon::Mirror,
    Icon::Elevator,
];

/// What each chamber uses (REFLECT.md, "Chambers").
fn chamber_uses(number: u32) -> &'static [Icon] {
    match number {
        1 => &[Icon::Cube, Icon::Plate],
        2 => &[Icon::Laser, Icon::Mirror],
        3 => &[Icon::Laser, Icon::Cube],
        4 => &[
            Icon::Cube,
            Icon::Plate,
            Icon::Laser,
            Icon::Mirror,
            Icon::Elevator,
        ],
        _ => &[Icon::Elevator],
    }
}

/// Whether texel `(x, y)` (0..16 each) of `icon` is drawn.
fn icon_pixel(icon: Icon, x: i32, y: i32) -> bool {
    match icon {
        Icon::Cube => {
            let outer = (1..15).contains(&x) && (1..15).contains(&y);
            let inner = (4..12).contains(&x) && (4..12).contains(&y);
            (outer && !((3..13).contains(&x) && (3..13).contains(&y))) || inner
        }
        Icon::Plate => {
            (y == 11 || y == 12) && (1..15).contains(&x)
                || (y == 9 || y == 10) && (4..12).contains(&x)
        }
        Icon::Laser => {
            let dot = (x - 3).pow(2) + (y - 8).pow(2) <= 6;
            dot || ((7..9).contains(&y) && (3..15).contains(&x))
        }
        Icon::Mirror => (x - y).abs() <= 1 && (1..15).contains(&x) || x == 15 - y && y >= 11,
        Icon::Elevator => {
            let shaft = (7..9).contains(&x) && (6..15).contains(&y);
            let head = (1..8).contains(&y) && (2 * x - 15).abs() <= 2 * (y - 1);
            shaft || head
        }
    }
}

/// The colour and glow textures of sign `number`.
pub fn sign_textures(number: u32) -> (RgbImage, RgbImage) {
    const BACK: [u8; 3] = [38, 40, 44];
    const WHITE: [u8; 3] = [242, 242, 238];
    const ORANGE: [u8; 3] = [240, 118, 20];
    const DIM: [u8; 3] = [82, 84, 90];
    let mut color = RgbImage::from_pixel(SIZE, SIZE, Rgb(BACK));
    let mut glow = RgbImage::from_pixel(SIZE, SIZE, Rgb([0, 0, 0]));
    let mut put = |x: u32, y: u32, c: [u8; 3], lit: u8| {
        if x < SIZE && y < SIZE {
            color.put_pixel(x, y, Rgb(c));
            glow.put_pixel(x, y, Rgb([lit; 3]));
        }
    };
    // A white border 3 texels wide, and a rule under the digits.
    for y in 0..SIZE {
        for x in 0..SIZE {
            let d = x.min(y).min(SIZE - 1 - x).min(SIZE - 1 - y);
            if (3..6).contains(&d) || ((16..112).contains(&x) && (80..82).contains(&y)) {
                put(x, y, WHITE, 0);
            }
        }
    }
    // "0N": two digits of 8-texel cells (40 × 56 each), 8 texels apart.
    let digits = [0, number as usize % 10];
    for (k, digit) in digits.iter().enumerate() {
        let left = 20 + k as u32 * 48;
        for (row, bits) in FONT[*digit].iter().enumerate() {
            for col in 0..5u32 {
                if bits & (0x10 >> col) == 0 {
                    continue;
                }
                for dy in 0..8 {
                    for dx in 0..8 {
                        put(left + col * 8 + dx, 16 + row as u32 * 8 + dy, WHITE, 255);
                    }
                }
            }
        }
    }
    // Progress: five squares, the first `number` filled (and glowing).
    for i in 0..SIGN_COUNT {
        let left = 24 + i * 17;
        for dy in 0..9 {
            for dx in 0..12 {
                let edge = dx == 0 || dy == 0 || dx == 11 || dy == 8;
                if i < number {
                    put(left + dx, 86 + dy, WHITE, 200);
                } else if edge {
                    put(left + dx, 86 + dy, DIM, 0);
                }
            }
        }
    }
    // Icons, 16 × 16 each, 6 texels apart, centred.
    let uses = chamber_uses(number);
    for (i, icon) in ICONS.iter().enumerate() {
        let left = 11 + i as u32 * 22;
        let c = if uses.contains(icon) { ORANGE } else { DIM };
        for y in 0..16 {
            for x in 0..16 {
                if icon_pixel(*icon, x, y) {
                    put(left + x as u32, 102 + y as u32, c, 0);
                }
            }
        }
    }
    (color, glow)
}

/// Sign `number` (1 ..= [`SIGN_COUNT`]): a bevelled dark metal plate x ∈ [−0.5, 0.5],
/// y ∈ [0, 1], z ∈ [−0.05, −0.004], and the face (4 × 4 quads) at z = 0.
pub fn sign(number: u32, name: &'static str) -> Piece {
    let (face, metal) = (0, 1);
    let mut b = Builder::new(2);
    b.bevel_box(
        metal,
        Vec3::new(-0.5, 0.0, -0.05),
        Vec3::new(0.5, 1.0, -0.004),
        0.02,
        Uv::Planar(1.0),
    );
    b.panel(
        face,
        Vec3::new(-0.47, 0.03, 0.0),
        Vec3::new(0.94, 0.0, 0.0),
        Vec3::new(0.0, 0.94, 0.0),
        4,
        4,
        |s| Vec2::new(s.x, 1.0 - s.y),
    );
    Piece::new(name, vec![mat::sign_face(number), mat::metal_dark()], b)
}
