//! Symmetric cycles, and where their mirror symmetry breaks. A cycle of a
//! mirror-symmetric column (an odd field) that is its own mirror image
//! half a period on, `x(T/2) = -x(0)`, is solved for by shooting over half
//! its period: `Phi(T/2; x0, p) + x0 = 0`, the start on a plane across the
//! flow, and one more equation (the chord's plane of `chord`). Newton's
//! matrix `[Phi'(T/2) + I, f/2, dPhi/dp]` is singular only where the
//! half-period map `R = -Phi'(T/2)` has a multiplier +1 besides the
//! trivial one (a fold), not where one is -1: there the whole period's
//! Newton matrix is singular (a branch point, where asymmetric cycles
//! branch off), and this one places it as a simple root of `det(I + R)`.
//! Pure: no UI, no clock.

use nalgebra::{DMatrix, DVector};

use super::convergence::converged;
use super::cycle::{Cycle, REAL};
use super::shooting::{Phase, Shooting, load_derivative, sorted_multipliers};
use crate::analysis::gauss::Monodromy;

/// A cycle is its own mirror image half a period on when `x(T/2) + x(0)`
/// is within this share of `x(0)`'s largest coordinate (the flow's error
/// is about 1e-9 of it; a cycle of the roller, whose band has a
/// direction, is off by a tenth or more).
const MIRROR: f64 = 1e-6;

/// Newton iterations for one symmetric cycle.
const ITERATIONS: usize = 12;

/// A symmetric cycle: its unknowns `(x0, T, p)`, its largest angle's
/// amplitude, and `det(I + R)`, the product of `1 + rho` over its
/// half-period map's multipliers: of the sign of `(-1)^k`, k the count of
/// real ones below -1 (a complex pair adds `|1 + rho|^2`, the trivial one
/// 2), and a simple root where one goes through -1.
pub(super) struct Symmetric {
    pub(super) unknowns: DVector<f64>,
    pub(super) amplitude_rad: f64,
    pub(super) shifted_determinant: f64,
}

/// The symmetric cycle of `shooting`'s column near `guess = (x0, T, p)`,
/// its start on `phase`'s plane and `tangent . (u - guess) = 0`; `None`
/// where Newton's method does not converge.
pub(super) fn solve_symmetric(
    shooting: &Shooting,
    guess: &DVector<f64>,
    tangent: &DVector<f64>,
    phase: &Phase,
) -> Option<Symmetric> {
    let d = shooting.field.dimension();
    let mut u = guess.clone();
    for _ in 0..ITERATIONS {
        let (x0, period, load) = (u.rows(0, d).into_owned(), u[d], u[d + 1]);
        if !(period > 0.0 && load >= 0.0 && u.iter().all(|v| v.is_finite())) {
            return None;
        }
        let orbit = shooting.half_flow((&x0, period, load), Monodromy::Exact)?;
        let mut residual = DVector::<f64>::zeros(d + 2);
        residual.rows_mut(0, d).copy_from(&(&orbit.end + &x0));
        residual[d] = phase.normal.dot(&(&x0 - &phase.point));
        residual[d + 1] = tangent.dot(&(&u - guess));
        let mut matrix = DMatrix::<f64>::zeros(d + 2, d + 2);
        matrix
            .view_mut((0, 0), (d, d))
            .copy_from(&(orbit.monodromy? + DMatrix::identity(d, d)));
        let field = shooting.field.at_load(load);
        matrix
            .view_mut((0, d), (d, 1))
            .copy_from(&(field.at(&orbit.end) / 2.0));
        let by_load = load_derivative(load, |p| {
            shooting
                .half_flow((&x0, period, p), Monodromy::None)
                .map(|orbit| orbit.end)
        })?;
        matrix.view_mut((0, d + 1), (d, 1)).copy_from(&by_load);
        matrix
            .view_mut((d, 0), (1, d))
            .copy_from(&phase.normal.transpose());
        matrix
            .view_mut((d + 1, 0), (1, d + 2))
            .copy_from(&tangent.transpose());
        let step = matrix.lu().solve(&residual)?;
        u -= &step;
        if converged(&step, &u, d) {
            let (x0, period, load) = (u.rows(0, d).into_owned(), u[d], u[d + 1]);
            let orbit = shooting.half_flow((&x0, period, load), Monodromy::Multipliers)?;
            // I + R = I - Phi'(T/2).
            let shifted = DMatrix::identity(d, d) - orbit.monodromy?;
            return Some(Symmetric {
                amplitude_rad: orbit.amplitude_rad.iter().copied().fold(0.0, f64::max),
                unknowns: u,
                shifted_determinant: shifted.determinant(),
            });
        }
    }
    None
}

/// Whether the multiplier through +1 between the neighbouring cycles `a`
/// and `b` of `shooting`'s branch breaks the mirror symmetry: both cycles
/// are their own mirror images half a period on (to [`MIRROR`] of their
/// largest coordinate) and the count of real multipliers of the
/// half-period map `R = -Phi(T/2)` below -1 differs between them (see the
/// module's notes). `false` where a cycle is not symmetric (the roller's
/// band has a direction) or its half period cannot be flowed.
pub(super) fn breaks_symmetry(shooting: &Shooting, a: &Cycle, b: &Cycle) -> bool {
    let below_minus_one = |cycle: &Cycle| -> Option<usize> {
        let half = shooting.half_flow(
            (&cycle.start, cycle.period_secs, cycle.load),
            Monodromy::Multipliers,
        )?;
        if !mirrored(&half.end, &cycle.start) {
            return None;
        }
        let map = -half.monodromy?;
        Some(
            sorted_multipliers(&map)
                .iter()
                .filter(|rho| rho.im.abs() <= REAL * rho.norm() && rho.re < -1.0)
                .count(),
        )
    };
    matches!(
        (below_minus_one(a), below_minus_one(b)),
        (Some(x), Some(y)) if x != y
    )
}

/// Whether `cycle` is its own mirror image half a period on (to
/// [`MIRROR`] of its largest coordinate); `false` where its half period
/// cannot be flowed.
pub(super) fn own_mirror_image(shooting: &Shooting, cycle: &Cycle) -> bool {
    shooting
        .half_flow(
            (&cycle.start, cycle.period_secs, cycle.load),
            Monodromy::None,
        )
        .is_some_and(|half| mirrored(&half.end, &cycle.start))
}

/// Whether the flow from `start` ends half a period on at `end = -start`,
/// to [`MIRROR`] of its largest coordinate.
fn mirrored(end: &DVector<f64>, start: &DVector<f64>) -> bool {
    (end + start).amax() <= MIRROR * start.amax()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cycle of Ziegler's column with joint dampers, found by shooting
    /// over the whole period, is its own mirror image half a period on:
    /// shooting over half the period from it at its load gives it back
    /// (start, period and load to 1e-9), and `det(I + R)` is positive
    /// (no real multiplier of the half-period map below -1 on this stable
    /// cycle).
    #[test]
    fn half_period_shooting_finds_the_whole_period_s_cycle() {
        let mut model = crate::model::PresetId::Ziegler1952.model();
        model.column.c1_nms_per_rad = 0.3;
        model.column.c2_nms_per_rad = 0.3;
        let never = std::sync::atomic::AtomicBool::new(false);
        let onset = crate::analysis::cycle_branches(&model, 1.8, 2.4, &never)
            .unwrap()
            .remove(0);
        let branch = onset.branch.unwrap();
        let cycle = branch
            .cycles
            .iter()
            .find(|c| c.load > 2.1 && c.stable)
            .unwrap();
        let shooting = Shooting::of(&model.at_load(cycle.load));
        let u = cycle.unknowns();
        let d = u.len() - 2;
        let load_only = DVector::from_fn(d + 2, |i, _| f64::from(u8::from(i == d + 1)));
        let phase = shooting.phase_through(&u);
        let symmetric = solve_symmetric(&shooting, &u, &load_only, &phase).unwrap();
        let off = (&symmetric.unknowns - &u).amax();
        assert!(off < 1e-9 * u.amax(), "{off}");
        assert!(symmetric.shifted_determinant > 0.0);
        assert!((symmetric.amplitude_rad / cycle.largest_amplitude_rad() - 1.0).abs() < 1e-6);
    }
}
