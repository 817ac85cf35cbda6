//! The Jacobian of a chain's equations of motion in closed form, for a
//! tip force that turns with the last rod (follower, partial or dead load),
//! the joints' springs and dampers and the drag along the rods: one
//! factorization of the mass matrix and 2N solves, where differences take
//! 2N or more evaluations of the equations (each its own factorization).
//! The roller is not written here.
//!
//! With `M(phi) phi'' = r(phi, phi')` (Lagrange's equations, see `chain`),
//! `M_jl = mu_jl cos(phi_j - phi_l)`, and `r_j = Q_j + T_j - sum_k mu_jk
//! sin(phi_j - phi_k) phi_k'^2` (joints, tip load, the centripetal terms),
//! the accelerations `a` have
//!
//! ```text
//! da/dphi_m  = M^-1 (dr/dphi_m - (dM/dphi_m) a),   da/dphi'_m = M^-1 dr/dphi'_m,
//! ```
//!
//! where `dM/dphi_m` has only row and column m. The follower force
//! `-P (cos theta, sin theta)`, `theta = eta phi_N`, works on rod j through
//! `l_j (-sin phi_j, cos phi_j)`: `T_j = -P l_j sin(theta - phi_j)`.

use nalgebra::DMatrix;

use super::chain::lagrange_rhs;
use super::loads::{angles_trig, tip_load_trig};
use super::mass::chain_inertia;
use super::params::{Load, Model};
use super::state::{StateVec, StateViewMut, state_len};

/// The Jacobian of the reduced field `(phi, phi') -> (phi', phi'')` of
/// `model`'s chain at these angles and rates, `2N x 2N`; `None` where the
/// equations are not covered (the roller) or the mass matrix cannot be
/// factored.
#[must_use]
pub fn chain_jacobian(model: &Model, phi: &[f64], rate: &[f64]) -> Option<DMatrix<f64>> {
    let column = &model.column;
    let Load::Follower { force_n, eta } = model.load else {
        return None;
    };
    let n = phi.len();
    let mut state = StateVec::zeros(state_len(n));
    let mut view = StateViewMut::new(&mut state);
    view.angles_rad().copy_from_slice(phi);
    view.rates_rad_per_s().copy_from_slice(rate);
    // The equations themselves (`chain::lagrange_rhs`): the mass matrix,
    // factored, and the accelerations. Factored dense here, not by its
    // structure as in the equations of motion (`chain_factor`): the two
    // Jacobians agree to 5e-14 of their largest entry, yet with the
    // structured one the shooting's Newton iterations on a 32-rod chain's
    // cycle next to its onset (whose monodromy this Jacobian builds) no
    // longer converged. They are that sensitive there; until that is
    // mended, this keeps the arithmetic they were tested with.
    let inertia = chain_inertia(model);
    let mu = inertia.matrix();
    let trig = angles_trig(&state);
    let tip = tip_load_trig(model, &state, &trig).generalized_n_m;
    let mut a = lagrange_rhs(model, &inertia, &state, &tip[..n], &trig);
    let factor = DMatrix::from_fn(n, n, |j, k| mu[(j, k)] * cos_diff(&trig, j, k)).cholesky()?;
    cholesky_solve_rows(factor.l_dirty(), &mut a);

    let theta = eta * phi[n - 1];
    let length = |j: usize| column.rod(j).length_m;

    // dr/dphi - (dM/dphi) a (left n columns) and dr/dphi' (right n), each
    // row of them a column of `rhs_t` (so that the solve below sweeps along
    // contiguous rows).
    let mut rhs_t = DMatrix::<f64>::zeros(2 * n, n);
    for i in 0..n {
        // Joint i's torque `-k_i b_i - c_i b_i'` on its bend `b_i = phi_i -
        // phi_{i-1}` acts on rod i (+) and back on rod i - 1 (-), through
        // the bend's dependence on phi_i (+1) and phi_{i-1} (-1).
        let (k, c) = (column.spring_nm_per_rad(i), column.damper_nms_per_rad(i));
        let bent: &[(usize, f64)] = if i == 0 {
            &[(0, 1.0)]
        } else {
            &[(i, 1.0), (i - 1, -1.0)]
        };
        for &(m, sign) in bent {
            rhs_t[(m, i)] -= k * sign;
            rhs_t[(n + m, i)] -= c * sign;
            if i > 0 {
                rhs_t[(m, i - 1)] += k * sign;
                rhs_t[(n + m, i - 1)] += c * sign;
            }
        }
    }
    for j in 0..n {
        let tip_slope = force_n * length(j) * (theta - phi[j]).cos();
        rhs_t[(j, j)] += tip_slope;
        rhs_t[(n - 1, j)] -= eta * tip_slope;
        for m in (0..n).filter(|&m| m != j) {
            let (s, c) = (sin_diff(&trig, j, m), cos_diff(&trig, j, m));
            // The centripetal term's and dM/dphi_m a's parts.
            rhs_t[(m, j)] += mu[(j, m)] * c * rate[m] * rate[m] - mu[(j, m)] * s * a[m];
            rhs_t[(j, j)] -= mu[(j, m)] * c * rate[m] * rate[m] - mu[(j, m)] * s * a[m];
            rhs_t[(n + m, j)] -= 2.0 * mu[(j, m)] * s * rate[m];
        }
    }
    if column.drag_ns_per_m2 != 0.0 {
        add_drag_derivatives(column, rate, &trig, &mut rhs_t);
    }
    cholesky_solve_rows(factor.l_dirty(), rhs_t.as_mut_slice());
    let mut jacobian = DMatrix::<f64>::zeros(2 * n, 2 * n);
    for i in 0..n {
        jacobian[(i, n + i)] = 1.0;
    }
    jacobian
        .view_mut((n, 0), (n, 2 * n))
        .copy_from(&rhs_t.transpose());
    Some(jacobian)
}

/// Adds to `rhs_t` (laid out as in [`chain_jacobian`]: row `m` and `n + m`
/// the derivatives by `phi_m` and `phi'_m`, column `j` those of `Q_j`) the
/// derivatives of the drag's generalized forces (`chain`'s
/// `joint_and_drag_forces`, physics.md's external drag):
///
/// ```text
/// Q_m = -c (M_m + l_m sum_{i>m} cos(phi_i - phi_m) T_i),
/// T_i = l_i u_i + l_i^2/2 phi_i',   M_i = l_i^2/2 u_i + l_i^3/3 phi_i',
/// u_i = sum_{j<i} l_j cos(phi_i - phi_j) phi_j'
/// ```
///
/// (`T_i` and `M_i` the integrals of the velocity across rod i and of its
/// moment about the rod's inner joint). Its derivative by the rates is the
/// Rayleigh function's Hessian, symmetric; O(N^3) in all, as the solve.
fn add_drag_derivatives(
    column: &super::params::Column,
    rate: &[f64],
    trig: &[(f64, f64)],
    rhs_t: &mut DMatrix<f64>,
) {
    let n = rate.len();
    let c = column.drag_ns_per_m2;
    let l: Vec<f64> = (0..n).map(|i| column.rod(i).length_m).collect();
    let cos = |i: usize, j: usize| cos_diff(trig, i, j);
    let sin = |i: usize, j: usize| sin_diff(trig, i, j);
    // u_i, its derivative by phi_i (-v_i) and the rod's integral T_i.
    let u: Vec<f64> = (0..n)
        .map(|i| (0..i).map(|j| l[j] * cos(i, j) * rate[j]).sum())
        .collect();
    let v: Vec<f64> = (0..n)
        .map(|i| (0..i).map(|j| l[j] * sin(i, j) * rate[j]).sum())
        .collect();
    let total: Vec<f64> = (0..n)
        .map(|i| l[i] * u[i] + l[i] * l[i] / 2.0 * rate[i])
        .collect();
    for m in 0..n {
        for k in 0..n {
            // The rods beyond both m and k, through u_i's dependence on phi_k
            // and phi_k'.
            let (mut by_rate, mut by_angle) = (0.0, 0.0);
            for (i, &l_i) in l.iter().enumerate().skip(m.max(k) + 1) {
                by_rate += cos(i, m) * l_i * cos(i, k);
                by_angle += cos(i, m) * l_i * sin(i, k);
            }
            let mut d_rate = l[m] * l[k] * by_rate;
            let mut d_angle = l[m] * l[k] * rate[k] * by_angle;
            match k.cmp(&m) {
                std::cmp::Ordering::Less => {
                    // M_m through u_m.
                    d_rate += l[m] * l[m] / 2.0 * l[k] * cos(m, k);
                    d_angle += l[m] * l[m] / 2.0 * l[k] * sin(m, k) * rate[k];
                }
                std::cmp::Ordering::Equal => {
                    d_rate += l[m].powi(3) / 3.0;
                    let turned: f64 = (m + 1..n).map(|i| sin(i, m) * total[i]).sum();
                    d_angle += -l[m] * l[m] / 2.0 * v[m] + l[m] * turned;
                }
                std::cmp::Ordering::Greater => {
                    // T_k itself, its cosine and its u_k.
                    d_rate += l[m] * cos(k, m) * l[k] * l[k] / 2.0;
                    d_angle += l[m] * (-sin(k, m) * total[k] - cos(k, m) * l[k] * v[k]);
                }
            }
            rhs_t[(k, m)] -= c * d_angle;
            rhs_t[(n + k, m)] -= c * d_rate;
        }
    }
}

/// `cos(phi_j - phi_k)` from each angle's `(sin, cos)` in `trig`.
fn cos_diff(trig: &[(f64, f64)], j: usize, k: usize) -> f64 {
    trig[j].1 * trig[k].1 + trig[j].0 * trig[k].0
}

/// `sin(phi_j - phi_k)` from each angle's `(sin, cos)` in `trig`.
fn sin_diff(trig: &[(f64, f64)], j: usize, k: usize) -> f64 {
    trig[j].0 * trig[k].1 - trig[j].1 * trig[k].0
}

/// Solves `L L^T X = B` in place, `L` the lower triangle of `l` (column
/// major, `n x n`) and `B` given by its rows, one after another (`bt`, the
/// rows' length `m`), with the operations nalgebra's `Cholesky::solve`
/// does on each column, in the same order, so that each entry is the same
/// to the bit; but all columns at once, along contiguous rows, which the
/// compiler vectorizes (nalgebra's column-by-column solve through generic
/// views took 9% of a 32-rod chain's cycles).
fn cholesky_solve_rows(l: &DMatrix<f64>, bt: &mut [f64]) {
    let n = l.nrows();
    let m = bt.len() / n.max(1);
    let l = l.as_slice();
    // L Y = B: row i of Y, then column i of L scaled by it off the rows
    // below.
    for i in 0..n {
        let diag = l[i * n + i];
        let (done, below) = bt.split_at_mut((i + 1) * m);
        let y = &mut done[i * m..];
        for value in y.iter_mut() {
            *value /= diag;
        }
        for (row, &entry) in below
            .chunks_exact_mut(m)
            .zip(&l[i * n + i + 1..(i + 1) * n])
        {
            for (value, &y) in row.iter_mut().zip(y.iter()) {
                *value += -y * entry;
            }
        }
    }
    // L^T X = Y: x_i = (y_i - sum_{k>i} L_ki x_k) / L_ii, the sum as
    // nalgebra's `dot` sums a dynamic vector: eight running sums over whole
    // blocks of eight (lane j takes k = i + 1 + 8 b + j), paired (0 with 4,
    // 1 with 5, ...) into the total, then the rest one by one.
    let mut sums = vec![0.0; 8 * m];
    let mut total = vec![0.0; m];
    for i in (0..n).rev() {
        let below = n - i - 1;
        let blocks = below / 8 * 8;
        sums.fill(0.0);
        total.fill(0.0);
        let (head, tail) = bt.split_at_mut((i + 1) * m);
        for (offset, row) in tail.chunks_exact(m).enumerate() {
            let entry = l[i * n + i + 1 + offset];
            let into = if offset < blocks {
                &mut sums[(offset % 8) * m..(offset % 8 + 1) * m]
            } else {
                if offset == blocks {
                    add_pairs(&sums, &mut total, m);
                }
                &mut total[..]
            };
            for (sum, &x) in into.iter_mut().zip(row) {
                *sum += entry * x;
            }
        }
        if blocks == below {
            add_pairs(&sums, &mut total, m);
        }
        let diag = l[i * n + i];
        for (value, &dot) in head[i * m..].iter_mut().zip(&total) {
            *value = (*value - dot) / diag;
        }
    }
}

/// `total += (sums_0 + sums_4) + ... + (sums_3 + sums_7)`, pair by pair,
/// for rows of length `m`.
fn add_pairs(sums: &[f64], total: &mut [f64], m: usize) {
    for lane in 0..4 {
        let (low, high) = (
            &sums[lane * m..(lane + 1) * m],
            &sums[(lane + 4) * m..(lane + 5) * m],
        );
        for ((t, &a), &b) in total.iter_mut().zip(low).zip(high) {
            *t += a + b;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{PresetId, StateVec, state_derivative, state_len};

    /// The row-wise solve gives nalgebra's `Cholesky::solve` to the bit,
    /// with and without a remainder past the blocks of eight, and solves
    /// the system.
    #[test]
    fn the_row_wise_solve_is_nalgebra_s_to_the_bit() {
        for (n, m) in [(1_u32, 3_u32), (3, 5), (8, 2), (9, 4), (19, 7), (32, 64)] {
            let (n, m, size) = (n as usize, m as usize, f64::from(n));
            let base = DMatrix::from_fn(n, n, |i, j| {
                f64::from(u32::try_from(i * 7 + j * 3).expect("small")).sin()
            });
            let matrix = &base * base.transpose() + DMatrix::identity(n, n) * 0.5;
            let b = DMatrix::from_fn(n, m, |i, j| {
                f64::from(u32::try_from(i * 5 + j * 11).expect("small")).cos()
            });
            let factor = matrix.clone().cholesky().expect("positive definite");
            let expected = factor.solve(&b);
            let mut rows = b.transpose();
            cholesky_solve_rows(factor.l_dirty(), rows.as_mut_slice());
            let got = rows.transpose();
            for (x, y) in got.iter().zip(expected.iter()) {
                assert_eq!(x.to_bits(), y.to_bits(), "n = {n}, m = {m}");
            }
            assert!((&matrix * &got - &b).amax() < 1e-9 * b.amax() * size);
        }
    }

    /// The reduced field `(phi, phi') -> (phi', phi'')` by the equations
    /// of motion themselves.
    fn field(model: &Model, x: &[f64]) -> Vec<f64> {
        let n = model.column.rods;
        let mut full = StateVec::zeros(state_len(n));
        full.as_mut_slice()[..n].copy_from_slice(&x[..n]);
        full.as_mut_slice()[n + 1..=2 * n].copy_from_slice(&x[n..]);
        let d = state_derivative(model, &full);
        [&d.as_slice()[..n], &d.as_slice()[n + 1..=2 * n]].concat()
    }

    /// The Jacobian by central differences at `h` and `h/2`, extrapolated
    /// (error of order `h^4`).
    fn differences(model: &Model, x: &[f64], h: f64) -> DMatrix<f64> {
        let d = x.len();
        let central = |h: f64| {
            DMatrix::from_fn(d, d, |i, j| {
                let (mut plus, mut minus) = (x.to_vec(), x.to_vec());
                plus[j] += h;
                minus[j] -= h;
                (field(model, &plus)[i] - field(model, &minus)[i]) / (2.0 * h)
            })
        };
        (central(h / 2.0) * 4.0 - central(h)) / 3.0
    }

    /// Far from rest (angles up to 1.2 rad, fast rates), with every joint's
    /// spring and damper, a tip mass and a partial follower, the closed
    /// form agrees with differences of the equations of motion (the
    /// chain's general ones for five rods, the closed form of `two_rods`
    /// for two) to their accuracy; likewise for a follower and a dead load,
    /// and with the drag along the rods (rods of unequal lengths).
    #[test]
    fn the_closed_form_is_the_derivative_of_the_equations() {
        for (rods, eta, drag) in [
            (5, 0.6, 0.0),
            (2, 1.0, 0.0),
            (3, 0.0, 0.0),
            (2, 0.3, 0.0),
            (5, 0.6, 0.07),
            (2, 1.0, 0.05),
            (4, 1.0, 0.3),
        ] {
            let mut model = PresetId::UniformRods.model().at_load(1.7);
            model.column.rods = rods;
            model.column.drag_ns_per_m2 = drag;
            model.column.rod1.length_m = 1.3;
            model.column.c1_nms_per_rad = 0.3;
            model.column.c2_nms_per_rad = 0.2;
            model.column.k2_nm_per_rad = 0.13;
            model.column.tip_mass_kg = 0.4;
            if let Load::Follower { eta: e, .. } = &mut model.load {
                *e = eta;
            }
            #[expect(clippy::cast_precision_loss, reason = "a few rods")]
            let x: Vec<f64> = (0..2 * rods)
                .map(|i| 1.2 * (0.7 * i as f64 + 0.3).sin() + 0.1 * i as f64)
                .collect();
            let closed = chain_jacobian(&model, &x[..rods], &x[rods..]).expect("covered");
            let reference = differences(&model, &x, 1e-3);
            let off = (&closed - &reference).amax();
            assert!(
                off < 1e-8 * reference.amax(),
                "{rods} rods, eta {eta}, drag {drag}: {off}\n{closed}\n{reference}"
            );
        }
    }

    /// The roller is left to differences.
    #[test]
    fn the_roller_is_not_covered() {
        let roller = PresetId::Roller.model();
        assert!(chain_jacobian(&roller, &[0.1, 0.2], &[0.0, 0.0]).is_none());
    }
}
