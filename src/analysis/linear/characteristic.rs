//! The characteristic polynomial `det(lambda^2 M + lambda D + K)` of a
//! pencil affine in the load, as a polynomial in lambda and p, for 2 or 3
//! degrees of freedom: its coefficients at a load without a matrix.

use crate::analysis::roots::MAX_DEGREE;
use crate::model::LinearModel;

/// Highest power of the load in a coefficient of the characteristic
/// polynomial (each entry of the pencil is affine in p; 3 degrees of freedom).
const LOAD_DEGREE: usize = 3;

/// A polynomial in lambda and p: `c[k][m]` multiplies `lambda^k p^m`.
type Bivariate = [[f64; LOAD_DEGREE + 1]; MAX_DEGREE + 1];

fn bivariate_mul(a: &Bivariate, b: &Bivariate) -> Bivariate {
    let mut out = [[0.0; LOAD_DEGREE + 1]; MAX_DEGREE + 1];
    for (k, row) in a.iter().enumerate() {
        for (m, &x) in row.iter().enumerate() {
            if x == 0.0 {
                continue;
            }
            for (l, other) in b.iter().enumerate().take(MAX_DEGREE + 1 - k) {
                for (q, &y) in other.iter().enumerate().take(LOAD_DEGREE + 1 - m) {
                    out[k + l][m + q] += x * y;
                }
            }
        }
    }
    out
}

fn bivariate_add(sign: f64, a: &Bivariate, out: &mut Bivariate) {
    for (row, add) in out.iter_mut().zip(a) {
        for (c, &x) in row.iter_mut().zip(add) {
            *c += sign * x;
        }
    }
}

/// `det(lambda^2 M + lambda D(p) + K(p))` expanded once in lambda and p, so
/// that the hot loop of the locus evaluates 2n + 1 cubics in p per load
/// instead of the cofactor expansion.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct CharacteristicPolynomial {
    coefficients: Bivariate,
}

impl CharacteristicPolynomial {
    /// By cofactor expansion for 2 or 3 degrees of freedom; `None` otherwise.
    pub(super) fn new(at_zero: &LinearModel, per_unit_load: &LinearModel) -> Option<Self> {
        let entry = |i: usize, j: usize| {
            let mut e = [[0.0; LOAD_DEGREE + 1]; MAX_DEGREE + 1];
            e[0] = [
                at_zero.stiffness[(i, j)],
                per_unit_load.stiffness[(i, j)],
                0.0,
                0.0,
            ];
            e[1] = [
                at_zero.damping[(i, j)],
                per_unit_load.damping[(i, j)],
                0.0,
                0.0,
            ];
            e[2][0] = at_zero.mass[(i, j)];
            e
        };
        let minor = |r: [usize; 2], c: [usize; 2]| {
            let mut m = bivariate_mul(&entry(r[0], c[0]), &entry(r[1], c[1]));
            bivariate_add(
                -1.0,
                &bivariate_mul(&entry(r[0], c[1]), &entry(r[1], c[0])),
                &mut m,
            );
            m
        };
        let coefficients = match at_zero.mass.nrows() {
            2 => minor([0, 1], [0, 1]),
            3 => {
                let mut det = [[0.0; LOAD_DEGREE + 1]; MAX_DEGREE + 1];
                let terms = [
                    (1.0, entry(0, 0), minor([1, 2], [1, 2])),
                    (-1.0, entry(0, 1), minor([1, 2], [0, 2])),
                    (1.0, entry(0, 2), minor([1, 2], [0, 1])),
                ];
                for (sign, e, m) in &terms {
                    bivariate_add(*sign, &bivariate_mul(e, m), &mut det);
                }
                det
            }
            _ => return None,
        };
        Some(Self { coefficients })
    }

    /// The coefficients in lambda at load p, lowest degree first.
    pub(super) fn at(&self, p: f64) -> [f64; MAX_DEGREE + 1] {
        self.coefficients
            .map(|[c0, c1, c2, c3]| ((c3 * p + c2) * p + c1) * p + c0)
    }
}
