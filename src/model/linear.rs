//! The linearization about the straight column: analytic M, D, K (physics.md section 4).

use nalgebra::DMatrix;

use super::ModelError;
use super::params::{Column, Model};

/// `M x'' + D x' + K x = 0` about the straight column, `x = (phi1, phi2[, psi])`.
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

/// The analytic linearization of `model` about `phi = 0` at rest.
///
/// A massless roller (`m3 = 0`) turns its spin equation into the constraint
/// `Q3 = 0`; eliminating the slaved spin rate leaves exactly the ideal follower
/// column with `P = mu R` (physics.md section 3), plus the spin angle's zero root.
///
/// # Errors
/// The model's own validation; and a roller with `V = 0`, where Coulomb
/// friction is not differentiable about the state of rest.
pub fn linearize(model: &Model) -> Result<LinearModel, ModelError> {
    model.validate()?;
    let Column {
        rod1,
        rod2,
        k1_nm_per_rad: k1,
        k2_nm_per_rad: k2,
        c1_nms_per_rad: c1,
        c2_nms_per_rad: c2,
        drag_ns_per_m2: drag,
        ..
    } = model.column;
    let (l1, l2) = (rod1.length_m, rod2.length_m);
    let inertia = model.inertia();
    if let Some(roller) = model.roller()
        && roller.band_speed_m_per_s <= 0.0
    {
        return Err(ModelError::invalid(
            "V",
            roller.band_speed_m_per_s,
            "must be > 0 for the linear analysis: at V = 0 Coulomb friction is not differentiable about rest (stick-slip)",
        ));
    }
    // A massless roller is linearized as the ideal follower column it equals.
    let roller = model.roller().filter(|roller| roller.mass_kg > 0.0);
    let n = if roller.is_some() { 3 } else { 2 };
    let mut mass = DMatrix::zeros(n, n);
    let mut damping = DMatrix::zeros(n, n);
    let mut stiffness = DMatrix::zeros(n, n);
    mass[(0, 0)] = inertia.a_kg_m2;
    mass[(0, 1)] = inertia.b_kg_m2;
    mass[(1, 0)] = inertia.b_kg_m2;
    mass[(1, 1)] = inertia.c_kg_m2;
    damping[(0, 0)] = c1 + c2;
    damping[(0, 1)] = -c2;
    damping[(1, 0)] = -c2;
    damping[(1, 1)] = c2;
    // The drag on the rods, by its Rayleigh function: rod 1 moves with
    // s phi1', rod 2 with l1 phi1' + s phi2' (physics.md section 4).
    damping[(0, 0)] += drag * (l1.powi(3) / 3.0 + l1 * l1 * l2);
    damping[(0, 1)] += drag * l1 * l2 * l2 / 2.0;
    damping[(1, 0)] += drag * l1 * l2 * l2 / 2.0;
    damping[(1, 1)] += drag * l2.powi(3) / 3.0;
    stiffness[(0, 0)] = k1 + k2;
    stiffness[(0, 1)] = -k2;
    stiffness[(1, 0)] = -k2;
    stiffness[(1, 1)] = k2;
    let force_n = model.follower_force_n();
    // A massless roller is the ideal follower force (eta = 1).
    let eta = model.load.eta().or(roller.is_none().then_some(1.0));
    if let Some(eta) = eta {
        // Q_i = P l_i sin(phi_i - eta phi2) (physics.md section 2), linearized.
        stiffness[(0, 0)] -= force_n * l1;
        stiffness[(0, 1)] += eta * force_n * l1;
        stiffness[(1, 1)] -= (1.0 - eta) * force_n * l2;
    }
    if let Some(roller) = roller {
        let r = roller.radius_m;
        mass[(2, 2)] = inertia.spin_kg_m2;
        // G = (mu R / V) g g^T with g = (l1, l2, -r): the transverse slip acts
        // as a viscous damper of coefficient mu R / V at the contact point.
        let g = [l1, l2, -r];
        let coefficient = force_n / roller.band_speed_m_per_s;
        for i in 0..3 {
            for j in 0..3 {
                damping[(i, j)] += coefficient * g[i] * g[j];
            }
        }
        stiffness[(0, 0)] -= force_n * l1;
        stiffness[(1, 1)] -= force_n * l2;
        stiffness[(2, 1)] = force_n * r;
    }
    let extra_zero_roots = usize::from(model.roller().is_some() && roller.is_none());
    Ok(LinearModel {
        mass,
        damping,
        stiffness,
        extra_zero_roots,
    })
}
