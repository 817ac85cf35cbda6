//! The column taken by the mouse, any joint of any chain: the angles that
//! put the grabbed joint where the pointer is (inverse kinematics of the
//! one or two rods before it; every other rod keeps its direction).

use std::f64::consts::{PI, TAU};

/// How near (in points) a press must be to a joint or the tip to grab it.
pub const GRAB_RADIUS: f32 = 28.0;

/// The absolute angles of the rods (from the base) that put the end of rod
/// `held` (1 for the first joint above the base, N for the tip) at `point`
/// (m). The rod ending there turns toward the point when it is the first;
/// otherwise it and the rod before it bend (of the two ways, the one nearer
/// the present angles), stretched toward a point beyond their reach. Every
/// other rod keeps its direction, so the rods beyond follow rigidly. On two
/// rods: the joint turns rod 1 alone, the tip bends both.
#[must_use]
pub fn grab_angles(
    held: usize,
    lengths_m: &[f64],
    angles_now_rad: &[f64],
    point: [f64; 2],
) -> Vec<f64> {
    let mut angles = angles_now_rad.to_vec();
    let held = held.clamp(1, lengths_m.len().min(angles.len()));
    // The rods that move: the held one, and the one before it if any.
    let first = held.saturating_sub(2);
    let (base_x, base_y) = (0..first).fold((0.0, 0.0), |(x, y), i| {
        (
            x + lengths_m[i] * angles[i].cos(),
            y + lengths_m[i] * angles[i].sin(),
        )
    });
    let (x, y) = (point[0] - base_x, point[1] - base_y);
    let toward = y.atan2(x);
    if held == 1 {
        angles[0] = toward;
        return angles;
    }
    let (l1, l2) = (lengths_m[first], lengths_m[first + 1]);
    let distance = x.hypot(y).clamp((l1 - l2).abs(), l1 + l2);
    let cos = ((l1 * l1 + distance * distance - l2 * l2) / (2.0 * l1 * distance.max(1e-12)))
        .clamp(-1.0, 1.0);
    let bend = cos.acos();
    let nearer = |a: f64| (a - angles_now_rad[first] + PI).rem_euclid(TAU) - PI;
    let phi1 = if nearer(toward + bend).abs() <= nearer(toward - bend).abs() {
        toward + bend
    } else {
        toward - bend
    };
    let joint = [l1 * phi1.cos(), l1 * phi1.sin()];
    let target = [distance * toward.cos(), distance * toward.sin()];
    angles[first] = phi1;
    angles[first + 1] = (target[1] - joint[1]).atan2(target[0] - joint[0]);
    angles
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The position of the end of rod `k` (1-based) at `angles`.
    fn end(lengths: &[f64], angles: &[f64], k: usize) -> [f64; 2] {
        (0..k).fold([0.0, 0.0], |p, i| {
            [
                p[0] + lengths[i] * angles[i].cos(),
                p[1] + lengths[i] * angles[i].sin(),
            ]
        })
    }

    /// Two rods: the tip dragged to a point within reach lands there (the
    /// bend nearer the present angle); beyond reach, the column points at
    /// it; the joint dragged turns rod 1 alone.
    #[test]
    fn a_grabbed_tip_or_joint_goes_where_the_mouse_is() {
        let lengths = [1.0, 1.0];
        let angles = grab_angles(2, &lengths, &[0.1, 0.1], [1.2, 0.9]);
        let at = end(&lengths, &angles, 2);
        assert!(
            (at[0] - 1.2).abs() < 1e-9 && (at[1] - 0.9).abs() < 1e-9,
            "{at:?}"
        );
        // Of the two bends (phi1 = 0.6435 -/+ 0.7227), the one nearer 0.1.
        assert!((angles[0] - (0.6435 - 0.7227)).abs() < 1e-3, "{angles:?}");
        let far = grab_angles(2, &lengths, &[0.0, 0.0], [0.0, 5.0]);
        assert!(
            (far[0] - std::f64::consts::FRAC_PI_2).abs() < 1e-6 && (far[1] - far[0]).abs() < 1e-6
        );
        assert_eq!(grab_angles(1, &lengths, &[0.0, 0.3], [0.0, 2.0])[1], 0.3);
    }

    /// A chain of five rods: any joint above the first dragged within reach
    /// lands where the mouse is (the first turns toward it); the rods before
    /// the two that bend keep their directions, and so do the rods beyond
    /// (they follow rigidly).
    #[test]
    fn any_joint_of_a_chain_goes_where_the_mouse_is() {
        let lengths = [0.2, 0.2, 0.2, 0.2, 0.2];
        let now = [0.05, 0.02, -0.03, 0.04, 0.01];
        for held in 1..=5 {
            let start = end(&lengths, &now, held);
            let point = [start[0] - 0.05, start[1] + 0.08];
            let angles = grab_angles(held, &lengths, &now, point);
            if held == 1 {
                assert_eq!(angles[0], point[1].atan2(point[0]));
                continue;
            }
            let at = end(&lengths, &angles, held);
            assert!(
                (at[0] - point[0]).abs() < 1e-9 && (at[1] - point[1]).abs() < 1e-9,
                "joint {held}: {at:?} for {point:?}"
            );
            let moved = held.saturating_sub(2)..held;
            for i in (0..5).filter(|i| !moved.contains(i)) {
                assert_eq!(angles[i], now[i], "joint {held}: rod {} kept", i + 1);
            }
        }
    }
}
