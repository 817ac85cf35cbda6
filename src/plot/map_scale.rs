//! How deep a stability map's cell is coloured: its growth rate against
//! the map's largest.

use crate::analysis::Row;

/// The largest size of a growth rate over the map's rows: the rate that
/// takes the deepest colour.
#[must_use]
pub fn largest_rate<'a>(rows: impl IntoIterator<Item = &'a Row>) -> f64 {
    rows.into_iter()
        .flat_map(|row| row.cells.iter().map(|c| c.growth_per_s.abs()))
        .filter(|g| g.is_finite())
        .fold(0.0, f64::max)
}

/// How deep a cell's colour is, in [0, 1]: the square root of its rate over
/// the map's largest ([`largest_rate`]), so slow rates still show.
#[must_use]
pub fn rate_strength(growth_per_s: f64, largest_per_s: f64) -> f64 {
    if largest_per_s > 0.0 {
        (growth_per_s.abs() / largest_per_s).sqrt().clamp(0.0, 1.0)
    } else {
        0.0
    }
}
