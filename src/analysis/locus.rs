//! Root loci: eigenvalue branches followed continuously along the load axis,
//! with samples added where branches meet or cross an axis.

use super::pencil::AffinePencil;
use super::roots::{MAX_DEGREE, aberth, modulus};
use super::stability::RELATIVE_TOLERANCE;
use super::{AnalysisError, C64};

/// Neighbouring grid loads must differ by at least this many units of
/// `f64::EPSILON` relative to the range's end, so that every load is distinct.
const RESOLVED_STEPS: f64 = 4.0;

/// The smallest step between distinct loads of a range ending at `load_max`.
pub(crate) fn load_resolution(load_max: f64) -> f64 {
    RESOLVED_STEPS * f64::EPSILON * load_max.abs()
}

/// Largest number of evenly spaced loads a locus accepts.
pub const MAX_SAMPLES: usize = 1_000_000;

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
}

impl Locus {
    /// The eigenvalues at sample i, branch by branch (structural zeros included).
    pub fn at(&self, i: usize) -> impl Iterator<Item = C64> + '_ {
        self.branches.iter().map(move |branch| branch[i])
    }

    /// The moving eigenvalues at sample i.
    #[must_use]
    pub fn moving_at(&self, i: usize) -> Vec<C64> {
        let moving = self.branches.len() - self.structural_zeros;
        self.branches[..moving]
            .iter()
            .map(|branch| branch[i])
            .collect()
    }
}

/// The evenly spaced loads from `min` to `max` inclusive.
///
/// # Errors
/// Non-finite or negative bounds, `max < min`, no samples or too many (also
/// more than the range can hold distinct in f64), or one sample over a range.
pub fn load_grid(min: f64, max: f64, samples: usize) -> Result<Vec<f64>, AnalysisError> {
    let bad = |what, value, allowed| {
        Err(AnalysisError::BadRange {
            what,
            value,
            allowed,
        })
    };
    if !(min.is_finite() && min >= 0.0) {
        return bad("load-min", min, "must be a finite load >= 0");
    }
    if !(max.is_finite() && max >= min) {
        return bad("load-max", max, "must be finite and >= load-min");
    }
    if samples == 0 || samples > MAX_SAMPLES {
        #[expect(clippy::cast_precision_loss, reason = "a count shown in a message")]
        return bad("samples", samples as f64, "must be between 1 and 1000000");
    }
    if samples == 1 {
        return if min == max {
            Ok(vec![min])
        } else {
            bad(
                "samples",
                1.0,
                "must be >= 2 unless load-min equals load-max",
            )
        };
    }
    #[expect(
        clippy::cast_precision_loss,
        reason = "sample counts are far below 2^52"
    )]
    let step = (max - min) / (samples - 1) as f64;
    if step < load_resolution(max) {
        #[expect(clippy::cast_precision_loss, reason = "a count shown in a message")]
        return bad(
            "samples",
            samples as f64,
            "too many for so narrow a range: neighbouring loads would not be distinct in double precision (use fewer samples or a wider range)",
        );
    }
    #[expect(
        clippy::cast_precision_loss,
        reason = "sample counts are far below 2^52"
    )]
    Ok((0..samples)
        .map(|i| {
            if i + 1 == samples {
                max
            } else {
                min + step * i as f64
            }
        })
        .collect())
}

/// Reorders `found` to follow `guess` branch by branch (least total distance;
/// exhaustive up to 6 eigenvalues, greedy beyond).
fn assign(found: &[C64], guess: &[C64]) -> Vec<C64> {
    let n = found.len();
    if n <= 6 {
        let mut best: (f64, Vec<usize>) = (f64::INFINITY, (0..n).collect());
        let mut perm: Vec<usize> = (0..n).collect();
        permute(&mut perm, 0, &mut |perm| {
            let cost: f64 = perm
                .iter()
                .zip(guess)
                .map(|(&k, g)| (found[k] - g).norm())
                .sum();
            if cost < best.0 {
                best = (cost, perm.to_vec());
            }
        });
        return best.1.iter().map(|&k| found[k]).collect();
    }
    let mut free: Vec<C64> = found.to_vec();
    guess
        .iter()
        .map(|g| {
            let k = (0..free.len())
                .min_by(|&a, &b| (free[a] - g).norm().total_cmp(&(free[b] - g).norm()))
                .unwrap_or(0);
            free.swap_remove(k)
        })
        .collect()
}

fn permute(perm: &mut [usize], k: usize, visit: &mut impl FnMut(&[usize])) {
    if k == perm.len() {
        visit(perm);
        return;
    }
    for i in k..perm.len() {
        perm.swap(k, i);
        permute(perm, k + 1, visit);
        perm.swap(k, i);
    }
}

/// The moving eigenvalues at load p, attached branch by branch to the guess
/// that `roots` holds on entry: Aberth from the guess when the
/// characteristic polynomial is available, the Schur path and an assignment
/// otherwise. Allocation-free on the polynomial path (the locus's hot loop).
pub(super) fn eigenvalues_near(
    pencil: &AffinePencil,
    p: f64,
    roots: &mut [C64],
) -> Result<(), AnalysisError> {
    let n = roots.len();
    if n <= MAX_DEGREE
        && let Some(poly) = pencil.char_poly(p)
    {
        // Refined on a copy: a failed iteration leaves the guess for the Schur path.
        let mut refined = [C64::new(0.0, 0.0); MAX_DEGREE];
        refined[..n].copy_from_slice(roots);
        if aberth(&poly, &mut refined[..n], 60) {
            roots.copy_from_slice(&refined[..n]);
            return Ok(());
        }
    }
    let spectrum = pencil.spectrum(p)?;
    let assigned = assign(&spectrum.eigenvalues, roots);
    roots.copy_from_slice(&assigned);
    Ok(())
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

/// The eigenvalue branches of `pencil` over the evenly spaced loads from
/// `min` to `max`, with samples added by adaptive halving of the step where
/// the linear prediction of a branch misses (branches meeting, turning; see
/// [`TURN_TOLERANCE`]) or a
/// branch's real or imaginary part changes sign (crossing Re = 0, landing on
/// the real axis).
///
/// # Errors
/// A bad range (see [`load_grid`]) or an eigenvalue computation that fails.
pub fn locus(
    pencil: &AffinePencil,
    min: f64,
    max: f64,
    samples: usize,
) -> Result<Locus, AnalysisError> {
    let grid = load_grid(min, max, samples)?;
    // Never below a few units in the last place: p + step must move p.
    let min_step = ((max - min) * MIN_STEP_FRACTION).max(load_resolution(max));
    let mut first = pencil.spectrum(grid[0])?.eigenvalues;
    first.sort_by(|a, b| b.im.total_cmp(&a.im).then(b.re.total_cmp(&a.re)));
    let structural_zeros = pencil.structural_zeros();
    let mut out = Locus {
        loads: Vec::with_capacity(grid.len()),
        on_grid: Vec::with_capacity(grid.len()),
        branches: vec![Vec::with_capacity(grid.len()); first.len() + structural_zeros],
        structural_zeros,
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
    let (mut p, mut current) = (grid[0], first);
    let mut previous: Option<(f64, Vec<C64>)> = None;
    let mut step = grid.get(1).map_or(0.0, |g| g - grid[0]);
    let (mut guess, mut next) = (Vec::new(), Vec::new());
    for &target in &grid[1..] {
        while p < target {
            let next_p = loop {
                let trial = step.max(min_step).min(target - p);
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
                next.clone_from(&guess);
                eigenvalues_near(pencil, next_p, &mut next)?;
                let scale = pencil.scale_per_s(next_p);
                let tolerance = RELATIVE_TOLERANCE * scale;
                let smooth = next.iter().zip(&guess).zip(&current).all(|((z, g), w)| {
                    modulus(z - g)
                        <= TURN_TOLERANCE * modulus(g - w) + FLOOR_TOLERANCE * (modulus(*z) + scale)
                });
                let crosses = next.iter().zip(&current).any(|(z, w)| {
                    sign_with_tolerance(z.re, tolerance) != sign_with_tolerance(w.re, tolerance)
                        || sign_with_tolerance(z.im, tolerance)
                            != sign_with_tolerance(w.im, tolerance)
                });
                if (smooth && !crosses) || trial <= min_step {
                    step = if smooth { 2.0 * trial } else { trial };
                    break next_p;
                }
                step = trial / 2.0;
            };
            push(&mut out, next_p, next_p == target, &next);
            // The samples rotate through three buffers: no allocation per step.
            let mut older = previous.take().map_or_else(Vec::new, |(_, z)| z);
            std::mem::swap(&mut older, &mut current);
            std::mem::swap(&mut current, &mut next);
            previous = Some((p, older));
            p = next_p;
        }
    }
    Ok(out)
}
