//! The linearization about the straight column: analytic M, D, K (physics.md section 4).

use nalgebra::DMatrix;

use super::ModelError;
use super::mass::chain_mass_matrix;
use super::params::Column;
use super::valid::AsValid;

/// `M x'' + D x' + K x = 0` about the straight column, `x = (phi_1 .. phi_N[, psi])`.
#[derive(Clone, Debug, PartialEq)]
pub struct LinearModel {
    pub mass: DMatrix<f64>,
    /// Joint dampers plus the roller's slip damping `G = (mu R / V) g g^T`.
    pub damping: DMatrix<f64>,
    /// Springs plus the load's stiffness (non-symmetric for circulatory loads).
    pub stiffness: DMatrix<f64>,
    /// Zero roots of the model that the matrices above do not carry: a massless
    /// roller's free spin angle, whose rate is slaved (see [`linearize`]).
    pub extra_zero_roots: usize,
}

/// The external drag's damping matrix on the rods' angles, from its
/// Rayleigh function: `D_jk = c_ext sum_i int_0^l_i a_ij a_ik ds` with
/// `a_ij = l_j` (j < i), `s` (j = i), 0 (j > i) (physics.md section 4).
fn drag_matrix(column: &Column) -> DMatrix<f64> {
    let n = column.rods;
    let length = |i: usize| column.rod(i).length_m;
    // The length of the rods beyond rod i.
    let mut beyond_m = vec![0.0; n];
    for i in (0..n.saturating_sub(1)).rev() {
        beyond_m[i] = beyond_m[i + 1] + length(i + 1);
    }
    DMatrix::from_fn(n, n, |j, k| {
        let (lo, hi) = (j.min(k), j.max(k));
        let own = if j == k {
            length(j).powi(3) / 3.0
        } else {
            length(lo) * length(hi).powi(2) / 2.0
        };
        column.drag_ns_per_m2 * (own + beyond_m[hi] * length(lo) * length(hi))
    })
}

/// The joints' springs and dampers on the rods' angles: joint i acts on
/// `phi_i - phi_{i-1}` (`phi_0 = 0`), so both matrices are tridiagonal.
#[must_use]
pub fn joint_matrices(column: &Column) -> (DMatrix<f64>, DMatrix<f64>) {
    let n = column.rods;
    let mut stiffness = DMatrix::zeros(n, n);
    let mut damping = DMatrix::zeros(n, n);
    for i in 0..n {
        let (k, c) = (column.spring_nm_per_rad(i), column.damper_nms_per_rad(i));
        stiffness[(i, i)] += k;
        damping[(i, i)] += c;
        if i > 0 {
            stiffness[(i - 1, i - 1)] += k;
            stiffness[(i - 1, i)] -= k;
            stiffness[(i, i - 1)] -= k;
            damping[(i - 1, i - 1)] += c;
            damping[(i - 1, i)] -= c;
            damping[(i, i - 1)] -= c;
        }
    }
    (stiffness, damping)
}

/// The analytic linearization of `model` about `phi = 0` at rest.
///
/// A massless roller (`m3 = 0`) turns its spin equation into the constraint
/// `Q3 = 0`; eliminating the slaved spin rate leaves exactly the ideal follower
/// column with `P = mu R` (physics.md section 3), plus the spin angle's zero root.
///
/// # Errors
/// The model's own validation; and a roller with `V = 0`, where Coulomb
/// friction is not differentiable about the state of rest.
pub fn linearize(model: &impl AsValid) -> Result<LinearModel, ModelError> {
    let valid = model.as_valid()?;
    let model = valid.model();
    let column = &model.column;
    if let Some(roller) = model.roller()
        && roller.band_speed_m_per_s <= 0.0
    {
        return Err(ModelError::invalid(
            super::Key::V,
            roller.band_speed_m_per_s,
            super::Allowed::BandAtRest,
        ));
    }
    // A massless roller is linearized as the ideal follower column it equals.
    let roller = model.roller().filter(|roller| roller.mass_kg > 0.0);
    let rods = column.rods;
    let last = rods - 1;
    let n = rods + usize::from(roller.is_some());
    let length = |i: usize| column.rod(i).length_m;
    let mut mass = DMatrix::zeros(n, n);
    mass.view_mut((0, 0), (rods, rods))
        .copy_from(&chain_mass_matrix(model));
    let mut damping = DMatrix::zeros(n, n);
    damping
        .view_mut((0, 0), (rods, rods))
        .copy_from(&drag_matrix(column));
    let (joint_stiffness, joint_damping) = joint_matrices(column);
    let mut rods_damping = damping.view_mut((0, 0), (rods, rods));
    rods_damping += &joint_damping;
    let mut stiffness = DMatrix::zeros(n, n);
    stiffness
        .view_mut((0, 0), (rods, rods))
        .copy_from(&joint_stiffness);
    let force_n = model.follower_force_n();
    // Every tip force pushes each rod by P l_i sin(phi_i - ...): the -P l_i
    // on the diagonal; a follower (eta) or the friction adds the rest.
    for i in 0..rods {
        stiffness[(i, i)] -= force_n * length(i);
    }
    // A massless roller is the ideal follower force (eta = 1).
    let eta = model.load.eta().or(roller.is_none().then_some(1.0));
    if let Some(eta) = eta {
        // Q_i = P l_i sin(phi_i - eta phi_N) (physics.md section 2), linearized.
        for i in 0..rods {
            stiffness[(i, last)] += eta * force_n * length(i);
        }
    }
    if let Some(roller) = roller {
        let r = roller.radius_m;
        mass[(rods, rods)] = roller.spin_inertia_kg_m2(column.rod2.length_m);
        // G = (mu R / V) g g^T with g = (l_1 .. l_N, -r): the transverse slip
        // acts as a viscous damper of coefficient mu R / V at the contact point.
        let g: Vec<f64> = (0..rods).map(length).chain([-r]).collect();
        let coefficient = force_n / roller.band_speed_m_per_s;
        for i in 0..n {
            for j in 0..n {
                damping[(i, j)] += coefficient * g[i] * g[j];
            }
        }
        stiffness[(rods, last)] = force_n * r;
    }
    let extra_zero_roots = usize::from(model.roller().is_some() && roller.is_none());
    Ok(LinearModel {
        mass,
        damping,
        stiffness,
        extra_zero_roots,
    })
}
