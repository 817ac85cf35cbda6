//! Whether an answer about stability can be trusted: the classification's
//! resolution against the slowest mode, and the same states from a 100 times
//! finer classification.

use crate::analysis::AnalysisError;
use crate::analysis::locus::Locus;
use crate::analysis::pencil::AffinePencil;
use crate::analysis::stability::{
    LARGEST_MODE_SPAN, RELATIVE_TOLERANCE, State, beyond_resolution, classify_with, mode_span,
};
use crate::format::load_text;

/// The sensitivity check classifies again with a tolerance this much finer.
const FINER_TOLERANCE_FACTOR: f64 = 1e-2;
/// Eigenvalues closer than this (relative to their size) are a double root.
const NEAR_DOUBLE_ROOT: f64 = 1e-3;
/// The classification's tolerance must stay below this fraction of the
/// slowest mode's |lambda| for a growth rate of that mode to be told from zero.
const SLOWEST_MODE_FRACTION: f64 = 1e-3;

/// Why the stability along a locus cannot be trusted (each with where);
/// its `Display` says it in English, for the command line.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum NotResolved {
    /// The modes span more than [`LARGEST_MODE_SPAN`] at `load`.
    ModeSpan {
        load: f64,
        fastest_per_s: f64,
        slowest_per_s: f64,
    },
    /// The classification's tolerance is not well below the slowest mode.
    SlowModeLost {
        load: f64,
        scale_per_s: f64,
        slowest_per_s: f64,
        tolerance_per_s: f64,
    },
    /// The tracked roots and the Schur decomposition disagree at `load`.
    MethodsDisagree { load: f64 },
    /// From `low` to `high` the growth rates lie where rounding decides.
    RoundingDecides { low: f64, high: f64 },
    /// The refinement stopped at `load` (its bound on time and memory).
    RefinementCut { load: f64 },
}

impl NotResolved {
    /// A short stable id (for message catalogues).
    #[must_use]
    pub const fn id(&self) -> &'static str {
        match self {
            Self::ModeSpan { .. } => "mode-span",
            Self::SlowModeLost { .. } => "slow-mode-lost",
            Self::MethodsDisagree { .. } => "methods-disagree",
            Self::RoundingDecides { .. } => "rounding-decides",
            Self::RefinementCut { .. } => "refinement-cut",
        }
    }
}

impl std::fmt::Display for NotResolved {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match *self {
            Self::ModeSpan {
                load,
                fastest_per_s: fastest,
                slowest_per_s: slowest,
            } => write!(
                f,
                "the stability is not resolved: at p = {} the modes span {fastest:.1e} 1/s to {slowest:.1e} 1/s, a ratio beyond {LARGEST_MODE_SPAN:.0e}, so the slow modes' growth rates are left to rounding (a mode far faster than the others, such as the spin of a roller of tiny mass nu)",
                load_text(load)
            ),
            Self::SlowModeLost {
                load,
                scale_per_s,
                slowest_per_s: slowest,
                tolerance_per_s: tolerance,
            } => write!(
                f,
                "the stability is not resolved: at p = {} the modes span {scale_per_s:.0e} 1/s to {slowest:.1e} 1/s, so growth rates below {tolerance:.1e} 1/s are lost to rounding (the model is near a singular limit: a very slow band V, or very large damping)",
                load_text(load)
            ),
            Self::MethodsDisagree { load } => write!(
                f,
                "the stability is not resolved: at p = {} the tracked roots and the Schur decomposition disagree on the state (rounding decides it: a mode far faster than the others, such as the spin of a roller of tiny mass nu); the critical loads shown may be spurious or missing",
                load_text(load)
            ),
            Self::RoundingDecides { low, high } => write!(
                f,
                "the stability is not resolved: for p from {} to {} the growth rates lie between 1e-12 and 1e-10 of the frequency scale, where rounding decides the state (a roller of tiny mass nu, whose weak flutter grows in proportion to nu, or a very slow band V); the critical loads shown may be misplaced or missing",
                load_text(low),
                load_text(high)
            ),
            Self::RefinementCut { load } => write!(
                f,
                "the root locus was refined only up to p = {}: beyond it the branches are sampled at the evenly spaced loads alone, so a window of another state narrower than their spacing may be missing (the refinement's bound on time and memory was reached; use a narrower range)",
                load_text(load)
            ),
        }
    }
}

/// Whether the stability along `locus` can be trusted, and if not, why. Two checks, both on what is already computed:
/// - the tolerance of the classification (1e-10 of the frequency scale, which
///   a very stiff mode such as the roller's spin relaxation at a tiny band
///   speed V inflates) must be well below the slowest mode;
/// - no sample of the locus may change its state when classified with a 100
///   times finer tolerance. One does when the stability hinges on growth
///   rates at the resolution of double precision (a roller of tiny mass nu,
///   whose weak flutter grows in proportion to nu; a very slow band). Samples
///   whose dominant eigenvalue is within 1e-3 of its size of another are
///   left out: near a double root rounding moves eigenvalues by more than
///   either tolerance, and the critical loads there come from bisection on
///   the robust path, not from these samples. So are the samples beside a
///   change of state, where the growth rate passes through zero (in a long
///   chain a mode there can be isolated to 1e-3 and still carry rounding of
///   1e-12 of the frequency scale).
///
/// # Errors
/// A failed eigenvalue computation.
pub fn resolution_warning(
    pencil: &AffinePencil,
    locus: &Locus,
) -> Result<Option<NotResolved>, AnalysisError> {
    let (Some(&first), Some(&last)) = (locus.loads.first(), locus.loads.last()) else {
        return Ok(None);
    };
    // The stiffest load of the range: each term of the scale is a norm of
    // matrices affine in p, largest at an end.
    let stiffest = if pencil.scale_per_s(last) >= pencil.scale_per_s(first) {
        last
    } else {
        first
    };
    let spectrum = pencil.spectrum(stiffest)?;
    let tolerance = RELATIVE_TOLERANCE * spectrum.scale_per_s;
    let (fastest, slowest) = mode_span(&spectrum.eigenvalues);
    if beyond_resolution(&spectrum.eigenvalues) {
        return Ok(Some(NotResolved::ModeSpan {
            load: stiffest,
            fastest_per_s: fastest,
            slowest_per_s: slowest,
        }));
    }
    if slowest.is_finite() && tolerance > SLOWEST_MODE_FRACTION * slowest {
        return Ok(Some(NotResolved::SlowModeLost {
            load: stiffest,
            scale_per_s: spectrum.scale_per_s,
            slowest_per_s: slowest,
            tolerance_per_s: tolerance,
        }));
    }
    let samples: Vec<Sample> = (0..locus.loads.len())
        .map(|i| {
            let scale = pencil.scale_per_s(locus.loads[i]);
            let moving = locus.moving_at(i);
            let coarse = classify_with(&moving, scale, RELATIVE_TOLERANCE);
            let fine = classify_with(&moving, scale, RELATIVE_TOLERANCE * FINER_TOLERANCE_FACTOR);
            let d = coarse.dominant;
            let isolated = moving
                .iter()
                .filter(|&&z| z != d)
                .all(|z| (z - d).norm() > NEAR_DOUBLE_ROOT * z.norm().max(d.norm()));
            Sample {
                state: coarse.state,
                fine_state: fine.state,
                isolated,
            }
        })
        .collect();
    // A sample beside a change of state has a growth rate passing through
    // zero by definition: it is the crossing (found by bisection on the
    // robust path), not a range that rounding decides.
    let at_crossing = |i: usize| {
        let state = samples[i].state;
        (i > 0 && samples[i - 1].state != state)
            || samples.get(i + 1).is_some_and(|next| next.state != state)
    };
    let undecided: Vec<f64> = (0..samples.len())
        .filter(|&i| {
            let sample = &samples[i];
            sample.state != sample.fine_state && sample.isolated && !at_crossing(i)
        })
        .map(|i| locus.loads[i])
        .collect();
    if let Some(p) = methods_disagree(pencil, locus, &samples)? {
        return Ok(Some(NotResolved::MethodsDisagree { load: p }));
    }
    let (Some(low), Some(high)) = (undecided.first(), undecided.last()) else {
        return Ok(locus
            .refinement_cut_at
            .map(|load| NotResolved::RefinementCut { load }));
    };
    Ok(Some(NotResolved::RoundingDecides {
        low: *low,
        high: *high,
    }))
}

/// Samples compared between the two eigenvalue paths: evenly spaced ones,
/// and those next to a change of the tracked state, at most this many.
const CROSS_CHECKED_SAMPLES: usize = 48;

/// The first load among a few samples of `locus` where the state of the
/// tracked roots (polynomial continuation) differs from the state of the
/// Schur path, away from double roots. Two independent methods agreeing is
/// the evidence that rounding does not decide the state; where they do not,
/// it does.
fn methods_disagree(
    pencil: &AffinePencil,
    locus: &Locus,
    samples: &[Sample],
) -> Result<Option<f64>, AnalysisError> {
    let n = samples.len();
    let mut checked: Vec<usize> = Vec::with_capacity(CROSS_CHECKED_SAMPLES);
    for i in 1..n {
        if samples[i].state != samples[i - 1].state {
            checked.extend([i - 1, i]);
        }
        if checked.len() >= CROSS_CHECKED_SAMPLES / 2 {
            break;
        }
    }
    let stride = (n / (CROSS_CHECKED_SAMPLES / 2)).max(1);
    checked.extend((0..n).step_by(stride));
    checked.sort_unstable();
    checked.dedup();
    for i in checked.into_iter().filter(|&i| samples[i].isolated) {
        let p = locus.loads[i];
        let spectrum = pencil.spectrum(p)?;
        let schur = classify_with(
            &spectrum.eigenvalues,
            spectrum.scale_per_s,
            RELATIVE_TOLERANCE,
        );
        if schur.state != samples[i].state {
            return Ok(Some(p));
        }
    }
    Ok(None)
}

/// One locus sample as the checks see it: its state at the classification's
/// tolerance and at a 100 times finer one, and whether its dominant
/// eigenvalue is clear of the others (not at a double root).
struct Sample {
    state: State,
    fine_state: State,
    isolated: bool,
}
