//! The eigenvalues at a load matched to the branches they continue: by
//! Aberth's iteration from the branches' last values where the
//! characteristic polynomial is available, else by the least total
//! distance between the Schur path's eigenvalues and those last values.

use crate::analysis::pencil::AffinePencil;
use crate::analysis::roots::{MAX_DEGREE, aberth, modulus};
use crate::analysis::{AnalysisError, C64};

/// Reorders `found` to follow `guess` branch by branch (least total distance;
/// exhaustive up to 6 eigenvalues, greedy beyond).
pub(in crate::analysis) fn assign(found: &[C64], guess: &[C64]) -> Vec<C64> {
    assignment(found, guess).iter().map(|&k| found[k]).collect()
}

/// For each eigenvalue of `guess`, the index of the one of `found` that
/// continues it (see [`assign`]).
pub(in crate::analysis) fn assignment(found: &[C64], guess: &[C64]) -> Vec<usize> {
    let n = found.len();
    if n <= 6 {
        let mut best: (f64, Vec<usize>) = (f64::INFINITY, (0..n).collect());
        let mut perm: Vec<usize> = (0..n).collect();
        permute(&mut perm, 0, &mut |perm| {
            let cost: f64 = perm
                .iter()
                .zip(guess)
                .map(|(&k, g)| modulus(found[k] - g))
                .sum();
            if cost < best.0 {
                best = (cost, perm.to_vec());
            }
        });
        return best.1;
    }
    // Distances compared by their squares, of the differences over the
    // largest guess: no square root, and no square small enough to be
    // subnormal but of eigenvalues equal to rounding.
    let largest = guess.iter().map(|&g| modulus(g)).fold(0.0, f64::max);
    let per_scale = if largest > 0.0 && largest.is_finite() {
        largest.recip()
    } else {
        1.0
    };
    let mut free: Vec<usize> = (0..n).collect();
    guess
        .iter()
        .map(|&g| {
            let mut nearest = (0, f64::INFINITY);
            for (slot, &k) in free.iter().enumerate() {
                let distance_sqr = ((found[k] - g) * per_scale).norm_sqr();
                if distance_sqr < nearest.1 {
                    nearest = (slot, distance_sqr);
                }
            }
            free.swap_remove(nearest.0)
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
pub(in crate::analysis) fn eigenvalues_near(
    pencil: &AffinePencil,
    p: f64,
    roots: &mut [C64],
) -> Result<(), AnalysisError> {
    let n = roots.len();
    if n <= MAX_DEGREE
        && let Some(poly) = pencil.char_poly(p)
    {
        // A failed iteration leaves the guess for the Schur path.
        if aberth(&poly, roots, 60) {
            return Ok(());
        }
    }
    let spectrum = pencil.spectrum(p)?;
    let assigned = assign(&spectrum.eigenvalues, roots);
    roots.copy_from_slice(&assigned);
    Ok(())
}
