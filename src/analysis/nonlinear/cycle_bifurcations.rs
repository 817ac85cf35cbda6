//! The bifurcations of the limit cycles themselves along a branch, read
//! from their Floquet multipliers: a fold of cycles (a real multiplier
//! through +1, where the branch turns back in the load), a period doubling
//! (a real multiplier through -1) and a Neimark-Sacker (torus) bifurcation
//! (a complex pair through the unit circle), and a break of the mirror
//! symmetry (a real multiplier through +1 where the branch goes on: a
//! pitchfork, from which two mirror images of each other branch off).
//! Each is bracketed by the two
//! cycles of the branch it lies between (the count of multipliers outside
//! the circle changes, and the count of one kind with it) and placed by
//! regula falsi on the cycles between them (`chord`): a period doubling or
//! a torus where the crossing multiplier's modulus passes 1 (the k-th
//! largest of its kind, k the count of the kind outside at the cycle with
//! more: a continuous function of the cycle whatever other multipliers of
//! the kind do), a fold where the load's rate along the branch passes zero
//! (there the multiplier is a double 1, known to the square root of the
//! monodromy's accuracy only, while the rate is a simple root), a break of
//! symmetry on the symmetric cycles (`symmetric`) where `det(I + R)`
//! passes zero.
//!
//! Fold or break of symmetry: a cycle of a mirror-symmetric column born at
//! a Hopf point is its own mirror image half a period on, `x(T/2) = -x(0)`
//! (the field is odd), so its monodromy is `R^2`, with `R = -Phi(T/2)` the
//! half-period map. A multiplier `mu = rho^2` passes +1 where a real
//! multiplier `rho` of `R` passes +1 (a fold: the branch turns back) or -1
//! (the branch of symmetric cycles goes on, and two asymmetric cycles,
//! mirror images of each other, branch off it).

use std::sync::atomic::{AtomicBool, Ordering};

use nalgebra::DVector;
use serde::Serialize;

use super::chord::{Chord, OnChord};
use super::cycle::{Cycle, REAL};
use super::falsi::{Stop, illinois};
use super::shooting::Shooting;
use super::symmetric::breaks_symmetry;
use crate::analysis::C64;

/// Where regula falsi stops for a modulus: within 1e-12 of its bracket's
/// size (a multiplier's modulus is known to about 1e-10), or the bracket
/// narrowed to 1e-9 of the chord, in at most 30 cycles.
const MODULUS_STOP: Stop = Stop {
    value: 1e-12,
    width: 1e-9,
    steps: 30,
};
/// The same for the load's rate, which is known to a few 1e-10 of its
/// bracket's (it takes the flow's derivative in the load by differences):
/// where it is 1e-8 of that, the fold's share is off by about as much of
/// the chord, and its load (the least or the most along the branch) by the
/// square of that.
const RATE_STOP: Stop = Stop {
    value: 1e-8,
    ..MODULUS_STOP
};

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

/// A bifurcation of the cycles along a branch.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct CycleBifurcation {
    pub kind: CycleBifurcationKind,
    /// The load.
    pub load: f64,
    /// The largest angle's amplitude there, in rad.
    pub amplitude_rad: f64,
    /// Whether the cycle at the bifurcation was solved for (else both
    /// values are interpolated linearly between the two cycles it lies
    /// between: the multiplier's modulus or the load's rate did not change
    /// sign between them, or a solve failed).
    pub refined: bool,
    /// The index of the first of the two cycles it lies between.
    #[serde(skip)]
    pub(in crate::analysis) after: usize,
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
}

impl Bracket {
    /// The share of the way from the first cycle to the second where the
    /// modulus passes 1 on the line between them (the middle where the
    /// moduli do not straddle 1).
    fn linear_share(&self) -> f64 {
        match self.moduli {
            [Some(ra), Some(rb)] if ra * rb < 0.0 => ra / (ra - rb),
            _ => 0.5,
        }
    }

    /// The bifurcation placed on the line between its two cycles of
    /// `cycles`, where the modulus passes 1 on it: not solved for.
    fn interpolated(&self, cycles: &[Cycle]) -> CycleBifurcation {
        let (a, b) = (&cycles[self.after], &cycles[self.after + 1]);
        let t = self.linear_share();
        let along = |x: f64, y: f64| x + t * (y - x);
        CycleBifurcation {
            kind: self.kind,
            load: along(a.load, b.load),
            amplitude_rad: along(a.largest_amplitude_rad(), b.largest_amplitude_rad()),
            refined: false,
            after: self.after,
        }
    }

    /// The crossing multiplier's distance `|m| - 1` from the circle on
    /// `cycle`, where it has that many of the kind.
    fn modulus(&self, cycle: &Cycle) -> Option<f64> {
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
        let total = |moduli: &[Vec<f64>; 3]| moduli.iter().map(|m| outside(m)).sum::<usize>();
        let (total_a, total_b) = (total(&moduli_a), total(&moduli_b));
        if total_a == total_b {
            continue;
        }
        for (k, kind) in kinds.into_iter().enumerate() {
            let (count_a, count_b) = (outside(&moduli_a[k]), outside(&moduli_b[k]));
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
            });
        }
    }
    out
}

/// A break of the mirror symmetry solved for: its place among a branch's
/// bifurcations and the symmetric cycle's unknowns `(x0, T, p)` there,
/// where the asymmetric cycles branch off (`offshoot`).
pub(super) struct BreakPoint {
    pub(super) index: usize,
    pub(super) unknowns: DVector<f64>,
}

/// Every bifurcation along the branch `cycles` of `shooting`'s column, in
/// the order of the continuation, each solved for between the two cycles
/// it lies between (see [`CycleBifurcation::refined`]), and the breaks of
/// symmetry among them that were solved for; `scales` are the
/// continuation's scales of the unknowns. Once `cancel` is set no cycle
/// is solved: the rest are interpolated.
pub(super) fn cycle_bifurcations(
    shooting: &Shooting,
    cycles: &[Cycle],
    scales: &DVector<f64>,
    cancel: &AtomicBool,
) -> (Vec<CycleBifurcation>, Vec<BreakPoint>) {
    let (mut found, mut breaks) = (Vec::new(), Vec::new());
    for bracket in brackets(cycles) {
        let (a, b) = (&cycles[bracket.after], &cycles[bracket.after + 1]);
        let kind = if bracket.kind == CycleBifurcationKind::Fold
            && !cancel.load(Ordering::Relaxed)
            && breaks_symmetry(shooting, a, b)
        {
            CycleBifurcationKind::SymmetryBreaking
        } else {
            bracket.kind
        };
        let chord = Chord::new(shooting, (a, b), scales);
        let refined = if kind == CycleBifurcationKind::SymmetryBreaking {
            chord
                .and_then(|chord| chord.symmetry_break(MODULUS_STOP, cancel))
                .map(|symmetric| {
                    let load = symmetric.unknowns[symmetric.unknowns.len() - 1];
                    breaks.push(BreakPoint {
                        index: found.len(),
                        unknowns: symmetric.unknowns,
                    });
                    (load, symmetric.amplitude_rad)
                })
        } else {
            chord
                .and_then(|chord| refine(&chord, &bracket, kind, cancel))
                .map(|on| {
                    let cycle = &on.solved.cycle;
                    (cycle.load, cycle.largest_amplitude_rad())
                })
        };
        found.push(refined.map_or_else(
            || CycleBifurcation {
                kind,
                ..bracket.interpolated(cycles)
            },
            |(load, amplitude_rad)| CycleBifurcation {
                kind,
                load,
                amplitude_rad,
                refined: true,
                after: bracket.after,
            },
        ));
    }
    (found, breaks)
}

/// The cycle at `bracket`'s bifurcation (of `kind`) on `chord` between its
/// two cycles: a fold where the load's rate passes zero (solved at both
/// ends for it), else (a real multiplier through +1 where the load does
/// not turn, or another kind) where the modulus passes 1, as read off the
/// two cycles. `None` where that fails or once
/// `cancel` is set.
fn refine(
    chord: &Chord,
    bracket: &Bracket,
    kind: CycleBifurcationKind,
    cancel: &AtomicBool,
) -> Option<OnChord> {
    type Sample = (f64, f64, Option<OnChord>);
    let solve = |share: f64, near: &Option<OnChord>| {
        if cancel.load(Ordering::Relaxed) {
            return None;
        }
        chord.solve(share, near.as_ref().map(|on| &on.solved))
    };
    if kind == CycleBifurcationKind::Fold {
        let rated =
            |on: OnChord| -> Option<Sample> { Some((on.share, chord.load_rate(&on)?, Some(on))) };
        let low = rated(solve(0.0, &None)?)?;
        let high = rated(solve(1.0, &low.2)?)?;
        if low.1 * high.1 < 0.0 {
            return illinois(low, high, RATE_STOP, |share, near| {
                rated(solve(share, near)?)
            })?
            .2;
        }
    }
    let [Some(low), Some(high)] = bracket.moduli else {
        return None;
    };
    let moduli = |on: OnChord| -> Option<Sample> {
        Some((on.share, bracket.modulus(&on.solved.cycle)?, Some(on)))
    };
    illinois(
        (0.0, low, None),
        (1.0, high, None),
        MODULUS_STOP,
        |share, near| moduli(solve(share, near)?),
    )?
    .2
}

#[cfg(test)]
mod tests {
    use super::*;

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
            let linear = b.interpolated(&cycles);
            assert!((linear.load - at).abs() < 1e-12, "{b:?}");
            assert!((linear.amplitude_rad - at).abs() < 1e-12, "{b:?}");
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

    /// Where the constructed field below has its period doubling.
    const DOUBLING_P: f64 = 0.61;

    /// The cycle's angular frequency at `p`, rad/s.
    fn omega(p: f64) -> f64 {
        0.8 + 0.4 * p
    }

    /// A field in four dimensions with a period doubling at a known load:
    /// the circle `x^2 + y^2 = 1` run round at `omega(p)` attracts `(x,
    /// y)`, and `w = (u, v)` obeys
    ///
    /// ```text
    /// w' = (l I + d S(x, y) + omega/2 J) w - |w|^2 w,
    /// S = [[x, y], [y, -x]],  J = [[0, -1], [1, 0]],
    /// ```
    ///
    /// with `l +- d = l1, l2`, `l1 = p - DOUBLING_P`, `l2 = -1`. On the
    /// circle `S(theta)` is the reflection `R(theta/2) diag(1, -1)
    /// R(-theta/2)`, so in the frame turned by `theta/2` the linear part is
    /// `diag(l1, l2)`, and over a period the frame turns by half a turn:
    /// `w`'s multipliers are `-exp(l1 T)` and `-exp(l2 T)`, the first
    /// through -1 exactly at `p = DOUBLING_P` (the band of a Moebius strip
    /// flipping its stability). The circle's own are 1 and `exp(-2 T)`.
    fn doubling_field(s: &DVector<f64>, p: f64, out: &mut DVector<f64>) {
        let (x, y, u, v) = (s[0], s[1], s[2], s[3]);
        let (l1, l2, w) = (p - DOUBLING_P, -1.0, omega(p));
        let (l, d) = (f64::midpoint(l1, l2), (l1 - l2) / 2.0);
        let (radial, cubic) = (1.0 - x * x - y * y, u * u + v * v);
        out[0] = x * radial - w * y;
        out[1] = y * radial + w * x;
        out[2] = l * u + d * (x * u + y * v) - w / 2.0 * v - cubic * u;
        out[3] = l * v + d * (y * u - x * v) + w / 2.0 * u - cubic * v;
    }

    /// The shooting, its multipliers and the bifurcations on a field whose
    /// period doubling is known in closed form (above): every cycle's
    /// multipliers are the closed form's to 1e-8; the doubling is solved
    /// for at `DOUBLING_P` to 1e-9, where the line between its two cycles
    /// puts it `T h^2 / 8` away for loads `h` apart (the modulus
    /// `exp((p - DOUBLING_P) T)` is not linear in the load).
    #[test]
    fn a_constructed_period_doubling_is_found_where_it_is() {
        let field = crate::analysis::field::Field::constructed(doubling_field, 2, 0.3);
        let shooting = Shooting::on(field);
        let h = 0.02;
        let cycles: Vec<Cycle> = (0..30)
            .map(|i| {
                let p = 0.3 + h * f64::from(i);
                let period = std::f64::consts::TAU / omega(p);
                let cycle = solved_at(&shooting, &[1.0, 0.0, 0.0, 0.0], period, p);
                assert!((cycle.period_secs - period).abs() < 1e-9 * period);
                let expected = [1.0, (-2.0 * period).exp()]
                    .into_iter()
                    .chain([-((p - DOUBLING_P) * period).exp(), -(-period).exp()]);
                for m in expected {
                    let off = cycle
                        .multipliers
                        .iter()
                        .map(|z| (z - m).norm())
                        .fold(f64::INFINITY, f64::min);
                    assert!(off < 1e-8, "p = {p}: {m} against {:?}", cycle.multipliers);
                }
                cycle
            })
            .collect();
        let found = bifurcations(&shooting, &cycles);
        assert_eq!(found.len(), 1, "{found:?}");
        let doubling = found[0];
        assert_eq!(doubling.kind, CycleBifurcationKind::PeriodDoubling);
        assert!(doubling.refined);
        assert!((doubling.load - DOUBLING_P).abs() < 1e-9, "{doubling:?}");
        let linear = brackets(&cycles)[0].interpolated(&cycles).load;
        let period = std::f64::consts::TAU / omega(DOUBLING_P);
        let off = (linear - DOUBLING_P).abs();
        assert!(off < period * h * h / 8.0, "{linear}: {off}");
        assert!(off > 1e-5, "the line alone is this close: {off}");
    }

    /// Where the field below has its Hopf point and its fold of cycles.
    const BAUTIN_HOPF_P: f64 = 1.5;
    const FOLD_P: f64 = BAUTIN_HOPF_P - 1.0;

    /// The load of the field below's cycle of radius `r`.
    fn fold_field_load(r: f64) -> f64 {
        BAUTIN_HOPF_P - 2.0 * r * r + r.powi(4)
    }

    /// A plane field with a hard Hopf point and a fold of cycles at known
    /// loads (Bautin's normal form): in polar coordinates `r' = r g`,
    /// `theta' = -1`, `g = p - BAUTIN_HOPF_P + 2 r^2 - r^4`, turning the
    /// way that makes `y` the rate of the angle `x` on a cycle. Its cycles
    /// `g = 0` have the load [`fold_field_load`], least at `r = 1`: the
    /// fold, at `FOLD_P`. A cycle's nontrivial multiplier is `exp(T
    /// div f) = exp(2 pi 4 r^2 (1 - r^2))`: 1 at the fold, outside the
    /// circle on the small (unstable) cycles, inside on the large ones.
    fn fold_field(s: &DVector<f64>, p: f64, out: &mut DVector<f64>) {
        let (x, y) = (s[0], s[1]);
        let r2 = x * x + y * y;
        let g = p - BAUTIN_HOPF_P + 2.0 * r2 - r2 * r2;
        out[0] = x * g + y;
        out[1] = y * g - x;
    }

    /// The fold of cycles of the field above, from cycles on both sides
    /// of it (radii 0.8 to 1.2): solved for at `FOLD_P` to 1e-10 and on
    /// the cycle of radius 1 to 1e-5 (the load is the least there, so an
    /// error in where the fold is costs the load its square only), where
    /// the line between the two cycles round it misses by 0.04 (and is
    /// what a cancelled refinement gives, marked so).
    #[test]
    fn a_constructed_fold_of_cycles_is_found_where_it_is() {
        let field = crate::analysis::field::Field::constructed(fold_field, 1, FOLD_P);
        let shooting = Shooting::on(field);
        let cycles: Vec<Cycle> = [0.8, 0.9, 1.1, 1.2]
            .iter()
            .map(|&r| {
                let p = fold_field_load(r);
                let cycle = solved_at(&shooting, &[r, 0.0], std::f64::consts::TAU, p);
                let growth = (std::f64::consts::TAU * 4.0 * r * r * (1.0 - r * r)).exp();
                let off = (cycle.nontrivial_multipliers().next().unwrap() - growth).norm();
                assert!(
                    off < 1e-8 * growth.max(1.0),
                    "r = {r}: {:?}",
                    cycle.multipliers
                );
                assert!((cycle.largest_amplitude_rad() - r).abs() < 1e-9);
                cycle
            })
            .collect();
        let found = bifurcations(&shooting, &cycles);
        assert_eq!(found.len(), 1, "{found:?}");
        let fold = found[0];
        assert_eq!(fold.kind, CycleBifurcationKind::Fold);
        assert!(fold.refined);
        assert!((fold.load - FOLD_P).abs() < 1e-10, "{fold:?}");
        assert!((fold.amplitude_rad - 1.0).abs() < 1e-5, "{fold:?}");
        let linear = brackets(&cycles)[0].interpolated(&cycles);
        assert!((linear.load - FOLD_P).abs() > 0.03, "{linear:?}");
        // Asked to stop, it solves nothing and says so.
        let scales = DVector::from_element(4, 1.0);
        let (stopped, breaks) =
            cycle_bifurcations(&shooting, &cycles, &scales, &AtomicBool::new(true));
        assert_eq!(stopped, [linear]);
        assert!(breaks.is_empty());
        assert!(!linear.refined && linear.kind == fold.kind && linear.after == 1);
    }

    /// The cycle through `(start, period)` at load `p`, solved there.
    fn solved_at(shooting: &Shooting, start: &[f64], period: f64, p: f64) -> Cycle {
        use crate::analysis::nonlinear::shooting::Constraint;
        let guess =
            DVector::from_iterator(start.len() + 2, start.iter().copied().chain([period, p]));
        shooting
            .solve(&guess, &Constraint::Load(p))
            .expect("a cycle")
            .cycle
    }

    /// The bifurcations along `cycles`, with every unknown's scale 1.
    fn bifurcations(shooting: &Shooting, cycles: &[Cycle]) -> Vec<CycleBifurcation> {
        let scales = DVector::from_element(cycles[0].start.len() + 2, 1.0);
        cycle_bifurcations(shooting, cycles, &scales, &AtomicBool::new(false)).0
    }
}
