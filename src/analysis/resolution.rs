//! Whether an answer about stability can be trusted: the classification's
//! resolution against the slowest mode, and the same critical loads from a
//! 100 times finer classification.

use super::AnalysisError;
use super::critical::{Classifier, Transition, load_label, transitions_along};
use super::locus::Locus;
use super::pencil::AffinePencil;
use super::stability::RELATIVE_TOLERANCE;

/// The sensitivity check classifies again with a tolerance this much finer.
const FINER_TOLERANCE_FACTOR: f64 = 1e-2;
/// Transitions of the two classifications agree to this relative load.
const LOAD_AGREEMENT: f64 = 1e-6;
/// The classification's tolerance must stay below this fraction of the
/// slowest mode's |lambda| for a growth rate of that mode to be told from zero.
const SLOWEST_MODE_FRACTION: f64 = 1e-3;

/// Whether `transitions` (found along `locus`) can be trusted, and if not, why,
/// in words for the user. Two checks:
/// - the tolerance of the classification (1e-10 of the frequency scale, which
///   a very stiff mode such as the roller's spin relaxation at a tiny band
///   speed V inflates) must be well below the slowest mode;
/// - classifying again with a 100 times finer tolerance must find the same
///   changes at the same loads. They differ when the stability hinges on
///   growth rates at the resolution of double precision (a roller of tiny
///   mass nu, whose weak flutter grows in proportion to nu; a very slow band).
///
/// # Errors
/// A failed eigenvalue computation.
pub fn resolution_warning(
    pencil: &AffinePencil,
    locus: &Locus,
    transitions: &[Transition],
) -> Result<Option<String>, AnalysisError> {
    // The stiffest load of the range (for the roller the largest: R = p k/(mu l)).
    let Some(&stiffest) = locus
        .loads
        .iter()
        .max_by(|&&a, &&b| pencil.scale_per_s(a).total_cmp(&pencil.scale_per_s(b)))
    else {
        return Ok(None);
    };
    let spectrum = pencil.spectrum(stiffest)?;
    let tolerance = RELATIVE_TOLERANCE * spectrum.scale_per_s;
    let slowest = spectrum
        .eigenvalues
        .iter()
        .map(|z| z.norm())
        .filter(|&r| r > 0.0)
        .fold(f64::INFINITY, f64::min);
    if slowest.is_finite() && tolerance > SLOWEST_MODE_FRACTION * slowest {
        return Ok(Some(format!(
            "the stability is not resolved: at p = {stiffest:.4} the modes span {:.0e} 1/s to {slowest:.1e} 1/s, so growth rates below {tolerance:.1e} 1/s are lost to rounding (the model is near a singular limit: a very slow band V, or very large damping)",
            spectrum.scale_per_s
        )));
    }
    let finer = Classifier {
        pencil,
        relative_tolerance: RELATIVE_TOLERANCE * FINER_TOLERANCE_FACTOR,
    };
    let refined = transitions_along(&finer, locus)?;
    let agree = refined.len() == transitions.len()
        && refined.iter().zip(transitions).all(|(a, b)| {
            (a.from, a.to) == (b.from, b.to)
                && (a.load - b.load).abs() <= LOAD_AGREEMENT * a.load.abs().max(b.load.abs())
        });
    if agree {
        return Ok(None);
    }
    let loads = |ts: &[Transition]| {
        let named: Vec<String> = ts
            .iter()
            .map(|t| {
                format!(
                    "{} ({} -> {})",
                    load_label(t.load),
                    t.from.name(),
                    t.to.name()
                )
            })
            .collect();
        if named.is_empty() {
            "none".to_owned()
        } else {
            named.join(", ")
        }
    };
    Ok(Some(format!(
        "the stability is not resolved: the growth rates are at the resolution of the analysis ({tolerance:.1e} 1/s), and a 100x finer tolerance moves the changes from p = {} to p = {} (a roller of tiny mass nu, whose weak flutter grows in proportion to nu, or a very slow band V)",
        loads(transitions),
        loads(&refined)
    )))
}
