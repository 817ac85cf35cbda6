//! A stability boundary as followed through the plane of the load and a
//! second parameter: what it is asked of, its points and how it ends, and
//! the distance of a point from a followed curve. What the boundaries and
//! the folds of cycles share. Pure: no UI, no clock.

use serde::Serialize;

use super::arclength::{End, Node};
use crate::analysis::C64;
use crate::model::{Axis, Model};

/// What the boundaries are asked of: a column, the second parameter and
/// its range, and the load range.
#[derive(Clone, Debug, PartialEq)]
pub struct BoundarySpec {
    pub model: Model,
    pub axis: Axis,
    pub axis_range: (f64, f64),
    pub load_range: (f64, f64),
}

/// What kind of stability boundary a curve is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum BoundaryKind {
    /// A pair of eigenvalues on the imaginary axis: flutter sets in.
    Flutter,
    /// A real eigenvalue at zero: divergence sets in.
    Divergence,
}

/// One point of a boundary.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BoundaryPoint {
    /// The second parameter's value.
    pub value: f64,
    pub load: f64,
    /// The eigenvalue on the imaginary axis (its upper one, for a pair).
    pub eigenvalue: C64,
    /// On a Hopf curve: the first Lyapunov coefficient (negative: soft
    /// onset; positive: hard), `None` where there is none (a reversible
    /// column) or it failed.
    pub first_lyapunov: Option<f64>,
}

/// How a boundary ends, at either end.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum CurveEnd {
    /// At an end of the second parameter's range.
    ParameterEdge,
    /// At an end of the load range.
    LoadEdge,
    /// The pair met on the real axis: a Bogdanov-Takens point.
    PairMerged,
    /// The curve is closed.
    Closed,
    /// The continuation could not go on (a reversible column, where a
    /// pair's growth rate is zero over a whole region, or a corner).
    Lost,
    /// The most steps were taken.
    Steps,
}

impl From<End> for CurveEnd {
    fn from(end: End) -> Self {
        match end {
            End::ParameterEdge => Self::ParameterEdge,
            End::LoadEdge => Self::LoadEdge,
            End::Merged => Self::PairMerged,
            End::Closed => Self::Closed,
            End::Lost => Self::Lost,
            End::Steps => Self::Steps,
        }
    }
}

/// A stability boundary followed through the plane.
#[derive(Clone, Debug, PartialEq)]
pub struct Boundary {
    pub kind: BoundaryKind,
    /// In the order followed.
    pub points: Vec<BoundaryPoint>,
    /// How its first and its last point end it.
    pub ends: [CurveEnd; 2],
}

/// Where `z` falls beside the segment from `a` to `b`: the fraction of
/// the way along it of its foot on the segment's line, and its distance
/// from the segment (from the nearer end past either end); `None` for a
/// segment of no length.
pub(super) fn project(z: [f64; 2], a: [f64; 2], b: [f64; 2]) -> Option<(f64, f64)> {
    let d = [b[0] - a[0], b[1] - a[1]];
    let length2 = d[0] * d[0] + d[1] * d[1];
    if length2 <= 0.0 {
        return None;
    }
    let s = ((z[0] - a[0]) * d[0] + (z[1] - a[1]) * d[1]) / length2;
    let t = s.clamp(0.0, 1.0);
    Some((s, (z[0] - a[0] - t * d[0]).hypot(z[1] - a[1] - t * d[1])))
}

/// The distance from `z` to the polyline through `nodes` (scaled).
pub(super) fn near_polyline<N>(z: [f64; 2], nodes: &[Node<N>]) -> f64 {
    let segment = |a: [f64; 2], b: [f64; 2]| {
        project(z, a, b).map_or_else(|| (z[0] - a[0]).hypot(z[1] - a[1]), |(_, d)| d)
    };
    match nodes {
        [] => f64::INFINITY,
        [only] => segment(only.0, only.0),
        _ => nodes
            .windows(2)
            .map(|w| segment(w[0].0, w[1].0))
            .fold(f64::INFINITY, f64::min),
    }
}

/// The load at `value` on the chord from `a` to `b` (each `(value,
/// load)`), where the chord spans `value` (ends included) and is not
/// upright.
#[must_use]
pub fn load_on_chord(a: (f64, f64), b: (f64, f64), value: f64) -> Option<f64> {
    let ((x0, y0), (x1, y1)) = (a, b);
    if x0 == x1 || !(x0.min(x1)..=x0.max(x1)).contains(&value) {
        return None;
    }
    Some(y0 + (value - x0) / (x1 - x0) * (y1 - y0))
}
