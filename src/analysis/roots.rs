//! The fast path for continuation: the characteristic polynomial of a small
//! pencil and Aberth-Ehrlich refinement of its roots from a previous estimate.

use super::C64;
use super::pencil::AffinePencil;

/// Largest degree handled by the polynomial path (3 degrees of freedom).
pub const MAX_DEGREE: usize = 6;

/// Real polynomial coefficients, lowest degree first.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Poly {
    pub coeffs: [f64; MAX_DEGREE + 1],
    pub degree: usize,
}

fn mul(a: &[f64], b: &[f64], out: &mut [f64]) {
    out.fill(0.0);
    for (i, &x) in a.iter().enumerate() {
        for (j, &y) in b.iter().enumerate() {
            out[i + j] += x * y;
        }
    }
}

/// `det(lambda^2 M + lambda D + K)` at load p for 2 or 3 degrees of freedom,
/// by cofactor expansion, with the structural zero roots divided out (their
/// coefficients are exact zeros: every term carries an entry of a zero column).
/// `None` for other sizes or a vanishing leading coefficient.
#[must_use]
pub fn char_poly(pencil: &AffinePencil, p: f64) -> Option<Poly> {
    let n = pencil.dof();
    let e = |i, j| pencil.entry(p, i, j);
    let mut full = [0.0; MAX_DEGREE + 1];
    match n {
        2 => {
            let (mut x, mut y) = ([0.0; 5], [0.0; 5]);
            mul(&e(0, 0), &e(1, 1), &mut x);
            mul(&e(0, 1), &e(1, 0), &mut y);
            for k in 0..5 {
                full[k] = x[k] - y[k];
            }
        }
        3 => {
            let minor = |r: [usize; 2], c: [usize; 2]| {
                let (mut x, mut y) = ([0.0; 5], [0.0; 5]);
                mul(&e(r[0], c[0]), &e(r[1], c[1]), &mut x);
                mul(&e(r[0], c[1]), &e(r[1], c[0]), &mut y);
                let mut m = [0.0; 5];
                for k in 0..5 {
                    m[k] = x[k] - y[k];
                }
                m
            };
            let terms = [
                (1.0, e(0, 0), minor([1, 2], [1, 2])),
                (-1.0, e(0, 1), minor([1, 2], [0, 2])),
                (1.0, e(0, 2), minor([1, 2], [0, 1])),
            ];
            let mut t = [0.0; 7];
            for (sign, entry, m) in terms {
                mul(&entry, &m, &mut t);
                for k in 0..7 {
                    full[k] += sign * t[k];
                }
            }
        }
        _ => return None,
    }
    let zeros = pencil.cyclic_zeros();
    let degree = 2 * n - zeros;
    if full[..zeros].iter().any(|&c| c != 0.0) || full[2 * n] == 0.0 {
        return None;
    }
    let mut coeffs = [0.0; MAX_DEGREE + 1];
    coeffs[..=degree].copy_from_slice(&full[zeros..=2 * n]);
    Some(Poly { coeffs, degree })
}

/// Value, derivative and rounding bound `sum |c_k| |z|^k` of `poly` at z (Horner).
/// |z|: the square root of |z|^2 where that neither overflows nor
/// underflows, `hypot` (several times slower) only where it does.
pub(crate) fn modulus(z: C64) -> f64 {
    let squared = z.norm_sqr();
    if squared.is_finite() && squared >= f64::MIN_POSITIVE {
        squared.sqrt()
    } else {
        z.norm()
    }
}

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
    for _ in 0..max_iterations {
        let mut done = true;
        for i in 0..roots.len() {
            let z = roots[i];
            let (value, slope, bound) = horner(poly, z);
            if modulus(value) <= noise * bound {
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
            roots[i] = z - step;
        }
        if done {
            return true;
        }
    }
    false
}
