//! The nonlinear equations of motion as a vector field on the reduced state
//! (the coordinates the motion depends on), with its Jacobian by central
//! differences: what the Hopf and limit-cycle analyses differentiate and
//! integrate.
//!
//! The reduced state is `(phi_1 .. phi_N, phi_1' .. phi_N')`, plus the
//! roller's spin rate `psi'` last when the roller has mass. The spin angle
//! `psi` is left out: no force depends on it (a cyclic coordinate), so a
//! column at rest on a sliding band is an equilibrium of the reduced field.
//! A follower column has no spin, and a massless roller's spin rate is
//! slaved to the rods' motion, so neither carries `psi'`.

use nalgebra::{DMatrix, DVector};

use crate::model::{
    ChainInertia, Model, StateVec, chain_derivative_with, chain_derivatives_with, chain_inertia,
    chain_jacobian, friction, state_len, two_rod_derivative,
};

/// The reduced field of one model at one load.
#[derive(Clone, Debug)]
pub struct Field {
    model: Model,
    rods: usize,
    /// Whether `psi'` is a coordinate (a roller with mass).
    spin: bool,
    /// The chain's mass matrix at rest (`chain_inertia`), taken once.
    mass_at_rest: ChainInertia,
    /// Equations `f(x, p)` in place of the column's, and their `p`.
    #[cfg(test)]
    constructed: Option<(Constructed, f64)>,
}

/// A field `f(x, p)` with a known answer, put in place of a column's
/// equations by the tests of what is built on the field (the flow, the
/// monodromy, the cycles' bifurcations).
#[cfg(test)]
pub(crate) type Constructed = fn(&DVector<f64>, f64, &mut DVector<f64>);

impl Field {
    /// The field of `model` (at its own load).
    #[must_use]
    pub fn new(model: &Model) -> Self {
        Self {
            model: *model,
            rods: model.column.rods,
            spin: model.roller().is_some_and(|r| r.mass_kg > 0.0),
            mass_at_rest: chain_inertia(model),
            #[cfg(test)]
            constructed: None,
        }
    }

    /// The field `f(x, p)` on a state of `2 * half` entries (the first
    /// `half` read as the angles), at `p`.
    #[cfg(test)]
    pub(crate) fn constructed(f: Constructed, half: usize, p: f64) -> Self {
        let mut model = crate::model::PresetId::Ziegler1952.model();
        model.column.rods = half;
        Self {
            constructed: Some((f, p)),
            ..Self::new(&model)
        }
    }

    /// The field of the same column at load `p`.
    #[must_use]
    pub fn at_load(&self, p: f64) -> Self {
        Self {
            model: self.model.at_load(p),
            #[cfg(test)]
            constructed: self.constructed.map(|(f, _)| (f, p)),
            ..self.clone()
        }
    }

    /// The model the field is of.
    #[must_use]
    pub fn model(&self) -> &Model {
        &self.model
    }

    /// How many rods: the reduced state's first `rods` entries are the angles.
    #[must_use]
    pub fn rods(&self) -> usize {
        self.rods
    }

    /// Whether the reduced state is `(phi, phi')` alone, so that the
    /// field's first half is exactly the state's second (a column without
    /// the spin; not a constructed field).
    #[must_use]
    pub fn mechanical(&self) -> bool {
        !self.spin && !self.is_constructed()
    }

    /// Whether constructed equations stand in for the column's (tests only).
    #[cfg_attr(
        not(test),
        expect(
            clippy::unused_self,
            reason = "constructed equations exist in tests only"
        )
    )]
    fn is_constructed(&self) -> bool {
        #[cfg(test)]
        {
            self.constructed.is_some()
        }
        #[cfg(not(test))]
        {
            false
        }
    }

    /// The reduced state's length.
    #[must_use]
    pub fn dimension(&self) -> usize {
        2 * self.rods + usize::from(self.spin)
    }

    /// The full state of the model for reduced state `x` (spin angle zero;
    /// the spin rate zero where it is not a coordinate).
    #[must_use]
    pub fn full_state(&self, x: &DVector<f64>) -> StateVec {
        let n = self.rods;
        let mut full = StateVec::zeros(state_len(n));
        for i in 0..n {
            full[i] = x[i];
            full[n + 1 + i] = x[n + i];
        }
        if self.spin {
            full[2 * n + 1] = x[2 * n];
        }
        full
    }

    /// `f(x)`: the reduced state's time derivative.
    #[must_use]
    pub fn at(&self, x: &DVector<f64>) -> DVector<f64> {
        let mut f = DVector::zeros(self.dimension());
        self.at_into(x, &mut f);
        f
    }

    /// [`Self::at`] into `out` (of the reduced state's length). Two rods'
    /// closed form allocates nothing: the flows' inner loop.
    pub fn at_into(&self, x: &DVector<f64>, out: &mut DVector<f64>) {
        #[cfg(test)]
        if let Some((f, p)) = self.constructed {
            return f(x, p, out);
        }
        let n = self.rods;
        if n == 2 {
            let spin = if self.spin { x[4] } else { 0.0 };
            let d = two_rod_derivative(&self.model, [x[0], x[1], 0.0, x[2], x[3], spin]);
            for (o, v) in out.iter_mut().zip([d[0], d[1], d[3], d[4], d[5]]) {
                *o = v;
            }
            return;
        }
        let full = self.full_state(x);
        let d = chain_derivative_with(&self.model, &self.mass_at_rest, &full);
        self.reduce_into(d, out);
    }

    /// [`Self::at_into`] at `L` points at once (a step's stages): a
    /// chain's equations of motion evaluated side by side
    /// (`chain_derivatives_with`), each to the bit as alone.
    pub fn at_into_each<const L: usize>(
        &self,
        xs: [&DVector<f64>; L],
        outs: [&mut DVector<f64>; L],
    ) {
        if self.is_constructed() || self.rods == 2 {
            for (x, out) in xs.into_iter().zip(outs) {
                self.at_into(x, out);
            }
            return;
        }
        let fulls = xs.map(|x| self.full_state(x));
        let derivatives = chain_derivatives_with(&self.model, &self.mass_at_rest, fulls.each_ref());
        for (d, out) in derivatives.into_iter().zip(outs) {
            self.reduce_into(d, out);
        }
    }

    /// The full state's derivative `d` (NaN where there is none) on the
    /// reduced state, into `out`.
    fn reduce_into(&self, d: Option<StateVec>, out: &mut DVector<f64>) {
        let n = self.rods;
        let d = d.unwrap_or_else(|| StateVec::from_element(state_len(n), f64::NAN));
        for (i, o) in out.iter_mut().enumerate() {
            *o = match i {
                i if i < n => d[i],
                i if i < 2 * n => d[n + 1 + (i - n)],
                _ => d[2 * n + 1],
            };
        }
    }

    /// The roller's slip speed on the band in state `x`, m/s (none without
    /// a roller).
    #[must_use]
    pub fn slip_m_per_s(&self, x: &DVector<f64>) -> Option<f64> {
        let roller = self.model.roller()?;
        Some(
            friction(&self.model.column, roller, &self.full_state(x))
                .slip_m_per_s
                .norm(),
        )
    }

    /// The roller's band speed, m/s (none without a roller).
    #[must_use]
    pub fn band_speed_m_per_s(&self) -> Option<f64> {
        self.model.roller().map(|r| r.band_speed_m_per_s)
    }

    /// The Jacobian of `f` at `x` in closed form where the equations are
    /// covered (`chain_jacobian`: a tip force turning with the last rod,
    /// joints' springs and dampers, the drag along the rods; not the
    /// roller), else `None`.
    fn closed_form_jacobian(&self, x: &DVector<f64>) -> Option<DMatrix<f64>> {
        if self.spin || self.is_constructed() {
            return None;
        }
        let n = self.rods;
        chain_jacobian(&self.model, &x.as_slice()[..n], &x.as_slice()[n..2 * n])
    }

    /// The Jacobian of `f` at `x`: in closed form where covered (exact to
    /// rounding, for about two evaluations of `f`), else by central
    /// differences, steps `h` scaled by each coordinate's size (at least 1).
    #[must_use]
    pub fn jacobian(&self, x: &DVector<f64>, h: f64) -> DMatrix<f64> {
        self.closed_form_jacobian(x)
            .unwrap_or_else(|| self.differences(x, h, None))
    }

    /// The Jacobian of `f` at `x` by central differences at steps `h` and
    /// `h/2`, extrapolated (Richardson's `(4 D(h/2) - D(h)) / 3`): the
    /// error of order `h^2` cancels, for twice the evaluations. For the
    /// monodromy of a long chain, whose higher derivatives are large (a
    /// 32-rod chain's trivial multiplier came out 5e-7 from 1 with
    /// [`Self::jacobian`] at `h = 1e-7`, and `h` cannot shrink much before
    /// rounding takes over).
    #[must_use]
    pub fn jacobian_extrapolated(&self, x: &DVector<f64>, h: f64) -> DMatrix<f64> {
        self.closed_form_jacobian(x)
            .unwrap_or_else(|| self.extrapolated_differences(x, h))
    }

    /// The Jacobian of `f` at `x` by central differences, steps `h` scaled
    /// by each coordinate's size, even where the closed form covers the
    /// equations: the stage iterations' Newton matrix of a flow with its
    /// exact monodromy (see [`Self::jacobian_one_sided`] for why not the
    /// closed form).
    #[must_use]
    pub fn central_differences(&self, x: &DVector<f64>, h: f64) -> DMatrix<f64> {
        self.differences(x, h, None)
    }

    /// Central differences at steps `h` and `h/2`, extrapolated.
    fn extrapolated_differences(&self, x: &DVector<f64>, h: f64) -> DMatrix<f64> {
        (self.differences(x, h / 2.0, None) * 4.0 - self.differences(x, h, None)) / 3.0
    }

    /// The Jacobian of `f` at `x` by forward differences (half the
    /// evaluations of [`Self::jacobian`], to about the square root of its
    /// accuracy: for Newton's matrices, not for the multipliers).
    ///
    /// Always by differences, even where the closed form covers the
    /// equations: as the stage iterations' Newton matrix of the flows that
    /// the shooting's Newton iterations compare, the exact matrix left a
    /// 32-rod chain's flows noisier at the shooting's tolerance (the period
    /// of a cycle next to its onset jittered by 1e-10 from one iteration to
    /// the next and never converged); with this one it converges in four.
    #[must_use]
    pub fn jacobian_one_sided(&self, x: &DVector<f64>, h: f64) -> DMatrix<f64> {
        self.differences(x, h, Some(&self.at(x)))
    }

    /// The Jacobian by differences with steps `h` scaled by each
    /// coordinate's size (at least 1): forward from `at_x` (`f(x)`) where
    /// given, else central.
    fn differences(&self, x: &DVector<f64>, h: f64, at_x: Option<&DVector<f64>>) -> DMatrix<f64> {
        let n = self.dimension();
        let mut a = DMatrix::zeros(n, n);
        let mut shifted = x.clone();
        let (mut plus, mut minus) = (DVector::zeros(n), DVector::zeros(n));
        for j in 0..n {
            let step = h * x[j].abs().max(1.0);
            shifted[j] = x[j] + step;
            self.at_into(&shifted, &mut plus);
            let (minus, width) = if let Some(at_x) = at_x {
                (at_x, step)
            } else {
                shifted[j] = x[j] - step;
                self.at_into(&shifted, &mut minus);
                (&minus, 2.0 * step)
            };
            shifted[j] = x[j];
            for i in 0..n {
                a[(i, j)] = (plus[i] - minus[i]) / width;
            }
        }
        a
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{PresetId, linearize};

    /// At rest the Jacobian is the first-order form of the analytic
    /// linearization `M x'' + D x' + K x = 0`: `[[0, I], [-M⁻¹K, -M⁻¹D]]`.
    #[test]
    fn the_jacobian_at_rest_is_the_linearization() {
        let mut model = PresetId::Ziegler1952.model().at_load(1.5);
        model.column.c1_nms_per_rad = 0.2;
        model.column.c2_nms_per_rad = 0.1;
        let field = Field::new(&model);
        let a = field.jacobian(&DVector::zeros(4), 1e-6);
        let lin = linearize(&model).expect("a valid model");
        let inverse = lin.mass.clone().try_inverse().expect("invertible");
        let (k, d) = (-&inverse * &lin.stiffness, -&inverse * &lin.damping);
        for i in 0..2 {
            for j in 0..2 {
                assert!((a[(i, 2 + j)] - f64::from(u8::from(i == j))).abs() < 1e-9);
                assert!((a[(2 + i, j)] - k[(i, j)]).abs() < 1e-7, "{a} {k}");
                assert!((a[(2 + i, 2 + j)] - d[(i, j)]).abs() < 1e-7, "{a} {d}");
            }
        }
    }

    /// Extrapolation cancels the central differences' `h^2` error: along a
    /// direction, against the exact derivative from Taylor arithmetic
    /// (`jet`), at a step large enough for that error to show.
    #[test]
    fn the_extrapolated_jacobian_cancels_the_step_s_square() {
        let mut model = PresetId::UniformRods.model().at_load(1.3);
        model.column.rods = 3;
        model.column.c1_nms_per_rad = 0.1;
        model.column.c2_nms_per_rad = 0.2;
        let field = Field::new(&model);
        let v = DVector::from_column_slice(&[0.3, -0.2, 0.5, 0.1, 0.4, -0.3]);
        let [exact, ..] =
            crate::analysis::jet::directional_derivatives(&model, &v).expect("covered");
        let at_rest = DVector::zeros(6);
        let h = 1e-2;
        let central = (field.differences(&at_rest, h, None) * &v - &exact).amax();
        let extrapolated = (field.extrapolated_differences(&at_rest, h) * &v - &exact).amax();
        assert!(central > 1e-6, "the step's error shows: {central}");
        assert!(extrapolated < 1e-3 * central, "{extrapolated} vs {central}");
        // The closed form (this chain is covered) to rounding.
        let closed = (field.jacobian_extrapolated(&at_rest, h) * &v - &exact).amax();
        assert!(closed < 1e-12 * exact.amax(), "{closed}");
    }

    /// The roller's spin rate is a coordinate only when the roller has mass.
    #[test]
    fn the_spin_rate_is_a_coordinate_of_a_roller_with_mass() {
        let roller = PresetId::Roller.model();
        let has_mass = roller.roller().is_some_and(|r| r.mass_kg > 0.0);
        assert_eq!(Field::new(&roller).dimension(), 4 + usize::from(has_mass));
        assert_eq!(Field::new(&PresetId::Ziegler1952.model()).dimension(), 4);
    }
}
