//! Time simulation of the nonlinear column: two engines behind one interface,
//! the observables of each step, and identification of eigenvalues from a run.

mod identify;
mod observe;
mod ramp;
mod rapier;
mod reference;
mod sweep;

pub use identify::identify;
pub use observe::{Observables, observe};
pub use ramp::{LONGEST_RAMP_SECS, Ramp, RampError, SLOWEST_RATE_P_PER_S};
pub use reference::{Advance, MAX_STEPS_PER_ADVANCE, Reference};
pub use sweep::{FLOOR_KICK_RAD, START_KICK_RAD, SweepStep, SweepTimes, sweep};

use crate::model::{
    Allowed, AsValid, Model, ModelError, Quantity, StateVec, StateView, StateViewMut, ValidModel,
    chain_mass_matrix, joint_matrices, joints_m, rest_state, state_derivative, state_len,
};
use std::ops::ControlFlow;

/// The app's simulation step: small against the fastest column period of
/// the presets (about 5 s) and the roller's spin time constant at p = 1.
pub const DEFAULT_STEP_SECS: f64 = 1.0 / 240.0;

/// Simulated seconds per wall-clock second a run may be shown at.
pub const SPEED_RANGE: std::ops::RangeInclusive<f64> = 0.1..=10.0;

/// A run stops when an angle of the column leaves this range (about 160
/// turns: a column spinning round under a huge load)...
pub const MAX_ANGLE_RAD: f64 = 1.0e3;
/// ... or a rate leaves this one.
pub const MAX_RATE_RAD_PER_S: f64 = 1.0e6;
/// The rapier engine's fixed step resolves a rod turning at most this much
/// per step; a run turning faster stops with [`Status::TooFast`].
pub const MAX_TURN_PER_STEP_RAD: f64 = 0.5;

/// Which engine advances the state.
#[derive(
    Clone,
    Copy,
    Debug,
    PartialEq,
    Eq,
    serde::Serialize,
    serde::Deserialize,
    strum::VariantArray,
    strum::IntoStaticStr,
)]
#[strum(serialize_all = "lowercase")]
pub enum EngineKind {
    /// rapier2d multibody with explicit forces and an implicit spin (the app's).
    Rapier,
    /// Adaptive Dormand-Prince 5(4) on the exact equations (f64).
    Reference,
}

impl EngineKind {
    /// The engine's name, as the command line and the settings text write it.
    #[must_use]
    pub fn name(self) -> &'static str {
        self.into()
    }

    /// The engine named `name`, if one is.
    #[must_use]
    pub fn named(name: &str) -> Option<Self> {
        crate::names::variant_named(name)
    }
}

/// Whether a run goes on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Status {
    Running,
    /// The state left finite bounds; the run stopped at this time.
    Diverged {
        t_secs: f64,
    },
    /// The reference integrator needed more than its budget of steps for one
    /// step of the run (a stiff case); the run stopped at this time.
    TooStiff {
        t_secs: f64,
    },
    /// The rapier engine's fixed step no longer resolves the motion: the
    /// column turned faster than [`MAX_TURN_PER_STEP_RAD`] per step (a
    /// column whirling round under a huge load).
    TooFast {
        t_secs: f64,
        rate_rad_per_s: f64,
    },
}

impl std::fmt::Display for Status {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Running => write!(f, "running"),
            Self::Diverged { t_secs } => write!(f, "diverged at t = {t_secs:.3} s"),
            Self::TooStiff { t_secs } => write!(
                f,
                "too stiff for the reference integrator at t = {t_secs:.3} s: a very light roller or a stopped band (the rapier engine handles those), or a load or stiffness so large that no step resolves the column's rates"
            ),
            Self::TooFast {
                t_secs,
                rate_rad_per_s,
            } => write!(
                f,
                "too fast for the rapier engine at t = {t_secs:.3} s: the column turns at {rate_rad_per_s:.0} rad/s, more than its fixed step resolves ({MAX_TURN_PER_STEP_RAD} rad per step); the reference engine follows it"
            ),
        }
    }
}

#[derive(Debug)]
enum Engine {
    Rapier(Box<rapier::RapierEngine>),
    Reference(Reference),
}

/// A run of the nonlinear column. The model can change between steps (the
/// next step uses it); the same inputs give a bit-identical run.
#[derive(Debug)]
pub struct Simulation {
    model: ValidModel,
    engine: Engine,
    step_secs: f64,
    /// Steps taken: the time is `steps * step_secs`, free of accumulated rounding.
    steps: u64,
    status: Status,
}

/// Why a simulation cannot start.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SimError {
    #[error(transparent)]
    Model(#[from] ModelError),
    #[error("{what} = {}: {allowed}", crate::model::Shown(*.value))]
    Bad {
        what: Quantity,
        value: f64,
        allowed: Allowed,
    },
    #[error(
        "the rapier engine cannot integrate this column at dt = {step_secs:.3e} s: its springs and dampers reach rates of {rate_per_s:.3e} 1/s, which need dt < {:.3e} s; use the reference engine",
        RAPIER_MAX_RATE_STEP / rate_per_s
    )]
    TooStiffForRapier { rate_per_s: f64, step_secs: f64 },
    #[error(
        "the rapier2d world could not be built for this column (its joints were refused); use the reference engine"
    )]
    RapierWorld,
}

/// The perturbation a run starts from when the number of rods changes, in rad.
const CHAIN_CHANGE_PERTURBATION_RAD: f64 = 1e-3;

impl SimError {
    /// The parameter (or argument) the error is about, when it is about one.
    #[must_use]
    pub fn parameter(&self) -> Option<&str> {
        match self {
            Self::Model(error) => error.parameter(),
            Self::Bad { what, .. } => Some(what.name()),
            Self::TooStiffForRapier { .. } => Some("dt"),
            Self::RapierWorld => None,
        }
    }
}

/// The rapier engine applies the joints' springs and dampers explicitly
/// (symplectic Euler), which is stable while the column's fastest own rate
/// times the step stays below 2 (oscillation: omega dt < 2; damping:
/// c dt / I < 2); runs are refused from half that, with the rate bounded
/// from above.
pub const RAPIER_MAX_RATE_STEP: f64 = 1.0;

/// An upper bound on the fastest rate of the column's own springs and
/// dampers about the straight column, in 1/s: `sqrt(|M^-1 K|) + |M^-1 D|`
/// with Frobenius norms (each bounds the spectral radius). The load is left
/// out: a load beyond the critical one makes the column diverge in fact, and
/// the run says so.
#[must_use]
pub fn column_rate_bound_per_s(model: &Model) -> f64 {
    let Some(inverse) = chain_mass_matrix(model).try_inverse() else {
        return f64::INFINITY;
    };
    let (stiffness, damping) = joint_matrices(&model.column);
    (&inverse * stiffness).norm().sqrt() + (&inverse * damping).norm()
}

/// Refuses a rapier run whose step is too long for the column's own rates.
fn check_rapier_step(model: &Model, step_secs: f64) -> Result<(), SimError> {
    let rate_per_s = column_rate_bound_per_s(model);
    if rate_per_s * step_secs > RAPIER_MAX_RATE_STEP {
        return Err(SimError::TooStiffForRapier {
            rate_per_s,
            step_secs,
        });
    }
    Ok(())
}

/// The standard start: every rod's angle `perturb_rad`, at rest (a massless
/// roller spins at its slaved rate, so the state is consistent).
#[must_use]
pub fn initial_state(model: &Model, perturb_rad: f64) -> StateVec {
    let mut x = rest_state(&model.column);
    StateViewMut::new(&mut x).angles_rad().fill(perturb_rad);
    if model.roller().is_some_and(|roller| roller.mass_kg == 0.0) {
        // psi' is slaved: state_derivative returns it as d(psi)/dt.
        let slaved = StateView::new(&state_derivative(model, &x)).spin_rad();
        *StateViewMut::new(&mut x).spin_rate_rad_per_s() = slaved;
    }
    x
}

#[expect(
    clippy::cast_precision_loss,
    reason = "step counts stay far below 2^52"
)]
fn time_of(steps: u64, step_secs: f64) -> f64 {
    steps as f64 * step_secs
}

fn within_bounds(x: &StateVec) -> bool {
    let half = x.len() / 2;
    x.iter().all(|v| v.is_finite())
        && x.rows(0, half - 1).iter().all(|v| v.abs() <= MAX_ANGLE_RAD)
        && x.rows(half, half)
            .iter()
            .all(|v| v.abs() <= MAX_RATE_RAD_PER_S)
}

impl Simulation {
    /// The engine that advances this run.
    #[must_use]
    pub fn engine(&self) -> EngineKind {
        match self.engine {
            Engine::Rapier(_) => EngineKind::Rapier,
            Engine::Reference(_) => EngineKind::Reference,
        }
    }

    /// Goes on from state `x` with engine `kind` (a kick, a change of
    /// engine): the time and the model are kept, a stopped run runs again.
    ///
    /// # Errors
    /// As [`Simulation::new`]; the run is then unchanged.
    pub fn restart_from(&mut self, kind: EngineKind, x: StateVec) -> Result<(), SimError> {
        let fresh = Self::new(self.model, kind, x, self.step_secs)?;
        let t_secs = self.time_secs();
        self.engine = fresh.engine;
        if let Engine::Reference(engine) = &mut self.engine {
            engine.t_secs = t_secs;
        }
        self.status = Status::Running;
        Ok(())
    }

    /// A run of `model` from state `x0`, advancing `step_secs` per step.
    ///
    /// # Errors
    /// An invalid model, or a step that is not a positive finite time.
    pub fn new(
        model: impl AsValid,
        kind: EngineKind,
        x0: StateVec,
        step_secs: f64,
    ) -> Result<Self, SimError> {
        let model = model.into_valid()?;
        if x0.len() != state_len(model.column.rods) {
            #[expect(clippy::cast_precision_loss, reason = "a state's length")]
            return Err(SimError::Bad {
                what: Quantity::StateLength,
                value: x0.len() as f64,
                allowed: Allowed::StateLength,
            });
        }
        if !(step_secs.is_finite() && step_secs > 0.0 && step_secs <= 1.0) {
            return Err(SimError::Bad {
                what: Quantity::TimeStep,
                value: step_secs,
                allowed: Allowed::TimeStep,
            });
        }
        let engine = match kind {
            EngineKind::Rapier => Engine::Rapier(Box::new({
                check_rapier_step(&model, step_secs)?;
                rapier::RapierEngine::new(&model, &x0, step_secs).ok_or(SimError::RapierWorld)?
            })),
            EngineKind::Reference => Engine::Reference(Reference::new(x0)),
        };
        Ok(Self {
            model,
            engine,
            step_secs,
            steps: 0,
            status: Status::Running,
        })
    }

    /// The model the next step uses.
    #[must_use]
    pub fn model(&self) -> &Model {
        self.model.model()
    }

    /// The model the next step uses, as checked when it was given: the
    /// analysis takes it without checking it again.
    #[must_use]
    pub fn valid_model(&self) -> &ValidModel {
        &self.model
    }

    /// Replaces the model for the next steps, without a reset.
    ///
    /// # Errors
    /// An invalid model, or one too stiff for the rapier engine at this step
    /// (the run keeps its previous one).
    pub fn set_model(&mut self, model: impl AsValid) -> Result<(), SimError> {
        let model = model.into_valid()?;
        if model.column.rods != self.model.column.rods {
            // Another chain needs another state: it starts afresh from the
            // standard perturbation.
            let previous = std::mem::replace(&mut self.model, model);
            let x = initial_state(&model, CHAIN_CHANGE_PERTURBATION_RAD);
            if let Err(error) = self.restart_from(self.engine(), x) {
                self.model = previous;
                return Err(error);
            }
            return Ok(());
        }
        if self.engine() == EngineKind::Rapier {
            check_rapier_step(&model, self.step_secs)?;
        }
        self.model = model;
        Ok(())
    }

    #[must_use]
    pub fn status(&self) -> Status {
        self.status
    }

    #[must_use]
    pub fn step_secs(&self) -> f64 {
        self.step_secs
    }

    /// The current state (see [`StateVec`]).
    #[must_use]
    pub fn state(&self) -> StateVec {
        match &self.engine {
            Engine::Rapier(engine) => engine.state(),
            Engine::Reference(engine) => engine.x.clone(),
        }
    }

    /// The joints from the clamp to the tip now, in m.
    #[must_use]
    pub fn joints_m(&self) -> Vec<[f64; 2]> {
        joints_m(&self.model.column, &self.state())
            .iter()
            .map(|p| [p.x, p.y])
            .collect()
    }

    /// Simulated time.
    #[must_use]
    pub fn time_secs(&self) -> f64 {
        time_of(self.steps, self.step_secs)
    }

    /// The observables now.
    #[must_use]
    pub fn observe(&self) -> Observables {
        observe(&self.model, self.time_secs(), &self.state())
    }

    /// Advances one step; nothing happens once the run has diverged.
    pub fn step(&mut self) -> Status {
        if self.status != Status::Running {
            return self.status;
        }
        let end = time_of(self.steps + 1, self.step_secs);
        let advance = match &mut self.engine {
            Engine::Rapier(engine) => {
                if engine.step(&self.model).is_some() {
                    Advance::Reached
                } else {
                    Advance::Collapsed
                }
            }
            Engine::Reference(engine) => engine.advance_to(&self.model, end),
        };
        if advance == Advance::Reached {
            self.steps += 1;
        }
        let t_secs = self.time_secs();
        let x = self.state();
        let n = self.model.column.rods;
        let rate_rad_per_s = x.rows(n + 1, n).amax();
        let too_fast = self.engine() == EngineKind::Rapier
            && rate_rad_per_s * self.step_secs > MAX_TURN_PER_STEP_RAD;
        self.status = match advance {
            Advance::Reached if too_fast && within_bounds(&x) => Status::TooFast {
                t_secs,
                rate_rad_per_s,
            },
            Advance::Reached if within_bounds(&x) => Status::Running,
            // Diverged means the state grew past its bounds; a step size that
            // collapsed while the state is bounded is stiffness.
            Advance::Collapsed if within_bounds(&x) && self.engine() == EngineKind::Reference => {
                Status::TooStiff { t_secs }
            }
            Advance::Reached | Advance::Collapsed => Status::Diverged { t_secs },
            Advance::TooStiff => Status::TooStiff { t_secs },
        };
        self.status
    }

    /// Advances whole steps until `duration_secs` more have passed (or the
    /// run diverges), calling `each` with the observables after every step.
    pub fn run(&mut self, duration_secs: f64, mut each: impl FnMut(&Observables)) -> Status {
        self.run_while(duration_secs, |o| {
            each(o);
            ControlFlow::Continue(())
        })
    }

    /// [`Self::run`], stopping early after a step where `each` says
    /// [`ControlFlow::Break`] (a reader that went away).
    pub fn run_while(
        &mut self,
        duration_secs: f64,
        mut each: impl FnMut(&Observables) -> ControlFlow<()>,
    ) -> Status {
        let end = self.time_secs() + duration_secs;
        while self.time_secs() < end - 0.5 * self.step_secs {
            if self.step() != Status::Running || each(&self.observe()).is_break() {
                break;
            }
        }
        self.status
    }
}
