//! The largest size of swinging quantities (the rods' angles) read off
//! samples of their values and rates, between samples by the cubic through
//! both ends' values and slopes.

/// The largest `|v_i|` of each of several quantities sampled with their
/// rates. Between two samples each is the cubic through the samples' values
/// and rates (Hermite's), so a peak between samples is read to the cubic's
/// accuracy, about `(h w)^4 / 384` of the amplitude for a swing of angular
/// frequency `w` sampled every `h` (2e-10 at 400 samples a period), instead
/// of `(h w)^2 / 8` for the samples alone.
#[derive(Clone, Debug)]
pub struct Peaks {
    /// The last samples' `[value, rate]`.
    last: Vec<[f64; 2]>,
    largest: Vec<f64>,
}

impl Peaks {
    /// Starting from the first samples `values` and their `rates`.
    #[must_use]
    pub fn new(values: &[f64], rates: &[f64]) -> Self {
        Self {
            last: values.iter().zip(rates).map(|(&v, &r)| [v, r]).collect(),
            largest: values.iter().map(|v| v.abs()).collect(),
        }
    }

    /// The largest `|v_i|` so far.
    #[must_use]
    pub fn largest(&self) -> &[f64] {
        &self.largest
    }

    /// The next samples, `dt_secs` after the last.
    pub fn push(&mut self, values: &[f64], rates: &[f64], dt_secs: f64) {
        for ((last, largest), (&value, &rate)) in self
            .last
            .iter_mut()
            .zip(&mut self.largest)
            .zip(values.iter().zip(rates))
        {
            let [v0, r0] = *last;
            let mut top = value.abs();
            // An extremum inside the interval: where the rate changes sign.
            if r0 * rate < 0.0 {
                top = top.max(cubic_extremum(v0, r0 * dt_secs, value, rate * dt_secs).abs());
            }
            *largest = largest.max(top);
            *last = [value, rate];
        }
    }
}

/// The value at the stationary point inside `[0, 1]` of the cubic with
/// values `v0, v1` and slopes `s0, s1` (per unit of its parameter) at the
/// ends, whose slopes have opposite signs. The slope is a quadratic with
/// one root in the interval, found by bisection (to rounding).
fn cubic_extremum(v0: f64, s0: f64, v1: f64, s1: f64) -> f64 {
    let a = 6.0 * (v0 - v1) + 3.0 * (s0 + s1);
    let b = 6.0 * (v1 - v0) - 2.0 * (2.0 * s0 + s1);
    let slope = |t: f64| (a * t + b) * t + s0;
    let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if slope(mid) * s0 > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let t = 0.5 * (lo + hi);
    let (t2, t3) = (t * t, t * t * t);
    (2.0 * t3 - 3.0 * t2 + 1.0) * v0
        + (t3 - 2.0 * t2 + t) * s0
        + (3.0 * t2 - 2.0 * t3) * v1
        + (t3 - t2) * s1
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `a sin(t) + b sin(3 t + c)` and its rate.
    fn swing(t: f64) -> (f64, f64) {
        let (a, b, c) = (1.0, 0.15, 0.4);
        (
            a * t.sin() + b * (3.0 * t + c).sin(),
            a * t.cos() + 3.0 * b * (3.0 * t + c).cos(),
        )
    }

    /// A swing with a third harmonic, sampled 400 times a period: its
    /// largest size (by a dense search of the exact curve) is read to its
    /// cubic's accuracy, while the samples alone miss it by far more.
    #[test]
    fn a_peak_between_samples_is_read_off_the_cubic() {
        let samples = 400;
        let h = std::f64::consts::TAU / f64::from(samples);
        let (v, r) = swing(0.0);
        let mut peaks = Peaks::new(&[v], &[r]);
        let mut sampled = v.abs();
        for i in 1..=samples {
            let (v, r) = swing(f64::from(i) * h);
            peaks.push(&[v], &[r], h);
            sampled = sampled.max(v.abs());
        }
        // The exact largest: a fine grid, then golden-section on its best.
        let fine = 200_000;
        let best = (0..fine)
            .map(|i| f64::from(i) * std::f64::consts::TAU / f64::from(fine))
            .max_by(|a, b| swing(*a).0.abs().total_cmp(&swing(*b).0.abs()))
            .expect("samples");
        let (mut lo, mut hi) = (best - 1e-4, best + 1e-4);
        for _ in 0..100 {
            let (m1, m2) = (lo + (hi - lo) / 3.0, hi - (hi - lo) / 3.0);
            if swing(m1).0.abs() < swing(m2).0.abs() {
                lo = m1;
            } else {
                hi = m2;
            }
        }
        let exact = swing(0.5 * (lo + hi)).0.abs();
        let read = peaks.largest()[0];
        assert!((read - exact).abs() < 1e-10, "{read} vs {exact}");
        assert!(
            exact - sampled > 1e-7,
            "the samples alone: {sampled} vs {exact}"
        );
    }
}
