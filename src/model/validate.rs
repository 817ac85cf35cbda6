//! The checks that make parameters a valid model: each number within its
//! range, named when it is not, and a mass matrix that rounding does not
//! decide.

use super::MAX_RODS;
use super::ModelError;
use super::params::{Column, Load, Model, Roller, analysis_range_text};

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
                "rods",
                rods as f64,
                &format!("must be a whole number from 2 to {MAX_RODS}"),
            ));
        }
        for (i, rod) in [(1, rod1), (2, rod2)] {
            positive(&format!("l{i}"), rod.length_m)?;
            non_negative(&format!("m{i}"), rod.mass_kg)?;
            non_negative(&format!("I{i}"), rod.inertia_kg_m2)?;
            within(&format!("s{i}"), rod.com_m, 0.0, rod.length_m, "l{i}", i)?;
        }
        non_negative("m_tip", tip_mass_kg)?;
        positive("k1", k1_nm_per_rad)?;
        positive("k2", k2_nm_per_rad)?;
        non_negative("c1", c1_nms_per_rad)?;
        non_negative("c2", c2_nms_per_rad)?;
        non_negative("c_ext", drag_ns_per_m2)?;
        match self.load {
            Load::Follower { force_n, eta } => {
                non_negative("P", force_n)?;
                finite("eta", eta)?;
                if !(0.0..=1.0).contains(&eta) {
                    return Err(ModelError::invalid(
                        "eta",
                        eta,
                        "must lie between 0 (dead load) and 1 (follower force)",
                    ));
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
                non_negative("m3", mass_kg)?;
                positive("r", radius_m)?;
                within("r", radius_m, 0.0, rod2.length_m, "l2", 2)?;
                if mu == 0.0 {
                    return Err(ModelError::invalid(
                        "mu",
                        mu,
                        "must be > 0: without friction the band exerts no load at all (use load=0 for an unloaded column)",
                    ));
                }
                positive("mu", mu)?;
                non_negative("R", normal_force_n)?;
                non_negative("V", band_speed_m_per_s)?;
            }
        }
        if let Some((what, value)) = self.beyond_analysis() {
            return Err(ModelError::invalid(what, value, &analysis_range_text()));
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
                "the masses are too unequal: the determinant of the mass matrix is below 1e-12 of its scale, so rounding decides the motion (e.g. a tip mass or roller over about 1e12 times the rods')"
            } else {
                "the column needs mass beyond the joint A (rod 2, tip or roller) and mass or inertia that moves with rod 1 on its own; the mass matrix is singular"
            };
            return Err(ModelError::invalid("mass matrix", det, why));
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
                    "rods",
                    rods as f64,
                    "a chain needs mass or inertia on every copy of rod 2 (m2 or I2 > 0): with rod 2 massless the chain's mass matrix is singular",
                ));
            }
        }
        Ok(())
    }
}

fn finite(key: &str, value: f64) -> Result<(), ModelError> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(ModelError::invalid(key, value, "must be a finite number"))
    }
}

fn positive(key: &str, value: f64) -> Result<(), ModelError> {
    finite(key, value)?;
    if value > 0.0 {
        Ok(())
    } else {
        Err(ModelError::invalid(key, value, "must be > 0"))
    }
}

fn non_negative(key: &str, value: f64) -> Result<(), ModelError> {
    finite(key, value)?;
    if value >= 0.0 {
        Ok(())
    } else {
        Err(ModelError::invalid(key, value, "must be >= 0"))
    }
}

/// `min <= value <= max`, where `max` is another parameter named by `max_key`.
fn within(
    key: &str,
    value: f64,
    min: f64,
    max: f64,
    max_key: &str,
    index: usize,
) -> Result<(), ModelError> {
    finite(key, value)?;
    if (min..=max).contains(&value) {
        Ok(())
    } else {
        let max_key = max_key.replace("{i}", &index.to_string());
        Err(ModelError::invalid(
            key,
            value,
            &format!("must lie between {min} and {max_key} = {max}"),
        ))
    }
}
