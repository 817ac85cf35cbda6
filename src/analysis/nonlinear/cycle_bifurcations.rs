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

pub use super::bracket::CycleBifurcationKind;
use super::bracket::{Bracket, brackets};
use super::chord::{Chord, OnChord};
use super::cycle::Cycle;
use super::falsi::{Stop, illinois};
use super::shooting::Shooting;
use super::symmetric::breaks_symmetry;

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

/// A break of the mirror symmetry solved for: its place among a branch's
/// bifurcations and the symmetric cycle's unknowns `(x0, T, p)` there,
/// where the asymmetric cycles branch off (`offshoot`).
pub(super) struct BreakPoint {
    pub(super) index: usize,
    pub(super) unknowns: DVector<f64>,
}

/// Halvings of the chord between two cycles allowed to untangle what
/// crosses the circle between them (a chord of 1/4096 of theirs).
const UNTANGLE_DEPTH: usize = 12;

/// Every bifurcation along the branch `cycles` of `shooting`'s column, in
/// the order of the continuation, each solved for between the two cycles
/// it lies between (see [`CycleBifurcation::refined`]), and the breaks of
/// symmetry among them that were solved for; `scales` are the
/// continuation's scales of the unknowns. Where more than one kind of
/// multiplier changes its count between two cycles (a complex pair
/// outside the circle meeting on the real axis and one of the two reals
/// going inside through -1 between them), the cycles between them are
/// solved for ([`untangle`]) until each change is one kind's. Once
/// `cancel` is set no cycle is solved: the rest are interpolated.
pub(super) fn cycle_bifurcations(
    shooting: &Shooting,
    cycles: &[Cycle],
    scales: &DVector<f64>,
    cancel: &AtomicBool,
) -> (Vec<CycleBifurcation>, Vec<BreakPoint>) {
    let (mut found, mut breaks) = (Vec::new(), Vec::new());
    let all = brackets(cycles);
    for group in all.chunk_by(|x, y| x.after == y.after) {
        let after = group[0].after;
        let (a, b) = (&cycles[after], &cycles[after + 1]);
        let as_read = || group.iter().map(|g| (a.clone(), b.clone(), *g)).collect();
        let pieces: Vec<(Cycle, Cycle, Bracket)> = if group.iter().all(|g| g.clean) {
            as_read()
        } else {
            untangle(shooting, (a, b), scales, UNTANGLE_DEPTH, cancel).unwrap_or_else(as_read)
        };
        for (a, b, bracket) in pieces {
            let bracket = Bracket { after, ..bracket };
            let (bifurcation, symmetric) = place(shooting, (&a, &b), &bracket, scales, cancel);
            if let Some(unknowns) = symmetric {
                breaks.push(BreakPoint {
                    index: found.len(),
                    unknowns,
                });
            }
            found.push(bifurcation);
        }
    }
    (found, breaks)
}

/// The brackets between the neighbouring cycles `a` and `b` each of one
/// kind's change alone, with the two cycles each lies between: the chord
/// between them halved (a cycle solved for at its middle) until each half
/// is clean, at most `depth` times; `None` where a solve fails, the depth
/// runs out or `cancel` is set.
fn untangle(
    shooting: &Shooting,
    (a, b): (&Cycle, &Cycle),
    scales: &DVector<f64>,
    depth: usize,
    cancel: &AtomicBool,
) -> Option<Vec<(Cycle, Cycle, Bracket)>> {
    if depth == 0 || cancel.load(Ordering::Relaxed) {
        return None;
    }
    let middle = Chord::new(shooting, (a, b), scales)?
        .solve(0.5, None)?
        .solved
        .cycle;
    let mut found = Vec::new();
    for (x, y) in [(a, &middle), (&middle, b)] {
        let halves = brackets(&[x.clone(), y.clone()]);
        if halves.iter().all(|h| h.clean) {
            found.extend(halves.into_iter().map(|h| (x.clone(), y.clone(), h)));
        } else {
            found.extend(untangle(shooting, (x, y), scales, depth - 1, cancel)?);
        }
    }
    Some(found)
}

/// `bracket`'s bifurcation between the cycles `a` and `b`, solved for
/// where that can be done (else interpolated), and where it breaks the
/// mirror symmetry, the symmetric cycle's unknowns there.
fn place(
    shooting: &Shooting,
    (a, b): (&Cycle, &Cycle),
    bracket: &Bracket,
    scales: &DVector<f64>,
    cancel: &AtomicBool,
) -> (CycleBifurcation, Option<DVector<f64>>) {
    let kind = if bracket.kind == CycleBifurcationKind::Fold
        && !cancel.load(Ordering::Relaxed)
        && breaks_symmetry(shooting, a, b)
    {
        CycleBifurcationKind::SymmetryBreaking
    } else {
        bracket.kind
    };
    let chord = Chord::new(shooting, (a, b), scales);
    let mut symmetric_cycle = None;
    let refined = if kind == CycleBifurcationKind::SymmetryBreaking {
        chord
            .and_then(|chord| chord.symmetry_break(MODULUS_STOP, cancel))
            .map(|symmetric| {
                let load = symmetric.unknowns[symmetric.unknowns.len() - 1];
                symmetric_cycle = Some(symmetric.unknowns);
                (load, symmetric.amplitude_rad)
            })
    } else {
        chord
            .and_then(|chord| refine(&chord, bracket, cancel))
            .map(|on| {
                let cycle = &on.solved.cycle;
                (cycle.load, cycle.largest_amplitude_rad())
            })
    };
    let bifurcation = refined.map_or_else(
        || CycleBifurcation {
            kind,
            ..interpolated(bracket, a, b)
        },
        |(load, amplitude_rad)| CycleBifurcation {
            kind,
            load,
            amplitude_rad,
            refined: true,
            after: bracket.after,
        },
    );
    (bifurcation, symmetric_cycle)
}

/// `bracket`'s bifurcation placed on the line between the cycles `a` and
/// `b`, where its multiplier's modulus passes 1 on it: not solved for.
fn interpolated(bracket: &Bracket, a: &Cycle, b: &Cycle) -> CycleBifurcation {
    let t = bracket.linear_share();
    let along = |x: f64, y: f64| x + t * (y - x);
    CycleBifurcation {
        kind: bracket.kind,
        load: along(a.load, b.load),
        amplitude_rad: along(a.largest_amplitude_rad(), b.largest_amplitude_rad()),
        refined: false,
        after: bracket.after,
    }
}

/// The cycle at `bracket`'s bifurcation on `chord` between its
/// two cycles: a fold where the load's rate passes zero (solved at both
/// ends for it), else (a real multiplier through +1 where the load does
/// not turn, or another kind) where the modulus passes 1, as read off the
/// two cycles. `None` where that fails or once
/// `cancel` is set.
fn refine(chord: &Chord, bracket: &Bracket, cancel: &AtomicBool) -> Option<OnChord> {
    type Sample = (f64, f64, Option<OnChord>);
    let solve = |share: f64, near: &Option<OnChord>| {
        if cancel.load(Ordering::Relaxed) {
            return None;
        }
        chord.solve(share, near.as_ref().map(|on| &on.solved))
    };
    if bracket.kind == CycleBifurcationKind::Fold {
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
        let first = &brackets(&cycles)[0];
        let (a, b) = (&cycles[first.after], &cycles[first.after + 1]);
        let linear = interpolated(first, a, b).load;
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
        let first = &brackets(&cycles)[0];
        let linear = interpolated(first, &cycles[first.after], &cycles[first.after + 1]);
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
