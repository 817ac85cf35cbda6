//! The nonlinear analysis: the reduced equations of motion and their
//! derivatives, the Hopf points' normal form (soft or hard onset), and the
//! limit cycles continued from them with their Floquet multipliers; the
//! stability boundaries followed in a second parameter, with where their
//! onsets turn from soft to hard, the folds of cycles and what a kick does
//! between them.

mod amplitude;
pub(super) mod arclength;
mod bautin;
pub(super) mod boundary;
pub(super) mod bracket;
mod chord;
mod column_lu;
mod continuation;
mod convergence;
pub(super) mod curve;
mod cycle;
pub(super) mod cycle_bifurcations;
pub(super) mod cycle_fold;
pub(super) mod cycles;
mod falsi;
pub(super) mod field;
pub(super) mod gauss;
pub(super) mod hopf;
pub(super) mod jet;
pub(super) mod kick;
mod offshoot;
mod period_steps;
mod shooting;
mod split_stages;
mod symmetric;
mod tableau;
