//! Where along a branch its cycles' Floquet multipliers cross the unit
//! circle: the pairs of neighbouring cycles between which the count
//! outside changes, the kind of multiplier that crosses (real through +1,
//! real through -1, a complex pair) and which of its kind it is, so that
//! `cycle_bifurcations` can place each. Pure: no UI, no clock.

use super::cycle::{Cycle, REAL};
use crate::analysis::C64;
use serde::Serialize;

/// What changes at a bifurcation of the cycles.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum CycleBifurcationKind {
    /// A real multiplier through +1: the branch folds back in the load.
    Fold,
    /// A real multiplier through -1: a cycle of twice the period is born.
    PeriodDoubling,
    /// A complex pair through the unit circle: a torus is born.
    NeimarkSacker,
    /// A real multiplier through +1 where the branch goes on: the mirror
    /// symmetry breaks (a pitchfork of cycles; see the module's notes).
    SymmetryBreaking,
}

/// Two neighbouring cycles of a branch with a bifurcation between them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Bracket {
    /// The first of the two cycles' index.
    pub(super) after: usize,
    pub(super) kind: CycleBifurcationKind,
    /// Which multiplier of the kind crosses the circle, counted from the
    /// largest modulus (0 the largest): the last one outside at the cycle
    /// with more outside.
    pub(super) rank: usize,
    /// Its distance `|m| - 1` from the circle at each cycle (where the
    /// cycle has that many of the kind): of opposite signs.
    pub(super) moduli: [Option<f64>; 2],
    /// Whether this kind's count is the only one that changes between the
    /// two cycles (by as much as the whole count): one crossing, of this
    /// kind. Else multipliers also changed kind between them (a complex
    /// pair met on the real axis) and the kind read may be wrong.
    pub(super) clean: bool,
}

impl Bracket {
    /// The share of the way from the first cycle to the second where the
    /// modulus passes 1 on the line between them (the middle where the
    /// moduli do not straddle 1).
    pub(super) fn linear_share(&self) -> f64 {
        match self.moduli {
            [Some(ra), Some(rb)] if ra * rb < 0.0 => ra / (ra - rb),
            _ => 0.5,
        }
    }

    /// The crossing multiplier's distance `|m| - 1` from the circle on
    /// `cycle`, where it has that many of the kind.
    pub(super) fn modulus(&self, cycle: &Cycle) -> Option<f64> {
        of_kind(cycle, self.kind).get(self.rank).copied()
    }
}

/// The class of a multiplier other than the trivial one.
fn class_of(m: C64) -> CycleBifurcationKind {
    if m.im.abs() > REAL * m.norm() {
        CycleBifurcationKind::NeimarkSacker
    } else if m.re > 0.0 {
        CycleBifurcationKind::Fold
    } else {
        CycleBifurcationKind::PeriodDoubling
    }
}

/// The distances `|m| - 1` from the unit circle of the multipliers of
/// `kind` (but the trivial one), largest first.
fn of_kind(cycle: &Cycle, kind: CycleBifurcationKind) -> Vec<f64> {
    let mut moduli: Vec<f64> = cycle
        .nontrivial_multipliers()
        .filter(|m| class_of(*m) == kind)
        .map(|m| m.norm() - 1.0)
        .collect();
    moduli.sort_by(|a, b| b.total_cmp(a));
    moduli
}

/// How many of `moduli` (distances from the circle) lie outside it.
fn outside(moduli: &[f64]) -> usize {
    moduli.iter().filter(|&&r| r > 0.0).count()
}

/// Every pair of neighbouring `cycles` (in the order of the continuation)
/// between which multipliers cross the unit circle: the count outside it
/// changes, and with it (the same way) the count of a kind. A pair of
/// multipliers that turns from complex to real (or back) outside the
/// circle changes the counts of two kinds and not the whole count: no
/// bifurcation.
pub(super) fn brackets(cycles: &[Cycle]) -> Vec<Bracket> {
    use CycleBifurcationKind::{Fold, NeimarkSacker, PeriodDoubling};
    let mut out = Vec::new();
    for (after, pair) in cycles.windows(2).enumerate() {
        let [a, b] = pair else { continue };
        let kinds = [Fold, PeriodDoubling, NeimarkSacker];
        let (moduli_a, moduli_b) = (kinds.map(|k| of_kind(a, k)), kinds.map(|k| of_kind(b, k)));
        let counts = |moduli: &[Vec<f64>; 3]| moduli.each_ref().map(|m| outside(m));
        let (counts_a, counts_b) = (counts(&moduli_a), counts(&moduli_b));
        let (total_a, total_b) = (
            counts_a.iter().sum::<usize>(),
            counts_b.iter().sum::<usize>(),
        );
        if total_a == total_b {
            continue;
        }
        let changed = counts_a
            .iter()
            .zip(&counts_b)
            .filter(|(x, y)| x != y)
            .count();
        for (k, kind) in kinds.into_iter().enumerate() {
            let (count_a, count_b) = (counts_a[k], counts_b[k]);
            if count_a == count_b || (count_b > count_a) != (total_b > total_a) {
                continue;
            }
            let rank = count_a.max(count_b) - 1;
            out.push(Bracket {
                after,
                kind,
                rank,
                moduli: [
                    moduli_a[k].get(rank).copied(),
                    moduli_b[k].get(rank).copied(),
                ],
                clean: changed == 1,
            });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::DVector;

    /// A cycle at `load` with the trivial multiplier and `others`.
    fn cycle(load: f64, others: &[C64]) -> Cycle {
        let mut multipliers = vec![C64::new(1.0, 0.0)];
        multipliers.extend_from_slice(others);
        Cycle {
            load,
            period_secs: 1.0,
            start: DVector::zeros(2),
            amplitude_rad: vec![load],
            multipliers,
            stable: true,
            closest_slip_m_per_s: None,
        }
    }

    /// Each kind is bracketed where its multiplier's modulus passes 1, and
    /// the line between the two cycles puts it there when the moduli
    /// change linearly with the load (as here): a real one through -1 at
    /// p = 1.25, a complex pair through the circle at p = 2.5, a real one
    /// through +1 at p = 3.75.
    #[test]
    fn each_kind_is_bracketed_where_its_multiplier_leaves_the_circle() {
        let pd = |p: f64| C64::new(-(0.5 + 0.4 * p), 0.0);
        let ns = |p: f64| C64::from_polar(0.5 + 0.2 * p, 1.0);
        let fold = |p: f64| C64::new(0.25 + 0.2 * p, 0.0);
        let loads = [1.0, 1.5, 2.0, 3.0, 3.5, 4.0];
        let cycles: Vec<Cycle> = loads
            .iter()
            .map(|&p| {
                cycle(
                    p,
                    &[pd(p.min(1.5)), ns(p.clamp(2.0, 3.0)), fold(p.max(3.5))],
                )
            })
            .collect();
        let found = brackets(&cycles);
        let kinds: Vec<_> = found.iter().map(|b| (b.after, b.kind)).collect();
        assert_eq!(
            kinds,
            [
                (0, CycleBifurcationKind::PeriodDoubling),
                (2, CycleBifurcationKind::NeimarkSacker),
                (4, CycleBifurcationKind::Fold)
            ]
        );
        for (b, at) in found.iter().zip([1.25, 2.5, 3.75]) {
            let (from, to) = (cycles[b.after].load, cycles[b.after + 1].load);
            let linear = from + b.linear_share() * (to - from);
            assert!((linear - at).abs() < 1e-12, "{b:?}");
            assert!(b.clean, "{b:?}");
        }
    }

    /// A complex pair outside the circle that turns into two real
    /// multipliers outside it (the counts of two kinds change, the whole
    /// count does not) is no bifurcation. Where another pair of the kind
    /// hugs the circle from inside, the test function is the second
    /// largest modulus (the last outside once the pair has crossed): it
    /// goes from the hugging pair's at the first cycle to the crossing
    /// pair's at the second, and is 1 exactly where the crossing pair is.
    /// The nearest pair's modulus, read before, did not change sign.
    #[test]
    fn only_multipliers_that_cross_the_circle_are_read() {
        let pair = |r: f64, angle: f64| [C64::from_polar(r, angle), C64::from_polar(r, -angle)];
        let turning = [
            cycle(1.0, &pair(1.2, 0.1)),
            cycle(1.1, &[C64::new(1.25, 0.0), C64::new(1.15, 0.0)]),
        ];
        assert_eq!(brackets(&turning), []);
        let hugging = pair(0.999_99, 2.0);
        let crossing = |r: f64| [hugging, pair(r, 1.0)].concat();
        let cycles = [cycle(2.0, &crossing(0.99)), cycle(2.1, &crossing(1.03))];
        let found = brackets(&cycles);
        assert_eq!(found.len(), 1, "{found:?}");
        assert_eq!(found[0].kind, CycleBifurcationKind::NeimarkSacker);
        assert_eq!(found[0].rank, 1);
        let [Some(ra), Some(rb)] = found[0].moduli else {
            panic!("{found:?}")
        };
        assert!(
            (ra + 1e-5).abs() < 1e-12 && (rb - 0.03).abs() < 1e-12,
            "{found:?}"
        );
        let at_one = cycle(2.05, &crossing(1.0));
        assert!(found[0].modulus(&at_one).unwrap().abs() < 1e-15);
    }

    /// A complex pair outside the circle that meets on the negative real
    /// axis and sends one of the two reals inside through -1 between two
    /// cycles changes the counts of two kinds (complex 2 -> 0, real below
    /// -1 0 -> 1) and the whole count by one: the crossing read is not
    /// clean (its kind is not known from the two cycles), where a lone
    /// pair through the circle is.
    #[test]
    fn a_pair_turning_real_as_it_crosses_is_not_read_clean() {
        let pair = [C64::from_polar(1.04, 2.9), C64::from_polar(1.04, -2.9)];
        let turned = [C64::new(-1.18, 0.0), C64::new(-0.92, 0.0)];
        let found = brackets(&[cycle(2.44, &pair), cycle(2.45, &turned)]);
        assert_eq!(found.len(), 1, "{found:?}");
        assert!(!found[0].clean, "{found:?}");
        let inside = [C64::from_polar(0.97, 2.9), C64::from_polar(0.97, -2.9)];
        let crossing = brackets(&[cycle(2.35, &inside), cycle(2.37, &pair)]);
        assert!(crossing.len() == 1 && crossing[0].clean, "{crossing:?}");
    }
}
