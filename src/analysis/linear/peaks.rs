//! The largest size of swinging quantities (the rods' angles) read off
//! samples of their values and rates (and accelerations, where known),
//! between samples by the cubic (quintic) through both ends' values and
//! derivatives.

/// The largest `|v_i|` of each of several quantities sampled with their
/// rates. Between two samples each is the cubic through the samples' values
/// and rates (Hermite's), so a peak between samples is read to the cubic's
/// accuracy, about `(h w)^4 / 384` of the amplitude for a swing of angular
/// frequency `w` sampled every `h` (2e-10 at 400 samples a period), instead
/// of `(h w)^2 / 8` for the samples alone.
#[derive(Clone, Debug)]
pub struct Peaks {
    /// The last samples' `[value, rate, acceleration]` (the acceleration
    /// NaN where not known).
    last: Vec<[f64; 3]>,
    largest: Vec<f64>,
}

impl Peaks {
    /// Starting from the first samples `values` and their `rates`.
    #[must_use]
    pub fn new(values: &[f64], rates: &[f64]) -> Self {
        Self {
            last: values
                .iter()
                .zip(rates)
                .map(|(&v, &r)| [v, r, f64::NAN])
                .collect(),
            largest: values.iter().map(|v| v.abs()).collect(),
        }
    }

    /// Starting from the first samples with their `accelerations` (see
    /// [`Self::push_with_accelerations`]).
    #[must_use]
    pub fn with_accelerations(values: &[f64], rates: &[f64], accelerations: &[f64]) -> Self {
        let mut peaks = Self::new(values, rates);
        for (last, &a) in peaks.last.iter_mut().zip(accelerations) {
            last[2] = a;
        }
        peaks
    }

    /// The largest `|v_i|` so far.
    #[must_use]
    pub fn largest(&self) -> &[f64] {
        &self.largest
    }

    /// The next samples, `dt_secs` after the last.
    pub fn push(&mut self, values: &[f64], rates: &[f64], dt_secs: f64) {
        self.push_samples(values, rates, None, dt_secs);
    }

    /// The next samples with their accelerations, `dt_secs` after the last:
    /// where the last samples had theirs too, a peak between them is read
    /// off the quintic through both ends' values, rates and accelerations
    /// (Hermite's), to about `(h w)^6 / 46080` of the amplitude (1e-12 at
    /// 100 samples a period).
    pub fn push_with_accelerations(
        &mut self,
        values: &[f64],
        rates: &[f64],
        accelerations: &[f64],
        dt_secs: f64,
    ) {
        self.push_samples(values, rates, Some(accelerations), dt_secs);
    }

    fn push_samples(
        &mut self,
        values: &[f64],
        rates: &[f64],
        accelerations: Option<&[f64]>,
        dt_secs: f64,
    ) {
        let h2 = dt_secs * dt_secs;
        for (i, (last, largest)) in self.last.iter_mut().zip(&mut self.largest).enumerate() {
            let (value, rate) = (values[i], rates[i]);
            let acceleration = accelerations.map_or(f64::NAN, |a| a[i]);
            let [v0, r0, a0] = *last;
            let mut top = value.abs();
            // An extremum inside the interval: where the rate changes sign.
            if r0 * rate < 0.0 {
                let ends = [
                    v0,
                    r0 * dt_secs,
                    a0 * h2,
                    value,
                    rate * dt_secs,
                    acceleration * h2,
                ];
                top = top.max(hermite_extremum(ends).abs());
            }
            *largest = largest.max(top);
            *last = [value, rate, acceleration];
        }
    }
}

/// The value at the stationary point inside `[0, 1]` of Hermite's
/// polynomial with values `v0, v1`, slopes `s0, s1` and second derivatives
/// `a0, a1` (per unit of its parameter) at the ends, whose slopes have
/// opposite signs: the quintic where both second derivatives are known,
/// else the cubic. The root of its slope inside the interval is found by
/// bisection (to rounding).
fn hermite_extremum([v0, s0, a0, v1, s1, a1]: [f64; 6]) -> f64 {
    let quintic = a0.is_finite() && a1.is_finite();
    // Each basis polynomial's value and slope at t, for the ends'
    // v0, s0, a0, v1, s1, a1 in turn.
    let basis = |t: f64| -> [[f64; 2]; 6] {
        let (t2, t3) = (t * t, t * t * t);
        if quintic {
            let (t4, t5) = (t3 * t, t3 * t2);
            [
                [
                    1.0 - 10.0 * t3 + 15.0 * t4 - 6.0 * t5,
                    -30.0 * t2 + 60.0 * t3 - 30.0 * t4,
                ],
                [
                    t - 6.0 * t3 + 8.0 * t4 - 3.0 * t5,
                    1.0 - 18.0 * t2 + 32.0 * t3 - 15.0 * t4,
                ],
                [
                    0.5 * (t2 - 3.0 * t3 + 3.0 * t4 - t5),
                    0.5 * (2.0 * t - 9.0 * t2 + 12.0 * t3 - 5.0 * t4),
                ],
                [
                    10.0 * t3 - 15.0 * t4 + 6.0 * t5,
                    30.0 * t2 - 60.0 * t3 + 30.0 * t4,
                ],
                [
                    -4.0 * t3 + 7.0 * t4 - 3.0 * t5,
                    -12.0 * t2 + 28.0 * t3 - 15.0 * t4,
                ],
                [
                    0.5 * (t3 - 2.0 * t4 + t5),
                    0.5 * (3.0 * t2 - 8.0 * t3 + 5.0 * t4),
                ],
            ]
        } else {
            [
                [2.0 * t3 - 3.0 * t2 + 1.0, 6.0 * t2 - 6.0 * t],
                [t3 - 2.0 * t2 + t, 3.0 * t2 - 4.0 * t + 1.0],
                [0.0, 0.0],
                [3.0 * t2 - 2.0 * t3, 6.0 * t - 6.0 * t2],
                [t3 - t2, 3.0 * t2 - 2.0 * t],
                [0.0, 0.0],
            ]
        }
    };
    // The cubic's basis has no second-derivative terms: its unknown
    // accelerations (NaN) stand as zeros.
    let ends = if quintic {
        [v0, s0, a0, v1, s1, a1]
    } else {
        [v0, s0, 0.0, v1, s1, 0.0]
    };
    let at = |t: f64, derivative: usize| -> f64 {
        basis(t)
            .iter()
            .zip(ends)
            .map(|(b, e)| b[derivative] * e)
            .sum()
    };
    let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if at(mid, 1) * s0 > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    at(0.5 * (lo + hi), 0)
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

    /// The swing's largest size, by a dense search of the exact curve and
    /// golden-section on its best.
    fn exact_largest() -> f64 {
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
        swing(0.5 * (lo + hi)).0.abs()
    }

    /// The swing's acceleration.
    fn acceleration(t: f64) -> f64 {
        let (a, b, c) = (1.0, 0.15, 0.4);
        -a * t.sin() - 9.0 * b * (3.0 * t + c).sin()
    }

    /// A swing with a third harmonic, sampled 400 times a period: its
    /// largest size is read to its cubic's accuracy, while the samples
    /// alone miss it by far more.
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
        let exact = exact_largest();
        let read = peaks.largest()[0];
        assert!((read - exact).abs() < 1e-10, "{read} vs {exact}");
        assert!(
            exact - sampled > 1e-7,
            "the samples alone: {sampled} vs {exact}"
        );
    }

    /// The same swing sampled only 100 times a period with its
    /// accelerations: the quintic reads the peak to 5e-11, a hundredth of
    /// what the cubic through the same samples misses it by.
    #[test]
    fn accelerations_read_a_peak_off_the_quintic() {
        let samples = 100;
        let h = std::f64::consts::TAU / f64::from(samples);
        let (v, r) = swing(0.0);
        let mut quintic = Peaks::with_accelerations(&[v], &[r], &[acceleration(0.0)]);
        let mut cubic = Peaks::new(&[v], &[r]);
        for i in 1..=samples {
            let t = f64::from(i) * h;
            let (v, r) = swing(t);
            quintic.push_with_accelerations(&[v], &[r], &[acceleration(t)], h);
            cubic.push(&[v], &[r], h);
        }
        let exact = exact_largest();
        let (read, rough) = (quintic.largest()[0], cubic.largest()[0]);
        let (off, cubic_off) = ((read - exact).abs(), (rough - exact).abs());
        assert!(off < 5e-11, "{read} vs {exact}");
        assert!(cubic_off > 100.0 * off, "the cubic: {rough} vs {exact}");
    }
}
