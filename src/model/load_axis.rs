//! The load axis p = P l / k of every column: the load bar's range and the
//! range the analysis searches, the same ranges of `P L^2 / EI` for a chain.

use super::params::{Column, Model};

/// The top of the load bar for two rods, on the common axis p (see
/// [`Model::load_bar_max_p`]): past both ideal columns' flutter loads
/// (Ziegler's 2.09, the uniform rods' 2.63) and the roller's divergence.
pub const LOAD_BAR_MAX_P: f64 = 8.0;

/// The top of the range the analysis searches for two rods (see
/// [`Model::analysis_max_p`]): the load bar and a margin beyond it, twice
/// the ideal columns' divergence loads.
pub const ANALYSIS_MAX_P: f64 = 10.0;

impl Column {
    /// The factor that takes a load range of two rods on the axis p to the
    /// same range of `P L^2 / EI` for this chain: `(2/N)^2` (1 for two rods).
    #[must_use]
    pub fn load_range_scale(&self) -> f64 {
        #[expect(clippy::cast_precision_loss, reason = "at most 64 rods")]
        let rods = self.rods as f64;
        (2.0 / rods).powi(2)
    }
}

impl Model {
    /// The top of the load bar (the slider, the ramp, the root locus, the
    /// overlay and the map) for this column: [`LOAD_BAR_MAX_P`] for two
    /// rods; for a chain of N rods `LOAD_BAR_MAX_P (2/N)^2`, the same range
    /// in the continuous column's units `P L^2 / EI` (0 to 32).
    #[must_use]
    pub fn load_bar_max_p(&self) -> f64 {
        LOAD_BAR_MAX_P * self.column.load_range_scale()
    }

    /// The load that stands where `before`'s load stands on its bar, on
    /// this model's bar: for a model whose rods were changed with no load
    /// given, so that a chain starts inside its own bar (`--set rods=16` on
    /// a preset at p = 1 starts at p = 1/64), as rods typed in the window do.
    #[must_use]
    pub fn load_in_place_of(&self, before: &Self) -> f64 {
        before.load_p() * self.load_bar_max_p() / before.load_bar_max_p()
    }

    /// The top of the load range the analysis searches by default (the
    /// critical loads, the paradox curves, the bench): [`ANALYSIS_MAX_P`]
    /// for two rods, the same range of `P L^2 / EI` for a chain.
    #[must_use]
    pub fn analysis_max_p(&self) -> f64 {
        ANALYSIS_MAX_P * self.column.load_range_scale()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::PresetId;

    /// A chain's ranges are the two-rod ranges in the continuous column's
    /// units: `N^2 p` is the same at every N.
    #[test]
    fn a_chain_s_ranges_are_the_same_in_p_l2_over_ei() {
        let mut model = PresetId::UniformRods.model();
        assert_eq!(model.load_bar_max_p(), LOAD_BAR_MAX_P);
        assert_eq!(model.analysis_max_p(), ANALYSIS_MAX_P);
        for rods in [3_usize, 16, 64] {
            model.column.rods = rods;
            #[expect(clippy::cast_precision_loss, reason = "small counts")]
            let n2 = (rods * rods) as f64;
            assert!((n2 * model.load_bar_max_p() - 4.0 * LOAD_BAR_MAX_P).abs() < 1e-12);
            assert!((n2 * model.analysis_max_p() - 4.0 * ANALYSIS_MAX_P).abs() < 1e-12);
        }
    }
}
