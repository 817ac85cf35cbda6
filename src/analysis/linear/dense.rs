//! Eigenvalues of a pencil's dense first-order matrices: the companion
//! matrix (or an undamped chain's squares' matrix), balanced, then a QR
//! iteration. nalgebra's serves only companions up to order 6 (the two-rod
//! columns, bit for bit as first computed): it has no exceptional shifts and
//! stalls on a long chain's imaginary pairs, so larger matrices go to `hqr`
//! (faer's where that does not converge).

use nalgebra::{DMatrix, linalg::Schur};

use crate::analysis::C64;
use crate::model::LinearModel;

/// The first-order companion matrix with the cyclic coordinates' positions
/// removed: state `(q_i for non-cyclic i, q')`, size `2n - cyclic`.
pub(super) fn companion(lin: &LinearModel, cyclic: &[usize]) -> Option<DMatrix<f64>> {
    let n = lin.mass.nrows();
    let mass_inv = lin.mass.clone().cholesky()?.inverse();
    let keep: Vec<usize> = (0..n).filter(|j| !cyclic.contains(j)).collect();
    let kept = keep.len();
    let minv_k = -&mass_inv * &lin.stiffness;
    let minv_d = -&mass_inv * &lin.damping;
    let mut a = DMatrix::zeros(kept + n, kept + n);
    for (row, &j) in keep.iter().enumerate() {
        a[(row, kept + j)] = 1.0;
    }
    for i in 0..n {
        for (col, &j) in keep.iter().enumerate() {
            a[(kept + i, col)] = minv_k[(i, j)];
        }
        for j in 0..n {
            a[(kept + i, kept + j)] = minv_d[(i, j)];
        }
    }
    Some(a)
}

/// Diagonal similarity scaling by powers of two (Parlett and Reinsch) so that
/// rows and columns have comparable norms: a light roller's fast spin row
/// would otherwise cost the slow eigenvalues their accuracy.
pub(super) fn balance(a: &mut DMatrix<f64>) {
    const RADIX: f64 = 2.0;
    let n = a.nrows();
    for _sweep in 0..64 {
        let mut changed = false;
        for i in 0..n {
            let (mut col, mut row) = (0.0, 0.0);
            for j in (0..n).filter(|&j| j != i) {
                col += a[(j, i)].abs();
                row += a[(i, j)].abs();
            }
            if col == 0.0 || row == 0.0 {
                continue;
            }
            let sum = col + row;
            let mut f = 1.0;
            while col < row / RADIX {
                f *= RADIX;
                col *= RADIX * RADIX;
            }
            while col > row * RADIX {
                f /= RADIX;
                col /= RADIX * RADIX;
            }
            if (col + row) / f < 0.95 * sum {
                changed = true;
                for j in 0..n {
                    a[(i, j)] /= f;
                    a[(j, i)] *= f;
                }
            }
        }
        if !changed {
            break;
        }
    }
}

/// Eigenvalues of a real matrix by Schur decomposition, `None` if the QR
/// iteration does not converge.
fn schur_eigenvalues(a: DMatrix<f64>) -> Option<Vec<C64>> {
    let schur = Schur::try_new(a, f64::EPSILON, 10_000)?;
    let eigenvalues: Vec<C64> = schur.complex_eigenvalues().iter().copied().collect();
    all_finite(eigenvalues)
}

/// Largest companion matrix given to nalgebra's QR iteration first (the
/// two-rod columns and the roller, bit for bit as before); larger ones, and
/// any it cannot finish, go to faer's, whose shifts do not stall on the
/// many imaginary pairs of a long undamped chain.
pub(super) const NALGEBRA_MAX_ORDER: usize = 6;

/// The eigenvalues of `a` by faer's real Hessenberg QR algorithm.
pub(super) fn faer_eigenvalues(a: &DMatrix<f64>) -> Option<Vec<C64>> {
    let matrix = faer::Mat::from_fn(a.nrows(), a.ncols(), |i, j| a[(i, j)]);
    let eigenvalues = matrix.eigenvalues().ok()?;
    all_finite(
        eigenvalues
            .into_iter()
            .map(|z| C64::new(z.re, z.im))
            .collect(),
    )
}

fn all_finite(eigenvalues: Vec<C64>) -> Option<Vec<C64>> {
    eigenvalues
        .iter()
        .all(|z| z.re.is_finite() && z.im.is_finite())
        .then_some(eigenvalues)
}

/// The eigenvalues of an undamped pencil `lambda^2 M + K` of a long chain:
/// `lambda = +/- sqrt(-mu)` for the eigenvalues mu of `a = M^-1 K`, a
/// matrix of half the companion's order (balanced, then the double-shift QR
/// iteration; faer's Schur decomposition where that does not converge).
pub(super) fn eigenvalues_from_squares(mut a: DMatrix<f64>) -> Option<Vec<C64>> {
    balance(&mut a);
    let squares = crate::analysis::hqr::eigenvalues(a.nrows(), |i, j| a[(i, j)])
        .or_else(|| faer_eigenvalues(&a))?;
    Some(
        squares
            .into_iter()
            .flat_map(|mu| {
                let root = (-mu).sqrt();
                [root, -root]
            })
            .collect(),
    )
}

/// The eigenvalues of the balanced companion matrix `balanced` (or, when
/// no iteration finishes on it, of the unbalanced `a`). Above
/// [`NALGEBRA_MAX_ORDER`] the EISPACK iteration ([`crate::analysis::hqr`],
/// at most 30 iterations an eigenvalue) comes first and faer's Schur
/// decomposition only where it does not converge: faer's reflectors take
/// each norm with a sum of squares scaled by `sqrt(f64::MIN_POSITIVE)`,
/// which makes subnormal numbers at every step of the bulge chase (6.9
/// million on one load scan of a damped 16-rod chain, each a microcode
/// assist of ~100 cycles on Intel CPUs), and its aggressive early deflation
/// ran for minutes on a matrix whose modes span 1e149.
pub(super) fn eigenvalues_of(balanced: &DMatrix<f64>, a: &DMatrix<f64>) -> Option<Vec<C64>> {
    if balanced.nrows() > NALGEBRA_MAX_ORDER {
        return crate::analysis::hqr::eigenvalues(balanced.nrows(), |i, j| balanced[(i, j)])
            .or_else(|| faer_eigenvalues(balanced))
            .or_else(|| faer_eigenvalues(a));
    }
    schur_eigenvalues(balanced.clone())
        .or_else(|| faer_eigenvalues(balanced))
        .or_else(|| schur_eigenvalues(a.clone()))
}
