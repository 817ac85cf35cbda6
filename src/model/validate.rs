//! The checks that make parameters a valid model: each number within its
//! range, named when it is not, and a mass matrix that rounding does not
//! decide.

use super::MAX_RODS;
use super::ModelError;
use super::keys::Key;
use super::params::{Column, Load, Model, Roller};
use super::{Allowed, Quantity};

impl Model {
    /// Checks every parameter and the mass matrix; the error names the parameter.
    ///
    /// # Errors
    /// [`ModelError::Invalid`] for the first parameter out of its range.
    pub fn validate(&self) -> Result<(), ModelError> {
        let Column {
            rod1,
            rod2,
            tip_mass_kg,
            k1_nm_per_rad,
            k2_nm_per_rad,
            c1_nms_per_rad,
            c2_nms_per_rad,
            drag_ns_per_m2,
            rods,
        } = self.column;
        if !(2..=MAX_RODS).contains(&rods) {
            #[expect(clippy::cast_precision_loss, reason = "a count shown in a message")]
            return Err(ModelError::invalid(
                Key::Rods,
                rods as f64,
                Allowed::Rods { most: MAX_RODS },
            ));
        }
        for (rod, [length, mass, inertia, com]) in [
            (rod1, [Key::L1, Key::M1, Key::I1, Key::S1]),
            (rod2, [Key::L2, Key::M2, Key::I2, Key::S2]),
        ] {
            positive(length, rod.length_m)?;
            non_negative(mass, rod.mass_kg)?;
            non_negative(inertia, rod.inertia_kg_m2)?;
            within(com, rod.com_m, 0.0, rod.length_m, length)?;
        }
        non_negative(Key::MTip, tip_mass_kg)?;
        positive(Key::K1, k1_nm_per_rad)?;
        positive(Key::K2, k2_nm_per_rad)?;
        non_negative(Key::C1, c1_nms_per_rad)?;
        non_negative(Key::C2, c2_nms_per_rad)?;
        non_negative(Key::CExt, drag_ns_per_m2)?;
        match self.load {
            Load::Follower { force_n, eta } => {
                non_negative(Key::P, force_n)?;
                finite(Key::Eta, eta)?;
                if !(0.0..=1.0).contains(&eta) {
                    return Err(ModelError::invalid(Key::Eta, eta, Allowed::EtaRange));
                }
            }
            Load::Roller(roller) => {
                let Roller {
                    mass_kg,
                    radius_m,
                    mu,
                    normal_force_n,
                    band_speed_m_per_s,
                    spin: _,
                } = roller;
                non_negative(Key::M3, mass_kg)?;
                positive(Key::RollerRadius, radius_m)?;
                within(Key::RollerRadius, radius_m, 0.0, rod2.length_m, Key::L2)?;
                if mu == 0.0 {
                    return Err(ModelError::invalid(Key::Mu, mu, Allowed::FrictionlessBand));
                }
                positive(Key::Mu, mu)?;
                non_negative(Key::NormalForce, normal_force_n)?;
                non_negative(Key::V, band_speed_m_per_s)?;
            }
        }
        if let Some((what, value)) = self.beyond_analysis() {
            return Err(ModelError::invalid(what, value, Allowed::BeyondAnalysis));
        }
        self.check_mass_matrix(rods)
    }

    /// The mass matrix is regular: the two-rod inertia's determinant well
    /// above rounding, and on a chain every pivot of its Cholesky factor.
    fn check_mass_matrix(&self, rods: usize) -> Result<(), ModelError> {
        let inertia = self.inertia();
        let det = inertia.a_kg_m2 * inertia.c_kg_m2 - inertia.b_kg_m2 * inertia.b_kg_m2;
        let scale = inertia.a_kg_m2 * inertia.c_kg_m2;
        if !(inertia.a_kg_m2 > 0.0 && inertia.c_kg_m2 > 0.0 && det > 1e-12 * scale) {
            let c = &self.column;
            let own_rod1 = c.rod1.inertia_kg_m2 + c.rod1.mass_kg * c.rod1.com_m * c.rod1.com_m;
            let beyond = c.rod2.mass_kg
                + c.rod2.inertia_kg_m2
                + c.tip_mass_kg
                + self.roller().map_or(0.0, |r| r.mass_kg);
            let why = if own_rod1 > 0.0 && beyond > 0.0 {
                // Both rods carry mass, but one mass outweighs the rest so
                // far that rounding leaves the other's inertia no digits.
                Allowed::MassesTooUnequal
            } else {
                Allowed::MassMissing
            };
            return Err(ModelError::invalid(Quantity::MassMatrix, det, why));
        }
        if rods > 2 {
            // Every copy of rod 2 must carry mass or inertia of its own: the
            // Cholesky factor's pivots stay well away from zero.
            let mass = super::mass::chain_mass_matrix(self);
            let pivots_ok = mass.clone().cholesky().is_some_and(|factor| {
                let l = factor.l();
                (0..rods).all(|i| l[(i, i)].powi(2) > 1e-12 * mass[(i, i)])
            });
            if !pivots_ok {
                #[expect(clippy::cast_precision_loss, reason = "a count shown in a message")]
                return Err(ModelError::invalid(
                    Key::Rods,
                    rods as f64,
                    Allowed::ChainMassless,
                ));
            }
        }
        Ok(())
    }
}

fn finite(key: Key, value: f64) -> Result<(), ModelError> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(ModelError::invalid(key, value, Allowed::Finite))
    }
}

fn positive(key: Key, value: f64) -> Result<(), ModelError> {
    finite(key, value)?;
    if value > 0.0 {
        Ok(())
    } else {
        Err(ModelError::invalid(key, value, Allowed::Positive))
    }
}

fn non_negative(key: Key, value: f64) -> Result<(), ModelError> {
    finite(key, value)?;
    if value >= 0.0 {
        Ok(())
    } else {
        Err(ModelError::invalid(key, value, Allowed::NonNegative))
    }
}

/// `min <= value <= max`, where `max` is the parameter `max_key`.
fn within(key: Key, value: f64, min: f64, max: f64, max_key: Key) -> Result<(), ModelError> {
    finite(key, value)?;
    if (min..=max).contains(&value) {
        Ok(())
    } else {
        Err(ModelError::invalid(
            key,
            value,
            Allowed::Between { min, max, max_key },
        ))
    }
}
