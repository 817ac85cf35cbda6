//! The column's physical parameters in SI units (their checks: `validate.rs`).

use super::quantity::Quantity;
use serde::{Deserialize, Serialize};

/// One rigid rod of the column: its own mass distribution, reduced to what the
/// kinetic energy needs (mass, centre of mass, moment of inertia).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Rod {
    /// Length between the rod's inner joint and its outer end.
    pub length_m: f64,
    /// Total mass of the rod, point masses riding on it included.
    pub mass_kg: f64,
    /// Distance of the centre of mass from the rod's inner joint.
    pub com_m: f64,
    /// Moment of inertia about the centre of mass, for rotation in the plane.
    pub inertia_kg_m2: f64,
}

impl Rod {
    /// A uniform slender rod (Fig. 1a): centre of mass at the middle, `I = m l^2 / 12`.
    #[must_use]
    pub fn uniform(length_m: f64, mass_kg: f64) -> Self {
        Self {
            length_m,
            mass_kg,
            com_m: length_m / 2.0,
            inertia_kg_m2: mass_kg * length_m * length_m / 12.0,
        }
    }

    /// A massless rod carrying a point mass at distance `at_m` from its inner joint.
    #[must_use]
    pub fn point_mass(length_m: f64, mass_kg: f64, at_m: f64) -> Self {
        Self {
            length_m,
            mass_kg,
            com_m: at_m,
            inertia_kg_m2: 0.0,
        }
    }

    /// Moment of inertia about the inner joint.
    #[must_use]
    pub fn inertia_about_joint_kg_m2(&self) -> f64 {
        self.inertia_kg_m2 + self.mass_kg * self.com_m * self.com_m
    }
}

/// The column without its load: rods, tip mass, springs, dampers. A chain
/// of more than two rods repeats rod 2, with joint A's spring and damper at
/// every joint beyond the clamp.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Column {
    pub rod1: Rod,
    pub rod2: Rod,
    /// How many rods: 2 (rod 1 and rod 2) up to [`MAX_RODS`].
    #[serde(default = "two_rods")]
    pub rods: usize,
    /// Point mass at the free end B (the roller's mass is not included here).
    pub tip_mass_kg: f64,
    /// Rotary spring at the clamp O, acting on `phi1`.
    pub k1_nm_per_rad: f64,
    /// Rotary spring at the joint A, acting on `phi2 - phi1`.
    pub k2_nm_per_rad: f64,
    /// Viscous damper at O on `phi1` (not in the paper; needed for the Ziegler paradox).
    pub c1_nms_per_rad: f64,
    /// Viscous damper at A on `phi2 - phi1`.
    pub c2_nms_per_rad: f64,
    /// External viscous drag along both rods (air drag, linearized): a
    /// force per unit length of `-c_ext` times the local transverse velocity.
    #[serde(default)]
    pub drag_ns_per_m2: f64,
}

/// The most rods a chain may have.
pub const MAX_RODS: usize = 64;

/// Settings stored before chains existed held two rods.
fn two_rods() -> usize {
    2
}

impl Column {
    /// Rod `i` of the chain, from 0 at the clamp: rod 1, then copies of rod 2.
    #[must_use]
    pub fn rod(&self, i: usize) -> &Rod {
        if i == 0 { &self.rod1 } else { &self.rod2 }
    }

    /// The spring at joint `i` (0: the clamp O, on the first rod's angle;
    /// then between rods i - 1 and i), in N m/rad.
    #[must_use]
    pub fn spring_nm_per_rad(&self, i: usize) -> f64 {
        if i == 0 {
            self.k1_nm_per_rad
        } else {
            self.k2_nm_per_rad
        }
    }

    /// The damper at joint `i`, in N m s/rad.
    #[must_use]
    pub fn damper_nms_per_rad(&self, i: usize) -> f64 {
        if i == 0 {
            self.c1_nms_per_rad
        } else {
            self.c2_nms_per_rad
        }
    }

    /// The length of the straight column, from the clamp to the tip, in m.
    #[must_use]
    pub fn reach_m(&self) -> f64 {
        #[expect(clippy::cast_precision_loss, reason = "at most 64 rods")]
        let copies = (self.rods - 1) as f64;
        self.rod1.length_m + copies * self.rod2.length_m
    }

    /// Whether every rod is the same and so is every spring: the chain that
    /// discretizes a uniform beam of stiffness `EI = k l`.
    #[must_use]
    pub fn has_equal_rods(&self) -> bool {
        self.rod1 == self.rod2 && self.k1_nm_per_rad == self.k2_nm_per_rad
    }
}

/// The roller at the tip, dragged by the moving band (Fig. 1c, Fig. 7).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Roller {
    /// Mass of the roller, a disc at the tip B (m3).
    pub mass_kg: f64,
    /// Radius of the roller (r).
    pub radius_m: f64,
    /// Coulomb friction coefficient between roller and band.
    pub mu: f64,
    /// Constant normal force pressing the roller on the band (R).
    pub normal_force_n: f64,
    /// Speed of the band, moving in the -x direction (V).
    pub band_speed_m_per_s: f64,
    /// Which spin inertia: the consistent one or the paper's printed eq. (39).
    pub spin: SpinInertia,
}

/// The roller's spin inertia: physics.md's erratum to eqs (28)-(30).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum SpinInertia {
    /// `m3 r^2 / 2`, from the virtual-power derivation.
    Consistent,
    /// `(r / l2) m3 r^2 / 2`: what the paper's linear system (35)-(39) amounts to.
    AsPrinted,
}

impl Roller {
    /// Magnitude of the friction force, `P = mu R`: the follower-force equivalent.
    #[must_use]
    pub fn friction_force_n(&self) -> f64 {
        self.mu * self.normal_force_n
    }

    /// Factor on the disc's spin inertia: 1, or `r / l2` as printed.
    #[must_use]
    pub fn spin_inertia_factor(&self, rod2_length_m: f64) -> f64 {
        match self.spin {
            SpinInertia::Consistent => 1.0,
            SpinInertia::AsPrinted => self.radius_m / rod2_length_m,
        }
    }

    /// Moment of inertia about the spin axis (along rod 2), with the model's factor.
    #[must_use]
    pub fn spin_inertia_kg_m2(&self, rod2_length_m: f64) -> f64 {
        self.spin_inertia_factor(rod2_length_m) * 0.5 * self.mass_kg * self.radius_m * self.radius_m
    }

    /// Moment of inertia of the disc about the vertical axis through its centre.
    #[must_use]
    pub fn yaw_inertia_kg_m2(&self) -> f64 {
        0.25 * self.mass_kg * self.radius_m * self.radius_m
    }
}

/// What pushes on the tip.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum Load {
    /// A tip force of magnitude P whose direction turns with the last rod
    /// by `eta` times its angle: `F = -P (cos(eta phi_N), sin(eta phi_N))`.
    /// `eta = 1` is the ideal follower force (along the last rod, inward),
    /// `eta = 0` the dead load (fixed direction -x, conservative).
    Follower {
        force_n: f64,
        /// The tangency: 0 (dead load) to 1 (follower).
        #[serde(default = "full_tangency")]
        eta: f64,
    },
    /// Coulomb friction of the moving band on the roller.
    Roller(Roller),
}

/// Settings stored before the key `eta` existed held follower forces.
fn full_tangency() -> f64 {
    1.0
}

impl Load {
    /// The ideal follower force of magnitude `force_n`.
    #[must_use]
    pub fn follower(force_n: f64) -> Self {
        Self::Follower { force_n, eta: 1.0 }
    }

    /// The dead load of magnitude `force_n`, in the fixed direction -x.
    #[must_use]
    pub fn dead(force_n: f64) -> Self {
        Self::Follower { force_n, eta: 0.0 }
    }

    /// The tangency `eta` of a tip force (none for the roller, whose
    /// force's direction follows the slip).
    #[must_use]
    pub fn eta(&self) -> Option<f64> {
        match *self {
            Self::Follower { eta, .. } => Some(eta),
            Self::Roller(_) => None,
        }
    }
}

/// A complete model: the column and its load.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Model {
    pub column: Column,
    pub load: Load,
}

impl Model {
    /// Degrees of freedom: one angle per rod, and the roller's spin.
    #[must_use]
    pub fn dof(&self) -> usize {
        match self.load {
            Load::Roller(_) => self.column.rods + 1,
            Load::Follower { .. } => self.column.rods,
        }
    }

    /// The load in the units of a continuous column, `P L^2 / EI` with
    /// `L = N l` and `EI = k l` (Beck's 20.05 for a follower force), for a
    /// chain of equal rods; `None` otherwise.
    #[must_use]
    pub fn beck_load(&self, p: f64) -> Option<f64> {
        #[expect(clippy::cast_precision_loss, reason = "at most 64 rods")]
        let n = self.column.rods as f64;
        self.column.has_equal_rods().then_some(n * n * p)
    }

    /// The roller, if the load is one.
    #[must_use]
    pub fn roller(&self) -> Option<&Roller> {
        match &self.load {
            Load::Roller(roller) => Some(roller),
            Load::Follower { .. } => None,
        }
    }

    /// Reference length `l` of the dimensionless groups: rod 1's length.
    #[must_use]
    pub fn reference_length_m(&self) -> f64 {
        self.column.rod1.length_m
    }

    /// Reference stiffness `k` of the dimensionless groups: the clamp spring k1.
    #[must_use]
    pub fn reference_stiffness_nm_per_rad(&self) -> f64 {
        self.column.k1_nm_per_rad
    }

    /// Reference mass `m` of the dimensionless groups: what rod 2 carries
    /// (its mass plus the tip mass, the roller excluded). This is the paper's
    /// `m` in every preset: the tip mass of Ziegler's column, the midpoint
    /// mass, the uniform rod's mass.
    #[must_use]
    pub fn reference_mass_kg(&self) -> f64 {
        self.column.rod2.mass_kg + self.column.tip_mass_kg
    }

    /// Magnitude of the follower-equivalent force at the tip: P, or `mu R` for the roller.
    #[must_use]
    pub fn follower_force_n(&self) -> f64 {
        match self.load {
            Load::Follower { force_n, .. } => force_n,
            Load::Roller(roller) => roller.friction_force_n(),
        }
    }

    /// The load on the product's common axis, `p = P l / k` (physics.md section 5).
    #[must_use]
    pub fn load_p(&self) -> f64 {
        self.follower_force_n() * self.reference_length_m() / self.reference_stiffness_nm_per_rad()
    }

    /// Sets the load on the common axis `p = P l / k`; for the roller this sets
    /// the normal force `R = p k / (mu l)` and keeps `mu`.
    pub fn set_load_p(&mut self, p: f64) {
        let force_n = p * self.reference_stiffness_nm_per_rad() / self.reference_length_m();
        match &mut self.load {
            Load::Follower { force_n: f, .. } => *f = force_n,
            Load::Roller(roller) => roller.normal_force_n = force_n / roller.mu,
        }
    }

    /// This model at another load `p`.
    #[must_use]
    pub fn at_load(&self, p: f64) -> Self {
        let mut model = *self;
        model.set_load_p(p);
        model
    }

    /// The first derived quantity beyond [`LARGEST_DERIVED`] in size (or not
    /// finite), if any: the load, the load p, the inertias, the spring
    /// stiffnesses, the dampers and the roller's slip damping `mu R / V`;
    /// or a roller's spin inertia below its inverse.
    /// The analysis squares such numbers (norms, the characteristic
    /// polynomial), so larger ones would overflow to infinity on screen.
    #[must_use]
    pub fn beyond_analysis(&self) -> Option<(Quantity, f64)> {
        let inertia = self.inertia();
        let mut quantities = vec![
            (Quantity::LoadForce, self.follower_force_n()),
            (Quantity::LoadP, self.load_p()),
            (Quantity::InertiaO, inertia.a_kg_m2),
            (Quantity::InertiaCoupling, inertia.b_kg_m2),
            (Quantity::InertiaA, inertia.c_kg_m2),
            (Quantity::StiffnessK1, self.column.k1_nm_per_rad),
            (Quantity::StiffnessK2, self.column.k2_nm_per_rad),
            (Quantity::DamperC1, self.column.c1_nms_per_rad),
            (Quantity::DamperC2, self.column.c2_nms_per_rad),
            (
                Quantity::Drag,
                self.column.drag_ns_per_m2
                    * self
                        .column
                        .rod1
                        .length_m
                        .max(self.column.rod2.length_m)
                        .powi(3),
            ),
        ];
        if let Some(roller) = self.roller()
            && roller.band_speed_m_per_s > 0.0
        {
            let l = self.column.rod1.length_m.max(self.column.rod2.length_m);
            quantities.push((
                Quantity::SlipDamping,
                roller.friction_force_n() / roller.band_speed_m_per_s * l * l,
            ));
        }
        // A roller with mass spins with inertia: one that underflows leaves
        // the mass matrix singular.
        let spin_underflows = self.roller().is_some_and(|r| r.mass_kg > 0.0)
            && inertia.spin_kg_m2 < 1.0 / LARGEST_DERIVED;
        if spin_underflows {
            return Some((Quantity::SpinInertia, inertia.spin_kg_m2));
        }
        quantities
            .into_iter()
            .find(|&(_, value)| !value.is_finite() || value.abs() > LARGEST_DERIVED)
    }
}

/// The largest size of a derived quantity the analysis accepts: its square
/// and products of two such stay far inside double precision.
pub const LARGEST_DERIVED: f64 = 1e150;
