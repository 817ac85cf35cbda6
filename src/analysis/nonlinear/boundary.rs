//! The stability boundaries of the straight column in the plane of the load
//! and a second parameter: every flutter onset (a Hopf curve, a pair's
//! growth rate zero) and every divergence onset (a real eigenvalue zero)
//! followed by pseudo-arclength continuation ([`super::arclength`]) from
//! the critical loads found at a few values of the parameter; along each
//! Hopf curve the first Lyapunov coefficient (soft or hard onset) and the
//! Bautin points where it changes sign; where the curves end or meet, the
//! Bogdanov-Takens, double-Hopf and zero-Hopf points. Pure: no UI, no clock.

use std::sync::atomic::AtomicBool;

use serde::Serialize;

use super::arclength::{Defining, End, Node, Plane, between, crossing, distance, follow_both};
use super::bautin::fitted_coefficients;
use super::curve::{Boundary, BoundaryKind, BoundaryPoint, BoundarySpec, near_polyline, project};
use super::cycle_fold::{CycleFold, cycle_folds};
use super::hopf::{Steps, dissipative, hopf_at, is_hopf};
use crate::analysis::{AffinePencil, AnalysisError, C64, State, critical_loads};
use crate::model::{Axis, Key, Model};

/// Values of the second parameter at which the critical loads are found
/// to start the curves from, ends included.
const SEEDS: usize = 9;
/// A pair is on the real axis below this share of the frequency scale.
const REAL: f64 = 1e-9;
/// A seed this near (scaled) a curve followed already may be on it; it is
/// when the curve's point beside it is within [`SAME_POINT`].
const NEAR_CURVE: f64 = 0.02;
const SAME_POINT: f64 = 1e-7;
/// A Hopf curve's end at this share of its highest frequency or less is
/// where its pair met on the real axis.
const MERGED: f64 = 0.01;
/// Bisection steps for a Bautin point along its Hopf curve.
const BISECTIONS: usize = 48;

/// What a special point is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum SpecialKind {
    /// The first Lyapunov coefficient changes sign along a Hopf curve
    /// (generalized Hopf): the onset turns from soft to hard.
    Bautin,
    /// A Hopf curve ends on a divergence curve, its frequency zero.
    BogdanovTakens,
    /// Two Hopf curves cross: two pairs on the imaginary axis.
    DoubleHopf,
    /// A Hopf curve crosses a divergence curve (fold-Hopf).
    ZeroHopf,
}

/// A point where the boundaries change character or meet.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpecialPoint {
    pub kind: SpecialKind,
    pub value: f64,
    pub load: f64,
    /// The curves (indices into [`Boundaries::curves`]) it lies on.
    pub curves: [usize; 2],
    /// At a Bautin point, the second Lyapunov coefficient (negative: the
    /// cycles born there are stable; see `bautin`), where the cycles were
    /// found.
    pub second_lyapunov: Option<f64>,
}

/// Every boundary in the plane, the special points on them, and the folds
/// of cycles from their hard stretches.
#[derive(Clone, Debug, PartialEq)]
pub struct Boundaries {
    pub curves: Vec<Boundary>,
    pub special_points: Vec<SpecialPoint>,
    pub folds: Vec<CycleFold>,
}

/// The defining function of a boundary: the growth rate of the tracked
/// eigenvalue, over the frequency scale.
struct Growth<'a> {
    spec: &'a BoundarySpec,
    kind: BoundaryKind,
}

impl Growth<'_> {
    /// The column at `value` of the second parameter.
    fn model(&self, value: f64) -> Option<Model> {
        self.spec.axis.apply(&self.spec.model, value).ok()
    }
}

impl Defining for Growth<'_> {
    type Near = C64;

    /// On a Hopf curve the growth rate of the pair nearest `near`; on a
    /// divergence curve the product of every eigenvalue over the frequency
    /// scale (the pencil's determinant, smooth through a Bogdanov-Takens
    /// point, where the real eigenvalue at zero meets another), with the
    /// real eigenvalue nearest zero.
    fn value(&self, y: f64, p: f64, near: &C64) -> Result<Option<(f64, C64)>, AnalysisError> {
        let near = *near;
        let Some(model) = self.model(y) else {
            return Ok(None);
        };
        let Ok(pencil) = AffinePencil::new(&model) else {
            return Ok(None);
        };
        let spectrum = pencil.spectrum(p)?;
        let scale = spectrum.scale_per_s;
        let real = REAL * scale;
        Ok(match self.kind {
            BoundaryKind::Flutter => spectrum
                .eigenvalues
                .iter()
                .copied()
                .filter(|z| z.im > real)
                .min_by(|a, b| (a - near).norm().total_cmp(&(b - near).norm()))
                .map(|z| (z.re / scale, z)),
            BoundaryKind::Divergence => {
                let determinant = spectrum
                    .eigenvalues
                    .iter()
                    .fold(C64::new(1.0, 0.0), |product, z| product * (z / scale));
                let zero = spectrum
                    .eigenvalues
                    .iter()
                    .filter(|z| z.im.abs() <= real)
                    .map(|z| C64::new(z.re, 0.0))
                    .min_by(|a, b| a.re.abs().total_cmp(&b.re.abs()))
                    .unwrap_or_default();
                Some((determinant.re, zero))
            }
        })
    }
}

/// The stability boundaries of `spec`'s column over its plane.
///
/// # Errors
/// A bad range, a second parameter that is the load, a column that cannot
/// be analysed at the range's ends, or an eigenvalue computation that fails.
pub fn boundaries(spec: &BoundarySpec) -> Result<Boundaries, AnalysisError> {
    boundaries_until(spec, &AtomicBool::new(false))
}

/// [`boundaries`], the folds of cycles cut short once `cancel` is set (a
/// window's job whose result is no longer wanted).
///
/// # Errors
/// As [`boundaries`].
pub fn boundaries_until(
    spec: &BoundarySpec,
    cancel: &AtomicBool,
) -> Result<Boundaries, AnalysisError> {
    check(spec)?;
    let plane = Plane {
        y: spec.axis_range,
        p: spec.load_range,
    };
    let curves = follow_all(spec, &plane)?;
    let mut out = Vec::with_capacity(curves.len());
    let mut special = Vec::new();
    for (index, followed) in curves.iter().enumerate() {
        let (boundary, found) = describe(spec, &plane, index, followed, &curves)?;
        out.push(boundary);
        special.extend(found);
    }
    // A Hopf curve's last chord reaches past its Bogdanov-Takens end and
    // may cut the divergence curve there: that is the same point.
    let ends: Vec<[f64; 2]> = special
        .iter()
        .filter(|s| s.kind == SpecialKind::BogdanovTakens)
        .map(|s| plane.scaled(s.value, s.load))
        .collect();
    special.extend(crossings(spec, &curves, &plane)?.into_iter().filter(|s| {
        let z = plane.scaled(s.value, s.load);
        ends.iter()
            .all(|e| (e[0] - z[0]).hypot(e[1] - z[1]) > NEAR_CURVE)
    }));
    let folds = cycle_folds(spec, &out, cancel)?;
    Ok(Boundaries {
        curves: out,
        special_points: special,
        folds,
    })
}

/// A curve as followed: its kind, its points and how each end ended.
type Followed = (BoundaryKind, Vec<Node>, [End; 2]);

/// Every curve through the critical loads at [`SEEDS`] values of the
/// second parameter, each followed both ways from the first of its
/// critical loads met.
fn follow_all(spec: &BoundarySpec, plane: &Plane) -> Result<Vec<Followed>, AnalysisError> {
    let mut curves: Vec<Followed> = Vec::new();
    for k in 0..SEEDS {
        #[expect(clippy::cast_precision_loss, reason = "a handful of seeds")]
        let u = k as f64 / (SEEDS - 1) as f64;
        let (y, _) = plane.point([u, 0.0]);
        let Ok(model) = spec.axis.apply(&spec.model, y) else {
            continue;
        };
        for (kind, load, eigenvalue) in seeds(&model, spec.load_range)? {
            if kind == BoundaryKind::Flutter && !dissipative(&model) {
                continue;
            }
            let start = (plane.scaled(y, load), eigenvalue);
            let growth = Growth { spec, kind };
            let mut on_one = false;
            for (other, nodes, _) in &curves {
                if *other == kind && on_curve(&growth, plane, start.0, nodes)? {
                    on_one = true;
                    break;
                }
            }
            if on_one {
                continue;
            }
            let (nodes, ends) = follow_both(&growth, plane, start)?;
            curves.push((kind, nodes, ends));
        }
    }
    Ok(curves)
}

/// The curve `index` of `curves` as a boundary: its points with the first
/// Lyapunov coefficient along a Hopf curve, and its Bautin and
/// Bogdanov-Takens points.
fn describe(
    spec: &BoundarySpec,
    plane: &Plane,
    index: usize,
    (kind, nodes, ends): &Followed,
    curves: &[Followed],
) -> Result<(Boundary, Vec<SpecialPoint>), AnalysisError> {
    let growth = Growth { spec, kind: *kind };
    let lyapunov = |(z, _): &Node| -> Option<f64> {
        let (y, p) = plane.point(*z);
        let model = growth.model(y)?;
        match hopf_at(&model, p, Steps::DEFAULT) {
            Ok(Ok(hopf)) => Some(hopf.first_lyapunov),
            _ => None,
        }
    };
    let first_lyapunov: Vec<Option<f64>> = match kind {
        BoundaryKind::Flutter => nodes.iter().map(lyapunov).collect(),
        BoundaryKind::Divergence => vec![None; nodes.len()],
    };
    let mut special = Vec::new();
    for (i, pair) in first_lyapunov.windows(2).enumerate() {
        if let [Some(a), Some(b)] = pair
            && a.signum() != b.signum()
            && let Some(node) = bautin(&growth, plane, nodes[i], nodes[i + 1].0, *a, &lyapunov)?
        {
            let (value, load) = plane.point(node.0);
            special.push(SpecialPoint {
                kind: SpecialKind::Bautin,
                value,
                load,
                curves: [index, index],
                second_lyapunov: growth
                    .model(value)
                    .and_then(|model| fitted_coefficients(&model, load))
                    .map(|[_, l2, ..]| l2),
            });
        }
    }
    if *kind == BoundaryKind::Flutter {
        // A Hopf curve ends at a Bogdanov-Takens point when its pair meets
        // on the real axis, at zero: its frequency falls to nothing (the
        // last step before the pair is gone).
        let fastest = nodes.iter().map(|n| n.1.im).fold(0.0, f64::max);
        for (end, node) in ends.iter().zip([nodes.first(), nodes.last()]) {
            if let (End::Merged | End::Lost, Some((z, lambda))) = (end, node)
                && lambda.im <= MERGED * fastest
            {
                let (value, load) = plane.point(*z);
                let on = curves
                    .iter()
                    .position(|(k, n, _)| {
                        *k == BoundaryKind::Divergence && near_polyline(*z, n) < 1e-3
                    })
                    .unwrap_or(index);
                special.push(SpecialPoint {
                    kind: SpecialKind::BogdanovTakens,
                    value,
                    load,
                    curves: [index, on],
                    second_lyapunov: None,
                });
            }
        }
    }
    let points = nodes
        .iter()
        .zip(first_lyapunov)
        .map(|((z, eigenvalue), first_lyapunov)| {
            let (value, load) = plane.point(*z);
            BoundaryPoint {
                value,
                load,
                eigenvalue: *eigenvalue,
                first_lyapunov,
            }
        })
        .collect();
    let boundary = Boundary {
        kind: *kind,
        points,
        ends: [ends[0].into(), ends[1].into()],
    };
    Ok((boundary, special))
}

/// Refuses a second parameter that is the load, a range that is not one,
/// and a column that cannot be analysed at the range's ends.
fn check(spec: &BoundarySpec) -> Result<(), AnalysisError> {
    if spec.axis == Axis::Key(Key::Load) {
        return Err(AnalysisError::BadRange {
            what: "y",
            value: spec.axis_range.0,
            allowed: "the second parameter cannot be the load, which the boundaries are found in",
        });
    }
    if spec.axis.counts() {
        return Err(AnalysisError::BadRange {
            what: "y",
            value: spec.axis_range.0,
            allowed: "the boundaries are followed in a parameter that varies continuously, and the rods are counted; compare chains with `map --y rods:MIN:MAX:N`",
        });
    }
    let (y0, y1) = spec.axis_range;
    if !(y0.is_finite() && y1.is_finite() && y1 > y0) {
        return Err(AnalysisError::BadRange {
            what: "y",
            value: y1,
            allowed: "MAX must be a finite number above MIN",
        });
    }
    let (p0, p1) = spec.load_range;
    if !(p0.is_finite() && p1.is_finite() && p1 > p0) {
        return Err(AnalysisError::BadRange {
            what: "load-max",
            value: p1,
            allowed: "must be a finite number above load-min",
        });
    }
    for y in [y0, y1] {
        AffinePencil::new(&spec.axis.apply(&spec.model, y)?)?;
    }
    Ok(())
}

/// The boundaries `model` crosses over the load range: each critical load
/// where a pair crosses the imaginary axis or a real eigenvalue zero, with
/// that eigenvalue there.
fn seeds(
    model: &Model,
    load_range: (f64, f64),
) -> Result<Vec<(BoundaryKind, f64, C64)>, AnalysisError> {
    let pencil = AffinePencil::new(model)?;
    let mut out = Vec::new();
    for t in critical_loads(&pencil, load_range.0, load_range.1)? {
        let spectrum = pencil.spectrum(t.load)?;
        let real = REAL * spectrum.scale_per_s;
        let nearest = |pick: &dyn Fn(&C64) -> bool| {
            spectrum
                .eigenvalues
                .iter()
                .copied()
                .filter(|z| pick(z))
                .min_by(|a, b| a.re.abs().total_cmp(&b.re.abs()))
        };
        let kind = if is_hopf(t.from, t.to) {
            BoundaryKind::Flutter
        } else if t.from == State::Divergence || t.to == State::Divergence {
            BoundaryKind::Divergence
        } else {
            continue;
        };
        let found = match kind {
            BoundaryKind::Flutter => nearest(&|z| z.im > real),
            BoundaryKind::Divergence => nearest(&|z| z.im.abs() <= real),
        };
        // A divergence that is not a zero crossing (a pair meeting on the
        // positive real axis, unstable on both sides) is no boundary.
        if let Some(z) = found
            && z.re.abs() <= 1e-6 * spectrum.scale_per_s
        {
            out.push((kind, t.load, z));
        }
    }
    Ok(out)
}

/// Whether `z` (a point of a curve of this kind) lies on the curve
/// followed through `nodes`: near its polyline, and on the curve where the
/// chord beside it is corrected onto the curve.
fn on_curve(
    growth: &Growth<'_>,
    plane: &Plane,
    z: [f64; 2],
    nodes: &[Node],
) -> Result<bool, AnalysisError> {
    if near_polyline(z, nodes) > NEAR_CURVE {
        return Ok(false);
    }
    for pair in nodes.windows(2) {
        let (a, b) = (pair[0], pair[1].0);
        let Some((s, across)) = project(z, a.0, b) else {
            continue;
        };
        if !(0.0..=1.0).contains(&s) || across > NEAR_CURVE {
            continue;
        }
        if let Some((point, _)) = between(growth, plane, &a, b, s)?
            && (point[0] - z[0]).hypot(point[1] - z[1]) <= SAME_POINT
        {
            return Ok(true);
        }
    }
    Ok(nodes
        .iter()
        .any(|(point, _)| (point[0] - z[0]).hypot(point[1] - z[1]) <= SAME_POINT))
}

/// The Bautin point between `a` and `b` (where the first Lyapunov
/// coefficient, `at_a` at `a`, changes sign), by bisection along the
/// curve.
fn bautin(
    growth: &Growth<'_>,
    plane: &Plane,
    a: Node,
    b: [f64; 2],
    at_a: f64,
    lyapunov: &dyn Fn(&Node) -> Option<f64>,
) -> Result<Option<Node>, AnalysisError> {
    let (mut low, mut high) = (0.0, 1.0);
    let mut found = None;
    for _ in 0..BISECTIONS {
        let middle = 0.5 * (low + high);
        let Some(node) = between(growth, plane, &a, b, middle)? else {
            return Ok(found);
        };
        match lyapunov(&node) {
            Some(l1) if l1.signum() == at_a.signum() => low = middle,
            Some(_) => high = middle,
            None => return Ok(found),
        }
        found = Some(node);
    }
    Ok(found)
}

/// Where two curves cross: double-Hopf (two Hopf curves) and zero-Hopf
/// (a Hopf curve and a divergence curve) points, where their polylines'
/// segments cross.
fn crossings(
    spec: &BoundarySpec,
    curves: &[Followed],
    plane: &Plane,
) -> Result<Vec<SpecialPoint>, AnalysisError> {
    let mut out = Vec::new();
    for (i, (kind_i, nodes_i, _)) in curves.iter().enumerate() {
        for (j, (kind_j, nodes_j, _)) in curves.iter().enumerate().skip(i + 1) {
            let kind = match (kind_i, kind_j) {
                (BoundaryKind::Flutter, BoundaryKind::Flutter) => SpecialKind::DoubleHopf,
                (BoundaryKind::Divergence, BoundaryKind::Divergence) => continue,
                _ => SpecialKind::ZeroHopf,
            };
            let (g, h) = (
                Growth {
                    spec,
                    kind: *kind_i,
                },
                Growth {
                    spec,
                    kind: *kind_j,
                },
            );
            for a in nodes_i.windows(2) {
                for b in nodes_j.windows(2) {
                    if let Some(chord) = segments_cross(a[0].0, a[1].0, b[0].0, b[1].0) {
                        // Refined onto both curves, within a chord's length.
                        let reach = distance(a[0].0, a[1].0).max(distance(b[0].0, b[1].0));
                        let z = crossing((&g, &h), plane, chord, (&a[0].1, &b[0].1), reach)?
                            .unwrap_or(chord);
                        let (value, load) = plane.point(z);
                        out.push(SpecialPoint {
                            kind,
                            value,
                            load,
                            curves: [i, j],
                            second_lyapunov: None,
                        });
                    }
                }
            }
        }
    }
    Ok(out)
}

/// Where the segments `a0 a1` and `b0 b1` cross, if they do.
fn segments_cross(a0: [f64; 2], a1: [f64; 2], b0: [f64; 2], b1: [f64; 2]) -> Option<[f64; 2]> {
    let r = [a1[0] - a0[0], a1[1] - a0[1]];
    let s = [b1[0] - b0[0], b1[1] - b0[1]];
    let den = r[0] * s[1] - r[1] * s[0];
    if den == 0.0 {
        return None;
    }
    let q = [b0[0] - a0[0], b0[1] - a0[1]];
    let t = (q[0] * s[1] - q[1] * s[0]) / den;
    let u = (q[0] * r[1] - q[1] * r[0]) / den;
    ((0.0..1.0).contains(&t) && (0.0..1.0).contains(&u))
        .then(|| [a0[0] + t * r[0], a0[1] + t * r[1]])
}
