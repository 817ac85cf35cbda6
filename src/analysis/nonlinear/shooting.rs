//! The shooting problem of one column's limit cycles: the flow over a
//! period and its monodromy by Gauss-Legendre steps, and Newton's (or
//! Broyden's) iterations on the periodicity, phase and load (or
//! arclength) equations of `cycles`.

use std::cell::Cell;

use nalgebra::{DMatrix, DVector};

use super::convergence::{broyden_update, converged, periodic_to_rounding};
use super::cycle::{Cycle, trivial_index};
use super::period_steps::{coarseness, raised_scale, scaled_steps};
pub(in crate::analysis) use super::period_steps::{fastest_rate, steps_for};
use crate::analysis::C64;
use crate::analysis::field::Field;
use crate::analysis::gauss::{Monodromy, Stepper};
use crate::analysis::hopf::HopfPoint;
use crate::analysis::peaks::Peaks;

/// Newton iterations for one cycle.
const NEWTON_ITERATIONS: usize = 12;
/// Broyden iterations for one cycle (each is one flow without the
/// monodromy).
const BROYDEN_ITERATIONS: usize = 16;

/// How Newton's matrix is updated over the iterations.
#[derive(Clone, Copy)]
pub(in crate::analysis) enum Update<'a> {
    /// Broyden's method: the matrix of the first iteration, corrected by a
    /// rank-one update from each later iteration's change of the residual
    /// (each later iteration is then one flow without the monodromy). The
    /// first iteration's monodromy is the one given (the last cycle's, next
    /// on the branch), or else the flow's with each step's Jacobian held
    /// over its stages.
    Broyden(Option<&'a DMatrix<f64>>),
    /// Broyden's method from this Newton matrix (a nearby cycle's, of the
    /// same equations): every iteration is one flow without the monodromy.
    Matrix(&'a DMatrix<f64>),
    /// Newton's method: the matrix anew at every iteration, with the
    /// monodromy taken as given.
    Newton(Monodromy),
}

/// A converged cycle with its exact monodromy, the steps of its flow and
/// Newton's iterations.
pub(in crate::analysis) struct Solved {
    pub(in crate::analysis) cycle: Cycle,
    pub(in crate::analysis) monodromy: DMatrix<f64>,
    pub(in crate::analysis) steps: usize,
    pub(in crate::analysis) iterations: usize,
}

/// A cycle with its exact monodromy, and the steps and end of its flow.
type CycleFlow = (Cycle, DMatrix<f64>, (usize, DVector<f64>));

/// The phase condition `normal . (x0 - point) = 0`: the plane a cycle's
/// start is held on.
pub(in crate::analysis) struct Phase {
    pub(in crate::analysis) normal: DVector<f64>,
    pub(in crate::analysis) point: DVector<f64>,
}

/// The flow over one period from `x0` in a number of steps: the
/// end point, the largest `|phi_i|` on the way, and (when asked) the monodromy.
pub(in crate::analysis) struct Orbit {
    pub(in crate::analysis) end: DVector<f64>,
    pub(in crate::analysis) amplitude_rad: Vec<f64>,
    pub(in crate::analysis) monodromy: Option<DMatrix<f64>>,
    pub(in crate::analysis) closest_slip_m_per_s: Option<f64>,
}

/// The flow over `period` from `x0` in `steps` steps of the Gauss-Legendre
/// method, with the monodromy as asked; `None` where a step fails.
pub(in crate::analysis) fn flow(
    field: &Field,
    x0: &DVector<f64>,
    period: f64,
    steps: usize,
    monodromy: Monodromy,
) -> Option<Orbit> {
    let d = x0.len();
    #[expect(clippy::cast_precision_loss, reason = "a step count")]
    let mut stepper = Stepper::new(field, period / steps as f64);
    let mut x = x0.clone();
    let mut y = (monodromy != Monodromy::None).then(|| DMatrix::<f64>::identity(d, d));
    let rods = field.rods();
    let h = stepper.step_secs();
    let (angles, rates) = (0..rods, rods..2 * rods);
    // The field at each step's end gives the angles' accelerations, for
    // the peaks between steps.
    let mut derivative = field.at(x0);
    let mut peaks = Peaks::with_accelerations(
        &x0.as_slice()[angles.clone()],
        &x0.as_slice()[rates.clone()],
        &derivative.as_slice()[rates.clone()],
    );
    let mut closest_slip_m_per_s = field.slip_m_per_s(x0);
    for _ in 0..steps {
        stepper.step(&mut x, y.as_mut(), monodromy)?;
        field.at_into(&x, &mut derivative);
        peaks.push_with_accelerations(
            &x.as_slice()[angles.clone()],
            &x.as_slice()[rates.clone()],
            &derivative.as_slice()[rates.clone()],
            h,
        );
        if let (Some(closest), Some(slip)) = (closest_slip_m_per_s.as_mut(), field.slip_m_per_s(&x))
        {
            *closest = closest.min(slip);
        }
    }
    Some(Orbit {
        end: x,
        amplitude_rad: peaks.largest().to_vec(),
        monodromy: y,
        closest_slip_m_per_s,
    })
}

/// What the third Newton equation holds fixed.
pub(in crate::analysis) enum Constraint<'a> {
    /// The load.
    Load(f64),
    /// The distance along the branch: `tangent . (u - predicted) = 0`.
    Arclength {
        tangent: &'a DVector<f64>,
        predicted: &'a DVector<f64>,
    },
}

/// The shooting problem of one column.
pub(in crate::analysis) struct Shooting {
    pub(in crate::analysis) field: Field,
    pub(in crate::analysis) fastest_per_s: f64,
    /// The steps per period are [`steps_for`]'s times this (rounded up to
    /// an even count, see `period_steps`): raised (never lowered) where a
    /// cycle needs more (see `period_steps`), and kept for the
    /// cycles after it on a branch.
    steps_scale: Cell<f64>,
}

impl Shooting {
    /// The shooting problem of `model` (at its own load, the start of its
    /// Newton iterations' load).
    pub(in crate::analysis) fn of(model: &crate::model::Model) -> Self {
        Self::on(Field::new(model))
    }

    /// The shooting problem of `field`.
    pub(in crate::analysis) fn on(field: Field) -> Self {
        Self {
            fastest_per_s: fastest_rate(&field),
            field,
            steps_scale: Cell::new(1.0),
        }
    }

    /// The factor its steps per period stand at (see `steps_scale`).
    pub(in crate::analysis) fn steps_scale(&self) -> f64 {
        self.steps_scale.get()
    }

    /// This shooting problem with its steps per period scaled by `scale`
    /// from the start: the pace a branch's cycles ended at.
    pub(in crate::analysis) fn with_steps_scale(self, scale: f64) -> Self {
        self.steps_scale.set(scale);
        self
    }

    /// The cycle through the guess `u = (x0, T, p)` under `constraint`,
    /// with its exact monodromy and Newton's iterations, or `None` where
    /// Newton fails: first by Broyden's method (see [`Update::Broyden`]),
    /// then, where that fails, by Newton's method with the matrix anew at
    /// every iteration, each step's Jacobian held over its stages, and last
    /// with the exact monodromy.
    pub(in crate::analysis) fn solve(
        &self,
        guess: &DVector<f64>,
        constraint: &Constraint,
    ) -> Option<Solved> {
        self.solve_on(guess, constraint, &self.phase_through(guess), None)
    }

    /// [`Self::solve`] with the start held on `phase`'s plane, first (when
    /// given) with Newton's matrix updated as `first` says.
    pub(in crate::analysis) fn solve_on(
        &self,
        guess: &DVector<f64>,
        constraint: &Constraint,
        phase: &Phase,
        first: Option<Update>,
    ) -> Option<Solved> {
        [
            first,
            Some(Update::Broyden(None)),
            Some(Update::Newton(Monodromy::HeldPerStep)),
            Some(Update::Newton(Monodromy::Exact)),
        ]
        .into_iter()
        .flatten()
        .find_map(|update| self.newton_on(guess, constraint, update, phase))
    }

    /// [`Self::solve`] with Newton's matrix updated as `update` says, the
    /// start on the plane through the guess's across its flow.
    pub(in crate::analysis) fn newton(
        &self,
        guess: &DVector<f64>,
        constraint: &Constraint,
        update: Update,
    ) -> Option<Solved> {
        self.newton_on(guess, constraint, update, &self.phase_through(guess))
    }

    /// The plane through the start of the unknowns `guess = (x0, T, p)`
    /// across the flow there.
    pub(in crate::analysis) fn phase_through(&self, guess: &DVector<f64>) -> Phase {
        let d = self.field.dimension();
        let point = guess.rows(0, d).into_owned();
        Phase {
            normal: self.field.at_load(guess[d + 1]).at(&point),
            point,
        }
    }

    /// [`Self::newton`] with the start held on `phase`'s plane.
    pub(in crate::analysis) fn newton_on(
        &self,
        guess: &DVector<f64>,
        constraint: &Constraint,
        update: Update,
        phase: &Phase,
    ) -> Option<Solved> {
        let d = self.field.dimension();
        let mut u = guess.clone();
        // The inverse of Newton's matrix, and the last step with the
        // residual it was taken from (for Broyden's update).
        let mut inverse: Option<DMatrix<f64>> = None;
        let mut last: Option<(DVector<f64>, DVector<f64>)> = None;
        let iterations = match update {
            Update::Broyden(_) | Update::Matrix(_) => BROYDEN_ITERATIONS,
            Update::Newton(_) => NEWTON_ITERATIONS,
        };
        for iteration in 1..=iterations {
            let (x0, period, load) = (u.rows(0, d).into_owned(), u[d], u[d + 1]);
            if !(period > 0.0 && load >= 0.0 && u.iter().all(|v| v.is_finite())) {
                return None;
            }
            let field = self.field.at_load(load);
            let taken = match update {
                Update::Broyden(None) if inverse.is_none() => Monodromy::HeldPerStep,
                Update::Broyden(_) | Update::Matrix(_) => Monodromy::None,
                Update::Newton(monodromy) => monodromy,
            };
            let (orbit, steps) = self.orbit(&field, &x0, period, taken)?;
            let mut residual = DVector::<f64>::zeros(d + 2);
            residual.rows_mut(0, d).copy_from(&(&orbit.end - &x0));
            residual[d] = phase.normal.dot(&(&x0 - &phase.point));
            residual[d + 1] = match constraint {
                Constraint::Load(target) => load - target,
                Constraint::Arclength { tangent, predicted } => tangent.dot(&(&u - *predicted)),
            };
            let monodromy = match (update, &inverse) {
                (Update::Matrix(known), None) => {
                    inverse = Some(known.clone().try_inverse()?);
                    None
                }
                (Update::Broyden(Some(known)), None) => Some(known),
                (Update::Broyden(_) | Update::Matrix(_), Some(_)) => None,
                _ => Some(orbit.monodromy.as_ref()?),
            };
            if let Some(monodromy) = monodromy {
                let jacobian = self.newton_matrix(
                    (&x0, period, load),
                    steps,
                    (&orbit.end, monodromy),
                    &phase.normal,
                    constraint,
                )?;
                inverse = Some(jacobian.try_inverse()?);
            } else if let (Some(h), Some((step, before))) = (inverse.as_mut(), &last) {
                broyden_update(h, &-step, &(&residual - before));
            }
            let step = inverse.as_ref()? * &residual;
            u -= &step;
            if converged(&step, &u, d) || periodic_to_rounding(&residual, &step, &u, d) {
                let (cycle, monodromy, (steps, end)) = self.cycle(&u)?;
                let scale = self.steps_scale.get();
                let error = || discretization_error(&self.field.at_load(u[d + 1]), &u, steps, &end);
                let state = u.rows(0, d).amax();
                if let Some(raised) = raised_scale(scale, || coarseness(error(), state)) {
                    // The flow's steps are too coarse for this cycle: again
                    // with as many as its error asks for, from it and its
                    // monodromy.
                    self.steps_scale.set(raised);
                    let finer =
                        self.newton_on(&u, constraint, Update::Broyden(Some(&monodromy)), phase);
                    if finer.is_some() {
                        return finer;
                    }
                    self.steps_scale.set(scale);
                }
                return Some(Solved {
                    cycle,
                    monodromy,
                    steps,
                    iterations: iteration,
                });
            }
            last = Some((step, residual));
        }
        None
    }

    /// The matrix of Newton's equations at `(x0, period, load)` (see the
    /// module's notes), from the flow's `end` there and a `monodromy`, and
    /// the flow's derivative in the load, by differences over `steps` steps.
    pub(in crate::analysis) fn newton_matrix(
        &self,
        (x0, period, load): (&DVector<f64>, f64, f64),
        steps: usize,
        (end, monodromy): (&DVector<f64>, &DMatrix<f64>),
        phase_normal: &DVector<f64>,
        constraint: &Constraint,
    ) -> Option<DMatrix<f64>> {
        let d = x0.len();
        let field = self.field.at_load(load);
        let mut jacobian = DMatrix::<f64>::zeros(d + 2, d + 2);
        jacobian
            .view_mut((0, 0), (d, d))
            .copy_from(&(monodromy - DMatrix::identity(d, d)));
        jacobian.view_mut((0, d), (d, 1)).copy_from(&field.at(end));
        jacobian
            .view_mut((d, 0), (1, d))
            .copy_from(&phase_normal.transpose());
        match constraint {
            Constraint::Load(_) => jacobian[(d + 1, d + 1)] = 1.0,
            Constraint::Arclength { tangent, .. } => {
                let by_load = load_derivative(load, |p| {
                    flow(&self.field.at_load(p), x0, period, steps, Monodromy::None)
                        .map(|orbit| orbit.end)
                })?;
                jacobian.view_mut((0, d + 1), (d, 1)).copy_from(&by_load);
                jacobian
                    .view_mut((d + 1, 0), (1, d + 2))
                    .copy_from(&tangent.transpose());
            }
        }
        Some(jacobian)
    }

    /// The cycle at the converged unknowns `u`, with its multipliers, its
    /// exact monodromy, and the steps and end of its flow.
    pub(in crate::analysis) fn cycle(&self, u: &DVector<f64>) -> Option<CycleFlow> {
        let d = self.field.dimension();
        let (x0, period, load) = (u.rows(0, d).into_owned(), u[d], u[d + 1]);
        let (orbit, steps) = self.orbit(
            &self.field.at_load(load),
            &x0,
            period,
            Monodromy::Multipliers,
        )?;
        let monodromy = orbit.monodromy?;
        let multipliers = sorted_multipliers(&monodromy);
        let trivial = trivial_index(&multipliers)?;
        let stable = multipliers
            .iter()
            .enumerate()
            .all(|(i, m)| i == trivial || m.norm() < 1.0);
        let cycle = Cycle {
            load,
            period_secs: period,
            start: x0,
            amplitude_rad: orbit.amplitude_rad,
            multipliers,
            stable,
            closest_slip_m_per_s: orbit.closest_slip_m_per_s,
        };
        Some((cycle, monodromy, (steps, orbit.end)))
    }

    /// The flow from `x0` over half of `period` at `load`, with the
    /// derivative as asked, at the pace of the branch's cycles' steps: the
    /// half-period map of a symmetric cycle (see `symmetric`).
    pub(in crate::analysis) fn half_flow(
        &self,
        (x0, period, load): (&DVector<f64>, f64, f64),
        monodromy: Monodromy,
    ) -> Option<Orbit> {
        let half = period / 2.0;
        let steps = scaled_steps(steps_for(half, self.fastest_per_s), self.steps_scale.get());
        flow(&self.field.at_load(load), x0, half, steps, monodromy)
    }

    /// The flow over `period` with its monodromy, and the steps it took.
    /// The roller's slip damping grows as the slip slows (its rate is the
    /// friction over the spin inertia and the slip speed), so an orbit
    /// whose slip falls below the band speed is taken again with the steps
    /// scaled up to match.
    pub(in crate::analysis) fn orbit(
        &self,
        field: &Field,
        x0: &DVector<f64>,
        period: f64,
        monodromy: Monodromy,
    ) -> Option<(Orbit, usize)> {
        let scale = self.steps_scale.get();
        let steps = scaled_steps(steps_for(period, self.fastest_per_s), scale);
        let orbit = flow(field, x0, period, steps, monodromy)?;
        let slowed = match (orbit.closest_slip_m_per_s, field.band_speed_m_per_s()) {
            (Some(slip), Some(band)) if slip > 0.0 && slip < band => band / slip,
            _ => return Some((orbit, steps)),
        };
        let needed = scaled_steps(steps_for(period, self.fastest_per_s * slowed), scale);
        if needed > steps {
            Some((flow(field, x0, period, needed, monodromy)?, needed))
        } else {
            Some((orbit, steps))
        }
    }

    /// Whether the roller's contact comes near sticking on `cycle`: its
    /// slip falls below `fraction` of the band speed.
    pub(in crate::analysis) fn near_sticking(&self, cycle: &Cycle, fraction: f64) -> bool {
        match (cycle.closest_slip_m_per_s, self.field.band_speed_m_per_s()) {
            (Some(slip), Some(band)) => slip < fraction * band,
            _ => false,
        }
    }

    /// The cycle whose largest angle's amplitude is about `amplitude_rad`
    /// by the normal form of the Hopf point `point`, on the side where
    /// cycles exist.
    pub(in crate::analysis) fn near_onset(
        &self,
        point: &HopfPoint,
        amplitude_rad: f64,
    ) -> Option<Solved> {
        let hopf = &point.hopf;
        let per_sqrt = hopf
            .amplitude_per_sqrt_load_rad
            .iter()
            .copied()
            .fold(0.0, f64::max);
        let distance = (amplitude_rad / per_sqrt).powi(2);
        // mu' (p - p_c) / l1 < 0 where the cycle exists.
        let side = -(hopf.growth_per_load * hopf.first_lyapunov).signum();
        self.normal_form_cycle(point, hopf.load + side * distance)
    }

    /// The cycle at `load` from the normal form's as the first guess.
    pub(in crate::analysis) fn normal_form_cycle(
        &self,
        point: &HopfPoint,
        load: f64,
    ) -> Option<Solved> {
        let hopf = &point.hopf;
        let radius = point.radius_per_sqrt_load * (load - hopf.load).abs().sqrt();
        let d = self.field.dimension();
        let guess = DVector::from_fn(d + 2, |i, _| match i {
            i if i < d => 2.0 * radius * point.eigenvector[i].re,
            i if i == d => std::f64::consts::TAU / hopf.frequency_rad_per_s,
            _ => load,
        });
        self.solve(&guess, &Constraint::Load(load))
    }
}

/// The derivative in the load of a flow's end, `end(p)`, at `load`, by
/// central differences (steps of 1e-6 of the load, at least 1e-9).
pub(in crate::analysis) fn load_derivative(
    load: f64,
    end: impl Fn(f64) -> Option<DVector<f64>>,
) -> Option<DVector<f64>> {
    let delta = 1e-6 * load.abs().max(1e-3);
    let (plus, minus) = (end(load + delta)?, end(load - delta)?);
    Some((plus - minus) / (2.0 * delta))
}

/// Eigenvalues of the monodromy, largest modulus first.
pub(in crate::analysis) fn sorted_multipliers(monodromy: &DMatrix<f64>) -> Vec<C64> {
    let mut multipliers: Vec<C64> = monodromy.complex_eigenvalues().iter().copied().collect();
    multipliers.sort_by(|a, b| b.norm().total_cmp(&a.norm()));
    multipliers
}

/// The error of the flow of `field` from `x0` over `period` (the unknowns
/// `u = (x0, T, p)`) in `steps` steps, which ends at `end`: the same flow
/// in half the steps ends `2^8 - 1` times that far from `end` (the
/// method's order is 8). Below the fewest steps per period the error is
/// not yet the order's, and the estimate errs on the large side.
fn discretization_error(field: &Field, u: &DVector<f64>, steps: usize, end: &DVector<f64>) -> f64 {
    let d = field.dimension();
    let x0 = u.rows(0, d).into_owned();
    flow(field, &x0, u[d], steps / 2, Monodromy::None)
        .map_or(f64::INFINITY, |orbit| (orbit.end - end).amax() / 255.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::nonlinear::period_steps::DISCRETIZATION_TOLERANCE;

    /// The damped Ziegler column swinging at large amplitude: its field,
    /// the unknowns of its flow over 10 s, and that flow's end in a number
    /// of steps.
    fn swinging_flows() -> (Field, DVector<f64>, impl Fn(usize) -> DVector<f64>) {
        let (field, x0) = crate::analysis::gauss::swinging_column();
        let u = DVector::from_iterator(6, x0.iter().copied().chain([10.0, 2.2]));
        let flown = field.clone();
        let end = move |steps| {
            flow(&flown, &x0, 10.0, steps, Monodromy::None)
                .expect("a flow")
                .end
        };
        (field, u, end)
    }

    /// The half-step estimate of a flow's error is its error: a damped
    /// Ziegler column swinging at large amplitude for 10 s, at 6 to 12
    /// steps (errors from 3e-10 to 1e-12), against the same flow at 1024
    /// steps: within 25 %.
    #[test]
    fn the_half_step_estimate_is_the_flow_s_error() {
        let (field, u, end) = swinging_flows();
        let exact = end(1024);
        for steps in [6, 8, 12] {
            let at = end(steps);
            let (estimate, error) = (
                discretization_error(&field, &u, steps, &at),
                (&at - &exact).amax(),
            );
            assert!(error > 1e-13, "{steps} steps: an error ({error})");
            let ratio = estimate / error;
            assert!(
                (0.8..1.25).contains(&ratio),
                "{steps} steps: {estimate} vs {error}"
            );
        }
    }

    /// A flow too coarse for the tolerance, taken again with the steps its
    /// error asks for (the order 8, `period_steps`' margin), is within the
    /// tolerance at the first try, with fewer steps than doubling them
    /// would take: the swinging column over 10 s at 6 steps (about three
    /// times too coarse), its error against 1024 steps.
    #[test]
    fn raised_steps_meet_the_tolerance_at_once() {
        let (field, u, end) = swinging_flows();
        let exact = end(1024);
        // The tolerance in the state's units, as `coarseness` measures it.
        let state = u.rows(0, 4).amax();
        let tolerance = DISCRETIZATION_TOLERANCE * state;
        let coarse = 6;
        let coarseness = coarseness(
            discretization_error(&field, &u, coarse, &end(coarse)),
            state,
        );
        assert!(
            (1.5..10.0).contains(&coarseness),
            "{coarseness}: not the case meant"
        );
        let scale = raised_scale(1.0, || coarseness).expect("too coarse");
        let raised = scaled_steps(coarse, scale);
        assert_eq!(raised % 2, 0, "{raised}: odd");
        assert!(raised < 2 * coarse, "{raised} steps");
        let error = (end(raised) - &exact).amax();
        assert!(
            error < 0.5 * tolerance,
            "{raised} steps: {error} against {tolerance}"
        );
        assert_eq!(scaled_steps(coarse, 1.0), coarse);
    }
}
