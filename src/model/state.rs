//! The state vector of a chain and its typed views: the rods' angles, the
//! roller's spin and their rates, by name rather than by index.

use nalgebra::DVector;

use super::params::Column;

/// `(phi_1 .. phi_N, psi, phi_1' .. phi_N', psi')` in rad and rad/s: for
/// two rods `(phi1, phi2, psi, phi1', phi2', psi')`. The spin entries stay
/// zero without a roller. Read and write it through [`StateView`] and
/// [`StateViewMut`].
pub type StateVec = DVector<f64>;

/// The state of rest of `column`'s chain (all angles and rates zero).
#[must_use]
pub fn rest_state(column: &Column) -> StateVec {
    StateVec::zeros(state_len(column.rods))
}

/// The length of the state vector of a chain of `rods` rods.
#[must_use]
pub fn state_len(rods: usize) -> usize {
    2 * (rods + 1)
}

/// A state read by name: `x` holds `(angles, spin, rates, spin rate)` of a
/// chain of `x.len() / 2 - 1` rods.
#[derive(Clone, Copy, Debug)]
pub struct StateView<'a> {
    x: &'a [f64],
}

impl<'a> StateView<'a> {
    /// The view of `x`, laid out as [`StateVec`] says.
    #[must_use]
    pub fn new(x: &'a StateVec) -> Self {
        Self { x: x.as_slice() }
    }

    /// How many rods the state has angles for.
    #[must_use]
    pub fn rods(self) -> usize {
        self.x.len() / 2 - 1
    }

    /// `phi_1 .. phi_N`, in rad.
    #[must_use]
    pub fn angles_rad(self) -> &'a [f64] {
        &self.x[..self.rods()]
    }

    /// `phi_1' .. phi_N'`, in rad/s.
    #[must_use]
    pub fn rates_rad_per_s(self) -> &'a [f64] {
        let n = self.rods();
        &self.x[n + 1..=2 * n]
    }

    /// Every rate, the spin's last: `phi_1' .. phi_N', psi'`, the order of
    /// the generalized forces.
    #[must_use]
    pub fn all_rates(self) -> &'a [f64] {
        &self.x[self.rods() + 1..]
    }

    /// The last rod's angle `phi_N`, in rad.
    #[must_use]
    pub fn last_angle_rad(self) -> f64 {
        self.x[self.rods() - 1]
    }

    /// The last rod's rate `phi_N'`, in rad/s.
    #[must_use]
    pub fn last_rate_rad_per_s(self) -> f64 {
        self.x[2 * self.rods()]
    }

    /// The roller's spin angle `psi`, in rad.
    #[must_use]
    pub fn spin_rad(self) -> f64 {
        self.x[self.rods()]
    }

    /// The roller's spin rate `psi'`, in rad/s.
    #[must_use]
    pub fn spin_rate_rad_per_s(self) -> f64 {
        self.x[2 * self.rods() + 1]
    }
}

/// A state written by name (see [`StateView`]).
#[derive(Debug)]
pub struct StateViewMut<'a> {
    x: &'a mut [f64],
}

impl<'a> StateViewMut<'a> {
    /// The writable view of `x`, laid out as [`StateVec`] says.
    #[must_use]
    pub fn new(x: &'a mut StateVec) -> Self {
        Self {
            x: x.as_mut_slice(),
        }
    }

    fn rods(&self) -> usize {
        self.x.len() / 2 - 1
    }

    /// `phi_1 .. phi_N`, in rad.
    pub fn angles_rad(&mut self) -> &mut [f64] {
        let n = self.rods();
        &mut self.x[..n]
    }

    /// `phi_1' .. phi_N'`, in rad/s.
    pub fn rates_rad_per_s(&mut self) -> &mut [f64] {
        let n = self.rods();
        &mut self.x[n + 1..=2 * n]
    }

    /// The roller's spin angle `psi`, in rad.
    pub fn spin_rad(&mut self) -> &mut f64 {
        let n = self.rods();
        &mut self.x[n]
    }

    /// The roller's spin rate `psi'`, in rad/s.
    pub fn spin_rate_rad_per_s(&mut self) -> &mut f64 {
        let n = self.rods();
        &mut self.x[2 * n + 1]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The views read and write the entries `StateVec`'s layout names.
    #[test]
    fn the_views_name_the_entries_of_the_layout() {
        let mut x = StateVec::from_vec((0..8).map(f64::from).collect());
        let view = StateView::new(&x);
        assert_eq!(view.rods(), 3);
        assert_eq!(view.angles_rad(), &[0.0, 1.0, 2.0]);
        assert_eq!(view.spin_rad(), 3.0);
        assert_eq!(view.rates_rad_per_s(), &[4.0, 5.0, 6.0]);
        assert_eq!(view.spin_rate_rad_per_s(), 7.0);
        assert_eq!(
            (view.last_angle_rad(), view.last_rate_rad_per_s()),
            (2.0, 6.0)
        );
        let mut write = StateViewMut::new(&mut x);
        write.angles_rad()[1] = -1.0;
        write.rates_rad_per_s()[2] = -6.0;
        *write.spin_rad() = -3.0;
        *write.spin_rate_rad_per_s() = -7.0;
        assert_eq!(x.as_slice(), &[0.0, -1.0, 2.0, -3.0, 4.0, 5.0, -6.0, -7.0]);
    }
}
