//! Sampling one channel at a time: step, linear (slerp for rotations) and cubic-spline
//! interpolation, exactly as glTF 2.0 (Appendix C) specifies.
//!
//! Owns: [`sample_channel`] and the quaternion [`slerp`]. Must not: know about poses or nodes.
//!
//! Conventions, chosen so that Candela matches three.js (the independent reference in
//! `shared/external/animation-reference`) to float32 precision:
//! - Time is float64 seconds; key times are the file's float32 values widened to float64.
//!   A float32 clock would round a time 3e-8 s before a STEP key onto the key and take the
//!   next value (the reference's InterpolationTest `0_Step_Scale` at 0.75 d).
//! - Arithmetic runs in float64 and the result is rounded to float32 (three does the same:
//!   JS numbers, then a `Float32Array` result buffer).
//! - Before the first key or after the last, the first or last key *value* holds (for a
//!   cubic spline, the spline vertex, never a tangent). A time exactly on a key takes that key.
//! - Rotation keys are used as stored, not normalised: two files (SimpleSkin,
//!   AnimatedTriangle) store keys up to 2.3e-4 off unit length, and three (like the glTF
//!   sample slerp) passes them through; normalising would move vertices by up to 4.5e-4.
//!   Linear rotation: shortest path; a time exactly on a key, or two identical keys, return
//!   the key unchanged; slerp below a dot product of 0.9995, above it lerp then normalise.
//!   Cubic-spline rotations are normalised after interpolation (glTF 2.0 requires it).

use super::clip::{Channel, Interpolation, Property};

/// Writes the value of `channel` at `time_seconds` into `out` (`channel.width` floats).
/// `channel` must have passed `check_clip` (at least one key, matching value count).
pub fn sample_channel(channel: &Channel, time_seconds: f64, out: &mut [f32]) {
    let width = channel.width;
    let times = &channel.times_seconds;
    let per_key = channel.elements_per_key();
    // Element `k`'s value (the spline vertex for cubic splines).
    let value = |k: usize| {
        let start = (k * per_key + per_key / 2) * width;
        &channel.values[start..start + width]
    };
    let count = times.len();
    if count == 0 || channel.values.len() < count * per_key * width || out.len() < width {
        return;
    }
    // First key with a time after `time_seconds`.
    let next = times.partition_point(|&t| f64::from(t) <= time_seconds);
    if next == 0 || count == 1 {
        out[..width].copy_from_slice(value(0));
        return;
    }
    if next == count {
        out[..width].copy_from_slice(value(count - 1));
        return;
    }
    let k = next - 1;
    let (t0, t1) = (f64::from(times[k]), f64::from(times[k + 1]));
    let span = t1 - t0;
    let u = (time_seconds - t0) / span;
    match channel.interpolation {
        Interpolation::Step => out[..width].copy_from_slice(value(k)),
        Interpolation::Linear if channel.property == Property::Rotation => {
            let q = slerp(as4(value(k)), as4(value(k + 1)), u);
            for (o, c) in out.iter_mut().zip(q) {
                *o = c as f32;
            }
        }
        Interpolation::Linear => {
            let (a, b) = (value(k), value(k + 1));
            for i in 0..width {
                out[i] = (f64::from(a[i]) * (1.0 - u) + f64::from(b[i]) * u) as f32;
            }
        }
        Interpolation::CubicSpline => {
            // Element layout per key: in-tangent, value, out-tangent.
            let element = |k: usize, e: usize| {
                let start = (k * 3 + e) * width;
                &channel.values[start..start + width]
            };
            let (p0, m0) = (element(k, 1), element(k, 2));
            let (m1, p1) = (element(k + 1, 0), element(k + 1, 1));
            let (u2, u3) = (u * u, u * u * u);
            let s2 = -2.0 * u3 + 3.0 * u2;
            let s3 = u3 - u2;
            let s0 = 1.0 - s2;
            let s1 = s3 - u2 + u;
            let at = |i: usize| {
                s0 * f64::from(p0[i])
                    + s1 * span * f64::from(m0[i])
                    + s2 * f64::from(p1[i])
                    + s3 * span * f64::from(m1[i])
            };
            if channel.property == Property::Rotation {
                let q: [f64; 4] = std::array::from_fn(at);
                let length = q.iter().map(|c| c * c).sum::<f64>().sqrt();
                let scale = if length > 0.0 { 1.0 / length } else { 1.0 };
                for (o, c) in out.iter_mut().zip(q) {
                    *o = (c * scale) as f32;
                }
            } else {
                for (i, o) in out[..width].iter_mut().enumerate() {
                    *o = at(i) as f32;
                }
            }
        }
    }
}

fn as4(values: &[f32]) -> [f64; 4] {
    [
        f64::from(values[0]),
        f64::from(values[1]),
        f64::from(values[2]),
        f64::from(values[3]),
    ]
}

/// Spherical linear interpolation of quaternions (x, y, z, w) from `a` (u = 0) to `b`
/// (u = 1) along the shortest path, as in the glTF 2.0 sample implementation: lerp and
/// normalise when the keys are nearly parallel (dot > 0.9995). `a` comes back unchanged at
/// u = 0 or when `a == b`; the keys are not normalised first (see the module doc).
pub fn slerp(a: [f64; 4], b: [f64; 4], u: f64) -> [f64; 4] {
    if u == 0.0 || a == b {
        return a;
    }
    let mut dot: f64 = a.iter().zip(&b).map(|(x, y)| x * y).sum();
    let mut b = b;
    if dot < 0.0 {
        b = b.map(|c| -c);
        dot = -dot;
    }
    if dot > 0.9995 {
        let lerped: [f64; 4] = std::array::from_fn(|i| a[i] + (b[i] - a[i]) * u);
        let length = lerped.iter().map(|c| c * c).sum::<f64>().sqrt();
        return if length > 0.0 {
            lerped.map(|c| c / length)
        } else {
            a
        };
    }
    let theta_0 = dot.min(1.0).acos();
    let theta = theta_0 * u;
    let (sin_theta, sin_theta_0) = (theta.sin(), theta_0.sin());
    let scale_a = theta.cos() - dot * sin_theta / sin_theta_0;
    let scale_b = sin_theta / sin_theta_0;
    std::array::from_fn(|i| scale_a * a[i] + scale_b * b[i])
}
