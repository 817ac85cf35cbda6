//! Limit cycles past a flutter onset: periodic orbits of the nonlinear
//! equations found by shooting, continued in the load from each Hopf point,
//! with their period, the amplitude of every angle and their Floquet
//! multipliers (stability).
//!
//! A cycle is a start `x0` on the reduced state (see `field`) and a period
//! `T` with `phi_T(x0) = x0`, `phi_T` the flow of the equations of motion.
//! The flow and its Jacobian (the monodromy matrix) are integrated together
//! by the two-stage Gauss-Legendre method at a fixed number of steps per
//! period (`gauss`: implicit and A-stable, so a chain's fast modes do not
//! set the step), the monodromy as the exact derivative of the computed
//! flow for the multipliers. Newton solves
//!
//! ```text
//! phi_T(x0; p) - x0 = 0                (d equations)
//! f(x_ref) . (x0 - x_ref) = 0          (phase: x0 on the plane through the
//!                                       last cycle, across its flow)
//! p = p_target  or  t . (u - u_pred) = 0   (fixed load, or pseudo-arclength)
//! ```
//!
//! for `u = (x0, T, p)`, by Broyden's method: Newton's matrix once (from
//! the last cycle's monodromy along a branch, else from a flow with each
//! step's Jacobian held over its stages), then rank-one corrections from
//! each iteration's change of the residual, so that a later iteration is
//! one flow without the monodromy; where that fails, by Newton's method
//! proper. A branch starts at the normal form's cycle near its
//! Hopf point (`hopf`) and is followed by pseudo-arclength continuation
//! (distances in unknowns scaled by the Hopf period and load), which passes
//! folds (a hard onset's unstable cycle turning into the large
//! stable one). The multipliers are the monodromy's eigenvalues: one is 1
//! (the shift along the orbit); the cycle is stable when every other one
//! lies inside the unit circle. Pure: no UI, no clock.

use std::sync::atomic::{AtomicBool, Ordering};

use nalgebra::{DMatrix, DVector};

use crate::analysis::field::Field;
use crate::analysis::gauss::{Monodromy, Stepper};
use crate::analysis::hopf::{HopfPoint, Steps as HopfSteps, hopf_point};
use crate::analysis::peaks::Peaks;
use crate::analysis::{AffinePencil, AnalysisError, C64, Hopf, HopfKind, critical_loads, is_hopf};
use crate::format::load_text;
use crate::model::{Model, StateVec};

/// One periodic orbit.
#[derive(Clone, Debug, PartialEq)]
pub struct Cycle {
    /// The load p.
    pub load: f64,
    pub period_secs: f64,
    /// A point of the orbit, on the reduced state.
    pub start: DVector<f64>,
    /// The largest `|phi_i|` over the cycle, for each rod, in rad.
    pub amplitude_rad: Vec<f64>,
    /// The Floquet multipliers, largest modulus first.
    pub multipliers: Vec<C64>,
    /// Every multiplier but the trivial one inside the unit circle.
    pub stable: bool,
    /// The roller's smallest slip speed on the band over the cycle, m/s
    /// (none without a roller).
    pub closest_slip_m_per_s: Option<f64>,
}

impl Cycle {
    /// The multiplier nearest 1 (the shift along the orbit): 1 to the
    /// accuracy of the monodromy.
    #[must_use]
    pub fn trivial_multiplier(&self) -> C64 {
        trivial_index(&self.multipliers).map_or(C64::new(f64::NAN, 0.0), |i| self.multipliers[i])
    }

    /// The cycle's start as a full state of `model` (the spin angle zero;
    /// a massless roller's spin rate, which follows the rods, too).
    #[must_use]
    pub fn start_state(&self, model: &Model) -> StateVec {
        Field::new(model).full_state(&self.start)
    }

    /// The largest amplitude of any rod's angle, rad.
    #[must_use]
    pub fn largest_amplitude_rad(&self) -> f64 {
        self.amplitude_rad.iter().copied().fold(0.0, f64::max)
    }

    fn unknowns(&self) -> DVector<f64> {
        let d = self.start.len();
        DVector::from_fn(d + 2, |i, _| match i {
            i if i < d => self.start[i],
            i if i == d => self.period_secs,
            _ => self.load,
        })
    }
}

/// Why a branch's continuation stopped.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum BranchEnd {
    /// The branch left the load range asked for.
    LeftRange,
    /// An angle's amplitude passed [`MAX_AMPLITUDE_RAD`].
    LargeAmplitude,
    /// The period grew past [`MAX_PERIOD_GROWTH`] times the Hopf period.
    LongPeriod,
    /// Newton's method failed even at the smallest step, at this load.
    Lost { load: f64 },
    /// The roller's contact came within [`STICK_FRACTION`] of the band
    /// speed of sticking on the next cycle, past this load: the dry
    /// friction turns non-smooth there (stick-slip), which shooting on
    /// smooth equations does not follow.
    StickSlip { load: f64 },
    /// The next cycle's trivial multiplier was further than
    /// [`TRIVIAL_TOLERANCE`] from 1, past this load: not resolved.
    Unresolved { load: f64 },
    /// [`MAX_POINTS`] cycles were computed.
    PointLimit,
    /// The caller asked to stop.
    Cancelled,
}

impl std::fmt::Display for BranchEnd {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::LeftRange => write!(f, "left the load range"),
            Self::LargeAmplitude => write!(
                f,
                "an angle's amplitude passed {MAX_AMPLITUDE_RAD} rad (the column swings round)"
            ),
            Self::LongPeriod => write!(
                f,
                "the period grew past {MAX_PERIOD_GROWTH} times the onset's"
            ),
            Self::Lost { load } => write!(
                f,
                "the shooting did not converge past p = {}",
                load_text(*load)
            ),
            Self::StickSlip { load } => write!(
                f,
                "the roller's contact nears sticking on the band past p = {} (stick-slip: the friction is not smooth there)",
                load_text(*load)
            ),
            Self::Unresolved { load } => write!(
                f,
                "the cycles past p = {} are not resolved (trivial multiplier off 1 by more than {TRIVIAL_TOLERANCE:e})",
                load_text(*load)
            ),
            Self::PointLimit => write!(f, "{MAX_POINTS} cycles computed"),
            Self::Cancelled => write!(f, "stopped on request"),
        }
    }
}

/// The cycles born at one Hopf point.
#[derive(Clone, Debug)]
pub struct Branch {
    onset: HopfPoint,
    /// `cycle-1`, `cycle-2`, ... in the order of the onsets' loads.
    name: String,
    /// In the order of the continuation, starting next to the Hopf point.
    pub cycles: Vec<Cycle>,
    pub end: BranchEnd,
}

impl Branch {
    /// The Hopf point the branch is born at.
    #[must_use]
    pub fn hopf(&self) -> &Hopf {
        &self.onset.hopf
    }

    /// The branch as runs of equal stability, each a polyline of
    /// `[load, largest angle's amplitude]` from the Hopf point on (each run
    /// starts where the one before ended, so the curve is unbroken).
    #[must_use]
    pub fn runs(&self) -> Vec<(Vec<[f64; 2]>, bool)> {
        let mut runs: Vec<(Vec<[f64; 2]>, bool)> = Vec::new();
        let mut last = [self.hopf().load, 0.0];
        for cycle in &self.cycles {
            let point = [cycle.load, cycle.largest_amplitude_rad()];
            match runs.last_mut() {
                Some((points, stable)) if *stable == cycle.stable => points.push(point),
                _ => runs.push((vec![last, point], cycle.stable)),
            }
            last = point;
        }
        runs
    }

    /// "soft" or "hard": how flutter sets in at the branch's onset.
    #[must_use]
    pub fn onset_word(&self) -> &'static str {
        if self.hopf().first_lyapunov < 0.0 {
            "soft"
        } else {
            "hard"
        }
    }

    /// The branch's name in tables: `cycle-1`, `cycle-2`, ... in the
    /// order of the onsets.
    #[must_use]
    pub fn name(&self) -> &str {
        &self.name
    }
}

/// A branch stops where an angle's amplitude passes this (rad): the column
/// swings round and the cycle is no longer a flutter of the straight column.
pub const MAX_AMPLITUDE_RAD: f64 = 3.0;
/// A branch stops where its period grows past this many times the onset's
/// (a cycle approaching a homoclinic orbit).
pub const MAX_PERIOD_GROWTH: f64 = 20.0;
/// Most cycles on one branch.
pub const MAX_POINTS: usize = 400;
/// A roller's branch stops before a cycle whose slip speed falls below
/// this fraction of the band speed (see [`BranchEnd::StickSlip`]).
pub const STICK_FRACTION: f64 = 0.1;
/// The cycle that ends a roller's branch has a slip speed between this
/// fraction of [`STICK_FRACTION`] of the band speed and that bound.
const STICK_END_FRACTION: f64 = 0.9;
/// A cycle is resolved when its trivial multiplier is within this of 1.
pub const TRIVIAL_TOLERANCE: f64 = 1e-6;

/// Fewest steps per period: with the Gauss-Legendre method's order 4, the
/// period to about 1e-10 and the amplitudes (read off the cubic between
/// steps, see `peaks`) to about 1e-9 of themselves.
const MIN_STEPS: u32 = 800;
/// The step times the spectral radius of the Jacobian at rest stays below
/// this. The method is stable at any step (see `gauss`); the bound keeps
/// the stage equations' Newton iterations, which start from the last
/// step's stages, in their quick range where a mode is far faster than the
/// flutter (the roller's spin as its slip slows).
const FAST_MODE_STEP: f64 = 100.0;
/// A continuation step that converged in at most this many iterations
/// makes the next one longer.
const GROW_ITERATIONS: usize = 8;
/// The cosine of the largest turn between a step of the continuation and
/// the last one (in the scaled unknowns) that is kept: 25 degrees.
const MAX_TURN_COS: f64 = 0.9;
/// The first cycles' amplitudes, rad: small enough for the normal form to be
/// a good first guess, large enough for a well conditioned shooting.
const START_AMPLITUDES_RAD: [f64; 3] = [0.003, 0.006, 0.012];
/// Newton iterations for one cycle.
const NEWTON_ITERATIONS: usize = 12;
/// Newton's iterations end when each part of the step is this fraction of
/// its part of the unknowns (see [`converged`]).
const NEWTON_TOLERANCE: f64 = 1e-9;
/// The smallest load the load's step is measured against.
const LOAD_SCALE_FLOOR: f64 = 1e-3;
/// Broyden iterations for one cycle (each is one flow without the
/// monodromy).
const BROYDEN_ITERATIONS: usize = 16;

/// How Newton's matrix is updated over the iterations.
#[derive(Clone, Copy)]
enum Update<'a> {
    /// Broyden's method: the matrix of the first iteration, corrected by a
    /// rank-one update from each later iteration's change of the residual
    /// (each later iteration is then one flow without the monodromy). The
    /// first iteration's monodromy is the one given (the last cycle's, next
    /// on the branch), or else the flow's with each step's Jacobian held
    /// over its stages.
    Broyden(Option<&'a DMatrix<f64>>),
    /// Newton's method: the matrix anew at every iteration, with the
    /// monodromy taken as given.
    Newton(Monodromy),
}

/// A converged cycle with its exact monodromy and Newton's iterations.
struct Solved {
    cycle: Cycle,
    monodromy: DMatrix<f64>,
    iterations: usize,
}

/// The flow over one period from `x0` in a number of steps: the
/// end point, the largest `|phi_i|` on the way, and (when asked) the monodromy.
struct Orbit {
    end: DVector<f64>,
    amplitude_rad: Vec<f64>,
    monodromy: Option<DMatrix<f64>>,
    closest_slip_m_per_s: Option<f64>,
}

/// The flow over `period` from `x0` in `steps` steps of the Gauss-Legendre
/// method, with the monodromy as asked; `None` where a step fails.
fn flow(
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
    let mut peaks = Peaks::new(
        &x0.as_slice()[angles.clone()],
        &x0.as_slice()[rates.clone()],
    );
    let mut closest_slip_m_per_s = field.slip_m_per_s(x0);
    for _ in 0..steps {
        stepper.step(&mut x, y.as_mut(), monodromy)?;
        peaks.push(
            &x.as_slice()[angles.clone()],
            &x.as_slice()[rates.clone()],
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

/// Steps for one period of `period` of a field whose Jacobian
/// at rest has spectral radius `fastest_per_s`.
fn steps_for(period: f64, fastest_per_s: f64) -> usize {
    let needed = (period * fastest_per_s / FAST_MODE_STEP)
        .ceil()
        .clamp(f64::from(MIN_STEPS), 1e7);
    if needed.is_finite() {
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "a positive step count below 1e7"
        )]
        let steps = needed as usize;
        steps
    } else {
        MIN_STEPS as usize
    }
}

/// The spectral radius of the field's Jacobian at rest, 1/s.
fn fastest_rate(field: &Field) -> f64 {
    let d = field.dimension();
    field
        .jacobian(&DVector::zeros(d), 1e-6)
        .complex_eigenvalues()
        .iter()
        .map(|z| z.norm())
        .fold(0.0, f64::max)
}

/// What the third Newton equation holds fixed.
enum Constraint<'a> {
    /// The load.
    Load(f64),
    /// The distance along the branch: `tangent . (u - predicted) = 0`.
    Arclength {
        tangent: &'a DVector<f64>,
        predicted: &'a DVector<f64>,
    },
}

/// The shooting problem of one column.
struct Shooting {
    field: Field,
    fastest_per_s: f64,
}

impl Shooting {
    /// The cycle through the guess `u = (x0, T, p)` under `constraint`,
    /// with its exact monodromy and Newton's iterations, or `None` where
    /// Newton fails: first by Broyden's method (see [`Update::Broyden`]),
    /// then, where that fails, by Newton's method with the matrix anew at
    /// every iteration, each step's Jacobian held over its stages, and last
    /// with the exact monodromy.
    fn solve(&self, guess: &DVector<f64>, constraint: &Constraint) -> Option<Solved> {
        self.newton(guess, constraint, Update::Broyden(None))
            .or_else(|| self.newton(guess, constraint, Update::Newton(Monodromy::HeldPerStep)))
            .or_else(|| self.newton(guess, constraint, Update::Newton(Monodromy::Exact)))
    }

    /// [`Self::solve`] with Newton's matrix updated as `update` says.
    fn newton(
        &self,
        guess: &DVector<f64>,
        constraint: &Constraint,
        update: Update,
    ) -> Option<Solved> {
        let d = self.field.dimension();
        let reference = guess.rows(0, d).into_owned();
        let reference_flow = self.field.at_load(guess[d + 1]).at(&reference);
        let mut u = guess.clone();
        // The inverse of Newton's matrix, and the last step with the
        // residual it was taken from (for Broyden's update).
        let mut inverse: Option<DMatrix<f64>> = None;
        let mut last: Option<(DVector<f64>, DVector<f64>)> = None;
        let iterations = match update {
            Update::Broyden(_) => BROYDEN_ITERATIONS,
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
                Update::Broyden(_) => Monodromy::None,
                Update::Newton(monodromy) => monodromy,
            };
            let (orbit, steps) = self.orbit(&field, &x0, period, taken)?;
            let mut residual = DVector::<f64>::zeros(d + 2);
            residual.rows_mut(0, d).copy_from(&(&orbit.end - &x0));
            residual[d] = reference_flow.dot(&(&x0 - &reference));
            residual[d + 1] = match constraint {
                Constraint::Load(target) => load - target,
                Constraint::Arclength { tangent, predicted } => tangent.dot(&(&u - *predicted)),
            };
            let monodromy = match (update, &inverse) {
                (Update::Broyden(Some(known)), None) => Some(known),
                (Update::Broyden(_), Some(_)) => None,
                _ => Some(orbit.monodromy.as_ref()?),
            };
            if let Some(monodromy) = monodromy {
                let jacobian = self.newton_matrix(
                    (&x0, period, load),
                    steps,
                    (&orbit.end, monodromy),
                    &reference_flow,
                    constraint,
                )?;
                inverse = Some(jacobian.try_inverse()?);
            } else if let (Some(h), Some((step, before))) = (inverse.as_mut(), &last) {
                broyden_update(h, &-step, &(&residual - before));
            }
            let step = inverse.as_ref()? * &residual;
            u -= &step;
            if converged(&step, &u, d) {
                let (cycle, monodromy) = self.cycle(&u)?;
                return Some(Solved {
                    cycle,
                    monodromy,
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
    fn newton_matrix(
        &self,
        (x0, period, load): (&DVector<f64>, f64, f64),
        steps: usize,
        (end, monodromy): (&DVector<f64>, &DMatrix<f64>),
        reference_flow: &DVector<f64>,
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
            .copy_from(&reference_flow.transpose());
        match constraint {
            Constraint::Load(_) => jacobian[(d + 1, d + 1)] = 1.0,
            Constraint::Arclength { tangent, .. } => {
                let delta = 1e-6 * load.abs().max(1e-3);
                let end = |p| {
                    flow(&self.field.at_load(p), x0, period, steps, Monodromy::None)
                        .map(|orbit| orbit.end)
                };
                let (plus, minus) = (end(load + delta)?, end(load - delta)?);
                jacobian
                    .view_mut((0, d + 1), (d, 1))
                    .copy_from(&((plus - minus) / (2.0 * delta)));
                jacobian
                    .view_mut((d + 1, 0), (1, d + 2))
                    .copy_from(&tangent.transpose());
            }
        }
        Some(jacobian)
    }

    /// The cycle at the converged unknowns `u`, with its multipliers, and
    /// its exact monodromy.
    fn cycle(&self, u: &DVector<f64>) -> Option<(Cycle, DMatrix<f64>)> {
        let d = self.field.dimension();
        let (x0, period, load) = (u.rows(0, d).into_owned(), u[d], u[d + 1]);
        let (orbit, _) = self.orbit(&self.field.at_load(load), &x0, period, Monodromy::Exact)?;
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
        Some((cycle, monodromy))
    }

    /// The flow over `period` with its monodromy, and the steps it took.
    /// The roller's slip damping grows as the slip slows (its rate is the
    /// friction over the spin inertia and the slip speed), so an orbit
    /// whose slip falls below the band speed is taken again with the steps
    /// scaled up to match.
    fn orbit(
        &self,
        field: &Field,
        x0: &DVector<f64>,
        period: f64,
        monodromy: Monodromy,
    ) -> Option<(Orbit, usize)> {
        let steps = steps_for(period, self.fastest_per_s);
        let orbit = flow(field, x0, period, steps, monodromy)?;
        let slowed = match (orbit.closest_slip_m_per_s, field.band_speed_m_per_s()) {
            (Some(slip), Some(band)) if slip > 0.0 && slip < band => band / slip,
            _ => return Some((orbit, steps)),
        };
        let needed = steps_for(period, self.fastest_per_s * slowed);
        if needed > steps {
            Some((flow(field, x0, period, needed, monodromy)?, needed))
        } else {
            Some((orbit, steps))
        }
    }

    /// Whether the roller's contact comes near sticking on `cycle`: its
    /// slip falls below `fraction` of the band speed.
    fn near_sticking(&self, cycle: &Cycle, fraction: f64) -> bool {
        match (cycle.closest_slip_m_per_s, self.field.band_speed_m_per_s()) {
            (Some(slip), Some(band)) => slip < fraction * band,
            _ => false,
        }
    }

    /// The cycle whose largest angle's amplitude is about `amplitude_rad`
    /// by the normal form of the Hopf point `point`, on the side where
    /// cycles exist.
    fn near_onset(&self, point: &HopfPoint, amplitude_rad: f64) -> Option<Solved> {
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
    fn normal_form_cycle(&self, point: &HopfPoint, load: f64) -> Option<Solved> {
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

/// Broyden's ("good") rank-one update of the inverse `h` of Newton's
/// matrix after a step `s` changed the residual by `y`, by the formula of
/// Sherman and Morrison: `h += (s - h y) (s^T h) / (s^T h y)`. The updated
/// matrix maps `y` to `s`, and is unchanged across `s`. Left as it is
/// where `s^T h y` vanishes.
fn broyden_update(h: &mut DMatrix<f64>, s: &DVector<f64>, y: &DVector<f64>) {
    let hy = &*h * y;
    let denominator = s.dot(&hy);
    if denominator.abs() > f64::MIN_POSITIVE && denominator.is_finite() {
        let st_h = s.transpose() * &*h;
        *h += (s - hy) * st_h / denominator;
    }
}

/// Whether Newton's `step` at the unknowns `u = (x0, T, p)` (the state's
/// length `d`) is down to [`NEWTON_TOLERANCE`] of each part's own size: the
/// state's largest entry, the period, the load (at least
/// [`LOAD_SCALE_FLOOR`]). Measured by one size for all, a cycle of small
/// amplitude and long period (a long chain's near its onset) would ask its
/// period to more digits than the state determines it to.
fn converged(step: &DVector<f64>, u: &DVector<f64>, d: usize) -> bool {
    let state = u.rows(0, d).amax();
    step.rows(0, d).amax() <= NEWTON_TOLERANCE * state
        && step[d].abs() <= NEWTON_TOLERANCE * u[d].abs()
        && step[d + 1].abs() <= NEWTON_TOLERANCE * u[d + 1].abs().max(LOAD_SCALE_FLOOR)
}

/// Where the multiplier nearest 1 (the shift along the orbit) stands.
fn trivial_index(multipliers: &[C64]) -> Option<usize> {
    multipliers
        .iter()
        .enumerate()
        .min_by(|a, b| (a.1 - 1.0).norm().total_cmp(&(b.1 - 1.0).norm()))
        .map(|(i, _)| i)
}

/// Eigenvalues of the monodromy, largest modulus first.
fn sorted_multipliers(monodromy: &DMatrix<f64>) -> Vec<C64> {
    let mut multipliers: Vec<C64> = monodromy.complex_eigenvalues().iter().copied().collect();
    multipliers.sort_by(|a, b| b.norm().total_cmp(&a.norm()));
    multipliers
}

/// The size of each unknown `u = (x0, T, p)` that the continuation
/// measures its steps in: the state as it is (rad, rad/s), the period in
/// Hopf periods and the load in Hopf loads (at least [`LOAD_SCALE_FLOOR`]).
/// In plain units a long chain's cycle near the onset (angles of 0.01 rad,
/// a period of 1000 s) weighs a change of its period by a second as much as
/// a change of its angles by a radian: the arclength equation all but
/// repeated the others (Newton's matrix had a singular value of 2e-7
/// against 51 at 16 rods), and the branch was lost there.
fn unknown_scales(point: &HopfPoint, d: usize) -> DVector<f64> {
    let hopf = &point.hopf;
    DVector::from_fn(d + 2, |i, _| match i {
        i if i < d => 1.0,
        i if i == d => std::f64::consts::TAU / hopf.frequency_rad_per_s,
        _ => hopf.load.abs().max(LOAD_SCALE_FLOOR),
    })
}

/// Where a branch whose last cycle is `cycles`' last stops for a reason
/// of its own (not the shooting's): it left `[load_min, load_max]`, grew
/// too large or too slow, has too many cycles, or the caller asked.
fn stop_reason(
    cycles: &[Cycle],
    (load_min, load_max): (f64, f64),
    hopf_period: f64,
    cancel: &AtomicBool,
) -> Option<BranchEnd> {
    let last = cycles.last()?;
    if !(load_min..=load_max).contains(&last.load) {
        Some(BranchEnd::LeftRange)
    } else if last.largest_amplitude_rad() > MAX_AMPLITUDE_RAD {
        Some(BranchEnd::LargeAmplitude)
    } else if last.period_secs > MAX_PERIOD_GROWTH * hopf_period {
        Some(BranchEnd::LongPeriod)
    } else if cycles.len() >= MAX_POINTS {
        Some(BranchEnd::PointLimit)
    } else if cancel.load(Ordering::Relaxed) {
        Some(BranchEnd::Cancelled)
    } else {
        None
    }
}

/// The branch of cycles born at the Hopf point `point` of `model`,
/// continued while its loads stay within `[load_min, load_max]`.
fn branch(
    model: &Model,
    point: &HopfPoint,
    name: String,
    (load_min, load_max): (f64, f64),
    cancel: &AtomicBool,
) -> Option<Branch> {
    let field = Field::new(&model.at_load(point.hopf.load));
    let shooting = Shooting {
        fastest_per_s: fastest_rate(&field),
        field,
    };
    let mut cycles = Vec::new();
    let mut monodromy = DMatrix::zeros(0, 0);
    for amplitude in START_AMPLITUDES_RAD {
        let solved = shooting.near_onset(point, amplitude)?;
        cycles.push(solved.cycle);
        monodromy = solved.monodromy;
    }
    let load_step_most = (load_max - load_min) / 40.0;
    let hopf_period = std::f64::consts::TAU / point.hopf.frequency_rad_per_s;
    let scales = unknown_scales(point, shooting.field.dimension());
    let scaled = |u: &DVector<f64>| u.component_div(&scales);
    let mut distance = {
        let [.., a, b] = cycles.as_slice() else {
            return None;
        };
        scaled(&(b.unknowns() - a.unknowns())).norm()
    };
    let end = loop {
        let [.., before, last] = cycles.as_slice() else {
            return None;
        };
        if let Some(end) = stop_reason(&cycles, (load_min, load_max), hopf_period, cancel) {
            break end;
        }
        // The step along the secant, in the scaled unknowns; the arclength
        // equation `direction . (u - predicted) / scales = 0`.
        let (u, previous) = (last.unknowns(), before.unknowns());
        let secant = scaled(&(&u - &previous));
        let direction = &secant / secant.norm();
        let load_rate = (direction[direction.len() - 1] * scales[scales.len() - 1]).abs();
        if load_rate * distance > load_step_most {
            distance = load_step_most / load_rate;
        }
        let predicted = &u + direction.component_mul(&scales) * distance;
        let tangent = direction.component_div(&scales);
        let constraint = Constraint::Arclength {
            tangent: &tangent,
            predicted: &predicted,
        };
        // Broyden's method from the last cycle's monodromy; where it fails,
        // a shorter step, and at the shortest the whole of `solve`.
        let shortest = distance <= 1e-6 * scaled(&u).norm().max(1.0);
        let solved =
            match shooting.newton(&predicted, &constraint, Update::Broyden(Some(&monodromy))) {
                None if !shortest => {
                    distance /= 3.0;
                    continue;
                }
                None => shooting.solve(&predicted, &constraint),
                solved => solved,
            };
        match solved {
            // A step far past the stick-slip bound is taken again shorter,
            // so that the branch ends next to the bound whatever the step.
            Some(solved)
                if !shortest
                    && shooting
                        .near_sticking(&solved.cycle, STICK_END_FRACTION * STICK_FRACTION) =>
            {
                distance /= 3.0;
            }
            Some(solved) if shooting.near_sticking(&solved.cycle, STICK_FRACTION) => {
                break BranchEnd::StickSlip { load: last.load };
            }
            // A step that turns the branch sharply may have jumped to
            // another part of it (or back along it): taken again shorter.
            Some(solved)
                if !shortest && {
                    let next = scaled(&(solved.cycle.unknowns() - &u));
                    next.dot(&direction) < MAX_TURN_COS * next.norm()
                } =>
            {
                distance /= 3.0;
            }
            Some(solved)
                if (solved.cycle.trivial_multiplier() - 1.0).norm() > TRIVIAL_TOLERANCE =>
            {
                break BranchEnd::Unresolved { load: last.load };
            }
            Some(solved) => {
                cycles.push(solved.cycle);
                monodromy = solved.monodromy;
                if solved.iterations <= GROW_ITERATIONS {
                    distance *= 1.5;
                }
            }
            None => break BranchEnd::Lost { load: last.load },
        }
    };
    Some(Branch {
        onset: point.clone(),
        name,
        cycles,
        end,
    })
}

/// Why no cycles were computed at a flutter onset (in words, as the
/// command line and the window say it after "flutter onset at p = ...: ").
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum NoBranch {
    /// The column is undamped (see [`crate::analysis::NoHopf`]).
    #[error("no damping, a reversible column: no limit cycle to follow")]
    Reversible,
    /// The first Lyapunov coefficient is zero within its accuracy.
    #[error("the first Lyapunov coefficient is zero within its accuracy; cycles not followed")]
    Degenerate,
    /// The shooting did not converge next to the onset.
    #[error("the shooting did not converge next to the onset; no cycles")]
    NotConverged,
}

/// A flutter onset or end and the cycles born there.
#[derive(Clone, Debug)]
pub struct Onset {
    pub load: f64,
    pub branch: Result<Branch, NoBranch>,
}

/// The cycles born at every flutter onset or end of `model` with a load in
/// `[load_min, load_max]`, each followed while its loads stay in that range.
/// Setting `cancel` ends the work early (the branches so far end
/// [`BranchEnd::Cancelled`]).
///
/// # Errors
/// A model that cannot be analysed.
pub fn cycle_branches(
    model: &Model,
    load_min: f64,
    load_max: f64,
    cancel: &AtomicBool,
) -> Result<Vec<Onset>, AnalysisError> {
    let pencil = AffinePencil::new(model)?;
    let mut branches = Vec::new();
    for t in critical_loads(&pencil, load_min, load_max)? {
        if !is_hopf(t.from, t.to) || cancel.load(Ordering::Relaxed) {
            continue;
        }
        let found = match hopf_point(model, t.load, HopfSteps::DEFAULT.into())? {
            Err(_) => Err(NoBranch::Reversible),
            Ok(point) if point.hopf.kind == HopfKind::Degenerate => Err(NoBranch::Degenerate),
            Ok(point) => {
                let name = format!("cycle-{}", branches.len() + 1);
                branch(model, &point, name, (load_min, load_max), cancel)
                    .ok_or(NoBranch::NotConverged)
            }
        };
        branches.push(Onset {
            load: t.load,
            branch: found,
        });
    }
    Ok(branches)
}

/// The cycles of `branch` at load `p`: one where each of its segments
/// crosses `p` (two where it folds back), each solved at exactly `p`;
/// between the Hopf point and the first computed cycle, from the normal
/// form's.
#[must_use]
pub fn cycles_at(model: &Model, branch: &Branch, p: f64) -> Vec<Cycle> {
    let field = Field::new(&model.at_load(branch.hopf().load));
    let shooting = Shooting {
        fastest_per_s: fastest_rate(&field),
        field,
    };
    let onset = branch.hopf().load;
    let near = branch.cycles.first().filter(|first| {
        let (lo, hi) = (onset.min(first.load), onset.max(first.load));
        lo < p && p < hi
    });
    let near_onset = near
        .and_then(|_| shooting.normal_form_cycle(&branch.onset, p))
        .map(|solved| solved.cycle);
    let along = branch.cycles.windows(2).filter_map(|pair| {
        let (a, b) = (&pair[0], &pair[1]);
        let (lo, hi) = (a.load.min(b.load), a.load.max(b.load));
        if !(lo..hi).contains(&p) {
            return None;
        }
        let t = if b.load == a.load {
            0.0
        } else {
            (p - a.load) / (b.load - a.load)
        };
        let guess = a.unknowns() * (1.0 - t) + b.unknowns() * t;
        shooting
            .solve(&guess, &Constraint::Load(p))
            .map(|solved| solved.cycle)
    });
    near_onset.into_iter().chain(along).collect()
}
