//! The light tree's importance (`render::cpu::light_tree::importance_pair`): the root-packed
//! form the walk uses computes PBRT-v4's `LightBounds::Importance`, and sampling and MIS read
//! the same probabilities from it.
//!
//! * On 20,000 random nodes (boxes from points to 20 m, any axis, normal cones from a single
//!   direction to the whole sphere, one- and two-sided, powers over six decades) and points
//!   inside, beside and far from them, with and without a normal, `importance` agrees with
//!   PBRT's formula (its sines from cosines, `acos`-free as in PBRT-v4) evaluated in f64 to
//!   within 2e-3 of φ/d² (f32's cancellation in 1 − cos² near an axis costs ~3e-4 there; a
//!   swapped sine or a dropped factor is off by O(1)). Points on the bounding sphere itself,
//!   where PBRT's bound jumps, are skipped.
//! * Each lane of the pair is that node's importance alone, bit for bit, whatever its partner.
//! * On a random 500-light tree the probability `sample` reports for its pick equals `pmf` of
//!   that light's leaf (the MIS side) to 1e-5, at 2,000 random points.

use candela::layout::{GpuLight, GpuLightNode, INVALID, LIGHT_NODE_TWO_SIDED};
use candela::render::cpu::light_tree::{importance, importance_pair, pmf, sample};
use candela::scene::light_tree::{build_tree, leaf_of};
use glam::{DVec3, Vec3};

/// A small deterministic generator (xorshift64*), uniform in [0, 1).
struct Rand(u64);

impl Rand {
    fn next(&mut self) -> f32 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let x = self.0.wrapping_mul(0x2545_f491_4f6c_dd1d);
        (x >> 40) as f32 / (1u64 << 24) as f32
    }

    fn vec(&mut self, lo: f32, hi: f32) -> Vec3 {
        Vec3::new(self.next(), self.next(), self.next()) * (hi - lo) + Vec3::splat(lo)
    }

    fn unit(&mut self) -> Vec3 {
        loop {
            let v = self.vec(-1.0, 1.0);
            if v.length_squared() > 0.01 && v.length_squared() <= 1.0 {
                return v.normalize();
            }
        }
    }
}

fn random_node(rand: &mut Rand) -> GpuLightNode {
    let centre = rand.vec(-10.0, 10.0);
    let half = match rand.next() {
        x if x < 0.1 => Vec3::ZERO,
        x if x < 0.3 => rand.vec(0.0, 0.05),
        _ => rand.vec(0.0, 10.0),
    };
    let cos_theta_o = match rand.next() {
        x if x < 0.4 => 1.0,
        x if x < 0.5 => -1.0,
        _ => 2.0 * rand.next() - 1.0,
    };
    GpuLightNode {
        bounds_min: (centre - half).to_array(),
        phi: 10f32.powf(6.0 * rand.next() - 3.0),
        bounds_max: (centre + half).to_array(),
        cos_theta_o,
        axis: rand.unit().to_array(),
        cos_theta_e: 0.0,
        child: 0,
        parent: INVALID,
        flags: if rand.next() < 0.3 {
            LIGHT_NODE_TWO_SIDED
        } else {
            0
        },
        _padding: 0,
    }
}

/// cos(max(0, θa − θb)) and sin(max(0, θa − θb)) from sines and cosines.
fn cos_sub(sin_a: f64, cos_a: f64, sin_b: f64, cos_b: f64) -> f64 {
    if cos_a > cos_b {
        1.0
    } else {
        cos_a * cos_b + sin_a * sin_b
    }
}

fn sin_sub(sin_a: f64, cos_a: f64, sin_b: f64, cos_b: f64) -> f64 {
    if cos_a > cos_b {
        0.0
    } else {
        sin_a * cos_b - cos_a * sin_b
    }
}

fn safe_sqrt(x: f64) -> f64 {
    x.max(0.0).sqrt()
}

/// PBRT-v4's `LightBounds::Importance` in f64, as the walk computed it before the pairing:
/// returns (importance, φ/d², |p − c|² − r² relative to r²).
fn reference(node: &GpuLightNode, p: Vec3, n: Vec3) -> (f64, f64, f64) {
    let min = Vec3::from(node.bounds_min).as_dvec3();
    let max = Vec3::from(node.bounds_max).as_dvec3();
    let (p, n) = (p.as_dvec3(), n.as_dvec3());
    let pc = (min + max) * 0.5;
    let d2 = p.distance_squared(pc).max((max - min).length() * 0.5);
    let phi = node.phi as f64;
    let scale = phi / d2;
    let to_p = p - pc;
    let len2 = to_p.length_squared();
    let radius2 = (max - pc).length_squared();
    let margin = (len2 - radius2).abs() / radius2.max(1e-12);
    let wi = if len2 > 0.0 {
        to_p / len2.sqrt()
    } else {
        DVec3::ZERO
    };
    let mut cos_w = Vec3::from(node.axis).as_dvec3().dot(wi);
    if node.flags & LIGHT_NODE_TWO_SIDED != 0 {
        cos_w = cos_w.abs();
    }
    let sin_w = safe_sqrt(1.0 - cos_w * cos_w);
    let cos_b = if len2 < radius2 {
        -1.0
    } else {
        safe_sqrt(1.0 - radius2 / len2)
    };
    let sin_b = safe_sqrt(1.0 - cos_b * cos_b);
    let cos_o = node.cos_theta_o as f64;
    let sin_o = safe_sqrt(1.0 - cos_o * cos_o);
    let cos_x = cos_sub(sin_w, cos_w, sin_o, cos_o);
    let sin_x = sin_sub(sin_w, cos_w, sin_o, cos_o);
    let cos_p = cos_sub(sin_x, cos_x, sin_b, cos_b);
    if cos_p <= node.cos_theta_e as f64 {
        return (0.0, scale, margin);
    }
    let mut importance = phi * cos_p / d2;
    if n != DVec3::ZERO {
        let cos_i = wi.dot(n).abs();
        let sin_i = safe_sqrt(1.0 - cos_i * cos_i);
        importance *= cos_sub(sin_i, cos_i, sin_b, cos_b);
    }
    (importance.max(0.0), scale, margin)
}

#[test]
fn importance_is_pbrts_on_random_nodes() {
    let mut rand = Rand(0x5eed);
    let mut checked = 0;
    for case in 0..20_000 {
        let node = random_node(&mut rand);
        let centre = (Vec3::from(node.bounds_min) + Vec3::from(node.bounds_max)) * 0.5;
        let p = match case % 3 {
            0 => centre + rand.vec(-1.0, 1.0),
            1 => centre + rand.vec(-15.0, 15.0),
            _ => centre + rand.unit() * 500.0,
        };
        let n = if case % 5 == 0 {
            Vec3::ZERO
        } else {
            rand.unit()
        };
        let (want, scale, margin) = reference(&node, p, n);
        if margin < 1e-4 || !scale.is_finite() {
            continue;
        }
        let got = importance(&node, p, n) as f64;
        assert!(
            (got - want).abs() <= 2e-3 * scale,
            "case {case}: importance {got} against PBRT's {want} (φ/d² {scale}) for {node:?} \
             from {p} (normal {n})"
        );
        // Each lane is its node's own value, whatever the other lane holds.
        let other = random_node(&mut rand);
        let [a, b] = importance_pair(&node, &other, p, n);
        let [c, d] = importance_pair(&other, &node, p, n);
        assert_eq!(a.to_bits(), (got as f32).to_bits(), "case {case}: lane 0");
        assert_eq!(d.to_bits(), a.to_bits(), "case {case}: lane 1");
        assert_eq!(b.to_bits(), importance(&other, p, n).to_bits());
        assert_eq!(c.to_bits(), b.to_bits());
        checked += 1;
    }
    assert!(checked > 19_000, "only {checked} cases off the sphere");
}

#[test]
fn the_pick_reports_the_pmf_mis_computes() {
    let mut rand = Rand(99);
    let mut lights = Vec::new();
    let mut phi = Vec::new();
    let mut two = Vec::new();
    for i in 0..500u32 {
        let c = rand.vec(-5.0, 5.0);
        let size = 0.05 + 0.5 * rand.next();
        let p = [c, c + rand.unit() * size, c + rand.unit() * size];
        lights.push(GpuLight {
            p0: p[0].to_array(),
            instance: i / 50,
            p1: p[1].to_array(),
            triangle: i % 50,
            p2: p[2].to_array(),
            weight: 1.0,
            alias_threshold: 1.0,
            alias_index: 0,
            _padding: [0; 2],
        });
        phi.push(10f32.powf(3.0 * rand.next()));
        two.push(i % 4 == 0);
    }
    let tree = build_tree(&lights, &phi, &two, 10, &[50; 10]);
    let mut picked = 0;
    for point in 0..2_000 {
        let p = rand.vec(-8.0, 8.0);
        let n = if point % 7 == 0 {
            Vec3::ZERO
        } else {
            rand.unit()
        };
        let Some((light, chance)) = sample(&tree.nodes, 500, p, n, rand.next()) else {
            continue;
        };
        let l = &lights[light as usize];
        let mis = pmf(
            &tree.nodes,
            leaf_of(&tree.lookup, l.instance, l.triangle),
            p,
            n,
        );
        assert!(
            chance > 0.0 && (chance - mis).abs() <= 1e-5 * chance,
            "point {point}: picked light {light} with {chance}, MIS reads {mis}"
        );
        picked += 1;
    }
    assert!(picked > 1_900, "only {picked} picks");
}
