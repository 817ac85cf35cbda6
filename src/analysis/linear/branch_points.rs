//! The locus's convention where two branches meet on the real axis (which
//! branch goes on where continuity cannot say), and when two eigenvalues
//! count as a conjugate pair.

use crate::analysis::C64;
use crate::analysis::roots::modulus;

/// Where two branches meet on the real axis, continuity cannot say which
/// goes where (the roots are equal at the branch point); the locus's
/// convention, so that a branch's colour means the same at every branch
/// point: where a conjugate pair lands on the real axis, the upper root's
/// branch goes on to the right and the lower one's to the left; where two
/// real roots leave the axis as a pair, the right one's branch takes the
/// upper root. `next` (the eigenvalues after `last`, branch by branch) is
/// reordered to follow it.
pub(super) fn at_branch_points(last: &[C64], next: &mut [C64], scale: f64) {
    // Real to the tolerance of a pair (an iteration on its own leaves a
    // real root's imaginary part at rounding, not at zero), against the
    // sum of the parts: no square root in the locus's hot loop.
    let real = |z: C64| z.im.abs() <= CONJUGATE_TOLERANCE * (z.re.abs() + z.im.abs() + scale);
    let upper = |z: C64| z.im > 0.0 && !real(z);
    for b in 0..next.len() {
        let (was, is) = (last[b], next[b]);
        let partner = if upper(was) && real(is) {
            // Landed: the lower root of the pair, now real too.
            (0..next.len()).find(|&l| l != b && real(next[l]) && conjugate(last[l], was, scale))
        } else if upper(is) && real(was) {
            // Took off: the real root that became the lower root.
            (0..next.len()).find(|&l| l != b && real(last[l]) && conjugate(next[l], is, scale))
        } else {
            None
        };
        // Branch b holds the upper root before or after: it must be the
        // right one of the two real roots.
        if let Some(l) = partner {
            let b_is_right = if real(is) {
                is.re >= next[l].re
            } else {
                was.re >= last[l].re
            };
            if !b_is_right {
                next.swap(b, l);
            }
        }
    }
}

/// Two eigenvalues this close to conjugate, relative to their size plus the
/// frequency scale, are a pair (near a double root rounding parts a pair's
/// computed roots by about the square root of the machine epsilon).
const CONJUGATE_TOLERANCE: f64 = 1e-6;

/// Whether `a` and `b` are a conjugate pair (see [`CONJUGATE_TOLERANCE`]).
pub(super) fn conjugate(a: C64, b: C64, scale: f64) -> bool {
    modulus(a - b.conj()) <= CONJUGATE_TOLERANCE * (modulus(a) + scale)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::locus::{ROUNDING_BAND, locus};
    use crate::analysis::pencil::AffinePencil;
    use crate::model::PresetId;

    /// The convention at branch points, on its own: a landed pair's upper
    /// branch goes right, a pair's upper root goes to the branch that was
    /// right; an ordinary step and an order already right are left alone.
    #[test]
    fn branch_points_follow_the_convention() {
        let c = C64::new;
        let pair = [c(0.3, 0.01), c(-1.0, 0.0), c(0.3, -0.01)];
        let reals = [c(0.29, 0.0), c(-1.0, 0.0), c(0.31, 0.0)];
        let swapped = [reals[2], reals[1], reals[0]];
        let mut next = reals;
        at_branch_points(&pair, &mut next, 1.0);
        assert_eq!(next, swapped);
        at_branch_points(&pair, &mut next, 1.0);
        assert_eq!(next, swapped);
        let mut next = pair;
        at_branch_points(&reals, &mut next, 1.0);
        assert_eq!(next, [pair[2], pair[1], pair[0]]);
        let mut next = pair;
        at_branch_points(&swapped, &mut next, 1.0);
        assert_eq!(next, pair);
        let moved = [c(0.31, 0.02), c(-1.1, 0.0), c(0.31, -0.02)];
        let mut next = moved;
        at_branch_points(&pair, &mut next, 1.0);
        assert_eq!(next, moved);
    }

    /// Along whole loci through divergence and flutter (undamped, damped,
    /// the roller, three rods), every pair that lands on the real axis
    /// goes on with its upper branch to the right, and every pair that
    /// leaves it takes its upper root from the right one.
    #[test]
    fn loci_keep_the_branch_point_convention() {
        let cases: [(PresetId, &[(crate::model::Key, f64)]); 4] = [
            (PresetId::Ziegler1952, &[]),
            (PresetId::Ziegler1952, &[(crate::model::Key::C1, 0.05)]),
            (PresetId::Roller, &[]),
            (PresetId::UniformRods, &[(crate::model::Key::Rods, 3.0)]),
        ];
        let mut landed = 0;
        for (preset, keys) in cases {
            let mut model = preset.model();
            let assignments: Vec<_> = keys
                .iter()
                .map(|&(key, value)| crate::model::Assignment { key, value })
                .collect();
            crate::model::apply_assignments(&mut model, &assignments).unwrap();
            let pencil = AffinePencil::new(&model).unwrap();
            let found = locus(&pencil, 0.0, 8.0, 500).unwrap();
            let branches = found.moving_branches();
            for i in 1..found.loads.len() {
                let scale = pencil.scale_per_s(found.loads[i]);
                let sizeable = |z: C64| modulus(z) > ROUNDING_BAND * scale;
                let real =
                    |z: C64| z.im.abs() <= CONJUGATE_TOLERANCE * (z.re.abs() + z.im.abs() + scale);
                for (b, branch) in branches.iter().enumerate() {
                    let (was, is) = (branch[i - 1], branch[i]);
                    let partner = |at: usize, of: C64| {
                        (0..branches.len())
                            .find(|&l| l != b && conjugate(branches[l][at], of, scale))
                    };
                    if was.im > 0.0 && !real(was) && real(is) && sizeable(was) {
                        let l = partner(i - 1, was).unwrap();
                        assert!(
                            is.re >= branches[l][i].re,
                            "{preset:?} at {}",
                            found.loads[i]
                        );
                        landed += 1;
                    }
                    if real(was) && is.im > 0.0 && !real(is) && sizeable(is) {
                        let l = partner(i, is).unwrap();
                        assert!(was.re >= branches[l][i - 1].re, "{preset:?}");
                    }
                }
            }
        }
        assert!(landed >= 4, "{landed}");
    }
}
