//! The linear analysis: the eigenvalues of the column's quadratic pencil
//! at each load, their classification, the tracked root locus, the
//! critical loads, the stability map and the paradox curves.

pub(super) mod along;
mod branch_points;
mod characteristic;
pub(super) mod critical;
pub(super) mod crossing;
mod dense;
mod grid;
pub(super) mod hqr;
pub(super) mod locus;
pub(super) mod map;
mod matching;
pub(super) mod paradox;
pub(super) mod peaks;
pub(super) mod pencil;
mod prefetch;
pub(super) mod resolution;
pub(super) mod roots;
pub(super) mod stability;
