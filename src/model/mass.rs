//! The chain's inertia: its mass matrix at rest on the rods' angles, and
//! the two-rod coefficients of the kinetic energy (eq. 13).

use nalgebra::DMatrix;

use super::params::{Column, Model};

/// The chain's mass matrix about the straight column by its generators:
/// with rod i's points at `sum_{j<i} l_j e_j + s e_i`,
/// `M_jk = sum_i m_i c_ij c_ik + delta_jk I_j + m_end l_j l_k`, where
/// `c_ij = l_j` (j < i), `s_i` (j = i), 0 (j > i), and the end mass (tip
/// mass and roller) with the roller's yaw inertia on the last rod. Off the
/// diagonal an entry is a product, `M_jk = l_j g_k` for `j < k`, with
/// `g_k = (m_beyond_k + m_end) l_k + m_k s_k` the first moment about joint k
/// of rod k and all it carries: a rank-two structure that the deformed
/// chain keeps (`cos(phi_j - phi_k)` is a dot product), which
/// `chain_factor` solves in O(N).
#[derive(Clone, Debug, PartialEq)]
pub struct ChainInertia {
    /// `M_jj`, kg m^2.
    pub diagonal_kg_m2: Vec<f64>,
    /// `l_j`, the factor of the row's inner rod, m.
    pub lever_m: Vec<f64>,
    /// `g_k`, the factor of the column's outer rod, kg m.
    pub moment_kg_m: Vec<f64>,
}

impl ChainInertia {
    /// The mass matrix at rest, `N x N`.
    #[must_use]
    pub fn matrix(&self) -> DMatrix<f64> {
        let n = self.diagonal_kg_m2.len();
        DMatrix::from_fn(n, n, |j, k| {
            if j == k {
                self.diagonal_kg_m2[j]
            } else {
                self.lever_m[j.min(k)] * self.moment_kg_m[j.max(k)]
            }
        })
    }
}

/// The generators of `model`'s chain mass matrix (see [`ChainInertia`]).
#[must_use]
pub fn chain_inertia(model: &Model) -> ChainInertia {
    let column = &model.column;
    let n = column.rods;
    let (roller_kg, yaw_kg_m2) = model
        .roller()
        .map_or((0.0, 0.0), |r| (r.mass_kg, r.yaw_inertia_kg_m2()));
    let end_kg = column.tip_mass_kg + roller_kg;
    // The mass of the rods beyond rod i, for i from the tip down.
    let mut beyond_kg = vec![0.0; n];
    for i in (0..n.saturating_sub(1)).rev() {
        beyond_kg[i] = beyond_kg[i + 1] + column.rod(i + 1).mass_kg;
    }
    let lever_m: Vec<f64> = (0..n).map(|i| column.rod(i).length_m).collect();
    let moment_kg_m = (0..n)
        .map(|i| {
            let rod = column.rod(i);
            (beyond_kg[i] + end_kg) * rod.length_m + rod.mass_kg * rod.com_m
        })
        .collect();
    let diagonal_kg_m2 = (0..n)
        .map(|i| {
            let rod = column.rod(i);
            (beyond_kg[i] + end_kg) * rod.length_m.powi(2)
                + rod.inertia_about_joint_kg_m2()
                + if i + 1 == n { yaw_kg_m2 } else { 0.0 }
        })
        .collect();
    ChainInertia {
        diagonal_kg_m2,
        lever_m,
        moment_kg_m,
    }
}

/// The chain's mass matrix about the straight column, on the rods' angles
/// `(phi_1 .. phi_N)` (see [`ChainInertia`]).
#[must_use]
pub fn chain_mass_matrix(model: &Model) -> DMatrix<f64> {
    chain_inertia(model).matrix()
}

/// The three inertia coefficients of the kinetic energy,
/// `T = A phi1'^2/2 + B cos(phi2 - phi1) phi1' phi2' + C phi2'^2/2 + J psi'^2/2` (eq. 13).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Inertia {
    pub a_kg_m2: f64,
    pub b_kg_m2: f64,
    pub c_kg_m2: f64,
    /// Spin inertia of the roller (0 without a roller).
    pub spin_kg_m2: f64,
}

impl Model {
    /// Inertia coefficients of the kinetic energy (13), for any mass model.
    #[must_use]
    pub fn inertia(&self) -> Inertia {
        let Column {
            rod1,
            rod2,
            tip_mass_kg,
            ..
        } = self.column;
        let (roller_mass_kg, yaw_kg_m2, spin_kg_m2) = self.roller().map_or((0.0, 0.0, 0.0), |r| {
            (
                r.mass_kg,
                r.yaw_inertia_kg_m2(),
                r.spin_inertia_kg_m2(rod2.length_m),
            )
        });
        let outer_mass_kg = tip_mass_kg + roller_mass_kg;
        let (l1, l2) = (rod1.length_m, rod2.length_m);
        Inertia {
            a_kg_m2: rod1.inertia_about_joint_kg_m2() + (rod2.mass_kg + outer_mass_kg) * l1 * l1,
            b_kg_m2: (rod2.mass_kg * rod2.com_m + outer_mass_kg * l2) * l1,
            c_kg_m2: rod2.inertia_about_joint_kg_m2() + outer_mass_kg * l2 * l2 + yaw_kg_m2,
            spin_kg_m2,
        }
    }
}
