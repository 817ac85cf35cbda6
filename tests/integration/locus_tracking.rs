//! The root locus is what the app plots: each branch must be one continuous
//! curve. Checked here: at every load the tracked eigenvalues (polynomial
//! continuation) are the Schur path's; between neighbouring samples the
//! branches are matched, not sorted (keeping each branch on its own
//! continuation is the least-distance assignment); and samples are added
//! where branches meet or cross Re = 0, so the critical loads lie between
//! samples a hair apart.

use crate::common;

use common::{pencil, set_distance};
use zieglerlab::analysis::{C64, critical_loads, locus};

const PRESETS: [&str; 5] = [
    "ziegler-1952",
    "uniform-rods",
    "midpoint-masses",
    "roller",
    "roller-as-printed",
];

/// Least total distance over all assignments of `b` to `a`.
fn best_assignment_cost(a: &[C64], b: &[C64]) -> f64 {
    fn go(a: &[C64], b: &mut Vec<C64>, k: usize, acc: f64, best: &mut f64) {
        if acc >= *best {
            return;
        }
        if k == a.len() {
            *best = acc;
            return;
        }
        for i in k..b.len() {
            b.swap(k, i);
            go(a, b, k + 1, acc + (a[k] - b[k]).norm(), best);
            b.swap(k, i);
        }
    }
    let mut best = f64::INFINITY;
    go(a, &mut b.to_vec(), 0, 0.0, &mut best);
    best
}

#[test]
fn tracked_eigenvalues_are_the_schur_spectrum() {
    for name in PRESETS {
        let pencil = pencil(name, &["c2=0.004"]);
        let locus = locus(&pencil, 0.0, 8.0, 161).unwrap();
        for (i, &p) in locus.loads.iter().enumerate() {
            let schur = pencil.spectrum(p).unwrap();
            let tracked = locus.moving_at(i);
            // Where two eigenvalues nearly meet, either method resolves them
            // only to about sqrt(eps) of the scale.
            let d = set_distance(&tracked, &schur.eigenvalues);
            assert!(d < 1e-7 * schur.scale_per_s.max(1.0), "{name} p={p}: {d:e}");
        }
    }
}

#[test]
fn branches_are_matched_not_sorted() {
    for name in PRESETS {
        let locus = locus(&pencil(name, &[]), 0.0, 8.0, 200).unwrap();
        for i in 1..locus.loads.len() {
            let (a, b) = (locus.moving_at(i - 1), locus.moving_at(i));
            let kept: f64 = a.iter().zip(&b).map(|(x, y)| (x - y).norm()).sum();
            let best = best_assignment_cost(&a, &b);
            // At a double root the two eigenvalues coincide to sqrt(eps) of
            // the scale (about 1): either assignment is then the same curve.
            assert!(
                kept <= best + 1e-7,
                "{name} between p={} and p={}: branches jump ({kept} vs {best})",
                locus.loads[i - 1],
                locus.loads[i]
            );
        }
    }
}

#[test]
fn sorting_would_not_do() {
    // On the roller's locus two branches exchange the order of their
    // imaginary parts; a locus sorted by Im would jump there. The tracked one
    // keeps each branch continuous, so Im order changes along some branch pair.
    let locus = locus(&pencil("roller", &[]), 0.0, 6.0, 600).unwrap();
    let order = |i: usize| {
        let mut idx: Vec<usize> = (0..5).collect();
        let z = locus.moving_at(i);
        idx.sort_by(|&a, &b| z[b].im.total_cmp(&z[a].im));
        idx
    };
    let first = order(0);
    assert!((1..locus.loads.len()).any(|i| order(i) != first));
}

#[test]
fn samples_are_dense_at_every_critical_load() {
    for name in PRESETS {
        let pencil = pencil(name, &[]);
        let (min, max) = (0.0, 8.0);
        let locus = locus(&pencil, min, max, 81).unwrap();
        assert_eq!(locus.on_grid.iter().filter(|&&g| g).count(), 81);
        for t in critical_loads(&pencil, min, max).unwrap() {
            let gap = locus
                .loads
                .windows(2)
                .find(|w| w[0] <= t.load && t.load <= w[1])
                .map(|w| w[1] - w[0])
                .unwrap();
            assert!(
                gap <= 1e-4 * (max - min),
                "{name}: gap {gap:e} around p = {}",
                t.load
            );
        }
    }
}

/// Zero or a normal f64: subnormal numbers cost about a hundred cycles per
/// operation on many Intel CPUs, and a root-finder that keeps them (a real
/// root's imaginary part decaying under Newton's corrections) runs several
/// times slower there while computing the same answer.
fn zero_or_normal(x: f64) -> bool {
    x == 0.0 || x.is_normal()
}

#[test]
fn every_kept_eigenvalue_component_is_zero_or_normal() {
    let cases: [(&str, &[&str]); 7] = [
        ("ziegler-1952", &[]),
        ("uniform-rods", &[]),
        ("midpoint-masses", &[]),
        ("roller", &[]),
        ("roller-as-printed", &[]),
        ("ziegler-1952", &["c1=0.01", "c2=0.02"]),
        ("roller", &["nu=1e-4"]),
    ];
    for (name, sets) in cases {
        let pencil = pencil(name, sets);
        let locus = locus(&pencil, 0.0, 10.0, 1000).unwrap();
        let bad = locus
            .branches
            .iter()
            .flatten()
            .filter(|z| !(zero_or_normal(z.re) && zero_or_normal(z.im)))
            .count();
        assert_eq!(bad, 0, "{name} {sets:?}: {bad} subnormal components");
    }
}
