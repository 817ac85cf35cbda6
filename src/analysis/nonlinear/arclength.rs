//! Pseudo-arclength continuation of a curve in a plane: the zero set of a
//! smooth scalar function `g(y, p)` (a pair's growth rate at a Hopf point,
//! a real eigenvalue at a divergence), followed by tangent predictor and
//! Newton corrector on `g = 0` and the arclength condition, so the curve is
//! followed through its folds (where it turns back in either coordinate).
//!
//! Both coordinates are scaled to the box asked for (`u`, `v` in [0, 1]);
//! the derivatives of `g` are central differences. Pure: no UI, no clock.

use crate::analysis::{AnalysisError, C64};

/// The box the curve is followed in: the second parameter's range and the
/// load's.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Plane {
    pub y: (f64, f64),
    pub p: (f64, f64),
}

impl Plane {
    /// The plane's point at scaled `[u, v]`.
    pub fn point(&self, z: [f64; 2]) -> (f64, f64) {
        (
            self.y.0 + z[0] * (self.y.1 - self.y.0),
            self.p.0 + z[1] * (self.p.1 - self.p.0),
        )
    }

    /// The scaled coordinates of `(y, p)`.
    pub fn scaled(&self, y: f64, p: f64) -> [f64; 2] {
        [
            (y - self.y.0) / (self.y.1 - self.y.0),
            (p - self.p.0) / (self.p.1 - self.p.0),
        ]
    }
}

/// What a curve is the zero set of.
pub(crate) trait Defining {
    /// What `g` is of at a point (the eigenvalue on the axis, a cycle),
    /// carried along the curve so that the next point's is the one
    /// continuing it.
    type Near: Clone;

    /// `g` at `(y, p)` (scaled: a growth rate over the pencil's frequency
    /// scale) with what it is of, the one nearest `near`; `None` where that
    /// is gone (a pair met on the real axis, a cycle not found) or the
    /// column cannot be analysed.
    ///
    /// # Errors
    /// An eigenvalue computation that fails.
    fn value(
        &self,
        y: f64,
        p: f64,
        near: &Self::Near,
    ) -> Result<Option<(f64, Self::Near)>, AnalysisError>;

    /// How finely `g` is known: its difference step and when a point is on
    /// the curve.
    fn accuracy(&self) -> Accuracy {
        Accuracy::EIGENVALUES
    }
}

/// The difference step of `g`'s derivatives and the distance from the
/// curve a point counts as on it, both scaled.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Accuracy {
    pub step: f64,
    pub on_curve: f64,
    /// Central differences; else forward ones (half the evaluations, for
    /// a `g` that costs much).
    pub central: bool,
}

impl Accuracy {
    /// For `g` an eigenvalue's part, known to rounding.
    pub const EIGENVALUES: Self = Self {
        step: 1e-6,
        on_curve: 1e-11,
        central: true,
    };
}

/// How a followed curve ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum End {
    /// It left the second parameter's range (the last point is on its end).
    ParameterEdge,
    /// It left the load range (the last point is on its end).
    LoadEdge,
    /// Its eigenvalue was gone past the last point: a pair met on the
    /// real axis (at zero, on a Hopf curve: a Bogdanov-Takens point).
    Merged,
    /// It came back to where it started.
    Closed,
    /// The corrector failed down to the smallest step.
    Lost,
    /// The most steps were taken.
    Steps,
}

/// A point of the curve: scaled coordinates and what `g` is of there.
pub(crate) type Node<N = C64> = ([f64; 2], N);

/// A followed curve's points and how it ended.
pub(crate) type Followed<N> = (Vec<Node<N>>, End);

/// A curve followed both ways: its points and how each end ended.
pub(crate) type Curve<N> = (Vec<Node<N>>, [End; 2]);
/// The first, the largest and the smallest arclength step (scaled).
const FIRST_STEP: f64 = 0.01;
const LARGEST_STEP: f64 = 0.03;
const SMALLEST_STEP: f64 = 1e-7;
/// The most steps along one direction.
const MOST_STEPS: usize = 5000;
/// The largest turn of the tangent in one step, in radians.
const LARGEST_TURN: f64 = 0.25;

/// Follows the curve through `start` in the direction `sign` (+1 or -1)
/// of its tangent there: its points from `start` on, and how it ended.
///
/// # Errors
/// An eigenvalue computation that fails.
pub(crate) fn follow<G: Defining + ?Sized>(
    g: &G,
    plane: &Plane,
    start: Node<G::Near>,
    sign: f64,
) -> Result<Followed<G::Near>, AnalysisError> {
    let (y, p) = plane.point(start.0);
    let Some((value, _)) = g.value(y, p, &start.1)? else {
        return Ok((vec![start], End::Lost));
    };
    let Some(gradient) = gradient(g, plane, &start, value)? else {
        return Ok((vec![start], End::Lost));
    };
    let mut tangent = scale(tangent_of(gradient), sign);
    let mut step = FIRST_STEP;
    let mut merged = false;
    let origin = start.0;
    let mut nodes = vec![start];
    for _ in 0..MOST_STEPS {
        let Some(last) = nodes.last() else {
            break;
        };
        let z = last.0;
        match advance(g, plane, last, tangent, step)? {
            Step::Point(node, t1) => {
                merged = false;
                let z1 = node.0;
                nodes.push(node);
                if nodes.len() > 8 && distance(z1, origin) < 0.5 * step {
                    return Ok((nodes, End::Closed));
                }
                tangent = t1;
                step = (step * 1.3).min(LARGEST_STEP);
            }
            Step::Edge(node, end) => {
                if distance(node.0, z) > 1e-12 {
                    nodes.push(node);
                }
                return Ok((nodes, end));
            }
            Step::Refused { gone } => {
                merged |= gone;
                step *= 0.5;
                if step < SMALLEST_STEP {
                    return Ok((nodes, if merged { End::Merged } else { End::Lost }));
                }
            }
        }
    }
    Ok((nodes, End::Steps))
}

/// Follows the curve through `start` both ways: its points from one end
/// to the other, and how each end ended.
///
/// # Errors
/// An eigenvalue computation that fails.
pub(crate) fn follow_both<G: Defining + ?Sized>(
    g: &G,
    plane: &Plane,
    start: Node<G::Near>,
) -> Result<Curve<G::Near>, AnalysisError> {
    let (back, first_end) = follow(g, plane, start.clone(), -1.0)?;
    let (ahead, last_end) = follow(g, plane, start, 1.0)?;
    let nodes = back
        .into_iter()
        .rev()
        .chain(ahead.into_iter().skip(1))
        .collect();
    Ok((nodes, [first_end, last_end]))
}

/// What one step along the curve found.
enum Step<N> {
    /// The next point and the tangent there.
    Point(Node<N>, [f64; 2]),
    /// The curve's point on an edge of the box, which ends it.
    Edge(Node<N>, End),
    /// No point at this step (`gone`: the eigenvalue was gone).
    Refused { gone: bool },
}

/// One step of `step` from `node` along `tangent`: predicted, corrected
/// and its turn checked. A step past an edge of the box (where the column
/// may not exist: eta > 1) is replaced by the curve's point on the edge.
fn advance<G: Defining + ?Sized>(
    g: &G,
    plane: &Plane,
    from: &Node<G::Near>,
    tangent: [f64; 2],
    step: f64,
) -> Result<Step<G::Near>, AnalysisError> {
    let refused = Step::Refused { gone: false };
    let z = from.0;
    let predicted = [z[0] + step * tangent[0], z[1] + step * tangent[1]];
    let beyond = match outside(predicted) {
        Some(edge) => Some((predicted, edge)),
        None => match correct(g, plane, predicted, tangent, &from.1)? {
            Corrected::Point(node, grad) => match outside(node.0) {
                Some(edge) => Some((node.0, edge)),
                None => {
                    return Ok(match turned_tangent(grad, tangent) {
                        Some(t) => Step::Point(node, t),
                        None => refused,
                    });
                }
            },
            Corrected::Gone => return Ok(Step::Refused { gone: true }),
            Corrected::Failed => return Ok(refused),
        },
    };
    let Some((past, (edge, end))) = beyond else {
        return Ok(refused);
    };
    Ok(match on_edge(g, plane, from, past, edge)? {
        Some(node) => Step::Edge(node, end),
        None => refused,
    })
}

/// What the corrector found.
enum Corrected<N> {
    /// The point, and the gradient of `g` at the last iterate before it.
    Point(Node<N>, [f64; 2]),
    /// The eigenvalue is gone at the prediction or on the way.
    Gone,
    Failed,
}

/// Newton's method on `g = 0` and `tangent . (z - predicted) = 0`, with
/// the gradient of `g` kept while `|g|` at least halves at each iterate
/// (the chord method: a gradient costs two evaluations per coordinate).
fn correct<G: Defining + ?Sized>(
    g: &G,
    plane: &Plane,
    predicted: [f64; 2],
    tangent: [f64; 2],
    near: &G::Near,
) -> Result<Corrected<G::Near>, AnalysisError> {
    let accuracy = g.accuracy();
    let mut node = (predicted, near.clone());
    let mut kept: Option<([f64; 2], f64)> = None;
    for _ in 0..12 {
        let (y, p) = plane.point(node.0);
        let Some((value, found)) = g.value(y, p, &node.1)? else {
            return Ok(Corrected::Gone);
        };
        node.1 = found;
        let grad = match kept {
            Some((grad, before)) if value.abs() <= 0.5 * before.abs() => grad,
            _ => match gradient(g, plane, &node, value)? {
                Some(grad) => grad,
                None => return Ok(Corrected::Gone),
            },
        };
        kept = Some((grad, value));
        let z = node.0;
        let along = tangent[0] * (z[0] - predicted[0]) + tangent[1] * (z[1] - predicted[1]);
        let Some(dz) = solve2([grad, tangent], [-value, -along]) else {
            return Ok(Corrected::Failed);
        };
        node.0 = [z[0] + dz[0], z[1] + dz[1]];
        if value.abs() <= accuracy.on_curve * grad[0].hypot(grad[1])
            && dz[0].hypot(dz[1]) <= 10.0 * accuracy.on_curve
        {
            return Ok(Corrected::Point(node, grad));
        }
        if dz[0].hypot(dz[1]) > 1.0 {
            return Ok(Corrected::Failed);
        }
    }
    Ok(Corrected::Failed)
}

/// The tangent of the level curve with gradient `grad`, turned the way of
/// `before`, if it turned less than [`LARGEST_TURN`] from it.
fn turned_tangent(grad: [f64; 2], before: [f64; 2]) -> Option<[f64; 2]> {
    let mut t = tangent_of(grad);
    let cos = t[0] * before[0] + t[1] * before[1];
    if cos < 0.0 {
        t = scale(t, -1.0);
    }
    (cos.abs() >= LARGEST_TURN.cos()).then_some(t)
}

/// `(dg/du, dg/dv)` at `node`, where `g` is `value`, by central
/// differences, one-sided where the column does not exist on one side (an
/// end of its range, such as eta = 1); `None` where the eigenvalue is gone
/// on both sides, or the gradient vanishes.
fn gradient<G: Defining + ?Sized>(
    g: &G,
    plane: &Plane,
    (z, near): &Node<G::Near>,
    value: f64,
) -> Result<Option<[f64; 2]>, AnalysisError> {
    let Accuracy {
        step: h, central, ..
    } = g.accuracy();
    let mut out = [0.0; 2];
    for (k, slot) in out.iter_mut().enumerate() {
        let at = |sign: f64| -> Result<Option<f64>, AnalysisError> {
            let mut moved = *z;
            moved[k] += sign * h;
            let (y, p) = plane.point(moved);
            Ok(g.value(y, p, near)?.map(|(value, _)| value))
        };
        let plus = at(1.0)?;
        let minus = if central || plus.is_none() {
            at(-1.0)?
        } else {
            None
        };
        *slot = match (plus, minus) {
            (Some(plus), Some(minus)) => (plus - minus) / (2.0 * h),
            (Some(plus), None) => (plus - value) / h,
            (None, Some(minus)) => (value - minus) / h,
            (None, None) => return Ok(None),
        };
    }
    let size = out[0].hypot(out[1]);
    Ok((size.is_finite() && size > 0.0).then_some(out))
}

/// The unit tangent of the level curve with this gradient.
fn tangent_of(gradient: [f64; 2]) -> [f64; 2] {
    let size = gradient[0].hypot(gradient[1]);
    [-gradient[1] / size, gradient[0] / size]
}

fn scale(v: [f64; 2], s: f64) -> [f64; 2] {
    [s * v[0], s * v[1]]
}

pub(crate) fn distance(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// `rows x = rhs` for two rows, by Cramer's rule; `None` when singular.
fn solve2(rows: [[f64; 2]; 2], rhs: [f64; 2]) -> Option<[f64; 2]> {
    let [[a, b], [c, d]] = rows;
    let det = a * d - b * c;
    let size = (a.abs() + b.abs()) * (c.abs() + d.abs());
    (det.abs() > 1e-14 * size && det.is_finite()).then(|| {
        [
            (rhs[0] * d - b * rhs[1]) / det,
            (a * rhs[1] - c * rhs[0]) / det,
        ]
    })
}

/// Which edge of the box `z` is beyond, if any: the coordinate, the
/// edge's value and how the curve ends there.
fn outside(z: [f64; 2]) -> Option<((usize, f64), End)> {
    if z[0] < 0.0 {
        Some(((0, 0.0), End::ParameterEdge))
    } else if z[0] > 1.0 {
        Some(((0, 1.0), End::ParameterEdge))
    } else if z[1] < 0.0 {
        Some(((1, 0.0), End::LoadEdge))
    } else if z[1] > 1.0 {
        Some(((1, 1.0), End::LoadEdge))
    } else {
        None
    }
}

/// The curve's point on the edge `z[k] = value` between `inside` and the
/// point `beyond` past it: Newton's method on `g` in the other coordinate
/// from where the chord crosses the edge.
///
/// # Errors
/// An eigenvalue computation that fails.
pub(crate) fn on_edge<G: Defining + ?Sized>(
    g: &G,
    plane: &Plane,
    (inside, near): &Node<G::Near>,
    beyond: [f64; 2],
    (k, value): (usize, f64),
) -> Result<Option<Node<G::Near>>, AnalysisError> {
    let other = 1 - k;
    let s = (value - inside[k]) / (beyond[k] - inside[k]);
    let mut node = (*inside, near.clone());
    node.0[k] = value;
    node.0[other] = inside[other] + s * (beyond[other] - inside[other]);
    let tolerance = 0.1 * g.accuracy().on_curve;
    for _ in 0..20 {
        let (y, p) = plane.point(node.0);
        let Some((g0, found)) = g.value(y, p, &node.1)? else {
            return Ok(None);
        };
        node.1 = found;
        let Some(grad) = gradient(g, plane, &node, g0)? else {
            return Ok(None);
        };
        if grad[other] == 0.0 {
            return Ok(None);
        }
        let dz = -g0 / grad[other];
        node.0[other] += dz;
        if dz.abs() <= tolerance {
            // Past a corner the curve leaves by the other edge first.
            return Ok((0.0..=1.0).contains(&node.0[other]).then_some(node));
        }
        if dz.abs() > 1.0 {
            return Ok(None);
        }
    }
    Ok(None)
}

/// The curve's point nearest `fraction` of the way from `a` to `b` (two
/// of its points): the chord's point corrected onto the curve across the
/// chord.
///
/// # Errors
/// An eigenvalue computation that fails.
pub(crate) fn between<G: Defining + ?Sized>(
    g: &G,
    plane: &Plane,
    a: &Node<G::Near>,
    b: [f64; 2],
    fraction: f64,
) -> Result<Option<Node<G::Near>>, AnalysisError> {
    let chord = [b[0] - a.0[0], b[1] - a.0[1]];
    let length = chord[0].hypot(chord[1]);
    if length == 0.0 {
        return Ok(Some(a.clone()));
    }
    let along = scale(chord, 1.0 / length);
    let predicted = [a.0[0] + fraction * chord[0], a.0[1] + fraction * chord[1]];
    Ok(match correct(g, plane, predicted, along, &a.1)? {
        Corrected::Point(node, _) => Some(node),
        Corrected::Gone | Corrected::Failed => None,
    })
}

/// Where the curves of `g` and `h` cross, from `z` (scaled) near it with
/// what each is of there: Newton's method on both defining functions at
/// once; `None` where it does not converge within `reach` (scaled) of `z`.
///
/// # Errors
/// An eigenvalue computation that fails.
pub(crate) fn crossing<G: Defining + ?Sized, H: Defining + ?Sized>(
    (g, h): (&G, &H),
    plane: &Plane,
    z: [f64; 2],
    (near_g, near_h): (&G::Near, &H::Near),
    reach: f64,
) -> Result<Option<[f64; 2]>, AnalysisError> {
    let tolerance = 10.0 * g.accuracy().on_curve.max(h.accuracy().on_curve);
    let (mut at, mut near_g, mut near_h) = (z, near_g.clone(), near_h.clone());
    for _ in 0..20 {
        let (y, p) = plane.point(at);
        let (Some((vg, found_g)), Some((vh, found_h))) =
            (g.value(y, p, &near_g)?, h.value(y, p, &near_h)?)
        else {
            return Ok(None);
        };
        (near_g, near_h) = (found_g, found_h);
        let (Some(grad_g), Some(grad_h)) = (
            gradient(g, plane, &(at, near_g.clone()), vg)?,
            gradient(h, plane, &(at, near_h.clone()), vh)?,
        ) else {
            return Ok(None);
        };
        let Some(dz) = solve2([grad_g, grad_h], [-vg, -vh]) else {
            return Ok(None);
        };
        at = [at[0] + dz[0], at[1] + dz[1]];
        if distance(at, z) > reach {
            return Ok(None);
        }
        if dz[0].hypot(dz[1]) <= tolerance {
            return Ok(Some(at));
        }
    }
    Ok(None)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The unit circle about (0.5, 0.5) of radius 0.3: g = r^2 - 0.09.
    struct Circle;

    impl Defining for Circle {
        type Near = C64;
        fn value(&self, y: f64, p: f64, near: &C64) -> Result<Option<(f64, C64)>, AnalysisError> {
            Ok(Some(((y - 0.5).powi(2) + (p - 0.5).powi(2) - 0.09, *near)))
        }
    }

    /// A circle is followed round through both its folds in y and back
    /// to its start, every point on it.
    #[test]
    fn a_circle_is_followed_round_through_its_folds() {
        let plane = Plane {
            y: (0.0, 1.0),
            p: (0.0, 1.0),
        };
        let start = ([0.8, 0.5], C64::new(0.0, 1.0));
        let (nodes, end) = follow(&Circle, &plane, start, 1.0).unwrap();
        assert_eq!(end, End::Closed);
        for (z, _) in &nodes {
            let r = (z[0] - 0.5).hypot(z[1] - 0.5);
            assert!((r - 0.3).abs() < 1e-9, "r = {r}");
        }
        let lowest = nodes.iter().map(|n| n.0[0]).fold(1.0, f64::min);
        assert!(lowest < 0.21, "round the fold at y = 0.2: {lowest}");
    }

    /// A circle of radius 0.6 about the box's centre, cut by the box: each
    /// way it ends on an edge, its last point on the edge and the circle.
    #[test]
    fn a_curve_leaving_the_box_ends_on_its_edge() {
        struct Wide;
        impl Defining for Wide {
            type Near = C64;
            fn value(&self, y: f64, p: f64, n: &C64) -> Result<Option<(f64, C64)>, AnalysisError> {
                Ok(Some(((y - 0.5).powi(2) + (p - 0.5).powi(2) - 0.36, *n)))
            }
        }
        let plane = Plane {
            y: (0.0, 1.0),
            p: (0.0, 1.0),
        };
        let r = 0.6 / 2f64.sqrt();
        let start = ([0.5 + r, 0.5 + r], C64::new(0.0, 1.0));
        for sign in [1.0, -1.0] {
            let (nodes, end) = follow(&Wide, &plane, start, sign).unwrap();
            let (last, _) = *nodes.last().unwrap();
            let on_edge = |x: f64| x.abs() < 1e-15 || (x - 1.0).abs() < 1e-15;
            match end {
                End::ParameterEdge => assert!(on_edge(last[0]), "{last:?}"),
                End::LoadEdge => assert!(on_edge(last[1]), "{last:?}"),
                other => panic!("{other:?}"),
            }
            let radius = (last[0] - 0.5).hypot(last[1] - 0.5);
            assert!((radius - 0.6).abs() < 1e-9, "{radius}");
        }
    }

    /// A circle and a line through it cross where the algebra says,
    /// to rounding, from a chord's crossing 0.01 away.
    #[test]
    fn a_crossing_is_refined_onto_both_curves() {
        struct Line;
        impl Defining for Line {
            type Near = C64;
            fn value(&self, y: f64, p: f64, n: &C64) -> Result<Option<(f64, C64)>, AnalysisError> {
                Ok(Some((p - y, *n)))
            }
        }
        let plane = Plane {
            y: (0.0, 1.0),
            p: (0.0, 1.0),
        };
        let near = C64::new(0.0, 1.0);
        let exact = 0.5 + 0.3 / 2f64.sqrt();
        let start = [exact + 0.01, exact - 0.005];
        let found = crossing((&Circle, &Line), &plane, start, (&near, &near), 0.1)
            .unwrap()
            .unwrap();
        assert!(
            (found[0] - exact).abs() < 1e-12 && (found[1] - exact).abs() < 1e-12,
            "{found:?}"
        );
    }
}
