//! Curves cut to a plot's box (plotters draws past its axes otherwise): a
//! polyline becomes the pieces of it inside the box.

/// A box of the data plane: `x` and `y` ranges, low end first.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounds {
    pub x: (f64, f64),
    pub y: (f64, f64),
}

/// The part of the segment `a`-`b` inside `bounds` (Liang and Barsky's
/// clipping), or `None` when none is.
fn clip_segment(a: (f64, f64), b: (f64, f64), bounds: Bounds) -> Option<((f64, f64), (f64, f64))> {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
    for (p, q) in [
        (-dx, a.0 - bounds.x.0),
        (dx, bounds.x.1 - a.0),
        (-dy, a.1 - bounds.y.0),
        (dy, bounds.y.1 - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
        }
    }
    // An end inside is kept exactly (pieces join where one ends).
    let at = |t: f64| match t {
        0.0 => a,
        1.0 => b,
        _ => (a.0 + t * dx, a.1 + t * dy),
    };
    (t0 <= t1).then(|| (at(t0), at(t1)))
}

/// The pieces of the polyline `points` inside `bounds`, each a polyline;
/// points that are not finite break the line.
pub fn clip_polyline(points: &[(f64, f64)], bounds: Bounds) -> Vec<Vec<(f64, f64)>> {
    let mut pieces: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut open = false;
    for pair in points.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        let finite = [a.0, a.1, b.0, b.1].iter().all(|v| v.is_finite());
        let Some((from, to)) = clip_segment(a, b, bounds).filter(|_| finite) else {
            open = false;
            continue;
        };
        match pieces.last_mut() {
            Some(piece) if open && from == a => piece.push(to),
            _ => pieces.push(vec![from, to]),
        }
        // The piece goes on only while the segment ends inside.
        open = to == b;
    }
    pieces
}

#[cfg(test)]
mod tests {
    use super::*;

    const UNIT: Bounds = Bounds {
        x: (0.0, 1.0),
        y: (0.0, 1.0),
    };

    #[test]
    fn a_line_inside_is_kept_whole() {
        let line = [(0.1, 0.1), (0.5, 0.2), (0.9, 0.9)];
        assert_eq!(clip_polyline(&line, UNIT), vec![line.to_vec()]);
    }

    #[test]
    fn a_line_leaving_and_coming_back_is_two_pieces_ending_on_the_edge() {
        let line = [(0.5, 0.5), (0.5, 1.5), (0.8, 1.5), (0.8, 0.5)];
        let pieces = clip_polyline(&line, UNIT);
        assert_eq!(
            pieces,
            vec![vec![(0.5, 0.5), (0.5, 1.0)], vec![(0.8, 1.0), (0.8, 0.5)]]
        );
    }

    #[test]
    fn a_segment_crossing_the_box_keeps_its_chord() {
        let pieces = clip_polyline(&[(-1.0, 0.5), (2.0, 0.5)], UNIT);
        assert_eq!(pieces, vec![vec![(0.0, 0.5), (1.0, 0.5)]]);
        assert!(clip_polyline(&[(-1.0, 2.0), (2.0, 2.0)], UNIT).is_empty());
        assert!(clip_polyline(&[(0.5, f64::NAN), (0.5, 0.5)], UNIT).is_empty());
    }
}
