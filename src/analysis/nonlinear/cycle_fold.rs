//! The fold of cycles in the plane of the load and a second parameter:
//! where a hard onset's unstable cycle meets the large stable one and both
//! vanish, the lowest load at which the column can keep fluttering. Between
//! it and the Hopf curve a rest state and a large cycle coexist (hysteresis).
//!
//! Each fold is the zero set of `g(y, a) = dp/da`, the load's rate along the
//! branch of cycles at the second parameter `y` parametrized by the first
//! angle's amplitude `a` (`amplitude`), followed by pseudo-arclength
//! continuation in the plane `(y, a)` (`arclength`). The folds are found by
//! marching in `a` from the onset at the middle of each hard stretch of a
//! Hopf curve; a fold born at a Bautin point shrinks to it as `a` goes to
//! zero. Pure: no UI, no clock.

use std::sync::atomic::{AtomicBool, Ordering};

use nalgebra::{DMatrix, DVector};
use serde::Serialize;

use super::amplitude::{AtAmplitude, normal_form_start};
use super::arclength::{Accuracy, Curve, Defining, End, Node, Plane, follow_both};
use super::curve::{Boundary, BoundaryKind, BoundaryPoint, BoundarySpec, near_polyline};
use super::cycle::Cycle;
use super::cycles::{MAX_AMPLITUDE_RAD, STICK_FRACTION};
use super::falsi::{Stop, illinois};
use super::hopf::{Steps, hopf_point};
use super::shooting::Shooting;
use crate::analysis::{AnalysisError, C64};

/// The first angle's amplitudes the folds are followed between, rad. Below
/// the smallest the shooting loses digits (the cycle shrinks onto the rest
/// state, where a fold meets its Bautin point); the largest is where a
/// branch of cycles stops (the column swings round).
const SMALLEST_AMPLITUDE_RAD: f64 = 0.002;
const LARGEST_AMPLITUDE_RAD: f64 = MAX_AMPLITUDE_RAD;
/// The march in amplitude from an onset: each step this factor, at most
/// [`MARCH_MOST_RAD`], at most [`MARCH_STEPS`] steps.
const MARCH_GROWTH: f64 = 1.5;
const MARCH_MOST_RAD: f64 = 0.2;
const MARCH_STEPS: usize = 200;
/// Regula falsi points for a fold between two cycles of a march.
const FALSI_STEPS: usize = 40;
/// A fold point this near (scaled) a fold followed already is on it.
const SAME_FOLD: f64 = 0.01;

/// One point of a fold of cycles.
#[derive(Clone, Debug, PartialEq)]
pub struct FoldPoint {
    /// The second parameter's value.
    pub value: f64,
    pub load: f64,
    /// The first rod's angle's amplitude on the cycle at the fold, rad.
    pub amplitude_rad: f64,
    pub period_secs: f64,
    /// The Floquet multiplier nearest 1 after the trivial one: 1 at a fold
    /// (to the monodromy's accuracy, which a double multiplier halves).
    pub second_multiplier: C64,
}

/// How a fold of cycles ends, at either end.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum FoldEnd {
    /// At an end of the second parameter's range.
    ParameterEdge,
    /// Its cycles shrank to the rest state: at a Bautin point of a Hopf
    /// curve.
    SmallAmplitude,
    /// Its cycles grew to the largest amplitude followed.
    LargeAmplitude,
    /// Its cycles left the load range, neared stick-slip, or the shooting
    /// did not converge.
    Lost,
    /// It came back to where it started.
    Closed,
    /// The most steps were taken.
    Steps,
}

/// A fold of cycles followed through the plane.
#[derive(Clone, Debug, PartialEq)]
pub struct CycleFold {
    /// In the order followed.
    pub points: Vec<FoldPoint>,
    /// How its first and its last point end it.
    pub ends: [FoldEnd; 2],
}

/// The defining function of a fold: the load's rate along the branch.
struct LoadRate<'a> {
    spec: &'a BoundarySpec,
    /// Once set, no cycle is solved: the folds end where they are.
    cancel: &'a AtomicBool,
}

impl LoadRate<'_> {
    /// The cycle at `(y, a)` from the unknowns `guess` of one near it, if
    /// its load is in range and its roller's contact slips.
    fn solve(&self, y: f64, a: f64, guess: Guess<'_>) -> Option<AtAmplitude> {
        if self.cancel.load(Ordering::Relaxed) {
            return None;
        }
        let model = self.spec.axis.apply(&self.spec.model, y).ok()?;
        let load = guess.0[guess.0.len() - 1];
        let shooting = Shooting::of(&model.at_load(load));
        let found = shooting.at_amplitude(guess, a)?;
        let (p0, p1) = self.spec.load_range;
        let cycle = &found.solved.cycle;
        ((p0..=p1).contains(&cycle.load) && !shooting.near_sticking(cycle, STICK_FRACTION))
            .then_some(found)
    }
}

/// A cycle of a branch: its unknowns `(x0, T, p)`, the multiplier
/// nearest 1 after the trivial one, and Newton's matrix there.
type Found = (DVector<f64>, C64, DMatrix<f64>);

/// A first guess: a cycle's unknowns and, when known, Newton's matrix.
type Guess<'a> = (&'a DVector<f64>, Option<&'a DMatrix<f64>>);

impl AtAmplitude {
    fn found(self) -> Found {
        let second = second_nearest_one(&self.solved.cycle);
        (self.solved.cycle.unknowns(), second, self.matrix)
    }
}

impl Defining for LoadRate<'_> {
    type Near = Found;

    fn value(&self, y: f64, a: f64, near: &Found) -> Result<Option<(f64, Found)>, AnalysisError> {
        Ok(self
            .solve(y, a, (&near.0, Some(&near.2)))
            .map(|found| (found.load_per_rad, found.found())))
    }

    /// The rate is known to a few 1e-9 (Newton's tolerance on the cycle);
    /// a point's load is the least over the amplitude at its parameter, so
    /// it is off by the square of the point's distance from the fold.
    fn accuracy(&self) -> Accuracy {
        Accuracy {
            step: 1e-5,
            on_curve: 1e-6,
            central: false,
        }
    }
}

/// The folds of cycles of `spec`'s column that start from the hard
/// stretches of the Hopf curves among `curves` (those followed before
/// `cancel` is set).
///
/// # Errors
/// A Hopf point that cannot be computed.
pub fn cycle_folds(
    spec: &BoundarySpec,
    curves: &[Boundary],
    cancel: &AtomicBool,
) -> Result<Vec<CycleFold>, AnalysisError> {
    let plane = Plane {
        y: spec.axis_range,
        p: (SMALLEST_AMPLITUDE_RAD, LARGEST_AMPLITUDE_RAD),
    };
    let rate = LoadRate { spec, cancel };
    let mut followed: Vec<Curve<Found>> = Vec::new();
    for curve in curves.iter().filter(|c| c.kind == BoundaryKind::Flutter) {
        for (value, load) in hard_middles(curve) {
            for seed in march(&rate, &plane, value, load)? {
                if followed
                    .iter()
                    .any(|(nodes, _)| near_polyline(seed.0, nodes) <= SAME_FOLD)
                {
                    continue;
                }
                followed.push(follow_both(&rate, &plane, seed)?);
            }
        }
    }
    Ok(followed
        .into_iter()
        .map(|(nodes, ends)| describe(&plane, &nodes, ends))
        .collect())
}

/// The middle point `(value, load)` of each stretch of `curve` where the
/// onset is hard.
fn hard_middles(curve: &Boundary) -> Vec<(f64, f64)> {
    let hard = |point: &BoundaryPoint| point.first_lyapunov.is_some_and(|l1| l1 > 0.0);
    curve
        .points
        .chunk_by(|a, b| hard(a) == hard(b))
        .filter(|run| hard(&run[0]))
        .map(|run| (run[run.len() / 2].value, run[run.len() / 2].load))
        .collect()
}

/// The folds met marching in amplitude along the branch of cycles born at
/// the Hopf point `(value, load)`: each where `dp/da` changes sign, placed
/// by regula falsi.
///
/// # Errors
/// A Hopf point that cannot be computed.
fn march(
    rate: &LoadRate<'_>,
    plane: &Plane,
    value: f64,
    load: f64,
) -> Result<Vec<Node<Found>>, AnalysisError> {
    let Ok(model) = rate.spec.axis.apply(&rate.spec.model, value) else {
        return Ok(Vec::new());
    };
    let Ok(point) = hopf_point(&model, load, Steps::DEFAULT.into())? else {
        return Ok(Vec::new());
    };
    let a0 = SMALLEST_AMPLITUDE_RAD;
    let mut guess = normal_form_start(&point, a0);
    let mut seeds = Vec::new();
    let mut last: Option<Sample> = None;
    let mut a = a0;
    for _ in 0..MARCH_STEPS {
        let known = last.as_ref().map(|(_, _, found)| &found.2);
        let Some(found) = rate.solve(value, a, (&guess, known)) else {
            break;
        };
        let sample = (a, found.load_per_rad, found.found());
        let next = (a * MARCH_GROWTH).min(a + MARCH_MOST_RAD);
        guess = match &last {
            Some(before) => {
                if before.1 * sample.1 < 0.0
                    && let Some(node) = falsi(rate, plane, value, before, &sample)
                {
                    seeds.push(node);
                }
                let (u, u_before) = (&sample.2.0, &before.2.0);
                u + (u - u_before) * ((next - a) / (a - before.0))
            }
            None => sample.2.0.clone(),
        };
        last = Some(sample);
        a = next;
        if a > LARGEST_AMPLITUDE_RAD {
            break;
        }
    }
    Ok(seeds)
}

/// A cycle of a march: its amplitude, `dp/da`, and the cycle.
type Sample = (f64, f64, Found);

/// The fold between two cycles of a march at `value` whose rates `dp/da`
/// have opposite signs, by regula falsi in the amplitude.
fn falsi(
    rate: &LoadRate<'_>,
    plane: &Plane,
    value: f64,
    low: &Sample,
    high: &Sample,
) -> Option<Node<Found>> {
    let stop = Stop {
        value: 1e-10,
        width: 1e-10 * low.0.max(high.0),
        steps: FALSI_STEPS,
    };
    let (a, _, found) = illinois(low.clone(), high.clone(), stop, |a, nearer| {
        let found = rate.solve(value, a, (&nearer.0, Some(&nearer.2)))?;
        Some((a, found.load_per_rad, found.found()))
    })?;
    Some((plane.scaled(value, a), found))
}

/// A followed fold as its points.
fn describe(plane: &Plane, nodes: &[Node<Found>], ends: [End; 2]) -> CycleFold {
    let points = nodes
        .iter()
        .map(|(z, (u, second_multiplier, _))| {
            let (value, amplitude_rad) = plane.point(*z);
            let d = u.len() - 2;
            FoldPoint {
                value,
                load: u[d + 1],
                amplitude_rad,
                period_secs: u[d],
                second_multiplier: *second_multiplier,
            }
        })
        .collect();
    let end = |end: End, node: Option<&Node<Found>>| match end {
        End::ParameterEdge => FoldEnd::ParameterEdge,
        End::LoadEdge if node.is_some_and(|n| n.0[1] < 0.5) => FoldEnd::SmallAmplitude,
        End::LoadEdge => FoldEnd::LargeAmplitude,
        End::Merged | End::Lost => FoldEnd::Lost,
        End::Closed => FoldEnd::Closed,
        End::Steps => FoldEnd::Steps,
    };
    CycleFold {
        points,
        ends: [end(ends[0], nodes.first()), end(ends[1], nodes.last())],
    }
}

/// The multiplier nearest 1 but for the trivial one.
fn second_nearest_one(cycle: &Cycle) -> C64 {
    cycle
        .nontrivial_multipliers()
        .min_by(|a, b| (a - 1.0).norm().total_cmp(&(b - 1.0).norm()))
        .unwrap_or(C64::new(f64::NAN, 0.0))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::CycleBifurcationKind;
    use crate::analysis::cycles::cycle_branches;
    use crate::model::{Axis, Model};

    /// `model` with `key` set to `value`.
    fn set(model: &Model, key: &str, value: f64) -> Model {
        Axis::parse(key, model)
            .unwrap()
            .apply(model, value)
            .unwrap()
    }

    /// The hard onset of the two-rod column with an external damper 0.05
    /// and a first rod of mass 0.2: the fold of its branch of cycles, found
    /// along the branch (regula falsi on the load's rate in the share of
    /// the chord between two of its cycles) and by the march from the
    /// onset (regula falsi on `dp/da`, the cycles held at the first angle's
    /// amplitude) — two parametrizations of the branch, two phase
    /// conditions — is at one load to 1e-10 of it.
    #[test]
    fn the_fold_along_a_branch_is_the_march_s() {
        let base = crate::model::preset("ziegler-1952").unwrap().model();
        let model = set(&set(&base, "c_ext", 0.05), "m1", 0.2);
        let cancel = AtomicBool::new(false);
        let onsets = cycle_branches(&model, 2.1, 2.2, &cancel).unwrap();
        let branch = onsets[0].branch.as_ref().unwrap();
        let folds: Vec<_> = branch
            .bifurcations
            .iter()
            .filter(|b| b.kind == CycleBifurcationKind::Fold)
            .collect();
        assert_eq!(folds.len(), 1, "{:?}", branch.bifurcations);
        assert!(folds[0].refined);
        let spec = BoundarySpec {
            model,
            axis: Axis::parse("m1", &model).unwrap(),
            axis_range: (0.1, 0.3),
            load_range: (2.0, 2.3),
        };
        let rate = LoadRate {
            spec: &spec,
            cancel: &cancel,
        };
        let plane = Plane {
            y: spec.axis_range,
            p: (SMALLEST_AMPLITUDE_RAD, LARGEST_AMPLITUDE_RAD),
        };
        let seeds = march(&rate, &plane, 0.2, branch.hopf().load).unwrap();
        assert_eq!(seeds.len(), 1);
        let (_, (u, ..)) = &seeds[0];
        let marched = u[u.len() - 1];
        assert!(
            (folds[0].load - marched).abs() < 1e-10 * marched,
            "along the branch {}, marched {marched}",
            folds[0].load
        );
    }
}
