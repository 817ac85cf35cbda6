//! The evenly spaced loads of a locus, and the ranges they may span.

use crate::analysis::AnalysisError;

/// Neighbouring grid loads must differ by at least this many units of
/// `f64::EPSILON` relative to the range's end, so that every load is distinct.
const RESOLVED_STEPS: f64 = 4.0;

/// The smallest step between distinct loads of a range ending at `load_max`.
/// Never below the smallest normal number: subnormal loads carry too few
/// digits to be told apart (and slow every operation on some CPUs).
pub(crate) fn load_resolution(load_max: f64) -> f64 {
    (RESOLVED_STEPS * f64::EPSILON * load_max.abs()).max(f64::MIN_POSITIVE)
}

/// Largest number of evenly spaced loads a locus accepts.
pub const MAX_SAMPLES: usize = 1_000_000;

/// The largest load a range may reach, as for the load itself (`--set load`).
pub const LARGEST_LOAD: f64 = crate::model::LARGEST_DERIVED;

/// Refuses a range reaching past [`LARGEST_LOAD`]: beyond it the column's
/// stiffness is far below rounding and the eigenvalues are noise in scale.
///
/// # Errors
/// `load_max` above [`LARGEST_LOAD`].
pub fn check_largest_load(load_max: f64) -> Result<(), AnalysisError> {
    if load_max > LARGEST_LOAD {
        return Err(AnalysisError::BadRange {
            what: "load-max",
            value: load_max,
            allowed: "must be at most 1e150, the largest load the analysis resolves",
        });
    }
    Ok(())
}

/// The evenly spaced loads from `min` to `max` inclusive.
///
/// # Errors
/// Non-finite or negative bounds, `max < min`, no samples or too many (also
/// more than the range can hold distinct in f64), or one sample over a range.
pub fn load_grid(min: f64, max: f64, samples: usize) -> Result<Vec<f64>, AnalysisError> {
    let bad = |what, value, allowed| {
        Err(AnalysisError::BadRange {
            what,
            value,
            allowed,
        })
    };
    if !(min.is_finite() && min >= 0.0) {
        return bad("load-min", min, "must be a finite load >= 0");
    }
    if !(max.is_finite() && max >= min) {
        return bad("load-max", max, "must be finite and >= load-min");
    }
    if samples == 0 || samples > MAX_SAMPLES {
        #[expect(clippy::cast_precision_loss, reason = "a count shown in a message")]
        return bad("samples", samples as f64, "must be between 1 and 1000000");
    }
    if samples == 1 {
        return if min == max {
            Ok(vec![min])
        } else {
            bad(
                "samples",
                1.0,
                "must be >= 2 unless load-min equals load-max",
            )
        };
    }
    #[expect(
        clippy::cast_precision_loss,
        reason = "sample counts are far below 2^52"
    )]
    let step = (max - min) / (samples - 1) as f64;
    if step < load_resolution(max) {
        #[expect(clippy::cast_precision_loss, reason = "a count shown in a message")]
        return bad(
            "samples",
            samples as f64,
            "too many for so narrow a range: neighbouring loads would not be distinct in double precision (use fewer samples or a wider range)",
        );
    }
    #[expect(
        clippy::cast_precision_loss,
        reason = "sample counts are far below 2^52"
    )]
    Ok((0..samples)
        .map(|i| {
            if i + 1 == samples {
                max
            } else {
                min + step * i as f64
            }
        })
        .collect())
}
