//! Polynomial numerics for the fast path of continuation: real polynomials,
//! Horner's rule, and Aberth-Ehrlich refinement of all roots at once from a
//! previous estimate. Knows nothing of pencils.

use crate::analysis::C64;

/// Largest degree handled by the polynomial path (3 degrees of freedom).
pub const MAX_DEGREE: usize = 6;

/// Real polynomial coefficients, lowest degree first.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Poly {
    pub coeffs: [f64; MAX_DEGREE + 1],
    pub degree: usize,
}

/// |z| without ever squaring a number small enough to underflow: a
/// component below 1e-8 of the other changes |z| by less than rounding
/// (1 + 1e-16 rounds to 1), so the larger is returned as it is; the square
/// root of |z|^2 where both squares are normal f64; `hypot` (several times
/// slower) only for moduli beyond 1e145 or below 1e-145. Squares in the
/// subnormal range cost about a hundred cycles each on many Intel CPUs.
pub(crate) fn modulus(z: C64) -> f64 {
    /// Below this ratio the smaller component is lost to rounding in |z|.
    const LOST_RATIO: f64 = 1e-8;
    /// Moduli in this range square both components within the normal range
    /// (the smaller is at least `LOST_RATIO` of the larger).
    const SAFE: std::ops::RangeInclusive<f64> = 1e-145..=1e145;
    let (a, b) = (z.re.abs(), z.im.abs());
    let (big, small) = if a >= b { (a, b) } else { (b, a) };
    if small <= LOST_RATIO * big {
        big
    } else if SAFE.contains(&big) {
        z.norm_sqr().sqrt()
    } else {
        z.norm()
    }
}

/// A component of an eigenvalue estimate below this fraction of the other is
/// set to zero: it is far below the last digit f64 holds of the root, and
/// left alone it shrinks quadratically under Aberth's corrections (a real
/// root's imaginary part, an undamped mode's real part) down into the
/// subnormal range.
const NEGLIGIBLE_COMPONENT: f64 = f64::EPSILON * f64::EPSILON;

/// `z` with any component below [`NEGLIGIBLE_COMPONENT`] of the other set to zero.
pub(crate) fn without_negligible_component(z: C64) -> C64 {
    let (a, b) = (z.re.abs(), z.im.abs());
    if b < NEGLIGIBLE_COMPONENT * a {
        C64::new(z.re, 0.0)
    } else if a < NEGLIGIBLE_COMPONENT * b {
        C64::new(0.0, z.im)
    } else {
        z
    }
}

/// An Aberth step shorter than this fraction of the distance to the nearest
/// other root settles the root: the iteration converges cubically, so the
/// error left is about `SETTLED_STEP^2` times the step, `1e-10` of it, far
/// below the root's last digit (`1e-15` of the separation).
const SETTLED_STEP: f64 = 1e-5;

/// Value, derivative and rounding bound `sum |c_k| |z|^k` of `poly` at z (Horner).
fn horner(poly: &Poly, z: C64) -> (C64, C64, f64) {
    let coeffs = &poly.coeffs[..=poly.degree];
    let mut value = C64::new(coeffs[poly.degree], 0.0);
    let mut slope = C64::new(0.0, 0.0);
    let mut bound = coeffs[poly.degree].abs();
    let z_abs = modulus(z);
    for &c in coeffs[..poly.degree].iter().rev() {
        slope = slope * z + value;
        value = value * z + c;
        bound = bound * z_abs + c.abs();
    }
    (value, slope, bound)
}

/// Refines `roots` (one per degree, e.g. the previous load's eigenvalues) to
/// the roots of `poly` by Aberth-Ehrlich iteration, which keeps each estimate
/// attached to its own root. A root is done when its residual is at the level
/// of rounding (`|p(z)| <= 2 n eps sum |c_k||z|^k`), so near a double root it
/// stops at the attainable accuracy instead of iterating on noise.
///
/// The coefficients are real, so the roots are real or come in conjugate
/// pairs: when the estimates do too (to [`PAIR_TOLERANCE`]), only one of
/// each pair is iterated and the other is its mirror image, which halves
/// the work and keeps pairs exactly conjugate. A pair whose upper root
/// crosses the real axis has split into two real roots (past a branch
/// point): its estimates `a +- ib` are taken as the reals `a +- b` and the
/// iteration starts again, still mirrored. Where the mirrored iteration
/// cannot converge otherwise (two real roots about to become a pair)
/// every root is iterated on its own from the same estimates.
/// Returns false, the estimates unchanged, without convergence in
/// `max_iterations`.
pub fn aberth(poly: &Poly, roots: &mut [C64], max_iterations: usize) -> bool {
    let n = roots.len();
    if n != poly.degree {
        return false;
    }
    if let Some((mut starts, mut roles)) = conjugate_pairs(roots) {
        let iterations = max_iterations.min(MIRRORED_ITERATIONS);
        // Each split leaves one pair fewer: at most n / 2 restarts.
        for _ in 0..=n / 2 {
            let mut mirrored = starts;
            match iterate(poly, &mut mirrored[..n], &roles[..n], iterations) {
                Iterated::Converged => {
                    roots.copy_from_slice(&mirrored[..n]);
                    return true;
                }
                Iterated::Split { upper, lower } => {
                    let z = starts[upper];
                    starts[upper] = C64::new(z.re + z.im, 0.0);
                    starts[lower] = C64::new(z.re - z.im, 0.0);
                    roles[upper] = Role::Real;
                    roles[lower] = Role::Real;
                }
                Iterated::Failed => break,
            }
        }
    }
    let mut own = [C64::new(0.0, 0.0); MAX_DEGREE];
    own[..n].copy_from_slice(roots);
    let found = iterate(
        poly,
        &mut own[..n],
        &[Role::Own; MAX_DEGREE][..n],
        max_iterations,
    ) == Iterated::Converged;
    if found {
        roots.copy_from_slice(&own[..n]);
    }
    found
}

/// Estimates that are conjugate to this fraction of their size (the sum of
/// the parts' magnitudes) are taken as a pair, and one whose imaginary part
/// is this small beside its real part as real.
const PAIR_TOLERANCE: f64 = 1e-8;

/// Iterations of the mirrored estimates before every root is iterated on its
/// own instead: from a continuation's guess they converge in 2 to 5.
const MIRRORED_ITERATIONS: usize = 12;

/// How an estimate is iterated.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Role {
    /// On its own (no symmetry used).
    Own,
    /// A real root: kept real.
    Real,
    /// The upper one of a conjugate pair; the root at this index is its mirror.
    Upper(usize),
    /// The lower one of a pair: the mirror image of its partner, not iterated.
    Lower,
}

/// The estimates made exactly real or conjugate in pairs, and each one's
/// role; `None` when they are not real or conjugate to [`PAIR_TOLERANCE`].
fn conjugate_pairs(roots: &[C64]) -> Option<([C64; MAX_DEGREE], [Role; MAX_DEGREE])> {
    let n = roots.len();
    let mut mirrored = [C64::new(0.0, 0.0); MAX_DEGREE];
    mirrored[..n].copy_from_slice(roots);
    // `Own` marks an estimate not yet placed.
    let mut roles = [Role::Own; MAX_DEGREE];
    for i in 0..n {
        let z = roots[i];
        if roles[i] != Role::Own || z.im <= 0.0 {
            continue;
        }
        // The lower estimate nearest to z's mirror image, by the sum of the
        // components' differences (no square root: this runs per sample).
        let apart = |w: C64| (w.re - z.re).abs() + (w.im + z.im).abs();
        let partner = (0..n)
            .filter(|&j| roles[j] == Role::Own && roots[j].im < 0.0)
            .min_by(|&a, &b| apart(roots[a]).total_cmp(&apart(roots[b])));
        if let Some(j) = partner {
            let middle = (z + roots[j].conj()) * 0.5;
            if apart(roots[j]) <= PAIR_TOLERANCE * (z.re.abs() + z.im) && middle.im > 0.0 {
                mirrored[i] = middle;
                mirrored[j] = middle.conj();
                roles[i] = Role::Upper(j);
                roles[j] = Role::Lower;
            }
        }
    }
    for k in 0..n {
        if roles[k] == Role::Own {
            if roots[k].im.abs() > PAIR_TOLERANCE * roots[k].re.abs() {
                return None;
            }
            mirrored[k].im = 0.0;
            roles[k] = Role::Real;
        }
    }
    Some((mirrored, roles))
}

/// Aberth's correction of estimate `i` of `roots`: the step to subtract
/// from it and the squared distance to the nearest other estimate, or
/// `None` when its residual is at the level of rounding (`noise` times the
/// rounding bound: converged).
fn correction(poly: &Poly, roots: &[C64], i: usize, noise: f64) -> Option<(C64, f64)> {
    let z = roots[i];
    let (value, slope, bound) = horner(poly, z);
    if modulus(value) <= noise * bound {
        return None;
    }
    // The repulsion of the other roots, and the square of the distance to
    // the nearest.
    let (repulsion, nearest_sqr) = roots.iter().enumerate().filter(|&(j, _)| j != i).fold(
        (C64::new(0.0, 0.0), f64::INFINITY),
        |(sum, nearest), (_, &w)| {
            let d = z - w;
            let d_sqr = d.norm_sqr();
            (sum + d.conj() / d_sqr, nearest.min(d_sqr))
        },
    );
    // Newton's step n = value / slope over (1 - n repulsion), with one
    // division.
    Some((value / (slope - value * repulsion), nearest_sqr))
}

/// [`correction`] of a real estimate among estimates that are real or in
/// exactly conjugate pairs, in real arithmetic: the polynomial, its slope
/// and the repulsion are real there (a pair's terms' imaginary parts
/// cancel), at a third of the complex evaluation's cost.
fn real_correction(poly: &Poly, roots: &[C64], i: usize, noise: f64) -> Option<(f64, f64)> {
    let x = roots[i].re;
    let coeffs = &poly.coeffs[..=poly.degree];
    let (mut value, mut slope, mut bound) = (coeffs[poly.degree], 0.0, coeffs[poly.degree].abs());
    for &c in coeffs[..poly.degree].iter().rev() {
        slope = slope * x + value;
        value = value * x + c;
        bound = bound * x.abs() + c.abs();
    }
    if value.abs() <= noise * bound {
        return None;
    }
    let (mut repulsion, mut nearest_sqr) = (0.0, f64::INFINITY);
    for (j, w) in roots.iter().enumerate() {
        if j != i {
            let d = x - w.re;
            let d_sqr = d * d + w.im * w.im;
            repulsion += d / d_sqr;
            nearest_sqr = nearest_sqr.min(d_sqr);
        }
    }
    Some((value / (slope - value * repulsion), nearest_sqr))
}

/// How an iteration ended.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Iterated {
    /// Every root to rounding.
    Converged,
    /// The upper root of the pair at `upper` and `lower` left the upper
    /// half-plane: the pair's roots are real.
    Split { upper: usize, lower: usize },
    /// No convergence in the iterations allowed, or a step not finite.
    Failed,
}

/// Aberth-Ehrlich iteration of the estimates whose `roles` say so (see
/// [`aberth`]), stopped when a pair's upper root leaves the upper half-plane.
fn iterate(poly: &Poly, roots: &mut [C64], roles: &[Role], max_iterations: usize) -> Iterated {
    // Degree <= MAX_DEGREE: exact in f64.
    let noise = 2.0 * f64::from(u8::try_from(poly.degree).unwrap_or(u8::MAX)) * f64::EPSILON;
    // A converged root is not moved again, so its residual need not be
    // evaluated again either; a pair's lower root is never iterated.
    let mut converged = [false; MAX_DEGREE];
    for (done, role) in converged.iter_mut().zip(roles) {
        *done = *role == Role::Lower;
    }
    for _ in 0..max_iterations {
        let mut done = true;
        for i in 0..roots.len() {
            if converged[i] {
                continue;
            }
            let z = roots[i];
            let correction = if roles[i] == Role::Real {
                real_correction(poly, roots, i, noise)
                    .map(|(step, nearest_sqr)| (C64::new(step, 0.0), nearest_sqr))
            } else {
                correction(poly, roots, i, noise)
            };
            let Some((step, nearest_sqr)) = correction else {
                converged[i] = true;
                continue;
            };
            done = false;
            if !(step.re.is_finite() && step.im.is_finite()) {
                return Iterated::Failed;
            }
            let moved = without_negligible_component(z - step);
            match roles[i] {
                Role::Own => roots[i] = moved,
                Role::Real => roots[i] = C64::new(moved.re, 0.0),
                Role::Upper(j) => {
                    if moved.im <= 0.0 {
                        return Iterated::Split { upper: i, lower: j };
                    }
                    roots[i] = moved;
                    roots[j] = moved.conj();
                }
                Role::Lower => {}
            }
            // Cubic convergence: a step this small next to the root's
            // separation leaves an error below rounding, so the residual need
            // not be evaluated again to know it.
            converged[i] = step.norm_sqr() <= SETTLED_STEP * SETTLED_STEP * nearest_sqr;
        }
        if done {
            return Iterated::Converged;
        }
    }
    Iterated::Failed
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The real polynomial with these roots (each non-real one's conjugate
    /// must be among them), lowest degree first.
    fn poly_with_roots(roots: &[C64]) -> Poly {
        let mut coeffs = vec![C64::new(1.0, 0.0)];
        for &r in roots {
            let mut next = vec![C64::new(0.0, 0.0); coeffs.len() + 1];
            for (k, &c) in coeffs.iter().enumerate() {
                next[k + 1] += c;
                next[k] -= c * r;
            }
            coeffs = next;
        }
        let mut poly = Poly {
            coeffs: [0.0; MAX_DEGREE + 1],
            degree: roots.len(),
        };
        for (k, c) in coeffs.iter().enumerate() {
            poly.coeffs[k] = c.re;
        }
        poly
    }

    fn nearest_miss(found: &[C64], exact: &[C64]) -> f64 {
        exact
            .iter()
            .map(|&z| {
                found
                    .iter()
                    .map(|&w| (w - z).norm())
                    .fold(f64::INFINITY, f64::min)
            })
            .fold(0.0, f64::max)
    }

    /// The real arithmetic's correction of a real estimate is the complex
    /// one's, to rounding, with estimates real or in exact pairs around it:
    /// the same step (a few units in the last place apart), the same nearest
    /// distance, and the same verdict at a root.
    #[test]
    fn a_real_estimate_s_correction_is_the_complex_one() {
        let exact = [
            C64::new(-0.3, 2.1),
            C64::new(-0.3, -2.1),
            C64::new(0.7, 0.0),
            C64::new(-1.9, 0.0),
            C64::new(0.02, 0.4),
            C64::new(0.02, -0.4),
        ];
        let poly = poly_with_roots(&exact);
        let noise = 12.0 * f64::EPSILON;
        for offset in [3e-2, -1e-4, 2e-7, 1e-11] {
            let mut estimates = exact;
            estimates[2].re += offset;
            estimates[0] += C64::new(1e-3, -2e-3);
            estimates[1] = estimates[0].conj();
            let (step, nearest_sqr) = real_correction(&poly, &estimates, 2, noise).unwrap();
            let (complex, complex_nearest) = correction(&poly, &estimates, 2, noise).unwrap();
            assert!(complex.im.abs() <= 1e-15 * complex.re.abs(), "{complex}");
            assert!(
                (step - complex.re).abs() <= 8.0 * f64::EPSILON * step.abs(),
                "{offset}: {step} against {complex}"
            );
            assert!((nearest_sqr - complex_nearest).abs() <= 4.0 * f64::EPSILON * nearest_sqr);
            // The step moves the estimate most of the way to the root.
            assert!((estimates[2].re - step - 0.7).abs() <= 1e-2 * offset.abs());
        }
        assert_eq!(real_correction(&poly, &exact, 3, noise), None);
        assert_eq!(correction(&poly, &exact, 3, noise), None);
    }

    /// Two pairs and a real root, from estimates conjugate to 1e-12 (as a
    /// continuation's are): the pairs come out exactly conjugate, the real
    /// root exactly real, every root to rounding.
    #[test]
    fn conjugate_estimates_give_exact_pairs() {
        let exact = [
            C64::new(-0.1, 1.2),
            C64::new(-0.1, -1.2),
            C64::new(0.05, 0.3),
            C64::new(0.05, -0.3),
            C64::new(-2.0, 0.0),
        ];
        let poly = poly_with_roots(&exact);
        let mut roots = [
            C64::new(-0.101, 1.199),
            C64::new(-0.101, -1.199 + 1e-12),
            C64::new(0.049, 0.301),
            C64::new(0.049, -0.301),
            C64::new(-1.99, 1e-13),
        ];
        assert!(conjugate_pairs(&roots).is_some());
        assert!(aberth(&poly, &mut roots, 60));
        assert_eq!(roots[1], roots[0].conj());
        assert_eq!(roots[3], roots[2].conj());
        assert_eq!(roots[4].im, 0.0);
        assert!(nearest_miss(&roots, &exact) < 1e-14, "{roots:?}");
    }

    /// Where the mirrored iteration cannot reach the roots (estimates real
    /// to rounding of a pair that has just left the real axis, and a pair's
    /// estimates for two real roots), every root is iterated on its own and
    /// still found.
    #[test]
    fn a_pair_leaving_or_landing_on_the_axis_is_still_found() {
        let pair = [
            C64::new(-0.5, 1e-3),
            C64::new(-0.5, -1e-3),
            C64::new(1.0, 0.0),
        ];
        let mut from_reals = [
            C64::new(-0.49, 1e-12),
            C64::new(-0.51, -1e-12),
            C64::new(1.0, 0.0),
        ];
        let (mirrored, roles) = conjugate_pairs(&from_reals).unwrap();
        assert_eq!(roles[..3], [Role::Real; 3], "{mirrored:?}");
        assert!(aberth(&poly_with_roots(&pair), &mut from_reals, 60));
        assert!(nearest_miss(&from_reals, &pair) < 1e-12, "{from_reals:?}");
        let reals = [
            C64::new(-0.499, 0.0),
            C64::new(-0.501, 0.0),
            C64::new(1.0, 0.0),
        ];
        let mut from_pair = [
            C64::new(-0.5, 1e-4),
            C64::new(-0.5, -1e-4),
            C64::new(1.0, 0.0),
        ];
        assert!(aberth(&poly_with_roots(&reals), &mut from_pair, 60));
        assert!(nearest_miss(&from_pair, &reals) < 1e-12, "{from_pair:?}");
    }

    /// A pair's estimates for two real roots (a pair that has landed on the
    /// real axis between two loads): the mirrored iteration sees the upper
    /// root cross the axis, takes the pair as two reals and finds them
    /// exactly real, each to rounding, with the other roots still mirrored.
    #[test]
    fn a_landed_pair_is_split_into_two_reals() {
        let exact = [
            C64::new(0.43, 0.0),
            C64::new(-0.4, 0.02),
            C64::new(-96.0, 0.0),
            C64::new(-0.4, -0.02),
            C64::new(0.436, 0.0),
        ];
        let poly = poly_with_roots(&exact);
        for half_width in [1e-2, 3e-3, 1e-4] {
            let starts = [
                C64::new(0.432, half_width),
                C64::new(-0.4003, 0.0199),
                C64::new(-96.01, 0.0),
                C64::new(-0.4003, -0.0199),
                C64::new(0.432, -half_width),
            ];
            let (mut mirrored, roles) = conjugate_pairs(&starts).unwrap();
            assert_eq!(
                iterate(&poly, &mut mirrored[..5], &roles[..5], MIRRORED_ITERATIONS),
                Iterated::Split { upper: 0, lower: 4 }
            );
            let mut roots = starts;
            assert!(aberth(&poly, &mut roots, 60));
            assert_eq!(
                [roots[0].im, roots[2].im, roots[4].im],
                [0.0; 3],
                "{roots:?}"
            );
            assert_eq!(roots[3], roots[1].conj());
            assert!(nearest_miss(&roots, &exact) < 1e-13, "{roots:?}");
        }
    }

    /// Estimates that are not conjugate (no symmetry to use) are iterated
    /// each on its own to the same roots; a failed iteration leaves them.
    #[test]
    fn estimates_without_symmetry_are_iterated_on_their_own() {
        let exact = [C64::new(0.0, 2.0), C64::new(0.0, -2.0), C64::new(-1.0, 0.0)];
        let mut roots = [
            C64::new(0.1, 1.9),
            C64::new(-0.2, -2.1),
            C64::new(-0.9, 0.05),
        ];
        assert!(conjugate_pairs(&roots).is_none());
        // Without convergence the estimates are left as they were.
        let before = roots;
        assert!(!aberth(&poly_with_roots(&exact), &mut roots, 1));
        assert_eq!(roots, before);
        assert!(aberth(&poly_with_roots(&exact), &mut roots, 60));
        assert!(nearest_miss(&roots, &exact) < 1e-14, "{roots:?}");
    }
}
