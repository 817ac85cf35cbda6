//! The asymmetric cycles born where a branch's mirror symmetry breaks.
//!
//! At a break of symmetry (`cycle_bifurcations`, placed by `symmetric`) the
//! symmetric cycle `u* = (x*, T*, p*)` has a half-period map `R = -Phi'(T/2)`
//! with a multiplier -1: its eigenvector `v` (the null vector of `I + R`)
//! is the direction in which the cycles lose their symmetry. Two cycles
//! are solved for on the planes `v . (x0 - x*) = eps` (pseudo-arclength
//! with the tangent `(v, 0, 0)`: the standard switch of branches), and the
//! branch through them is continued as a Hopf point's is (`cycles`). Its
//! mirror image, `-x(t)`, is a branch of cycles too, with the same
//! amplitudes and multipliers: one is followed. Pure: no UI, no clock.

use nalgebra::{DMatrix, DVector};

use super::continuation::{BranchEnd, Course, cycles_along, follow, opening_at, runs_from};
use super::cycle::Cycle;
use super::cycle_bifurcations::{CycleBifurcation, cycle_bifurcations};
use super::shooting::{Constraint, Shooting};
use super::symmetric::own_mirror_image;
use crate::analysis::gauss::Monodromy;
use crate::model::Model;

/// The first two cycles' distances from the symmetric cycle along `v`, in
/// the state's own units (rad, rad/s) per unit of its largest coordinate
/// (at least 1).
const START_DISTANCES: [f64; 2] = [0.01, 0.02];

/// The asymmetric cycles born at one break of a branch's symmetry.
#[derive(Clone, Debug)]
pub struct Offshoot {
    /// `cycle-1-asymmetric` (`cycle-1-asymmetric-2` for the branch's
    /// second break, ...).
    name: String,
    /// The break of symmetry on the parent branch it is born at.
    pub born: CycleBifurcation,
    /// In the order of the continuation, starting next to the break.
    pub cycles: Vec<Cycle>,
    /// The cycles' own bifurcations, in the order of the continuation.
    pub bifurcations: Vec<CycleBifurcation>,
    pub end: BranchEnd,
    /// The factor of the steps per period its cycles were computed at
    /// (see `shooting`): a large swing's flow fails with fewer.
    steps_scale: f64,
}

impl Offshoot {
    /// The branch's name in tables.
    #[must_use]
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The branch as runs of equal stability (see
    /// [`Branch::runs`](super::cycles::Branch::runs)), from the break.
    #[must_use]
    pub fn runs(&self) -> Vec<(Vec<[f64; 2]>, bool)> {
        runs_from(
            [self.born.load, self.born.amplitude_rad],
            &self.cycles,
            &self.bifurcations,
        )
    }

    /// Which way the branch opens at its bifurcation `at` (see
    /// [`Branch::opening`](super::cycles::Branch::opening)).
    #[must_use]
    pub fn opening(&self, at: &CycleBifurcation) -> f64 {
        opening_at(&self.cycles, at)
    }

    /// The branch's cycles of `model` at load `p`: one where each of its
    /// segments crosses `p`, each solved at exactly `p` at the steps the
    /// branch was followed with.
    #[must_use]
    pub fn cycles_at(&self, model: &Model, p: f64) -> Vec<Cycle> {
        let shooting = Shooting::of(&model.at_load(p)).with_steps_scale(self.steps_scale);
        // Between the break and the first cycle: from that cycle, kept
        // where it has not fallen back onto the symmetric branch.
        let near_break = self
            .cycles
            .first()
            .filter(|first| {
                let (lo, hi) = (
                    self.born.load.min(first.load),
                    self.born.load.max(first.load),
                );
                lo < p && p < hi
            })
            .and_then(|first| {
                let mut guess = first.unknowns();
                let last = guess.len() - 1;
                guess[last] = p;
                shooting.solve(&guess, &Constraint::Load(p))
            })
            .map(|solved| solved.cycle)
            .filter(|cycle| !own_mirror_image(&shooting, cycle));
        near_break
            .into_iter()
            .chain(cycles_along(&shooting, &self.cycles, p))
            .collect()
    }
}

/// The asymmetric branch named `name` born at the break of symmetry `born`,
/// whose symmetric cycle has the unknowns `at`, followed along `course`;
/// `None` where its first cycles are not found (or come out symmetric).
pub(super) fn offshoot(
    course: &Course,
    name: String,
    born: CycleBifurcation,
    at: &DVector<f64>,
) -> Option<Offshoot> {
    let shooting = course.shooting;
    let d = shooting.field.dimension();
    let v = breaking_direction(shooting, at)?;
    let tangent = DVector::from_fn(d + 2, |i, _| if i < d { v[i] } else { 0.0 });
    let size = at.rows(0, d).amax().max(1.0);
    let (mut starts, mut monodromy) = (Vec::new(), None);
    for distance in START_DISTANCES {
        let predicted = at + &tangent * (distance * size);
        let constraint = Constraint::Arclength {
            tangent: &tangent,
            predicted: &predicted,
        };
        let solved = shooting.solve(&predicted, &constraint)?;
        if own_mirror_image(shooting, &solved.cycle) {
            return None;
        }
        starts.push(solved.cycle);
        monodromy = Some(solved.monodromy);
    }
    let (cycles, end) = follow(course, starts, monodromy?)?;
    let (bifurcations, _) = cycle_bifurcations(shooting, &cycles, &course.scales, course.cancel);
    Some(Offshoot {
        name,
        born,
        cycles,
        bifurcations,
        end,
        steps_scale: shooting.steps_scale(),
    })
}

/// The unit vector `v` with `(I + R) v = 0` at the symmetric cycle with
/// unknowns `at` (its right singular vector of the least singular value).
fn breaking_direction(shooting: &Shooting, at: &DVector<f64>) -> Option<DVector<f64>> {
    let d = shooting.field.dimension();
    let x0 = at.rows(0, d).into_owned();
    let half = shooting.half_flow((&x0, at[d], at[d + 1]), Monodromy::Exact)?;
    // I + R = I - Phi'(T/2).
    let shifted = DMatrix::identity(d, d) - half.monodromy?;
    let svd = shifted.svd(false, true);
    let least = svd.singular_values.argmin().0;
    let v_t = svd.v_t?;
    Some(v_t.row(least).transpose())
}
