//! A change of stability located between two loads: bisection on the
//! state, confirmed across a resolution band, and the crossing of the
//! imaginary axis polished by Brent's method on the growth rate.

use serde::Serialize;

use crate::analysis::AnalysisError;
use crate::analysis::C64;
use crate::analysis::locus::eigenvalues_near;
use crate::analysis::pencil::AffinePencil;
use crate::analysis::stability::{Stability, State, classify};
use crate::format::load_text;

/// Transitions are located to this relative width of the load bracket.
pub(in crate::analysis) const RELATIVE_LOAD_TOLERANCE: f64 = 1e-14;

/// A change of stability at a load.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Transition {
    /// The load p at which the state changes.
    pub load: f64,
    pub from: State,
    pub to: State,
}

impl std::fmt::Display for Transition {
    /// "p = 0.0238: stable -> flutter".
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "p = {}: {} -> {}",
            load_text(self.load),
            self.from.name(),
            self.to.name()
        )
    }
}

/// The classification at load p, on the Schur path.
fn stability_at(pencil: &AffinePencil, p: f64) -> Result<Stability, AnalysisError> {
    let spectrum = pencil.spectrum(p)?;
    Ok(classify(&spectrum.eigenvalues, spectrum.scale_per_s))
}

/// The stability ranges `(from, to, state)` covering `[min, max]`, from the
/// transitions over it and the state at `min`.
#[must_use]
pub fn stability_ranges(
    transitions: &[Transition],
    first: State,
    min: f64,
    max: f64,
) -> Vec<(f64, f64, State)> {
    let mut out = Vec::new();
    let (mut start, mut state) = (min, first);
    for t in transitions.iter().filter(|t| t.load > min) {
        if t.load > max {
            break;
        }
        out.push((start, t.load, state));
        (start, state) = (t.load, t.to);
    }
    out.push((start, max, state));
    out
}

pub(in crate::analysis) fn state_at(pencil: &AffinePencil, p: f64) -> Result<State, AnalysisError> {
    stability_at(pencil, p).map(|s| s.state)
}

/// Largest real part of the moving eigenvalues at p, with the tolerance there.
fn max_real_part(pencil: &AffinePencil, p: f64) -> Result<(f64, f64), AnalysisError> {
    stability_at(pencil, p).map(|s| (s.dominant.re, s.tolerance_per_s))
}

fn width_tolerance(a: f64, b: f64) -> f64 {
    width_at(RELATIVE_LOAD_TOLERANCE, a, b)
}

/// `relative` of the larger of the loads `a`, `b` (never zero).
fn width_at(relative: f64, a: f64, b: f64) -> f64 {
    relative * a.abs().max(b.abs()).max(f64::MIN_POSITIVE)
}

/// The polynomial path bisects to this relative width of the load bracket,
/// far wider than the band around a double root where rounding decides the
/// state (about 1e-13 here), so both paths read the bracket's ends alike.
const RELATIVE_FAST_WIDTH: f64 = 1e-9;

/// A load bracket with different states at its ends.
#[derive(Clone, Copy, Debug)]
struct Bracket {
    a: f64,
    sa: State,
    b: f64,
    sb: State,
}

/// Every transition in `[a, b]` whose ends have states `sa != sb`, as
/// brackets no wider than `relative_width` of the loads, by bisection on the
/// state that `state_at` reads. Exact at square-root branch points
/// (eigenvalues meeting on an axis), where the state flips with no
/// tolerance band.
fn bisect(
    state_at: &mut impl FnMut(f64) -> Result<State, AnalysisError>,
    (a, sa): (f64, State),
    (b, sb): (f64, State),
    relative_width: f64,
    out: &mut Vec<Bracket>,
) -> Result<(), AnalysisError> {
    if b - a <= width_at(relative_width, a, b) {
        out.push(Bracket { a, sa, b, sb });
        return Ok(());
    }
    let m = 0.5 * (a + b);
    let sm = state_at(m)?;
    if sm != sa {
        bisect(state_at, (a, sa), (m, sm), relative_width, out)?;
    }
    if sm != sb {
        bisect(state_at, (m, sm), (b, sb), relative_width, out)?;
    }
    Ok(())
}

/// Every transition in `[a, b]` (states `sa != sb` on the Schur path), as
/// brackets of [`RELATIVE_LOAD_TOLERANCE`], each with its load polished by
/// [`polish_crossing`] where it is a loss or gain of stability at a
/// transversal crossing. The first halvings, down to
/// [`RELATIVE_FAST_WIDTH`], read the state on the polynomial path (Aberth
/// refined from the nearest load's roots, a few times cheaper than a Schur
/// decomposition); the Schur path confirms both ends of each narrowed
/// bracket. A crossing is polished from there (Brent's method needs no
/// narrower bracket); any other change takes the last halvings on the
/// Schur path. Where the paths disagree the whole bisection is done again
/// on the Schur path, so the answer is always the Schur path's.
fn bisect_confirmed(
    pencil: &AffinePencil,
    near_a: &[C64],
    (a, sa): (f64, State),
    (b, sb): (f64, State),
    range: (f64, f64),
) -> Result<Vec<(Bracket, Option<f64>)>, AnalysisError> {
    let mut roots = near_a.to_vec();
    let mut fast_state = |p: f64| -> Result<State, AnalysisError> {
        eigenvalues_near(pencil, p, &mut roots)?;
        Ok(classify(&roots, pencil.scale_per_s(p)).state)
    };
    let mut schur_state = |p: f64| state_at(pencil, p);
    let polished = |bracket: Bracket, half_width: f64| {
        polish_crossing(pencil, &bracket, half_width, range).map(|root| (bracket, root))
    };
    let mut narrowed = Vec::new();
    bisect(
        &mut fast_state,
        (a, sa),
        (b, sb),
        RELATIVE_FAST_WIDTH,
        &mut narrowed,
    )?;
    let mut found = Vec::new();
    for bracket in narrowed {
        if schur_state(bracket.a)? != bracket.sa || schur_state(bracket.b)? != bracket.sb {
            let mut again = Vec::new();
            bisect(
                &mut schur_state,
                (a, sa),
                (b, sb),
                RELATIVE_LOAD_TOLERANCE,
                &mut again,
            )?;
            return again
                .into_iter()
                .map(|bracket| polished(bracket, width_tolerance(bracket.a, bracket.b)))
                .collect();
        }
        match polished(bracket, 0.5 * (bracket.b - bracket.a))? {
            (bracket, Some(root)) => found.push((bracket, Some(root))),
            (bracket, None) => {
                let mut last = Vec::new();
                bisect(
                    &mut schur_state,
                    (bracket.a, bracket.sa),
                    (bracket.b, bracket.sb),
                    RELATIVE_LOAD_TOLERANCE,
                    &mut last,
                )?;
                found.extend(last.into_iter().map(|bracket| (bracket, None)));
            }
        }
    }
    Ok(found)
}

/// The root of `f` in `[a, b]` with `f(a) < 0 < f(b)` by Brent's method.
fn brent(
    mut f: impl FnMut(f64) -> Result<f64, AnalysisError>,
    (mut a, mut fa): (f64, f64),
    (mut b, mut fb): (f64, f64),
) -> Result<f64, AnalysisError> {
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    for _ in 0..200 {
        if fb.signum() == fc.signum() {
            (c, fc) = (a, fa);
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            (a, fa) = (b, fb);
            (b, fb) = (c, fc);
            (c, fc) = (a, fa);
        }
        let tol = 0.5 * width_tolerance(b, c);
        let half = 0.5 * (c - b);
        if half.abs() <= tol || fb == 0.0 {
            return Ok(b);
        }
        if e.abs() >= tol && fa.abs() > fb.abs() {
            let s = fb / fa;
            let (mut p, mut q) = if a == c {
                (2.0 * half * s, 1.0 - s)
            } else {
                let (q, r) = (fa / fc, fb / fc);
                (
                    s * (2.0 * half * q * (q - r) - (b - a) * (r - 1.0)),
                    (q - 1.0) * (r - 1.0) * (s - 1.0),
                )
            };
            if p > 0.0 {
                q = -q;
            }
            p = p.abs();
            if 2.0 * p < (3.0 * half * q - (tol * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = half;
                e = d;
            }
        } else {
            d = half;
            e = d;
        }
        (a, fa) = (b, fb);
        b += if d.abs() > tol { d } else { tol.copysign(half) };
        fb = f(b)?;
    }
    Ok(b)
}

/// Every transition between the bracket's ends ([`bisect_confirmed`]), each
/// loss (or gain) of stability polished by [`polish_crossing`]. `near_a`:
/// the moving eigenvalues at a load near `a`.
pub(in crate::analysis) fn refine(
    pencil: &AffinePencil,
    near_a: &[C64],
    (a, sa): (f64, State),
    (b, sb): (f64, State),
    range: (f64, f64),
    out: &mut Vec<Transition>,
) -> Result<(), AnalysisError> {
    for (bracket, polished) in bisect_confirmed(pencil, near_a, (a, sa), (b, sb), range)? {
        out.push(Transition {
            load: polished.unwrap_or(0.5 * (bracket.a + bracket.b)),
            from: bracket.sa,
            to: bracket.sb,
        });
    }
    Ok(())
}

/// Bisection on the state finds where the growth rate exceeds the
/// classification's tolerance. Where an eigenvalue crosses Re = 0
/// transversally (a damped column), that is off by tolerance / slope; the
/// root of the smooth, signed `max Re(lambda)` is then found by Brent's method
/// in the smallest bracket around the bisection's answer where it changes
/// sign. That bracket may reach beyond the locus samples that bracketed the
/// flip (for weak damping the offset is large), but not beyond the load
/// range. An undamped column never has a strictly damped side (its stable
/// eigenvalues sit on the axis); the bisection's answer is exact there
/// (square-root branch point) and is kept.
///
/// The first loads tried are `half_width` either side of the bracket's
/// middle.
fn polish_crossing(
    pencil: &AffinePencil,
    bracket: &Bracket,
    half_width: f64,
    (load_min, load_max): (f64, f64),
) -> Result<Option<f64>, AnalysisError> {
    // An undamped pencil's eigenvalues come in pairs +-lambda: no load has
    // a strictly damped side to bracket a root with (the widening below
    // would go on to the range's end, a spectrum at each step, for none).
    if pencil.undamped() {
        return Ok(None);
    }
    let toward_unstable = match (bracket.sa, bracket.sb) {
        (State::Stable, State::Stable) => return Ok(None),
        (State::Stable, _) => 1.0,
        (_, State::Stable) => -1.0,
        _ => return Ok(None),
    };
    let growth = |p| max_real_part(pencil, p).map(|(re, _)| re);
    let p = 0.5 * (bracket.a + bracket.b);
    let unstable_p = (p + toward_unstable * half_width).clamp(load_min, load_max);
    let unstable_growth = growth(unstable_p)?;
    if unstable_growth <= 0.0 {
        return Ok(None);
    }
    let mut width = 2.0 * half_width;
    loop {
        let stable_p = p - toward_unstable * width;
        if !(load_min..=load_max).contains(&stable_p) {
            return Ok(None);
        }
        let (stable_growth, tolerance) = max_real_part(pencil, stable_p)?;
        if stable_growth > 2.0 * tolerance {
            // Clearly unstable again (near the flip itself the growth equals
            // the tolerance up to rounding): not a lone crossing.
            return Ok(None);
        }
        // Strictly damped: the sign is the crossing's, not rounding's.
        if stable_growth < -tolerance {
            let (lo, hi) = if toward_unstable > 0.0 {
                ((stable_p, stable_growth), (unstable_p, unstable_growth))
            } else {
                ((unstable_p, -unstable_growth), (stable_p, -stable_growth))
            };
            let sign = toward_unstable;
            return brent(|q| growth(q).map(|g| sign * g), lo, hi).map(Some);
        }
        width *= 2.0;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::bracketing_locus;
    use crate::model::{Axis, Key, Model, PRESETS, PresetId};

    #[test]
    fn stability_ranges_cover_the_range_from_its_start_to_its_end() {
        let t = |load, from, to| Transition { load, from, to };
        let transitions = [
            t(2.0, State::Stable, State::Flutter),
            t(4.0, State::Flutter, State::Divergence),
            t(9.0, State::Divergence, State::Flutter),
        ];
        assert_eq!(
            stability_ranges(&transitions, State::Stable, 0.0, 8.0),
            vec![
                (0.0, 2.0, State::Stable),
                (2.0, 4.0, State::Flutter),
                (4.0, 8.0, State::Divergence)
            ]
        );
        assert_eq!(
            stability_ranges(&transitions, State::Flutter, 3.0, 5.0),
            vec![(3.0, 4.0, State::Flutter), (4.0, 5.0, State::Divergence)]
        );
    }

    /// Bisects every change of stability that the bracketing locus of
    /// `model` shows both ways and returns how many there were.
    fn assert_fast_bisection_matches_schur(name: &str, model: &Model) -> usize {
        let pencil = AffinePencil::new(model).unwrap();
        let bracket_locus = bracketing_locus(&pencil, 0.0, model.analysis_max_p()).unwrap();
        let states: Vec<State> = bracket_locus
            .loads
            .iter()
            .map(|&q| state_at(&pencil, q).unwrap())
            .collect();
        let mut checked = 0;
        for i in 1..states.len() {
            if states[i] == states[i - 1] {
                continue;
            }
            let (a, b) = (bracket_locus.loads[i - 1], bracket_locus.loads[i]);
            let ends = ((a, states[i - 1]), (b, states[i]));
            let range = (0.0, model.analysis_max_p());
            let near_a = bracket_locus.moving_at(i - 1);
            let fast = bisect_confirmed(&pencil, &near_a, ends.0, ends.1, range).unwrap();
            let mut schur = Vec::new();
            let mut schur_state = |q| state_at(&pencil, q);
            bisect(
                &mut schur_state,
                ends.0,
                ends.1,
                RELATIVE_LOAD_TOLERANCE,
                &mut schur,
            )
            .unwrap();
            assert_eq!(fast.len(), schur.len(), "{name} near p = {a}");
            for ((bracket, polished), narrow) in fast.iter().zip(&schur) {
                match polished {
                    // Bisected to the end: the Schur path's own bracket.
                    None => assert_eq!((bracket.a, bracket.b), (narrow.a, narrow.b)),
                    // Polished from the wider bracket, which holds the
                    // Schur path's: the crossing polished from that one.
                    Some(root) => {
                        assert!(bracket.a <= narrow.a && narrow.b <= bracket.b);
                        let half_width = width_tolerance(narrow.a, narrow.b);
                        let from_narrow = polish_crossing(&pencil, narrow, half_width, range)
                            .unwrap()
                            .unwrap();
                        // Both are Brent's roots of a growth rate that
                        // rounding blurs: 4e-13 apart seen (roller).
                        assert!(
                            (root - from_narrow).abs() <= 2e-12 * root.abs(),
                            "{name}: {root} vs {from_narrow}"
                        );
                    }
                }
            }
            checked += 1;
        }
        checked
    }

    /// The polynomial path only speeds the bisection up: at every change of
    /// stability of every two-rod preset (a chain has no polynomial path),
    /// of a damped column and of a light roller, the brackets are those of
    /// the bisection on the Schur path alone, and a crossing polished from
    /// the wider bracket is the one polished from the Schur path's.
    #[test]
    fn the_fast_bisection_gives_the_schur_paths_brackets() {
        let mut checked = 0;
        let two_rods = PRESETS.iter().filter(|p| p.model().column.rods == 2);
        for p in two_rods.clone() {
            checked += assert_fast_bisection_matches_schur(p.id.name(), &p.model());
        }
        assert!(checked >= 2 * two_rods.count(), "{checked} changes checked");
        let column = PresetId::Ziegler1952.model();
        let damped = Axis::DampingLevel.apply(&column, 1e-3).unwrap();
        assert!(assert_fast_bisection_matches_schur("damped", &damped) >= 2);
        let roller = PresetId::Roller.model();
        let light = Axis::Key(Key::Nu).apply(&roller, 0.01).unwrap();
        assert!(assert_fast_bisection_matches_schur("light roller", &light) >= 2);
    }
}
