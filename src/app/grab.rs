//! The two-rod column taken by the mouse: which handle a press grabs, and
//! the angles that put it where the pointer is (inverse kinematics).

use std::f64::consts::{PI, TAU};

/// A part of the column the mouse can take hold of.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Handle {
    Joint,
    Tip,
}

/// How near (in points) a press must be to a joint or the tip to grab it.
pub const GRAB_RADIUS: f32 = 28.0;

/// The angles `(phi1, phi2)` that put `handle` at `point` (m): the joint
/// turns rod 1 toward the point and leaves rod 2's direction; the tip
/// bends both rods (of the two ways, the one nearer `phi1_now`), stretched
/// toward a point beyond their reach.
#[must_use]
pub fn grab_angles(
    handle: Handle,
    (l1, l2): (f64, f64),
    (phi1_now, phi2_now): (f64, f64),
    point: [f64; 2],
) -> (f64, f64) {
    let toward = point[1].atan2(point[0]);
    match handle {
        Handle::Joint => (toward, phi2_now),
        Handle::Tip => {
            let distance = point[0].hypot(point[1]).clamp((l1 - l2).abs(), l1 + l2);
            let cos = ((l1 * l1 + distance * distance - l2 * l2)
                / (2.0 * l1 * distance.max(1e-12)))
            .clamp(-1.0, 1.0);
            let bend = cos.acos();
            let nearer = |a: f64| (a - phi1_now + PI).rem_euclid(TAU) - PI;
            let phi1 = if nearer(toward + bend).abs() <= nearer(toward - bend).abs() {
                toward + bend
            } else {
                toward - bend
            };
            let joint = [l1 * phi1.cos(), l1 * phi1.sin()];
            let target = [distance * toward.cos(), distance * toward.sin()];
            (phi1, (target[1] - joint[1]).atan2(target[0] - joint[0]))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The tip dragged to a point within reach lands there; beyond reach,
    /// the column points at it; the joint dragged turns rod 1 alone.
    #[test]
    fn a_grabbed_tip_or_joint_goes_where_the_mouse_is() {
        let (l1, l2) = (1.0, 1.0);
        let tip = |(a, b): (f64, f64)| [l1 * a.cos() + l2 * b.cos(), l1 * a.sin() + l2 * b.sin()];
        let (phi1, phi2) = grab_angles(Handle::Tip, (l1, l2), (0.1, 0.1), [1.2, 0.9]);
        let at = tip((phi1, phi2));
        assert!(
            (at[0] - 1.2).abs() < 1e-9 && (at[1] - 0.9).abs() < 1e-9,
            "{at:?}"
        );
        // Of the two bends (phi1 = 0.6435 -/+ 0.7227), the one nearer 0.1.
        assert!((phi1 - (0.6435 - 0.7227)).abs() < 1e-3, "{phi1}");
        let (far1, far2) = grab_angles(Handle::Tip, (l1, l2), (0.0, 0.0), [0.0, 5.0]);
        assert!((far1 - std::f64::consts::FRAC_PI_2).abs() < 1e-6 && (far2 - far1).abs() < 1e-6);
        assert_eq!(
            grab_angles(Handle::Joint, (l1, l2), (0.0, 0.3), [0.0, 2.0]).1,
            0.3
        );
    }
}
