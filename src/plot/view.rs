//! Where the root locus looks: the default view that holds the eigenvalues
//! deciding stability, and where an eigenvalue outside the view is marked on
//! its edge (pure: no drawing).

use crate::analysis::{C64, Locus};
use crate::format::number_text;

/// Room left around the eigenvalues the view must hold, as a fraction.
const MARGIN: f64 = 0.2;

/// The extent of a locus that decides stability: the largest frequency of
/// any branch at any load (every oscillating mode, the pairs the status
/// card and the measured rings are about), and the largest real part, in
/// size, of the eigenvalue furthest right at any load (the growth rate the
/// card reports, a divergence's real root included). A mode that only dies
/// away fast far left on the real axis (the roller's spin settling to the
/// band) decides nothing and is left out: it would squeeze the rest to a
/// point. `(re, im)`, in 1/s and rad/s.
#[must_use]
pub fn deciding_extent(locus: &Locus) -> (f64, f64) {
    let branches = locus.moving_branches();
    let im = branches
        .iter()
        .flatten()
        .map(|z| z.im.abs())
        .fold(0.0, f64::max);
    let re = (0..locus.loads.len())
        .filter_map(|i| {
            branches
                .iter()
                .map(|branch| branch[i].re)
                .max_by(f64::total_cmp)
        })
        .map(f64::abs)
        .fold(0.0, f64::max);
    (re, im)
}

/// The half-height of a plot of Re (or, `imaginary`, Im) of the eigenvalues
/// of `loci` against the load: for Im the largest frequency; for Re the
/// real part of the eigenvalue furthest right at every load, which decides
/// stability (a chain's slow flutter shows; faster decaying modes run off
/// the plot). At least 1e-3.
#[must_use]
pub fn versus_load_extent<'a>(loci: impl IntoIterator<Item = &'a Locus>, imaginary: bool) -> f64 {
    loci.into_iter()
        .map(|locus| {
            if imaginary {
                deciding_extent(locus).1
            } else {
                deciding_extent(locus).0
            }
        })
        .fold(0.0, f64::max)
        .max(1e-3)
}

/// The default view of the root locus, centred on the origin with equal
/// scales on both axes, for a plot `shape` = width / height (in screen
/// units): it holds the deciding extents of the locus and of the overlay
/// with [`MARGIN`] to spare. `(half_width, half_height)`.
#[must_use]
pub fn default_view(extents: &[(f64, f64)], shape: f64) -> (f64, f64) {
    let (re, im) = extents
        .iter()
        .fold((0.0, 0.0), |(re, im): (f64, f64), &(r, i)| {
            (re.max(r), im.max(i))
        });
    let shape = if shape.is_finite() && shape > 0.0 {
        shape
    } else {
        1.0
    };
    let scale = 1.0 + MARGIN;
    // Nothing moving at all (a column with no load and no stiffness): a unit view.
    let half_height = (scale * im).max(scale * re / shape).max(1e-3);
    (half_height * shape, half_height)
}

/// The rectangle of the complex plane a plot shows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ViewRect {
    pub re: (f64, f64),
    pub im: (f64, f64),
}

impl ViewRect {
    #[must_use]
    pub fn contains(&self, z: C64) -> bool {
        (self.re.0..=self.re.1).contains(&z.re) && (self.im.0..=self.im.1).contains(&z.im)
    }
}

/// An eigenvalue outside the view, marked on the view's edge.
#[derive(Clone, Debug, PartialEq)]
pub struct EdgeMark {
    /// Where on the edge (inside the view by `inset` of its size).
    pub at: C64,
    /// Which edge, as the direction to the eigenvalue.
    pub side: Side,
    /// The eigenvalue's value in words: "-22.5623" or "-2 ± 1.5i".
    pub label: String,
}

/// The edge an eigenvalue lies beyond.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    Left,
    Right,
    Up,
    Down,
}

/// The eigenvalues of `current` outside `view`, each marked where the line
/// from the view's centre to it leaves the view (pulled in by `inset`, a
/// fraction of the view's size, so the mark is drawn whole). A conjugate
/// pair off the view is one mark per eigenvalue, each labelled with the pair.
#[must_use]
pub fn edge_marks(current: &[C64], view: ViewRect, inset: f64) -> Vec<EdgeMark> {
    let (width, height) = (view.re.1 - view.re.0, view.im.1 - view.im.0);
    if !(width > 0.0 && height > 0.0) {
        return Vec::new();
    }
    let centre = C64::new(0.5 * (view.re.0 + view.re.1), 0.5 * (view.im.0 + view.im.1));
    let (half_w, half_h) = (
        0.5 * width * (1.0 - 2.0 * inset),
        0.5 * height * (1.0 - 2.0 * inset),
    );
    current
        .iter()
        .filter(|z| z.re.is_finite() && z.im.is_finite() && !view.contains(**z))
        .map(|&z| {
            let d = z - centre;
            // The ray's parameter where it meets each pair of edges.
            let t_re = if d.re == 0.0 {
                f64::INFINITY
            } else {
                half_w / d.re.abs()
            };
            let t_im = if d.im == 0.0 {
                f64::INFINITY
            } else {
                half_h / d.im.abs()
            };
            let side = if t_re <= t_im {
                if d.re < 0.0 { Side::Left } else { Side::Right }
            } else if d.im < 0.0 {
                Side::Down
            } else {
                Side::Up
            };
            EdgeMark {
                at: centre + d * t_re.min(t_im),
                side,
                label: value_text(z),
            }
        })
        .collect()
}

/// An eigenvalue as the edge mark names it: its real part, and `± im i`
/// when it oscillates.
fn value_text(z: C64) -> String {
    if z.im == 0.0 {
        number_text(z.re)
    } else {
        format!("{} ± {}i", number_text(z.re), number_text(z.im.abs()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The view holds the extents with the margin, in the plot's shape.
    #[test]
    fn the_default_view_holds_both_extents_in_the_plots_shape() {
        // Wide plot, frequencies decide: the height is the frequency's.
        let (w, h) = default_view(&[(0.1, 1.0)], 2.0);
        assert!((h - 1.2).abs() < 1e-12 && (w - 2.4).abs() < 1e-12);
        // Tall plot, a large growth rate decides: the width is its.
        let (w, h) = default_view(&[(3.0, 1.0)], 0.5);
        assert!((w - 3.6).abs() < 1e-12 && (h - 7.2).abs() < 1e-12);
        // The overlay's extent counts too.
        let (_, h) = default_view(&[(0.1, 1.0), (0.0, 2.0)], 2.0);
        assert!((h - 2.4).abs() < 1e-12);
    }

    /// A real eigenvalue far left is marked on the left edge at the axis,
    /// one above the view on the top edge; those inside are not marked.
    #[test]
    fn eigenvalues_outside_the_view_are_marked_on_its_edge() {
        let view = ViewRect {
            re: (-2.0, 2.0),
            im: (-1.0, 1.0),
        };
        let current = [
            C64::new(-22.5, 0.0),
            C64::new(0.0, 0.92),
            C64::new(0.5, 3.0),
        ];
        let marks = edge_marks(&current, view, 0.0);
        assert_eq!(marks.len(), 2);
        assert_eq!(marks[0].side, Side::Left);
        assert_eq!(marks[0].at, C64::new(-2.0, 0.0));
        assert_eq!(marks[0].label, "-22.5");
        assert_eq!(marks[1].side, Side::Up);
        assert!((marks[1].at.im - 1.0).abs() < 1e-12);
        assert!((marks[1].at.re - 0.5 / 3.0).abs() < 1e-12);
        assert_eq!(marks[1].label, "0.5 ± 3i");
    }
}
