//! Exact directional derivatives of the equations of motion, the second
//! means beside the central differences of `hopf`: truncated Taylor
//! arithmetic ("jets", to third order in one variable) and the equations of
//! a follower column with joint springs and dampers written over it again
//! (Lagrange's equations of the chain, the follower force's generalized
//! forces), so that `f(t v)` comes out as its Taylor polynomial in `t`.
//! Drag along the rods and the roller are not written here.

use std::ops::{Add, Mul, Neg, Sub};

use nalgebra::DVector;

use crate::model::{Load, Model, chain_mass_matrix};

/// `a0 + a1 t + a2 t^2 + a3 t^3`, the rest dropped.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Jet([f64; 4]);

impl Jet {
    const ZERO: Self = Self([0.0; 4]);

    /// `sin` and `cos`: with `a = a0 + d`, `sin a = sin a0 cos d + cos a0
    /// sin d`, where `cos d = 1 - d^2/2` and `sin d = d - d^3/6` to third
    /// order (`d` has no constant term).
    fn sin_cos(self) -> (Self, Self) {
        let [a0, a1, a2, a3] = self.0;
        let cos_d = Self([1.0, 0.0, -a1 * a1 / 2.0, -a1 * a2]);
        let sin_d = Self([0.0, a1, a2, a3 - a1 * a1 * a1 / 6.0]);
        let (s, c) = a0.sin_cos();
        (cos_d * s + sin_d * c, cos_d * c - sin_d * s)
    }

    /// `1 / self`, by the recurrence of series division.
    fn recip(self) -> Option<Self> {
        let [b0, b1, b2, b3] = self.0;
        if b0 == 0.0 || !b0.is_finite() {
            return None;
        }
        let r0 = 1.0 / b0;
        let r1 = -b1 * r0 / b0;
        let r2 = -(b1 * r1 + b2 * r0) / b0;
        let r3 = -(b1 * r2 + b2 * r1 + b3 * r0) / b0;
        Some(Self([r0, r1, r2, r3]))
    }
}

impl Add for Jet {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Self(std::array::from_fn(|k| self.0[k] + o.0[k]))
    }
}

impl Sub for Jet {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Self(std::array::from_fn(|k| self.0[k] - o.0[k]))
    }
}

impl Neg for Jet {
    type Output = Self;
    fn neg(self) -> Self {
        Self(self.0.map(|a| -a))
    }
}

impl Mul for Jet {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        Self(std::array::from_fn(|k| {
            (0..=k).map(|i| self.0[i] * o.0[k - i]).sum()
        }))
    }
}

impl Mul<f64> for Jet {
    type Output = Self;
    fn mul(self, s: f64) -> Self {
        Self(self.0.map(|a| a * s))
    }
}

/// Whether [`directional_derivatives`] covers `model`: a follower column
/// (any chain, any eta) with joint springs and dampers and no drag.
#[must_use]
pub fn covers(model: &Model) -> bool {
    matches!(model.load, Load::Follower { .. }) && model.column.drag_ns_per_m2 == 0.0
}

/// The reduced field `(phi', phi'')` of a covered `model` on jets: Lagrange's
/// equations `sum_k mu_jk [cos(phi_j - phi_k) phi_k'' + sin(phi_j - phi_k)
/// phi_k'^2] = Q_j`, solved by Gaussian elimination (the mass matrix is
/// positive definite: no pivoting needed).
fn field(model: &Model, x: &[Jet]) -> Option<Vec<Jet>> {
    let Load::Follower { force_n, eta } = model.load else {
        return None;
    };
    let column = &model.column;
    let n = column.rods;
    let (phi, rate) = x.split_at(n);
    let mu = chain_mass_matrix(model);
    // The joints' springs and dampers: joint i on phi_i - phi_(i-1).
    let mut q = vec![Jet::ZERO; n];
    for i in 0..n {
        let (bend, bend_rate) = if i == 0 {
            (phi[0], rate[0])
        } else {
            (phi[i] - phi[i - 1], rate[i] - rate[i - 1])
        };
        let torque =
            -(bend * column.spring_nm_per_rad(i) + bend_rate * column.damper_nms_per_rad(i));
        q[i] = q[i] + torque;
        if i > 0 {
            q[i - 1] = q[i - 1] - torque;
        }
    }
    // The follower force -P (cos, sin)(eta phi_N) on the tip: its work on
    // rod i's swing l_i t_i is -P l_i sin(eta phi_N - phi_i).
    for i in 0..n {
        let (sin, _) = (phi[n - 1] * eta - phi[i]).sin_cos();
        q[i] = q[i] - sin * (force_n * column.rod(i).length_m);
    }
    let mut mass = vec![vec![Jet::ZERO; n]; n];
    let mut rhs = q;
    for j in 0..n {
        for k in 0..n {
            let (sin, cos) = (phi[j] - phi[k]).sin_cos();
            mass[j][k] = cos * mu[(j, k)];
            rhs[j] = rhs[j] - sin * rate[k] * rate[k] * mu[(j, k)];
        }
    }
    let accelerations = solve(mass, rhs)?;
    Some(rate.iter().copied().chain(accelerations).collect())
}

/// `mass⁻¹ rhs` by Gaussian elimination without pivoting.
fn solve(mut mass: Vec<Vec<Jet>>, mut rhs: Vec<Jet>) -> Option<Vec<Jet>> {
    let n = rhs.len();
    for col in 0..n {
        let pivot = mass[col][col].recip()?;
        for row in col + 1..n {
            let factor = mass[row][col] * pivot;
            let pivot_row = mass[col].clone();
            for (entry, above) in mass[row].iter_mut().zip(pivot_row).skip(col) {
                *entry = *entry - factor * above;
            }
            rhs[row] = rhs[row] - factor * rhs[col];
        }
    }
    let mut out = vec![Jet::ZERO; n];
    for row in (0..n).rev() {
        let known = (row + 1..n).fold(rhs[row], |sum, k| sum - mass[row][k] * out[k]);
        out[row] = known * mass[row][row].recip()?;
    }
    Some(out)
}

/// The first, second and third directional derivatives `D^k f(0)[v, .., v]`
/// of the reduced field of a covered `model` at rest, along `v` (angles
/// then rates): `k!` times the Taylor coefficients of `f(t v)`. `None` for
/// a model not covered or a singular mass matrix.
#[must_use]
pub fn directional_derivatives(model: &Model, v: &DVector<f64>) -> Option<[DVector<f64>; 3]> {
    if !covers(model) {
        return None;
    }
    let x: Vec<Jet> = v.iter().map(|&vi| Jet([0.0, vi, 0.0, 0.0])).collect();
    let f = field(model, &x)?;
    let order = |k: usize, factorial: f64| {
        DVector::from_iterator(f.len(), f.iter().map(|j| j.0[k] * factorial))
    };
    Some([order(1, 1.0), order(2, 2.0), order(3, 6.0)])
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The jets' products, quotients and sines are the Taylor polynomials
    /// of the functions of `t` they stand for.
    #[test]
    fn jets_are_truncated_taylor_series() {
        let t = Jet([0.3, 1.0, 0.0, 0.0]);
        let (sin, cos) = t.sin_cos();
        // sin(0.3 + t) = sin 0.3 + cos 0.3 t - sin 0.3 t^2/2 - cos 0.3 t^3/6.
        let (s, c) = 0.3f64.sin_cos();
        let expected = [s, c, -s / 2.0, -c / 6.0];
        for (got, want) in sin.0.iter().zip(expected) {
            assert!((got - want).abs() < 1e-15);
        }
        let one = sin * sin + cos * cos;
        assert!((one.0[0] - 1.0).abs() < 1e-15 && one.0[1..].iter().all(|a| a.abs() < 1e-15));
        // 1 / (1 - t) = 1 + t + t^2 + t^3.
        let r = (Jet([1.0, 0.0, 0.0, 0.0]) - Jet([0.0, 1.0, 0.0, 0.0]))
            .recip()
            .unwrap();
        assert_eq!(r.0, [1.0, 1.0, 1.0, 1.0]);
    }

    /// On the equations as the model writes them (the closed form of two
    /// rods, the chain's of three), the jets' derivatives agree with
    /// central differences along a direction, to the differences' own
    /// truncation (h^2 times the next derivative).
    #[test]
    fn the_jets_differentiate_the_model_s_equations() {
        for rods in [2, 3] {
            let mut model = crate::model::PresetId::UniformRods.model().at_load(1.3);
            model.column.rods = rods;
            model.column.c1_nms_per_rad = 0.1;
            model.column.c2_nms_per_rad = 0.2;
            let reduced = crate::analysis::field::Field::new(&model);
            let v = DVector::from_fn(2 * rods, |i, _| [0.3, -0.2, 0.5, 0.1, 0.4, -0.3][i]);
            let [d1, d2, d3] = directional_derivatives(&model, &v).unwrap();
            let at = |t: f64| reduced.at(&(&v * t));
            let h = 1e-3;
            let fd1 = (at(h) - at(-h)) / (2.0 * h);
            let fd2 = (at(h) - at(0.0) * 2.0 + at(-h)) / (h * h);
            let fd3 = (at(2.0 * h) - at(h) * 2.0 + at(-h) * 2.0 - at(-2.0 * h)) / (2.0 * h * h * h);
            assert!((&d1 - &fd1).amax() < 1e-5 * d1.amax(), "{rods}: {d1} {fd1}");
            assert!(
                (&d2 - &fd2).amax() < 1e-4 * d2.amax().max(1e-3),
                "{rods}: {d2} {fd2}"
            );
            assert!((&d3 - &fd3).amax() < 1e-3 * d3.amax(), "{rods}: {d3} {fd3}");
        }
    }
}
