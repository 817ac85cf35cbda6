//! Regula falsi in its Illinois form on a bracket whose ends carry what was
//! computed there (a cycle, Newton's matrix), so that each new point is
//! solved from the nearer end's: the root of a test function of one
//! variable whose every value costs a shooting solve.

/// A point of the bracket: where, the test function's value there, and
/// what was computed there.
pub(super) type Sample<T> = (f64, f64, T);

/// When the root is taken as found.
#[derive(Clone, Copy)]
pub(super) struct Stop {
    /// The value is within this share of the bracket's first two values'
    /// moduli summed.
    pub value: f64,
    /// Or the bracket is at most this wide.
    pub width: f64,
    /// Most new points.
    pub steps: usize,
}

/// The root of a function between `low` and `high`, whose values have
/// opposite signs: each new point is the secant's zero between the ends
/// (with the end kept twice in a row weighed by half, the Illinois rule,
/// so that one end does not stick), solved by `at(x, nearer)` from the
/// nearer end's payload. `None` where a solve fails, the signs do not
/// differ, or no root is found in `stop.steps` points.
pub(super) fn illinois<T>(
    mut low: Sample<T>,
    mut high: Sample<T>,
    stop: Stop,
    mut at: impl FnMut(f64, &T) -> Option<Sample<T>>,
) -> Option<Sample<T>> {
    let product = low.1 * high.1;
    if product.is_nan() || product >= 0.0 {
        return None;
    }
    let scale = low.1.abs() + high.1.abs();
    let mut side = 0i8;
    for _ in 0..stop.steps {
        let x = (low.0 * high.1 - high.0 * low.1) / (high.1 - low.1);
        let nearer = if (x - low.0).abs() < (x - high.0).abs() {
            &low.2
        } else {
            &high.2
        };
        let sample = at(x, nearer)?;
        let g = sample.1;
        if g.abs() <= stop.value * scale || (high.0 - low.0).abs() <= stop.width {
            return Some(sample);
        }
        if g * low.1 > 0.0 {
            low = sample;
            if side == -1 {
                high.1 *= 0.5;
            }
            side = -1;
        } else {
            high = sample;
            if side == 1 {
                low.1 *= 0.5;
            }
            side = 1;
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The cube root of 2 from the bracket [1, 2] of `x^3 - 2` (a convex
    /// function, where plain regula falsi keeps one end for ever): to
    /// 1e-14 in a dozen points, each solved from the nearer end's payload
    /// (here the end's own x, so the payload handed on is checked too).
    #[test]
    fn the_cube_root_of_two_in_a_dozen_points() {
        let f = |x: f64| x * x * x - 2.0;
        let stop = Stop {
            value: 1e-16,
            width: 1e-15,
            steps: 40,
        };
        let mut points = 0;
        let root = illinois((1.0, f(1.0), 1.0), (2.0, f(2.0), 2.0), stop, |x, near| {
            points += 1;
            assert!((x - near).abs() <= 0.5 + 1e-12, "{x} from {near}");
            Some((x, f(x), x))
        })
        .expect("a root");
        assert!((root.0 - 2f64.cbrt()).abs() < 1e-14, "{}", root.0);
        assert!(points <= 12, "{points} points");
        // No root without a change of sign, and a failed solve is passed on.
        assert!(illinois((2.0, 6.0, ()), (3.0, 25.0, ()), stop, |_, ()| None).is_none());
        assert!(illinois((1.0, -1.0, ()), (2.0, 6.0, ()), stop, |_, ()| None).is_none());
    }
}
