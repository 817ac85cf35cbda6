//! The scene's camera: it frames the column's recent motion, large in its
//! panel, zooming out at once when the column swings wide and back in slowly
//! as it settles; or, on request, the whole disc the tip can reach.

/// A box in world coordinates (m, y up).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WorldBox {
    pub min: [f64; 2],
    pub max: [f64; 2],
}

impl WorldBox {
    fn around(points: impl IntoIterator<Item = [f64; 2]>) -> Self {
        let mut out = Self {
            min: [f64::INFINITY; 2],
            max: [f64::NEG_INFINITY; 2],
        };
        for point in points {
            for ((min, max), value) in out.min.iter_mut().zip(&mut out.max).zip(point) {
                *min = min.min(value);
                *max = max.max(value);
            }
        }
        out
    }

    /// Whether `other` lies inside this box.
    #[must_use]
    pub fn contains(&self, other: &Self) -> bool {
        (0..2).all(|a| self.min[a] <= other.min[a] && other.max[a] <= self.max[a])
    }

    #[must_use]
    pub fn center(&self) -> [f64; 2] {
        [
            0.5 * (self.min[0] + self.max[0]),
            0.5 * (self.min[1] + self.max[1]),
        ]
    }

    #[must_use]
    pub fn size(&self) -> [f64; 2] {
        [self.max[0] - self.min[0], self.max[1] - self.min[1]]
    }
}

/// The margin around what is framed, as a fraction of the column's length.
const MARGIN: f64 = 0.12;
/// Seconds of the tip's trail the camera keeps in view.
pub const FOLLOW_SECS: f64 = 4.0;
/// Each frame the camera closes this fraction of the way in (zooming out is
/// immediate: the column never leaves the picture).
const SETTLE_PER_FRAME: f64 = 0.04;

/// What the camera aims at: the clamp, the joint, the tip and its recent
/// trail, at least the straight column, with a margin; for `whole_reach`
/// the whole disc the tip can reach.
#[must_use]
pub fn target(
    reach_m: f64,
    joint_m: [f64; 2],
    tip_m: [f64; 2],
    trail: impl IntoIterator<Item = [f64; 2]>,
    whole_reach: bool,
) -> WorldBox {
    let margin = MARGIN * reach_m;
    let framed = if whole_reach {
        WorldBox::around([[-reach_m, -reach_m], [reach_m, reach_m]])
    } else {
        let straight = [[0.0, 0.0], [reach_m, 0.0], joint_m, tip_m];
        WorldBox::around(straight.into_iter().chain(trail))
    };
    WorldBox {
        min: [framed.min[0] - margin, framed.min[1] - margin],
        max: [framed.max[0] + margin, framed.max[1] + margin],
    }
}

/// The camera's framing, carried from frame to frame.
#[derive(Clone, Debug, Default)]
pub struct Camera {
    framed: Option<WorldBox>,
    /// The column length the last frame was for: another column (a new
    /// preset) is framed at once.
    reach_m: f64,
    pub whole_reach: bool,
}

impl Camera {
    /// The box to draw this frame when aiming at `target` for a column of
    /// length `reach_m`: all of it at once when it does not fit the last
    /// frame's box or the column is another, otherwise a step of
    /// [`SETTLE_PER_FRAME`] toward it.
    pub fn frame(&mut self, target: WorldBox, reach_m: f64) -> WorldBox {
        let same_column = self.reach_m == reach_m;
        self.reach_m = reach_m;
        let framed = match self.framed {
            Some(last) if same_column && last.contains(&target) => {
                let step = |from: f64, to: f64| from + SETTLE_PER_FRAME * (to - from);
                WorldBox {
                    min: [
                        step(last.min[0], target.min[0]),
                        step(last.min[1], target.min[1]),
                    ],
                    max: [
                        step(last.max[0], target.max[0]),
                        step(last.max[1], target.max[1]),
                    ],
                }
            }
            _ => target,
        };
        self.framed = Some(framed);
        framed
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_camera_zooms_out_at_once_and_settles_back_slowly() {
        let still = target(2.0, [1.0, 0.0], [2.0, 0.0], [], false);
        assert!(still.contains(&WorldBox::around([[0.0, 0.0], [2.0, 0.0]])));
        assert!(still.size()[0] < 2.6, "the straight column fills the width");
        let swing = target(2.0, [0.9, 0.4], [1.4, 1.3], [[1.9, -0.8]], false);
        let mut camera = Camera::default();
        assert_eq!(camera.frame(still, 2.0), still, "the first frame frames it");
        assert_eq!(
            camera.frame(swing, 2.0),
            swing,
            "a wide swing is framed at once"
        );
        let next = camera.frame(still, 2.0);
        assert!(
            swing.contains(&next) && next != still,
            "settling takes frames"
        );
        for _ in 0..200 {
            camera.frame(still, 2.0);
        }
        let settled = camera.frame(still, 2.0);
        assert!((settled.size()[1] - still.size()[1]).abs() < 1e-3);
        let small = target(0.5, [0.25, 0.0], [0.5, 0.0], [], false);
        assert_eq!(camera.frame(small, 0.5), small, "another column: at once");
        let whole = target(2.0, [1.0, 0.0], [2.0, 0.0], [], true);
        assert!(whole.contains(&WorldBox::around([[-2.0, -2.0], [2.0, 2.0]])));
    }

    /// Wherever the column swings (a roller at p = 3 or 5 whips round),
    /// every frame the camera draws holds the clamp as the scene draws it:
    /// its wall 0.08 of the reach each side of O and the hatching 0.04
    /// behind and below it. The view moves; the clamp stays in it.
    #[test]
    fn every_frame_keeps_the_clamp_in_view() {
        let reach = 0.5;
        let clamp = WorldBox::around([[-0.04 * reach, -0.12 * reach], [0.0, 0.08 * reach]]);
        let mut camera = Camera::default();
        let at = |k: f64, r: f64| [r * reach * k.cos(), r * reach * k.sin()];
        let mut trail = std::collections::VecDeque::new();
        for i in 0..2000 {
            let t = f64::from(i) * 0.05;
            // A swing that grows and whirls round the clamp, then folds back.
            let angle = (0.2 + 0.002 * f64::from(i)) * (1.3 * t).sin() + 0.0015 * f64::from(i);
            let tip = at(angle, 1.0 - 0.3 * (0.7 * t).sin().abs());
            let joint = at(0.5 * angle, 0.5);
            trail.push_back(tip);
            if trail.len() > 80 {
                trail.pop_front();
            }
            let framed = camera.frame(
                target(reach, joint, tip, trail.iter().copied(), false),
                reach,
            );
            assert!(framed.contains(&clamp), "frame {i}: {framed:?}");
        }
    }
}
