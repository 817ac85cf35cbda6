//! The Lyapunov coefficients of a Hopf point read off its limit cycles: at
//! a Bautin point, where the first one vanishes, the second one, which
//! says whether the cycles born there are stable (negative) and so whether
//! the hard side's large swing exists.
//!
//! In the normal form `z' = (mu + i omega) z + c1 z|z|^2 + c2 z|z|^4 + ...`
//! with `z = <p, x>` (`hopf`'s eigenvectors, `<q, q> = <p, q> = 1`) a cycle
//! of radius `r` has `mu + omega (l1 r^2 + l2 r^4 + l3 r^6 + ...) = 0`,
//! where `l_k = Re c_k / omega` (`l1` is `hopf`'s first Lyapunov coefficient,
//! `l2` the second in the normalization of Kuznetsov's Elements, section
//! 8.3). Along the branch of cycles held at the first angle's amplitudes
//! (`amplitude`) at the Hopf point's parameters, each cycle gives `mu` (the
//! real part of the critical pair at its load) and `r^2`, the mean of
//! `|<p, x(t)>|^2` over its period; `-mu / omega` fitted by least squares
//! in powers of `r^2` gives the coefficients. Pure: no UI, no clock.

use nalgebra::{DMatrix, DVector};

use super::amplitude::normal_form_start;
use super::hopf::{HopfPoint, Steps, hopf_point};
use super::shooting::{Shooting, steps_for};
use crate::analysis::gauss::{Monodromy, Stepper};
use crate::analysis::{AffinePencil, C64};
use crate::model::Model;

/// The normal form's radii of the cycles the coefficients are fitted to
/// (their first angle's amplitude is about `2 |q_0| r`), after a march up
/// to the first from [`START_RADIUS`].
const RADII: [f64; 8] = [0.02, 0.03, 0.04, 0.05, 0.06, 0.07, 0.08, 0.09];
const START_RADIUS: f64 = 0.005;

/// The coefficients `[l1, l2, l3, l4]` fitted from the cycles of `model`
/// born at its Hopf point at `load`; `None` where a cycle is not found.
#[must_use]
pub(crate) fn fitted_coefficients(model: &Model, load: f64) -> Option<[f64; 4]> {
    let point = hopf_point(model, load, Steps::DEFAULT.into()).ok()?.ok()?;
    let omega = point.hopf.frequency_rad_per_s;
    let pencil = AffinePencil::new(model).ok()?;
    let shooting = Shooting::of(&model.at_load(load));
    let per_radius = 2.0 * point.eigenvector[0].norm();
    let mut guess = normal_form_start(&point, per_radius * START_RADIUS);
    let mut matrix = None;
    let mut rows = Vec::new();
    for r in std::iter::once(START_RADIUS).chain(RADII) {
        let found = shooting.at_amplitude((&guess, matrix.as_ref()), per_radius * r)?;
        let cycle = &found.solved.cycle;
        guess = cycle.unknowns();
        if r >= RADII[0] {
            let growth = pencil
                .spectrum(cycle.load)
                .ok()?
                .eigenvalues
                .into_iter()
                .min_by(|x, y| {
                    let target = C64::new(0.0, omega);
                    (x - target).norm().total_cmp(&(y - target).norm())
                })?
                .re;
            let r2 = mean_square_radius(&shooting, &point, &guess)?;
            rows.push((r2, -growth / omega));
        }
        matrix = Some(found.matrix);
    }
    // -mu / omega / r^4 = l1 / r^2 + l2 + l3 r^2 + l4 r^4.
    let a = DMatrix::from_fn(rows.len(), 4, |i, j| {
        let r2 = rows[i].0;
        [1.0 / r2, 1.0, r2, r2 * r2][j]
    });
    let b = DVector::from_fn(rows.len(), |i, _| rows[i].1 / rows[i].0.powi(2));
    let x = a.svd(true, true).solve(&b, 1e-15).ok()?;
    Some([x[0], x[1], x[2], x[3]])
}

/// The mean of `|<p, x(t)>|^2` over the cycle with unknowns `u`.
fn mean_square_radius(shooting: &Shooting, point: &HopfPoint, u: &DVector<f64>) -> Option<f64> {
    let d = u.len() - 2;
    let (period, load) = (u[d], u[d + 1]);
    let field = shooting.field.at_load(load);
    let steps = steps_for(period, shooting.fastest_per_s);
    #[expect(clippy::cast_precision_loss, reason = "a step count")]
    let mut stepper = Stepper::new(&field, period / steps as f64);
    let mut x = u.rows(0, d).into_owned();
    let to_complex = |x: &DVector<f64>| x.map(|v| C64::new(v, 0.0));
    let mut sum = 0.0;
    for _ in 0..steps {
        sum += point.adjoint.dotc(&to_complex(&x)).norm_sqr();
        stepper.step(&mut x, None, Monodromy::None)?;
    }
    #[expect(clippy::cast_precision_loss, reason = "a step count")]
    Some(sum / steps as f64)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::{critical_loads, hopf_at, is_hopf};

    /// The column with drag along the rods and first rod `m1`, at its
    /// flutter onset.
    fn drag_column(m1: f64) -> (Model, f64) {
        let mut m = crate::model::preset("ziegler-1952").unwrap().model();
        m.column.drag_ns_per_m2 = 0.05;
        let m = crate::model::Axis::parse("m1", &m)
            .unwrap()
            .apply(&m, m1)
            .unwrap();
        let pencil = AffinePencil::new(&m).unwrap();
        let onset = critical_loads(&pencil, 0.0, 8.0)
            .unwrap()
            .into_iter()
            .find(|t| is_hopf(t.from, t.to))
            .unwrap()
            .load;
        (m, onset)
    }

    /// The fit's first coefficient is `hopf`'s (Kuznetsov's formula with
    /// the equations' derivatives), to 1e-5 of it (seen 4e-8 soft, 2.4e-6
    /// hard; 6e-5 and 5e-4 before `hopf`'s third derivative was
    /// extrapolated): the radius and the time are normalized as there. At
    /// the Bautin point `boundary` finds (m1 = 1.0882840) the first is
    /// nothing beside the second (seen 5e-8 against 0.4003; 2.3e-5 at
    /// m1 = 1.0880964, where it was put before), which is negative: the
    /// cycles born there are stable, the hard side's large swing exists.
    #[test]
    fn the_fitted_coefficients_are_the_normal_form_s() {
        for m1 in [2.0, 0.5] {
            let (m, p) = drag_column(m1);
            let l1 = hopf_at(&m, p, Steps::DEFAULT)
                .unwrap()
                .unwrap()
                .first_lyapunov;
            let [fitted, ..] = fitted_coefficients(&m, p).unwrap();
            assert!(
                (fitted - l1).abs() < 1e-5 * l1.abs(),
                "m1 = {m1}: {fitted} {l1}"
            );
        }
        let (m, p) = drag_column(1.088_284_013_972_936_4);
        let [l1, l2, ..] = fitted_coefficients(&m, p).unwrap();
        assert!(l1.abs() < 1e-5 * l2.abs(), "{l1} {l2}");
        assert!(l2 < -0.3, "{l2}");
    }
}
