//! Root loci: eigenvalue branches followed continuously along the load axis,
//! with samples added where branches meet or cross an axis.

use crate::analysis::pencil::AffinePencil;
use crate::analysis::roots::{MAX_DEGREE, modulus};
use crate::analysis::stability::RELATIVE_TOLERANCE;
use crate::analysis::{AnalysisError, C64};

use super::branch_points::{at_branch_points, conjugate};
pub(crate) use super::grid::load_resolution;
pub use super::grid::{LARGEST_LOAD, MAX_SAMPLES, check_largest_load, load_grid};
pub(in crate::analysis) use super::matching::eigenvalues_near;
use super::matching::{assign, assignment};
use super::prefetch::{Prefetched, with_prefetched};

/// A step is accepted when the linear prediction misses each eigenvalue by
/// less than this fraction of the step's own length: the polyline then turns
/// by less than about 6 degrees per sample, also along the square-root
/// curves into a branch point, where a fixed tolerance would cut the corner.
const TURN_TOLERANCE: f64 = 0.1;

/// ... or by less than this fraction of the eigenvalue's size plus the
/// frequency scale: below that the miss is invisible in any plot.
const FLOOR_TOLERANCE: f64 = 1e-3;

/// Steps are never halved below this fraction of the load range (nor below
/// the resolution of f64 at the range's end).
const MIN_STEP_FRACTION: f64 = 1e-6;

/// Eigenvalues smaller than this fraction of the frequency scale are left out
/// of the search for axis crossings. Near a double root at zero (a mode whose
/// stiffness the load has cancelled) rounding moves an eigenvalue by about
/// the square root of the machine epsilon times the scale (1.5e-8), so its
/// real and imaginary parts change sign from sample to sample at random, and
/// halving the step would chase the rounding down to the smallest step
/// everywhere (a stiff first joint on a chain took minutes). A true crossing
/// of such a tiny eigenvalue is still bracketed by the samples' states and
/// located by the critical loads' bisection.
pub(super) const ROUNDING_BAND: f64 = 1e-6;

/// At most this many samples are added by refinement per evenly spaced load
/// (with [`MIN_REFINED_SAMPLES`] at least): a crossing or a meeting of
/// branches takes about 40 (halving down to the smallest step and doubling
/// back), so this bounds the time and memory of a locus by its arguments.
const REFINED_PER_SAMPLE: usize = 16;
const MIN_REFINED_SAMPLES: usize = 20_000;

/// Most eigenvalues a locus holds (evenly spaced loads times eigenvalues per
/// load): 2^24 complex numbers are 256 MiB.
pub const MAX_HELD_EIGENVALUES: usize = 1 << 24;

/// Eigenvalue branches over a range of loads.
#[derive(Clone, Debug, PartialEq)]
pub struct Locus {
    /// Loads, increasing: the evenly spaced ones and those added by refinement.
    pub loads: Vec<f64>,
    /// True where `loads[i]` is one of the evenly spaced loads asked for.
    pub on_grid: Vec<bool>,
    /// `branches[b][i]` is branch b at `loads[i]`. Each branch is continuous;
    /// the structural zero roots are the last `structural_zeros` branches.
    pub branches: Vec<Vec<C64>>,
    pub structural_zeros: usize,
    /// The load from which the refinement's budget was spent (samples then
    /// only at the evenly spaced loads): narrow windows of another state
    /// beyond it may be missed. `None` when the refinement was complete.
    pub refinement_cut_at: Option<f64>,
}

impl Locus {
    /// The eigenvalues at sample i, branch by branch (structural zeros included).
    pub fn at(&self, i: usize) -> impl Iterator<Item = C64> + '_ {
        self.branches.iter().map(move |branch| branch[i])
    }

    /// Appends `next`, a locus that starts at this one's last load, its
    /// branches reordered to continue this one's (its first sample, a repeat
    /// of this one's last, is left out).
    pub(crate) fn extend_with(&mut self, next: &Self) {
        let last = self.loads.len() - 1;
        let here: Vec<C64> = self.at(last).collect();
        let there: Vec<C64> = next.at(0).collect();
        // Which of `next`'s branches continues each of ours.
        let order = assignment(&there, &here);
        self.loads.extend_from_slice(&next.loads[1..]);
        self.on_grid.extend_from_slice(&next.on_grid[1..]);
        for (branch, &k) in self.branches.iter_mut().zip(&order) {
            branch.extend_from_slice(&next.branches[k][1..]);
        }
        self.refinement_cut_at = self.refinement_cut_at.or(next.refinement_cut_at);
    }

    /// The branches that move with the load (the structural zeros left out).
    #[must_use]
    pub fn moving_branches(&self) -> &[Vec<C64>] {
        &self.branches[..self.branches.len() - self.structural_zeros]
    }

    /// The moving eigenvalues at sample i.
    #[must_use]
    pub fn moving_at(&self, i: usize) -> Vec<C64> {
        self.moving_branches()
            .iter()
            .map(|branch| branch[i])
            .collect()
    }
}

/// -1, 0 or 1 with a dead band of `tolerance` around zero.
fn sign_with_tolerance(x: f64, tolerance: f64) -> i8 {
    if x > tolerance {
        1
    } else if x < -tolerance {
        -1
    } else {
        0
    }
}

/// The number of evenly spaced loads a locus of `pencil` may have: the
/// eigenvalues it holds stay within [`MAX_HELD_EIGENVALUES`].
#[must_use]
pub fn max_samples(pencil: &AffinePencil) -> usize {
    let per_load = 2 * pencil.dof();
    (MAX_HELD_EIGENVALUES / per_load.max(1)).min(MAX_SAMPLES)
}

/// The eigenvalue branches of `pencil` over the evenly spaced loads from
/// `min` to `max`, with samples added by adaptive halving of the step where
/// the linear prediction of a branch misses (branches meeting, turning; see
/// [`TURN_TOLERANCE`]) or a
/// branch's real or imaginary part changes sign (crossing Re = 0, landing on
/// the real axis). The refinement adds at most [`REFINED_PER_SAMPLE`] samples
/// per evenly spaced load; where that is spent, [`Locus::refinement_cut_at`] says so.
///
/// # Errors
/// A bad range (see [`load_grid`]), more samples than [`max_samples`], or an
/// eigenvalue computation that fails.
pub fn locus(
    pencil: &AffinePencil,
    min: f64,
    max: f64,
    samples: usize,
) -> Result<Locus, AnalysisError> {
    locus_until(pencil, (min, max, samples), Crossings::Refined, |_, _| {
        false
    })
}

/// [`locus`], handing each evenly spaced load, as soon as its samples are
/// final, to `each(index, p, row)`: its index in the grid (from 0) and every
/// branch's eigenvalue in order, structural zeros included (the rows of
/// [`Locus::at`]). `each` returning false ends the locus there (a reader
/// that has gone): a long chain's fine locus is written and shown as it is
/// computed, not after minutes.
///
/// # Errors
/// As [`locus`].
pub fn locus_streamed(
    pencil: &AffinePencil,
    min: f64,
    max: f64,
    samples: usize,
    each: impl FnMut(usize, f64, &[C64]) -> bool,
) -> Result<Locus, AnalysisError> {
    track(pencil, (min, max, samples), Crossings::Refined, each)
}

/// Whether a locus halves its step where a branch crosses an axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Crossings {
    /// Down to the smallest step: a plot shows where the branch crosses.
    Refined,
    /// Only where more than one crossing falls in a step (two branches not
    /// a conjugate pair, or more): the samples on either side of a lone
    /// crossing bracket it, and the critical loads locate it by bisection
    /// anyway, but two crossings in a step may hide a window of another
    /// state between them. The refinement where branches meet or turn,
    /// which keeps the tracking right, is the same in both.
    Bracketed,
}

/// [`locus_streamed`] over `samples` evenly spaced loads from `min` to
/// `max`, refining `crossings` or not.
#[expect(
    clippy::too_many_lines,
    reason = "one tracking loop: its step control, refinement budget and hand-on share its state"
)]
fn track(
    pencil: &AffinePencil,
    (min, max, samples): (f64, f64, usize),
    crossings: Crossings,
    mut each: impl FnMut(usize, f64, &[C64]) -> bool,
) -> Result<Locus, AnalysisError> {
    let most = max_samples(pencil);
    if samples > most {
        return Err(AnalysisError::TooManySamples {
            samples,
            most,
            eigenvalues: 2 * pencil.dof(),
        });
    }
    let grid = load_grid(min, max, samples)?;
    check_largest_load(max)?;
    let mut refinement_left = (REFINED_PER_SAMPLE * grid.len()).max(MIN_REFINED_SAMPLES);
    // Never below a few units in the last place: p + step must move p.
    let min_step = ((max - min) * MIN_STEP_FRACTION).max(load_resolution(max));
    let mut first = pencil.spectrum(grid[0])?.eigenvalues;
    first.sort_by(|a, b| b.im.total_cmp(&a.im).then(b.re.total_cmp(&a.re)));
    let structural_zeros = pencil.structural_zeros();
    // Room for the refinement's samples too (a tenth more is usual).
    let capacity = grid.len() + grid.len() / 4;
    let mut out = Locus {
        loads: Vec::with_capacity(capacity),
        on_grid: Vec::with_capacity(capacity),
        // Each branch its own capacity (a cloned empty Vec has none).
        branches: (0..first.len() + structural_zeros)
            .map(|_| Vec::with_capacity(capacity))
            .collect(),
        structural_zeros,
        refinement_cut_at: None,
    };
    let push = |out: &mut Locus, p: f64, on_grid: bool, eigenvalues: &[C64]| {
        out.loads.push(p);
        out.on_grid.push(on_grid);
        for (branch, &z) in out.branches.iter_mut().zip(eigenvalues) {
            branch.push(z);
        }
        for branch in &mut out.branches[eigenvalues.len()..] {
            branch.push(C64::new(0.0, 0.0));
        }
    };
    push(&mut out, grid[0], true, &first);
    // One grid load's eigenvalues, every branch, for `each`.
    let mut row = Vec::with_capacity(out.branches.len());
    let mut hand_on = |index: usize, p: f64, eigenvalues: &[C64], branches: usize| {
        row.clear();
        row.extend_from_slice(eigenvalues);
        row.resize(branches, C64::new(0.0, 0.0));
        each(index, p, &row)
    };
    if !hand_on(0, grid[0], &first, out.branches.len()) {
        return Ok(out);
    }
    let (mut p, mut current) = (grid[0], first);
    // The two samples before `current`, latest first.
    let mut previous: Option<(f64, Vec<C64>)> = None;
    let mut earlier: Option<(f64, Vec<C64>)> = None;
    let mut step = grid.get(1).map_or(0.0, |g| g - grid[0]);
    let (mut guess, mut next) = (Vec::new(), Vec::new());
    // A long chain: more eigenvalues than the polynomial path takes, so
    // the Schur path's, computed ahead for the evenly spaced loads.
    let chain = current.len() > MAX_DEGREE;
    let run = |mut prefetched: Option<&mut Prefetched<'_>>| -> Result<Locus, AnalysisError> {
        for (index, &target) in grid.iter().enumerate().skip(1) {
            while p < target {
                let next_p = loop {
                    // Once the refinement's budget is spent: the evenly spaced loads only.
                    let trial = if refinement_left == 0 {
                        target - p
                    } else {
                        step.max(min_step).min(target - p)
                    };
                    let next_p = if trial >= target - p {
                        target
                    } else {
                        p + trial
                    };
                    // The guess: a linear extrapolation from the last two samples.
                    guess.clear();
                    match &previous {
                        Some((p0, z0)) => {
                            let t = (next_p - p) / (p - p0);
                            guess.extend(current.iter().zip(z0).map(|(&z, &w)| z + (z - w) * t));
                        }
                        None => guess.extend_from_slice(&current),
                    }
                    // Aberth's start: a quadratic extrapolation from the last
                    // three, a digit or two closer on a smooth branch, which
                    // saves an iteration. (The Schur path's eigenvalues are
                    // assigned to the linear guess, which rounding moves less.)
                    next.clone_from(&guess);
                    if let (true, Some((p1, z1)), Some((p2, z2))) = (!chain, &previous, &earlier) {
                        let [a, b, c] = quadratic_weights([p, *p1, *p2], next_p);
                        for (((start, &z0), &z1), &z2) in
                            next.iter_mut().zip(&current).zip(z1).zip(z2)
                        {
                            *start = z0 * a + z1 * b + z2 * c;
                        }
                    }
                    match prefetched.as_mut() {
                        Some(held) if next_p == target => {
                            next = assign(held.at(index)?, &guess);
                        }
                        _ => eigenvalues_near(pencil, next_p, &mut next)?,
                    }
                    let scale = pencil.scale_per_s(next_p);
                    at_branch_points(&current, &mut next, scale);
                    let tolerance = RELATIVE_TOLERANCE * scale;
                    let rounding_band = ROUNDING_BAND * scale;
                    let smooth = next
                        .iter()
                        .zip(&guess)
                        .zip(&current)
                        .all(|((&z, &g), &w)| predicted(z, g, w, scale));
                    let crossed = |(z, w): (&C64, &C64)| {
                        (sign_with_tolerance(z.re, tolerance)
                            != sign_with_tolerance(w.re, tolerance)
                            || sign_with_tolerance(z.im, tolerance)
                                != sign_with_tolerance(w.im, tolerance))
                            && (modulus(*z) > rounding_band || modulus(*w) > rounding_band)
                    };
                    let crosses = match crossings {
                        Crossings::Refined => next.iter().zip(&current).any(crossed),
                        Crossings::Bracketed => {
                            let mut which =
                                (0..next.len()).filter(|&b| crossed((&next[b], &current[b])));
                            match (which.next(), which.next(), which.next()) {
                                (None | Some(_), None, _) => false,
                                (Some(a), Some(b), None) => {
                                    !(conjugate(next[a], next[b], scale)
                                        || conjugate(current[a], current[b], scale))
                                }
                                _ => true,
                            }
                        }
                    };
                    if (smooth && !crosses) || trial <= min_step || refinement_left == 0 {
                        step = if smooth { 2.0 * trial } else { trial };
                        break next_p;
                    }
                    step = trial / 2.0;
                };
                let on_grid = next_p == target;
                if !on_grid {
                    refinement_left = refinement_left.saturating_sub(1);
                    if refinement_left == 0 && out.refinement_cut_at.is_none() {
                        out.refinement_cut_at = Some(next_p);
                    }
                }
                push(&mut out, next_p, on_grid, &next);
                if on_grid && !hand_on(index, next_p, &next, out.branches.len()) {
                    return Ok(out);
                }
                // The samples rotate through three buffers: no allocation per step.
                let mut older = earlier.take().map_or_else(Vec::new, |(_, z)| z);
                earlier = previous.take();
                std::mem::swap(&mut older, &mut current);
                std::mem::swap(&mut current, &mut next);
                previous = Some((p, older));
                p = next_p;
            }
        }
        Ok(out)
    };
    if chain {
        with_prefetched(pencil, &grid, |prefetched| run(Some(prefetched)))
    } else {
        run(None)
    }
}

/// Whether the eigenvalue `z`, found where `guess` was extrapolated from
/// the last sample's `last`, was predicted as [`TURN_TOLERANCE`] and
/// [`FLOOR_TOLERANCE`] ask. Decided first without a square root, by the
/// sum of the miss's parts (at least its modulus) against the largest
/// part of each modulus on the right (at most it): on a smooth branch the
/// miss is orders of magnitude inside the bound, and only a near call
/// takes the moduli.
fn predicted(z: C64, guess: C64, last: C64, scale: f64) -> bool {
    let largest_part = |c: C64| c.re.abs().max(c.im.abs());
    let miss = z - guess;
    let bound = |size: fn(C64) -> f64| {
        TURN_TOLERANCE * size(guess - last) + FLOOR_TOLERANCE * (size(z) + scale)
    };
    miss.re.abs() + miss.im.abs() <= bound(largest_part) || modulus(miss) <= bound(modulus)
}

/// The weights of the values at `loads` in their interpolating quadratic's
/// value at `x` (Lagrange's basis).
fn quadratic_weights([p0, p1, p2]: [f64; 3], x: f64) -> [f64; 3] {
    [
        (x - p1) * (x - p2) / ((p0 - p1) * (p0 - p2)),
        (x - p0) * (x - p2) / ((p1 - p0) * (p1 - p2)),
        (x - p0) * (x - p1) / ((p2 - p0) * (p2 - p1)),
    ]
}

/// [`locus`], ended at the first evenly spaced load after the first where
/// `stop(p, eigenvalues)` is true (that sample included; the structural
/// zeros are not among the eigenvalues).
pub(crate) fn locus_until(
    pencil: &AffinePencil,
    (min, max, samples): (f64, f64, usize),
    crossings: Crossings,
    mut stop: impl FnMut(f64, &[C64]) -> bool,
) -> Result<Locus, AnalysisError> {
    let structural_zeros = pencil.structural_zeros();
    track(pencil, (min, max, samples), crossings, |index, p, row| {
        index == 0 || !stop(p, &row[..row.len() - structural_zeros])
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::PresetId;

    /// The prediction test without square roots decides as the moduli do:
    /// over misses from far inside the bound to far outside it, in every
    /// direction, at every size of the eigenvalue against the scale.
    #[test]
    fn the_cheap_prediction_test_decides_as_the_moduli_do() {
        let by_moduli = |z: C64, g: C64, w: C64, scale: f64| {
            modulus(z - g)
                <= TURN_TOLERANCE * modulus(g - w) + FLOOR_TOLERANCE * (modulus(z) + scale)
        };
        let mut checked = 0;
        for k in 0..4000_u32 {
            let t = f64::from(k);
            let size = 10f64.powf((t * 0.37).sin() * 3.0);
            let w = C64::from_polar(size, t * 0.91);
            let g = w + C64::from_polar(size * 10f64.powf((t * 0.53).cos() * 2.0 - 3.0), t * 1.3);
            let miss = modulus(g - w) * 10f64.powf((t * 0.29).sin() * 4.0 - 1.0);
            let z = g + C64::from_polar(miss, t * 2.7);
            let scale = 10f64.powf((t * 0.17).cos() * 2.0);
            assert_eq!(
                predicted(z, g, w, scale),
                by_moduli(z, g, w, scale),
                "{z} {g} {w}"
            );
            checked += usize::from(predicted(z, g, w, scale));
        }
        // Both outcomes were tried.
        assert!((500..3500).contains(&checked), "{checked}");
    }

    /// A chain's evenly spaced loads, computed ahead on three threads, hold
    /// exactly the eigenvalues of the Schur path at their loads (the
    /// tracking only orders them), and the locus is the one computed on
    /// one thread, to the last bit.
    #[test]
    fn a_chain_s_prefetched_loads_are_the_schur_path_s_eigenvalues() {
        let mut model = PresetId::UniformRods.model();
        crate::model::apply_assignments(
            &mut model,
            &[crate::model::Assignment {
                key: crate::model::Key::Rods,
                value: 8.0,
            }],
        )
        .unwrap();
        let pencil = AffinePencil::new(&model).unwrap().with_threads(3);
        assert!(2 * pencil.dof() > MAX_DEGREE, "the Schur path");
        let load_max = model.analysis_max_p();
        let whole = locus(&pencil, 0.0, load_max, 101).unwrap();
        let alone = locus(&pencil.clone().with_threads(1), 0.0, load_max, 101).unwrap();
        assert_eq!(whole.loads, alone.loads);
        assert_eq!(whole.branches, alone.branches);
        let key = |z: &C64| (z.re.to_bits(), z.im.to_bits());
        for i in (0..whole.loads.len()).filter(|&i| whole.on_grid[i]) {
            let mut tracked: Vec<_> = whole.moving_at(i).iter().map(key).collect();
            let mut schur: Vec<_> = pencil
                .spectrum(whole.loads[i])
                .unwrap()
                .eigenvalues
                .iter()
                .map(key)
                .collect();
            tracked.sort_unstable();
            schur.sort_unstable();
            assert_eq!(tracked, schur, "at p = {}", whole.loads[i]);
        }
    }

    /// Each evenly spaced load is handed on once, in order, with every
    /// branch, as the locus computed without it holds it; a `false` ends
    /// the locus at that load.
    #[test]
    fn a_streamed_locus_hands_on_every_load_once() {
        let pencil = AffinePencil::new(&PresetId::Roller.model()).unwrap();
        let whole = locus(&pencil, 0.0, 8.0, 101).unwrap();
        let grid: Vec<usize> = (0..whole.loads.len())
            .filter(|&i| whole.on_grid[i])
            .collect();
        let mut seen = Vec::new();
        let streamed = locus_streamed(&pencil, 0.0, 8.0, 101, |index, p, row: &[C64]| {
            let i = grid[index];
            assert_eq!(p, whole.loads[i]);
            assert_eq!(row, whole.at(i).collect::<Vec<_>>());
            seen.push(index);
            true
        })
        .unwrap();
        assert_eq!(seen, (0..=100).collect::<Vec<_>>());
        assert_eq!(streamed.loads, whole.loads);
        let mut handed = 0;
        let ended = locus_streamed(&pencil, 0.0, 8.0, 101, |index, _, _: &[C64]| {
            handed += 1;
            index < 10
        })
        .unwrap();
        assert_eq!(handed, 11);
        assert_eq!(ended.on_grid.iter().filter(|&&g| g).count(), 11);
    }
}
