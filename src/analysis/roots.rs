//! Polynomial numerics for the fast path of continuation: real polynomials,
//! Horner's rule, and Aberth-Ehrlich refinement of all roots at once from a
//! previous estimate. Knows nothing of pencils.

use super::C64;

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
/// Returns false (roots unusable) without convergence in `max_iterations`.
pub fn aberth(poly: &Poly, roots: &mut [C64], max_iterations: usize) -> bool {
    if roots.len() != poly.degree {
        return false;
    }
    // Degree <= MAX_DEGREE: exact in f64.
    let noise = 2.0 * f64::from(u8::try_from(poly.degree).unwrap_or(u8::MAX)) * f64::EPSILON;
    // A converged root is not moved again, so its residual need not be
    // evaluated again either.
    let mut converged = [false; MAX_DEGREE];
    for _ in 0..max_iterations {
        let mut done = true;
        for i in 0..roots.len() {
            if converged[i] {
                continue;
            }
            let z = roots[i];
            let (value, slope, bound) = horner(poly, z);
            if modulus(value) <= noise * bound {
                converged[i] = true;
                continue;
            }
            done = false;
            let newton = value / slope;
            let repulsion: C64 = roots
                .iter()
                .enumerate()
                .filter(|&(j, _)| j != i)
                .map(|(_, &w)| (z - w).inv())
                .sum();
            let step = newton / (C64::new(1.0, 0.0) - newton * repulsion);
            if !(step.re.is_finite() && step.im.is_finite()) {
                return false;
            }
            roots[i] = without_negligible_component(z - step);
        }
        if done {
            return true;
        }
    }
    false
}
