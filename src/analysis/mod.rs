//! The column's stability: the linear analysis (`linear/`: eigenvalues of
//! the quadratic pencil, classification, tracked root loci, critical
//! loads, maps, paradox curves) and the nonlinear one (`nonlinear/`: Hopf
//! points and limit cycles). Pure f64 (no UI, no clock).

mod linear;
mod nonlinear;

// Every module by its own name, as before the two folders: the files
// name each other through `crate::analysis::<module>`.
use linear::{
    along, critical, crossing, hqr, locus, map, paradox, peaks, pencil, resolution, roots,
    stability,
};
use nonlinear::{
    boundary, curve, cycle_bifurcations, cycle_fold, cycles, field, gauss, hopf, jet, kick,
};

pub use along::{AlongLoad, Sampling, Unresolved};
pub use boundary::{Boundaries, SpecialKind, SpecialPoint, boundaries, boundaries_until};
pub use critical::{
    BRACKET_SAMPLES, bracketing_locus, bracketing_locus_reporting, critical_loads,
    critical_loads_along, plotted_locus,
};
pub use crossing::{Transition, stability_ranges};
pub use curve::{Boundary, BoundaryKind, BoundaryPoint, BoundarySpec, CurveEnd, load_on_chord};
pub use cycle_bifurcations::{CycleBifurcation, CycleBifurcationKind};
pub use cycle_fold::{CycleFold, FoldEnd, FoldPoint};
pub use cycles::{
    Branch, BranchEnd, Cycle, MAX_AMPLITUDE_RAD, MAX_PERIOD_GROWTH, MAX_POINTS, NoBranch, Offshoot,
    Onset, TRIVIAL_TOLERANCE, cycle_branches, cycles_at,
};
pub use hopf::{Derivatives, Hopf, HopfKind, NoHopf, Steps as HopfSteps, hopf_at, is_hopf};
pub use kick::Kick;
pub use locus::{
    LARGEST_LOAD, Locus, MAX_HELD_EIGENVALUES, check_largest_load, load_grid, locus,
    locus_streamed, max_samples,
};
pub use map::{
    Cell, MapSpec, Row, RowResult, boundaries as map_boundaries, compute as compute_map,
    default_map_axis,
};
pub use paradox::{
    CurveName, Curves, DampingKind, NoCurve, ReferenceName, SweptRatio, curves as paradox_curves,
    first_instability, first_loss_of_stability, flutter_load_damped, flutter_load_external,
    own_point, swept_ratio,
};
pub use peaks::Peaks;
pub use pencil::{AffinePencil, Spectrum, spectrum};
pub use resolution::{NotResolved, resolution_warning};
pub use roots::{Poly, aberth};
pub use stability::{LARGEST_MODE_SPAN, RELATIVE_TOLERANCE, Stability, State, classify};

use crate::model::{ModelError, Shown};

/// Complex eigenvalue, in 1/s.
pub type C64 = nalgebra::Complex<f64>;

/// Why an analysis gave no answer.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum AnalysisError {
    #[error(transparent)]
    Model(#[from] ModelError),
    #[error("the eigenvalue iteration did not converge at load p = {}", Shown(*.load))]
    NotConverged { load: f64 },
    #[error(
        "samples = {samples}: at most {most} loads for a locus of {eigenvalues} eigenvalues per load (its memory is bounded to 256 MiB); use fewer samples"
    )]
    TooManySamples {
        samples: usize,
        most: usize,
        eigenvalues: usize,
    },
    #[error("{0}")]
    NotCovered(&'static str),
    #[error("{what} = {}: {allowed}", Shown(*.value))]
    BadRange {
        what: &'static str,
        value: f64,
        allowed: &'static str,
    },
}

impl AnalysisError {
    /// The parameter (or argument) the error is about, when it is about one.
    #[must_use]
    pub fn parameter(&self) -> Option<&str> {
        match self {
            Self::Model(error) => error.parameter(),
            Self::BadRange { what, .. } => Some(what),
            Self::TooManySamples { .. } => Some("samples"),
            Self::NotConverged { .. } | Self::NotCovered(_) => None,
        }
    }
}
