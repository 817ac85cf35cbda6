//! Where the chain is: the rods' directions, the joints and the tip for a
//! state.

use nalgebra::Vector2;

use super::params::Column;
use super::state::{StateVec, StateView};

/// The unit vector `e` along a rod at `angle_rad`.
#[must_use]
pub fn unit(angle_rad: f64) -> Vector2<f64> {
    Vector2::new(angle_rad.cos(), angle_rad.sin())
}

/// The unit normal `t` of a rod at `angle_rad` (`e` turned a quarter left).
#[must_use]
pub fn normal(angle_rad: f64) -> Vector2<f64> {
    Vector2::new(-angle_rad.sin(), angle_rad.cos())
}

/// Positions of the joints from the clamp O to the tip B in state `x`, in m
/// (`rods + 1` points).
#[must_use]
pub fn joints_m(column: &Column, x: &StateVec) -> Vec<Vector2<f64>> {
    let mut at = Vector2::zeros();
    let mut joints = vec![at];
    for (i, &angle) in StateView::new(x).angles_rad().iter().enumerate() {
        at += column.rod(i).length_m * unit(angle);
        joints.push(at);
    }
    joints
}

/// Position of the tip B in state `x`, in m.
#[must_use]
pub fn tip_m(column: &Column, x: &StateVec) -> Vector2<f64> {
    StateView::new(x)
        .angles_rad()
        .iter()
        .enumerate()
        .fold(Vector2::zeros(), |tip, (i, &angle)| {
            tip + column.rod(i).length_m * unit(angle)
        })
}
