//! Limit cycles past a flutter onset: periodic orbits of the nonlinear
//! equations found by shooting, continued in the load from each Hopf point,
//! with their period, the amplitude of every angle and their Floquet
//! multipliers (stability).
//!
//! A cycle is a start `x0` on the reduced state (see `field`) and a period
//! `T` with `phi_T(x0) = x0`, `phi_T` the flow of the equations of motion.
//! The flow and its Jacobian (the monodromy matrix, from the variational
//! equations `Y' = A(x) Y`) are integrated together by the classical
//! fourth-order Runge-Kutta method at a fixed number of steps per period:
//! with `A` at every stage the monodromy is the exact derivative of the
//! computed flow (for the multipliers); Newton's iterations hold each
//! step's `A` over its stages (a quarter of the work, fast-linear
//! convergence to the same solution). Newton solves
//!
//! ```text
//! phi_T(x0; p) - x0 = 0                (d equations)
//! f(x_ref) . (x0 - x_ref) = 0          (phase: x0 on the plane through the
//!                                       last cycle, across its flow)
//! p = p_target  or  t . (u - u_pred) = 0   (fixed load, or pseudo-arclength)
//! ```
//!
//! for `u = (x0, T, p)`. A branch starts at the normal form's cycle near its
//! Hopf point (`hopf`) and is followed by pseudo-arclength continuation,
//! which passes folds (a hard onset's unstable cycle turning into the large
//! stable one). The multipliers are the monodromy's eigenvalues: one is 1
//! (the shift along the orbit); the cycle is stable when every other one
//! lies inside the unit circle. Pure: no UI, no clock.

use std::sync::atomic::{AtomicBool, Ordering};

use nalgebra::{DMatrix, DVector};

use super::field::Field;
use super::hopf::{HopfPoint, Steps as HopfSteps, hopf_point};
use super::{AffinePencil, AnalysisError, C64, Hopf, HopfKind, critical_loads, is_hopf};
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
/// A cycle is resolved when its trivial multiplier is within this of 1.
pub const TRIVIAL_TOLERANCE: f64 = 1e-6;

/// Fewest Runge-Kutta steps per period.
const MIN_STEPS: u32 = 800;
/// The step times the spectral radius of the Jacobian at rest stays below
/// this: fast, strongly damped modes (a chain's highest, the roller's spin)
/// stay resolved and stable.
const FAST_MODE_STEP: f64 = 0.3;
/// The first cycles' amplitudes, rad: small enough for the normal form to be
/// a good first guess, large enough for a well conditioned shooting.
const START_AMPLITUDES_RAD: [f64; 3] = [0.003, 0.006, 0.012];
/// Newton iterations for one cycle.
const NEWTON_ITERATIONS: usize = 12;

/// The flow over one period from `x0` with `steps` Runge-Kutta steps: the
/// end point, the largest `|phi_i|` on the way, and (when asked) the monodromy.
struct Orbit {
    end: DVector<f64>,
    amplitude_rad: Vec<f64>,
    monodromy: Option<DMatrix<f64>>,
    closest_slip_m_per_s: Option<f64>,
}

/// Difference step of the Jacobian in the variational equations.
const JACOBIAN_STEP: f64 = 1e-7;

/// How the flow's Jacobian (the monodromy) is integrated.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Monodromy {
    /// Not at all: the end point only.
    None,
    /// The field's Jacobian at every Runge-Kutta stage: the exact derivative
    /// of the computed flow (for the multipliers).
    Exact,
    /// The Jacobian once per step, held over its stages: a quarter of the
    /// work, off by the step's change of the Jacobian, which slows Newton's
    /// convergence from quadratic to fast linear but not where it ends.
    HeldPerStep,
}

fn flow(
    field: &Field,
    x0: &DVector<f64>,
    period: f64,
    steps: usize,
    monodromy: Monodromy,
) -> Orbit {
    let d = x0.len();
    #[expect(clippy::cast_precision_loss, reason = "a step count")]
    let h = period / steps as f64;
    let mut x = x0.clone();
    let mut y = (monodromy != Monodromy::None).then(|| DMatrix::<f64>::identity(d, d));
    let rods = field.rods();
    let mut peaks = Peaks::new(&x0.as_slice()[..rods]);
    let mut closest_slip_m_per_s = field.slip_m_per_s(x0);
    for _ in 0..steps {
        let k1 = field.at(&x);
        let x2 = &x + &k1 * (h / 2.0);
        let k2 = field.at(&x2);
        let x3 = &x + &k2 * (h / 2.0);
        let k3 = field.at(&x3);
        let x4 = &x + &k3 * h;
        let k4 = field.at(&x4);
        if let Some(y) = y.as_mut() {
            let jacobian = |at: &DVector<f64>| field.jacobian(at, JACOBIAN_STEP);
            let a1 = jacobian(&x);
            let [a2, a3, a4] = match monodromy {
                Monodromy::Exact => [jacobian(&x2), jacobian(&x3), jacobian(&x4)],
                Monodromy::HeldPerStep | Monodromy::None => [a1.clone(), a1.clone(), a1.clone()],
            };
            let m1 = &a1 * &*y;
            let m2 = a2 * (&*y + &m1 * (h / 2.0));
            let m3 = a3 * (&*y + &m2 * (h / 2.0));
            let m4 = a4 * (&*y + &m3 * h);
            *y += (m1 + (m2 + m3) * 2.0 + m4) * (h / 6.0);
        }
        x += (k1 + (k2 + k3) * 2.0 + k4) * (h / 6.0);
        peaks.push(&x.as_slice()[..rods]);
        if let (Some(closest), Some(slip)) = (closest_slip_m_per_s.as_mut(), field.slip_m_per_s(&x))
        {
            *closest = closest.min(slip);
        }
    }
    Orbit {
        end: x,
        amplitude_rad: peaks.largest,
        monodromy: y,
        closest_slip_m_per_s,
    }
}

/// The largest `|v_i|` of each of several quantities along evenly spaced
/// samples (a swing's angles), each local peak refined by the parabola
/// through it and its neighbours: a sine sampled n times a period is read
/// to about `(pi/n)^4` instead of `(pi/n)^2 / 2`.
#[derive(Clone, Debug)]
pub struct Peaks {
    last: Vec<[f64; 2]>,
    largest: Vec<f64>,
}

impl Peaks {
    /// Starting from the first samples `values`.
    #[must_use]
    pub fn new(values: &[f64]) -> Self {
        Self {
            last: values.iter().map(|v| [v.abs(); 2]).collect(),
            largest: values.iter().map(|v| v.abs()).collect(),
        }
    }

    /// The largest `|v_i|` so far.
    #[must_use]
    pub fn largest(&self) -> &[f64] {
        &self.largest
    }

    /// The next samples.
    pub fn push(&mut self, values: &[f64]) {
        for ((last, largest), value) in self.last.iter_mut().zip(&mut self.largest).zip(values) {
            let [a, b] = *last;
            let c = value.abs();
            let mut top = b.max(c);
            if b >= a && b >= c {
                let curvature = a - 2.0 * b + c;
                if curvature < 0.0 {
                    top = top.max(b - (c - a).powi(2) / (8.0 * curvature));
                }
            }
            *largest = largest.max(top);
            *last = [b, c];
        }
    }
}

/// Runge-Kutta steps for one period of `period` of a field whose Jacobian
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
    /// with its Newton iterations, or `None` where Newton fails: first with
    /// each step's Jacobian held over its stages, then, where that fails
    /// (its slower convergence runs out of iterations on a hard stretch),
    /// with the exact monodromy.
    fn solve(&self, guess: &DVector<f64>, constraint: &Constraint) -> Option<(Cycle, usize)> {
        self.newton(guess, constraint, Monodromy::HeldPerStep)
            .or_else(|| self.newton(guess, constraint, Monodromy::Exact))
    }

    /// [`Self::solve`] with the monodromy of the iterations taken as `monodromy`.
    fn newton(
        &self,
        guess: &DVector<f64>,
        constraint: &Constraint,
        monodromy: Monodromy,
    ) -> Option<(Cycle, usize)> {
        let d = self.field.dimension();
        let reference = guess.rows(0, d).into_owned();
        let reference_flow = self.field.at_load(guess[d + 1]).at(&reference);
        let mut u = guess.clone();
        for iteration in 1..=NEWTON_ITERATIONS {
            let (x0, period, load) = (u.rows(0, d).into_owned(), u[d], u[d + 1]);
            if !(period > 0.0 && load >= 0.0 && u.iter().all(|v| v.is_finite())) {
                return None;
            }
            let field = self.field.at_load(load);
            let (orbit, steps) = self.orbit(&field, &x0, period, monodromy);
            let monodromy = orbit.monodromy?;
            let mut jacobian = DMatrix::<f64>::zeros(d + 2, d + 2);
            let mut residual = DVector::<f64>::zeros(d + 2);
            jacobian
                .view_mut((0, 0), (d, d))
                .copy_from(&(&monodromy - DMatrix::identity(d, d)));
            jacobian
                .view_mut((0, d), (d, 1))
                .copy_from(&field.at(&orbit.end));
            residual.rows_mut(0, d).copy_from(&(&orbit.end - &x0));
            jacobian
                .view_mut((d, 0), (1, d))
                .copy_from(&reference_flow.transpose());
            residual[d] = reference_flow.dot(&(&x0 - &reference));
            match constraint {
                Constraint::Load(target) => {
                    jacobian[(d + 1, d + 1)] = 1.0;
                    residual[d + 1] = load - target;
                }
                Constraint::Arclength { tangent, predicted } => {
                    let delta = 1e-6 * load.abs().max(1e-3);
                    let ends = [load + delta, load - delta].map(|p| {
                        flow(&self.field.at_load(p), &x0, period, steps, Monodromy::None).end
                    });
                    jacobian
                        .view_mut((0, d + 1), (d, 1))
                        .copy_from(&((&ends[0] - &ends[1]) / (2.0 * delta)));
                    jacobian
                        .view_mut((d + 1, 0), (1, d + 2))
                        .copy_from(&tangent.transpose());
                    residual[d + 1] = tangent.dot(&(&u - *predicted));
                }
            }
            let step = jacobian.lu().solve(&residual)?;
            u -= &step;
            let size = u.amax().max(1.0);
            if step.amax() <= 1e-11 * size {
                return Some((self.cycle(&u)?, iteration));
            }
        }
        None
    }

    /// The cycle at the converged unknowns `u`, with its multipliers.
    fn cycle(&self, u: &DVector<f64>) -> Option<Cycle> {
        let d = self.field.dimension();
        let (x0, period, load) = (u.rows(0, d).into_owned(), u[d], u[d + 1]);
        let (orbit, _) = self.orbit(&self.field.at_load(load), &x0, period, Monodromy::Exact);
        let multipliers = sorted_multipliers(&orbit.monodromy?);
        let trivial = trivial_index(&multipliers)?;
        let stable = multipliers
            .iter()
            .enumerate()
            .all(|(i, m)| i == trivial || m.norm() < 1.0);
        Some(Cycle {
            load,
            period_secs: period,
            start: x0,
            amplitude_rad: orbit.amplitude_rad,
            multipliers,
            stable,
            closest_slip_m_per_s: orbit.closest_slip_m_per_s,
        })
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
    ) -> (Orbit, usize) {
        let steps = steps_for(period, self.fastest_per_s);
        let orbit = flow(field, x0, period, steps, monodromy);
        let slowed = match (orbit.closest_slip_m_per_s, field.band_speed_m_per_s()) {
            (Some(slip), Some(band)) if slip > 0.0 && slip < band => band / slip,
            _ => return (orbit, steps),
        };
        let needed = steps_for(period, self.fastest_per_s * slowed);
        if needed > steps {
            (flow(field, x0, period, needed, monodromy), needed)
        } else {
            (orbit, steps)
        }
    }

    /// Whether the roller's contact comes near sticking on `cycle`.
    fn near_sticking(&self, cycle: &Cycle) -> bool {
        match (cycle.closest_slip_m_per_s, self.field.band_speed_m_per_s()) {
            (Some(slip), Some(band)) => slip < STICK_FRACTION * band,
            _ => false,
        }
    }

    /// The cycle whose largest angle's amplitude is about `amplitude_rad`
    /// by the normal form of the Hopf point `point`, on the side where
    /// cycles exist.
    fn near_onset(&self, point: &HopfPoint, amplitude_rad: f64) -> Option<Cycle> {
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
    fn normal_form_cycle(&self, point: &HopfPoint, load: f64) -> Option<Cycle> {
        let hopf = &point.hopf;
        let radius = point.radius_per_sqrt_load * (load - hopf.load).abs().sqrt();
        let d = self.field.dimension();
        let guess = DVector::from_fn(d + 2, |i, _| match i {
            i if i < d => 2.0 * radius * point.eigenvector[i].re,
            i if i == d => std::f64::consts::TAU / hopf.frequency_rad_per_s,
            _ => load,
        });
        self.solve(&guess, &Constraint::Load(load))
            .map(|(cycle, _)| cycle)
    }
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
    for amplitude in START_AMPLITUDES_RAD {
        cycles.push(shooting.near_onset(point, amplitude)?);
    }
    let load_step_most = (load_max - load_min) / 40.0;
    let hopf_period = std::f64::consts::TAU / point.hopf.frequency_rad_per_s;
    let mut distance = {
        let [.., a, b] = cycles.as_slice() else {
            return None;
        };
        (b.unknowns() - a.unknowns()).norm()
    };
    let end = loop {
        let [.., before, last] = cycles.as_slice() else {
            return None;
        };
        if !(load_min..=load_max).contains(&last.load) {
            break BranchEnd::LeftRange;
        }
        if last.largest_amplitude_rad() > MAX_AMPLITUDE_RAD {
            break BranchEnd::LargeAmplitude;
        }
        if last.period_secs > MAX_PERIOD_GROWTH * hopf_period {
            break BranchEnd::LongPeriod;
        }
        if cycles.len() >= MAX_POINTS {
            break BranchEnd::PointLimit;
        }
        if cancel.load(Ordering::Relaxed) {
            break BranchEnd::Cancelled;
        }
        let (u, previous) = (last.unknowns(), before.unknowns());
        let secant = &u - &previous;
        let tangent = &secant / secant.norm();
        let load_rate = tangent[tangent.len() - 1].abs();
        if load_rate * distance > load_step_most {
            distance = load_step_most / load_rate;
        }
        let predicted = &u + &tangent * distance;
        let constraint = Constraint::Arclength {
            tangent: &tangent,
            predicted: &predicted,
        };
        match shooting.solve(&predicted, &constraint) {
            Some((cycle, _)) if shooting.near_sticking(&cycle) => {
                break BranchEnd::StickSlip { load: last.load };
            }
            Some((cycle, _)) if (cycle.trivial_multiplier() - 1.0).norm() > TRIVIAL_TOLERANCE => {
                break BranchEnd::Unresolved { load: last.load };
            }
            Some((cycle, iterations)) => {
                cycles.push(cycle);
                if iterations <= 6 {
                    distance *= 1.5;
                }
            }
            None if distance > 1e-6 * u.norm().max(1.0) => distance /= 3.0,
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
    /// The column is undamped (see [`super::NoHopf`]).
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
    let near_onset = near.and_then(|_| shooting.normal_form_cycle(&branch.onset, p));
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
            .map(|(cycle, _)| cycle)
    });
    near_onset.into_iter().chain(along).collect()
}
