//! The light tree (`scene::light_tree`, sampled by `render::cpu::light_tree`): its structure,
//! and that sampling it is what its PMF says.
//!
//! * Structure: every light in exactly one leaf, parents linked, powers summed, the hit lookup
//!   finds every light's leaf and nothing else; no lights and zero power give the placeholder.
//! * The cone union contains both cones.
//! * For random shading points (inside and outside the lights' region, with and without a
//!   normal) the PMF summed over all lights plus the probability of a dead end is 1. A dead
//!   end (PBRT-v4 has them too) is a node whose bound lets the point see it while neither
//!   child's does: the walk then picks no light, which costs a sample but no bias (a light
//!   with PMF 0 cannot light the point). The probability `sample` reports equals the PMF of
//!   the light it picked, and the frequencies of 200,000 picks (dead ends one more bin) match
//!   the PMF by a chi-square test (bins of expected count < 5 merged; the
//!   p-value from the Wilson–Hilferty approximation must exceed 1e-6 at every point, so a false
//!   alarm has probability < 1e-5 over the whole test; a PMF off by a few per cent on any
//!   sizeable light fails it).

use candela::layout::{GpuLight, INVALID, LIGHT_NODE_LEAF};
use candela::render::cpu::light_tree::{pmf, sample};
use candela::scene::light_tree::{LightTree, build_tree, cone_union, leaf_of};
use glam::Vec3;

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

fn light(p: [Vec3; 3], instance: u32, triangle: u32) -> GpuLight {
    GpuLight {
        p0: p[0].to_array(),
        instance,
        p1: p[1].to_array(),
        triangle,
        p2: p[2].to_array(),
        weight: 1.0,
        alias_threshold: 1.0,
        alias_index: 0,
        _padding: [0; 2],
    }
}

/// `n` random triangles in a 10 m box, random orientations and powers over three decades,
/// every fifth two-sided; instances of 50 triangles each.
fn random_lights(n: u32, rand: &mut Rand) -> (Vec<GpuLight>, Vec<f32>, Vec<bool>) {
    let mut lights = Vec::new();
    let mut phi = Vec::new();
    let mut two = Vec::new();
    for i in 0..n {
        let c = rand.vec(-5.0, 5.0);
        let size = 0.05 + 0.5 * rand.next();
        let (a, b) = (rand.unit() * size, rand.unit() * size);
        lights.push(light([c, c + a, c + b], i / 50, i % 50));
        phi.push(10f32.powf(3.0 * rand.next()));
        two.push(i % 5 == 0);
    }
    (lights, phi, two)
}

fn tree_of(lights: &[GpuLight], phi: &[f32], two: &[bool]) -> LightTree {
    let instances = lights.iter().map(|l| l.instance + 1).max().unwrap_or(0) as usize;
    build_tree(lights, phi, two, instances, &vec![50; instances])
}

#[test]
fn every_light_has_one_leaf_and_parents_link_up() {
    let mut rand = Rand(7);
    let (lights, phi, two) = random_lights(333, &mut rand);
    let tree = tree_of(&lights, &phi, &two);
    let mut seen = vec![0; lights.len()];
    for (i, n) in tree.nodes.iter().enumerate() {
        if n.flags & LIGHT_NODE_LEAF != 0 {
            seen[n.child as usize] += 1;
        } else {
            let (a, b) = (&tree.nodes[i + 1], &tree.nodes[n.child as usize]);
            assert_eq!(a.parent, i as u32);
            assert_eq!(b.parent, i as u32);
            assert!((n.phi - a.phi - b.phi).abs() <= 1e-4 * n.phi);
            for k in 0..3 {
                assert!(n.bounds_min[k] <= a.bounds_min[k].min(b.bounds_min[k]));
                assert!(n.bounds_max[k] >= a.bounds_max[k].max(b.bounds_max[k]));
            }
        }
    }
    assert!(seen.iter().all(|&s| s == 1), "{seen:?}");
    assert_eq!(tree.nodes[0].parent, INVALID);
    // `build_tree` takes each light's power as given (the light table doubles two-sided ones).
    let total: f32 = phi.iter().sum();
    assert!((tree.nodes[0].phi - total).abs() < 1e-4 * total);
    for (i, l) in lights.iter().enumerate() {
        let leaf = leaf_of(&tree.lookup, l.instance, l.triangle);
        assert_eq!(tree.nodes[leaf as usize].child, i as u32);
    }
    // Triangles that are not lights, instances beyond the table, garbage: no leaf.
    assert_eq!(leaf_of(&tree.lookup, 1000, 0), INVALID);
    assert_eq!(leaf_of(&tree.lookup, 0, 10_000), INVALID);
    assert_eq!(leaf_of(&[], 0, 0), INVALID);
}

#[test]
fn no_lights_and_zero_power_give_the_placeholder() {
    let empty = build_tree(&[], &[], &[], 0, &[]);
    assert_eq!(empty, LightTree::default());
    let l = light([Vec3::ZERO, Vec3::X, Vec3::Z], 0, 0);
    assert_eq!(build_tree(&[l], &[0.0], &[false], 1, &[1]), empty);
    assert_eq!(build_tree(&[l], &[f32::NAN], &[false], 1, &[1]), empty);
    // A zero-area light has no orientation but still a box: it may be a leaf, never a NaN.
    let flat = light([Vec3::ZERO, Vec3::X, Vec3::X * 2.0], 0, 0);
    let tree = build_tree(&[flat], &[1.0], &[false], 1, &[1]);
    assert!(tree.nodes.iter().all(|n| n.phi.is_finite()));
    // Sampling the placeholder finds nothing.
    assert_eq!(sample(&empty.nodes, 0, Vec3::ZERO, Vec3::Y, 0.5), None);
    assert_eq!(pmf(&empty.nodes, 0, Vec3::ZERO, Vec3::Y), 0.0);
}

#[test]
fn cone_union_contains_both_cones() {
    let mut rand = Rand(3);
    for _ in 0..500 {
        let a = (rand.unit(), 2.0 * rand.next() - 1.0);
        let b = (rand.unit(), 2.0 * rand.next() - 1.0);
        let (w, cos) = cone_union(a, b);
        assert!((w.length() - 1.0).abs() < 1e-4 && cos.is_finite());
        for (axis, c) in [a, b] {
            // The farthest direction of each cone from the union's axis lies inside it.
            let far = c.clamp(-1.0, 1.0).acos() + w.dot(axis).clamp(-1.0, 1.0).acos();
            assert!(
                cos <= -0.9999 || far <= cos.clamp(-1.0, 1.0).acos() + 2e-3,
                "{a:?} ∪ {b:?} = ({w}, {cos}) misses {axis}"
            );
        }
    }
}

/// Upper tail of the chi-square distribution with `k` degrees of freedom at `x`
/// (Wilson–Hilferty: (x/k)^(1/3) is nearly normal with mean 1 − 2/(9k), variance 2/(9k)).
fn chi_square_tail(x: f64, k: f64) -> f64 {
    let z = ((x / k).cbrt() - (1.0 - 2.0 / (9.0 * k))) / (2.0 / (9.0 * k)).sqrt();
    0.5 * erfc(z / std::f64::consts::SQRT_2)
}

/// Complementary error function (Numerical Recipes' erfcc, relative error < 1.2e-7).
fn erfc(x: f64) -> f64 {
    let z = x.abs();
    let t = 1.0 / (1.0 + 0.5 * z);
    let r = t
        * (-z * z - 1.26551223
            + t * (1.00002368
                + t * (0.37409196
                    + t * (0.09678418
                        + t * (-0.18628806
                            + t * (0.27886807
                                + t * (-1.13520398
                                    + t * (1.48851587 + t * (-0.82215223 + t * 0.17087277)))))))))
            .exp();
    if x >= 0.0 { r } else { 2.0 - r }
}

#[test]
fn pmf_sums_to_one_and_matches_the_sampling_frequencies() {
    let mut rand = Rand(11);
    let (lights, phi, two) = random_lights(400, &mut rand);
    let tree = tree_of(&lights, &phi, &two);
    let count = lights.len() as u32;
    let leaves: Vec<u32> = lights
        .iter()
        .map(|l| leaf_of(&tree.lookup, l.instance, l.triangle))
        .collect();
    const SAMPLES: usize = 200_000;
    for point in 0..10 {
        // Inside the lights' region, then farther out; the last point has no normal.
        let p = rand.vec(-5.0, 5.0) * if point < 5 { 1.0 } else { 3.0 };
        let n = if point == 9 { Vec3::ZERO } else { rand.unit() };
        let pmfs: Vec<f64> = leaves
            .iter()
            .map(|&leaf| pmf(&tree.nodes, leaf, p, n) as f64)
            .collect();
        let sum: f64 = pmfs.iter().sum();
        assert!(sum <= 1.0 + 1e-4, "point {point}: PMF sums to {sum}");
        let mut pmfs = pmfs;
        pmfs.push((1.0 - sum).max(0.0));
        let mut counts = vec![0u64; lights.len() + 1];
        for _ in 0..SAMPLES {
            let u = rand.next();
            let Some((light, p_sample)) = sample(&tree.nodes, count, p, n, u) else {
                counts[lights.len()] += 1;
                continue;
            };
            counts[light as usize] += 1;
            let expected = pmfs[light as usize];
            assert!(
                ((p_sample as f64) - expected).abs() <= 1e-4 * expected,
                "point {point}: light {light} sampled with {p_sample}, PMF {expected}"
            );
        }
        // Chi-square over bins of expected count ≥ 5 (the rest merged into one bin).
        let (mut chi2, mut bins) = (0.0f64, 0usize);
        let (mut rest_expected, mut rest_observed) = (0.0f64, 0u64);
        for (p, &c) in pmfs.iter().zip(&counts) {
            let e = p * SAMPLES as f64;
            if e >= 5.0 {
                chi2 += (c as f64 - e).powi(2) / e;
                bins += 1;
            } else {
                rest_expected += e;
                rest_observed += c;
            }
        }
        if rest_expected >= 5.0 {
            chi2 += (rest_observed as f64 - rest_expected).powi(2) / rest_expected;
            bins += 1;
        } else {
            assert!(
                rest_observed as f64 <= rest_expected + 5.0 * rest_expected.sqrt() + 5.0,
                "point {point}: {rest_observed} picks of lights expected {rest_expected:.2} times"
            );
        }
        let dof = bins.saturating_sub(1).max(1) as f64;
        let tail = chi_square_tail(chi2, dof);
        eprintln!(
            "point {point}: PMF sum {sum:.5} (dead ends {:.5}, sampled {:.5}); χ² = {chi2:.1} over {dof} degrees of freedom, p = {tail:.3}",
            1.0 - sum,
            counts[lights.len()] as f64 / SAMPLES as f64
        );
        assert!(
            tail > 1e-6,
            "point {point}: sampling frequencies do not match the PMF (χ² = {chi2:.1}, {dof} dof, p = {tail:.2e})"
        );
    }
}

/// 100,000 emitters (and one): the tree builds, its PMF and dead ends sum to 1 from a few
/// points, and the walk stays shallow. The build time is printed for
/// `docs/PERFORMANCE.md` (not asserted).
#[test]
fn one_and_a_hundred_thousand_lights() {
    let mut rand = Rand(5);
    for n in [1u32, 100_000] {
        let (lights, phi, two) = random_lights(n, &mut rand);
        let started = std::time::Instant::now();
        let tree = tree_of(&lights, &phi, &two);
        let seconds = started.elapsed().as_secs_f64();
        let mut depth = vec![0u32; tree.nodes.len()];
        for (i, node) in tree.nodes.iter().enumerate() {
            if node.flags & LIGHT_NODE_LEAF == 0 {
                depth[i + 1] = depth[i] + 1;
                depth[node.child as usize] = depth[i] + 1;
            }
        }
        let deepest = depth.iter().copied().max().unwrap_or(0);
        eprintln!(
            "{n} lights: {} nodes, depth {deepest}, built in {:.1} ms",
            tree.nodes.len(),
            seconds * 1e3
        );
        assert_eq!(tree.nodes.len() as u32, 2 * n - 1);
        assert!(deepest <= 64, "depth {deepest}");
        for _ in 0..3 {
            let p = rand.vec(-6.0, 6.0);
            let normal = rand.unit();
            let sum: f64 = lights
                .iter()
                .map(|l| {
                    let leaf = leaf_of(&tree.lookup, l.instance, l.triangle);
                    pmf(&tree.nodes, leaf, p, normal) as f64
                })
                .sum();
            // Dead ends take the rest (see the module doc); count them by sampling.
            let tries = 20_000;
            let dead = (0..tries)
                .filter(|_| sample(&tree.nodes, n, p, normal, rand.next()).is_none())
                .count() as f64
                / tries as f64;
            let sigma = ((1.0 - sum).max(1e-4) / tries as f64).sqrt();
            eprintln!("{n} lights: PMF sum {sum:.5}, dead ends sampled {dead:.5}");
            assert!(
                sum <= 1.0 + 1e-3 && (sum + dead - 1.0).abs() <= 5.0 * sigma + 1e-3,
                "{n} lights: PMF sums to {sum}, dead ends {dead}"
            );
        }
    }
}
