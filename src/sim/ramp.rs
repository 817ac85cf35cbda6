//! The quasi-static load ramp: the load moving from one value to another at
//! a constant rate in simulated time (the paper's "force increasing
//! quasi-statically from zero"), and a run that follows it step by step.

use super::{Observables, SimError, Simulation, Status};
use crate::format::Shown;
use crate::model::{Model, ModelError};
use std::ops::ControlFlow;

/// Why a ramp is refused; each names the end or the rate at fault.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum RampError {
    /// An end that is not a load.
    #[error("ramp {end} = {}: must be a load p >= 0", Shown(*.value))]
    End { end: &'static str, value: f64 },
    /// A rate that is not a positive load per second.
    #[error("ramp rate = {}: must be a positive load per second", Shown(*.0))]
    Rate(f64),
    /// A rate so slow that the load would not visibly move.
    #[error(
        "ramp rate = {}: must be at least {} load per second (slower, the load would not move visibly within days)",
        Shown(*.0),
        Shown(SLOWEST_RATE_P_PER_S)
    )]
    TooSlow(f64),
    /// A ramp longer than any run watched.
    #[error(
        "ramp from {} to {} at {} per second takes {} s of simulated time; at most {} s (about four months): a faster rate or nearer ends",
        Shown(*from_p),
        Shown(*to_p),
        Shown(*rate_p_per_s),
        crate::format::number_text(*secs),
        Shown(LONGEST_RAMP_SECS)
    )]
    TooLong {
        from_p: f64,
        to_p: f64,
        rate_p_per_s: f64,
        secs: f64,
    },
    /// An end the model does not take, with the model's reason.
    #[error("ramp {end} = {}: {why}", Shown(*.value))]
    Refused {
        end: &'static str,
        value: f64,
        why: ModelError,
    },
    /// Text that is not `FROM:TO:RATE`.
    #[error("'{0}': must be FROM:TO:RATE (loads p and p per second, e.g. 0:4:0.05)")]
    Form(String),
    /// A part of `FROM:TO:RATE` that is not a number.
    #[error("ramp {part} '{text}' is not a number")]
    NotANumber { part: &'static str, text: String },
}

/// The slowest ramp, in load p per second: a chain's load bar of 0.008
/// (64 rods) takes about two hours at this rate, the two-rod bar of 8
/// three months.
pub const SLOWEST_RATE_P_PER_S: f64 = 1e-6;

/// The longest ramp, in simulated seconds (about four months).
pub const LONGEST_RAMP_SECS: f64 = 1e7;

/// A load ramp: `p` from `from_p` toward `to_p` at `rate_p_per_s` (> 0) per
/// simulated second, then held at `to_p`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ramp {
    pub from_p: f64,
    pub to_p: f64,
    pub rate_p_per_s: f64,
}

impl Ramp {
    /// The ramp, when its ends are loads and its rate a positive number.
    ///
    /// # Errors
    /// A negative or non-finite end, or a rate that is not positive and finite.
    pub fn new(from_p: f64, to_p: f64, rate_p_per_s: f64) -> Result<Self, RampError> {
        for (end, value) in [("from", from_p), ("to", to_p)] {
            if !(value.is_finite() && value >= 0.0) {
                return Err(RampError::End { end, value });
            }
        }
        if !(rate_p_per_s.is_finite() && rate_p_per_s > 0.0) {
            return Err(RampError::Rate(rate_p_per_s));
        }
        if rate_p_per_s < SLOWEST_RATE_P_PER_S {
            return Err(RampError::TooSlow(rate_p_per_s));
        }
        Ok(Self {
            from_p,
            to_p,
            rate_p_per_s,
        })
    }

    /// Whether `model` takes every load of the ramp: both ends (the loads
    /// between them are in between), so a ramp is refused before its run,
    /// not when it reaches a load the model cannot take; and whether it
    /// ends within [`LONGEST_RAMP_SECS`].
    ///
    /// # Errors
    /// The end the model refuses, with the model's reason, or a ramp too long.
    pub fn check_for(&self, model: &Model) -> Result<(), RampError> {
        for (end, value) in [("from", self.from_p), ("to", self.to_p)] {
            model
                .at_load(value)
                .validate()
                .map_err(|why| RampError::Refused { end, value, why })?;
        }
        let secs = self.duration_secs();
        if secs > LONGEST_RAMP_SECS {
            return Err(RampError::TooLong {
                from_p: self.from_p,
                to_p: self.to_p,
                rate_p_per_s: self.rate_p_per_s,
                secs,
            });
        }
        Ok(())
    }

    /// The load `elapsed_secs` after the ramp started (`from_p` before it).
    #[must_use]
    pub fn load_at(&self, elapsed_secs: f64) -> f64 {
        let moved = self.rate_p_per_s * elapsed_secs.max(0.0);
        if self.to_p >= self.from_p {
            (self.from_p + moved).min(self.to_p)
        } else {
            (self.from_p - moved).max(self.to_p)
        }
    }

    /// Simulated seconds from `from_p` to `to_p`.
    #[must_use]
    pub fn duration_secs(&self) -> f64 {
        (self.to_p - self.from_p).abs() / self.rate_p_per_s
    }
}

impl std::str::FromStr for Ramp {
    type Err = RampError;

    /// `FROM:TO:RATE`, e.g. `0:4:0.05` (loads p, rate in p per second).
    fn from_str(text: &str) -> Result<Self, RampError> {
        let parts: Vec<&str> = text.split(':').collect();
        let [from, to, rate] = parts.as_slice() else {
            return Err(RampError::Form(text.to_owned()));
        };
        let number = |name: &'static str, part: &str| {
            part.trim()
                .parse::<f64>()
                .map_err(|_| RampError::NotANumber {
                    part: name,
                    text: (*part).to_owned(),
                })
        };
        Self::new(
            number("from", from)?,
            number("to", to)?,
            number("rate", rate)?,
        )
    }
}

impl Simulation {
    /// Runs `duration_secs` with the load following `ramp` from now, set
    /// before every step; `each` gets the observables and the load of the
    /// step just taken.
    ///
    /// # Errors
    /// A load the engine cannot take (the run stops there).
    pub fn run_ramp(
        &mut self,
        ramp: &Ramp,
        duration_secs: f64,
        mut each: impl FnMut(&Observables, f64),
    ) -> Result<Status, SimError> {
        self.run_ramp_while(ramp, duration_secs, |o, load| {
            each(o, load);
            ControlFlow::Continue(())
        })
    }

    /// [`Self::run_ramp`], stopping early after a step where `each` says
    /// [`ControlFlow::Break`].
    ///
    /// # Errors
    /// A load the engine cannot take (the run stops there).
    pub fn run_ramp_while(
        &mut self,
        ramp: &Ramp,
        duration_secs: f64,
        mut each: impl FnMut(&Observables, f64) -> ControlFlow<()>,
    ) -> Result<Status, SimError> {
        let start = self.time_secs();
        let end = start + duration_secs;
        while self.time_secs() < end - 0.5 * self.step_secs() {
            let load = ramp.load_at(self.time_secs() - start);
            let model = self.model().at_load(load);
            self.set_model(model)?;
            if self.step() != Status::Running || each(&self.observe(), load).is_break() {
                break;
            }
        }
        Ok(self.status())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_ramp_moves_at_its_rate_and_holds_at_its_end() {
        let up: Ramp = "1:3:0.5".parse().unwrap();
        assert_eq!(up.load_at(-1.0), 1.0);
        assert_eq!(up.load_at(2.0), 2.0);
        assert_eq!(up.load_at(10.0), 3.0);
        assert_eq!(up.duration_secs(), 4.0);
        let down: Ramp = "3:1:0.5".parse().unwrap();
        assert_eq!(down.load_at(2.0), 2.0);
        assert_eq!(down.load_at(10.0), 1.0);
        for bad in [
            "1:2", "a:2:1", "0:2:0", "0:2:-1", "-1:2:1", "0:inf:1", "0:2:NaN",
        ] {
            assert!(bad.parse::<Ramp>().is_err(), "{bad}");
        }
    }
}
