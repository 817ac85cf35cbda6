//! The Butcher tableau of the Gauss-Legendre collocation method with
//! [`STAGES`] stages: its nodes (the roots of the Legendre polynomial on
//! the step), the integrals of the Lagrange polynomials through them, the
//! weights that carry one step's stage derivatives to the next's, and the
//! eigenvalues and eigenvectors of `A` that split the stage equations.

use std::sync::LazyLock;

use nalgebra::{Complex, SMatrix, SVector};

use crate::analysis::C64;

/// Stages of the method: order `2 * STAGES` at the steps' ends.
pub const STAGES: usize = 4;

/// The tableau: `A`, `b`, the extrapolation `next` and `A`'s
/// eigenvalues. The stage times `c` (fractions of a step) are the
/// Gauss-Legendre nodes on `[0, 1]`, [`legendre_nodes`].
#[derive(Debug)]
pub struct Tableau {
    /// `a[i][j]`: the integral from 0 to `c_i` of the Lagrange polynomial
    /// through the nodes that is 1 at `c_j`.
    pub a: [[f64; STAGES]; STAGES],
    /// `b[j]`: the same integral from 0 to 1 (the quadrature's weights).
    pub b: [f64; STAGES],
    /// `next[i][j]`: the Lagrange polynomial of node `j` at `1 + c_i`, which
    /// extrapolates one step's stage derivatives to the next step's stage
    /// times (the first guess of its Newton iterations).
    pub next: [[f64; STAGES]; STAGES],
    /// `A = V diag(lambda) V^-1` with the eigenvalues in conjugate pairs,
    /// the first of each pair (positive imaginary part) at the even
    /// indices, and the pair's eigenvectors conjugate: `lambda`.
    pub eigenvalues: [C64; STAGES],
    /// `V`.
    pub eigenvectors: SMatrix<C64, STAGES, STAGES>,
    /// `V^-1`.
    pub eigenvectors_inverse: SMatrix<C64, STAGES, STAGES>,
}

/// The stages come in conjugate pairs of `A`'s eigenvalues (a Gauss
/// method of an even number of stages has no real one).
const _: () = assert!(STAGES.is_multiple_of(2));

/// The tableau, computed once.
pub static GAUSS: LazyLock<Tableau> = LazyLock::new(Tableau::gauss_legendre);

impl Tableau {
    fn gauss_legendre() -> Self {
        let c = legendre_nodes();
        let basis: [[f64; STAGES]; STAGES] = std::array::from_fn(|j| lagrange_coefficients(&c, j));
        // The integral from 0 to t of sum_m q_m s^m: sum_m q_m t^(m+1) / (m+1),
        // by Horner's rule.
        let integral = |coefficients: &[f64; STAGES], t: f64| {
            (1..=STAGES).rev().fold(0.0, |sum, m| {
                #[expect(clippy::cast_precision_loss, reason = "a small power")]
                let power = m as f64;
                (sum + coefficients[m - 1] / power) * t
            })
        };
        let value = |coefficients: &[f64; STAGES], t: f64| {
            coefficients.iter().rev().fold(0.0, |sum, &q| sum * t + q)
        };
        let a: [[f64; STAGES]; STAGES] =
            std::array::from_fn(|i| std::array::from_fn(|j| integral(&basis[j], c[i])));
        let (eigenvalues, eigenvectors) = eigen(&a);
        let eigenvectors_inverse = eigenvectors
            .try_inverse()
            .unwrap_or_else(|| SMatrix::from_element(C64::new(f64::NAN, 0.0)));
        Self {
            a,
            b: std::array::from_fn(|j| integral(&basis[j], 1.0)),
            next: std::array::from_fn(|i| std::array::from_fn(|j| value(&basis[j], 1.0 + c[i]))),
            eigenvalues,
            eigenvectors,
            eigenvectors_inverse,
        }
    }
}

/// The eigenvalues of `a` in conjugate pairs (positive imaginary part
/// first) and their eigenvectors as columns, each pair's conjugate: each
/// by inverse iteration from the eigenvalue (the Schur form's) nudged off
/// itself.
fn eigen(a: &[[f64; STAGES]; STAGES]) -> ([C64; STAGES], SMatrix<C64, STAGES, STAGES>) {
    let real = SMatrix::<f64, STAGES, STAGES>::from_fn(|i, j| a[i][j]);
    let complex = real.map(|v| Complex::new(v, 0.0));
    let mut upper: Vec<C64> = real
        .complex_eigenvalues()
        .iter()
        .copied()
        .filter(|z| z.im > 0.0)
        .collect();
    upper.sort_by(|x, y| x.re.total_cmp(&y.re));
    let mut values = [C64::new(f64::NAN, 0.0); STAGES];
    let mut vectors = SMatrix::<C64, STAGES, STAGES>::from_element(C64::new(f64::NAN, 0.0));
    for (pair, &lambda) in upper.iter().take(STAGES / 2).enumerate() {
        let shifted = complex - SMatrix::identity() * (lambda * (1.0 + 1e-9));
        let lu = shifted.lu();
        let mut v = SVector::<C64, STAGES>::from_element(C64::new(1.0, 0.0));
        for _ in 0..4 {
            if let Some(next) = lu.solve(&v) {
                v = next.unscale(next.norm());
            }
        }
        values[2 * pair] = lambda;
        values[2 * pair + 1] = lambda.conj();
        vectors.set_column(2 * pair, &v);
        vectors.set_column(2 * pair + 1, &v.map(|z| z.conj()));
    }
    (values, vectors)
}

/// The roots of the Legendre polynomial of degree [`STAGES`], mapped from
/// `[-1, 1]` to `[0, 1]`, ascending: Newton's method on the three-term
/// recurrence from the Chebyshev-like first guesses.
fn legendre_nodes() -> [f64; STAGES] {
    #[expect(clippy::cast_precision_loss, reason = "small counts")]
    let (n, node) = (STAGES as f64, |i: usize| i as f64);
    std::array::from_fn(|i| {
        let mut x = -(std::f64::consts::PI * (node(i) + 0.75) / (n + 0.5)).cos();
        for _ in 0..100 {
            let (p, dp) = legendre(x);
            let step = p / dp;
            x -= step;
            if step.abs() < 1e-17 {
                break;
            }
        }
        0.5 * (1.0 + x)
    })
}

/// The Legendre polynomial of degree [`STAGES`] at `x` and its derivative.
fn legendre(x: f64) -> (f64, f64) {
    let (mut p0, mut p1) = (1.0, x);
    for k in 2..=STAGES {
        #[expect(clippy::cast_precision_loss, reason = "a small degree")]
        let k = k as f64;
        (p0, p1) = (p1, ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k);
    }
    #[expect(clippy::cast_precision_loss, reason = "a small degree")]
    let n = STAGES as f64;
    (p1, n * (x * p1 - p0) / (x * x - 1.0))
}

/// The monomial coefficients (constant first) of the Lagrange polynomial
/// through `nodes` that is 1 at node `j` and 0 at the others.
fn lagrange_coefficients(nodes: &[f64; STAGES], j: usize) -> [f64; STAGES] {
    let mut q = [0.0; STAGES];
    q[0] = 1.0;
    let mut degree = 0;
    for (k, &node) in nodes.iter().enumerate() {
        if k == j {
            continue;
        }
        // q *= (t - node) / (c_j - node)
        let scale = 1.0 / (nodes[j] - node);
        for m in (0..=degree + 1).rev() {
            let shifted = if m > 0 { q[m - 1] } else { 0.0 };
            q[m] = (shifted - node * q[m]) * scale;
        }
        degree += 1;
    }
    q
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The order conditions of a collocation method of order `2s`: the
    /// quadrature integrates `t^(k-1)` exactly for `k <= 2s`, each row of
    /// `A` integrates `t^(k-1)` from 0 to `c_i` for `k <= s` (the
    /// simplifying conditions `B(2s)` and `C(s)`), and the extrapolation
    /// reproduces polynomials of degree below `s`.
    #[test]
    fn the_tableau_meets_the_order_conditions() {
        let t = &*GAUSS;
        let c = legendre_nodes();
        for k in 1..=2 * STAGES {
            let power = i32::try_from(k - 1).unwrap();
            let sum: f64 = (0..STAGES).map(|j| t.b[j] * c[j].powi(power)).sum();
            assert!(
                (sum - 1.0 / f64::from(power + 1)).abs() < 1e-14,
                "B({k}): {sum}"
            );
        }
        for k in 1..=STAGES {
            let power = i32::try_from(k - 1).unwrap();
            for i in 0..STAGES {
                let sum: f64 = (0..STAGES).map(|j| t.a[i][j] * c[j].powi(power)).sum();
                let exact = c[i].powi(power + 1) / f64::from(power + 1);
                assert!((sum - exact).abs() < 1e-14, "C({k}) row {i}: {sum} {exact}");
            }
            for i in 0..STAGES {
                let sum: f64 = (0..STAGES).map(|j| t.next[i][j] * c[j].powi(power)).sum();
                let exact = (1.0 + c[i]).powi(power);
                assert!((sum - exact).abs() < 1e-12, "next {k} row {i}: {sum}");
            }
        }
        // A = V diag(lambda) V^-1, in conjugate pairs.
        let a = SMatrix::<f64, STAGES, STAGES>::from_fn(|i, j| t.a[i][j]);
        let rebuilt = t.eigenvectors
            * SMatrix::<C64, STAGES, STAGES>::from_diagonal(&SVector::from(t.eigenvalues))
            * t.eigenvectors_inverse;
        for i in 0..STAGES {
            for j in 0..STAGES {
                assert!(
                    (rebuilt[(i, j)] - a[(i, j)]).norm() < 1e-13,
                    "{rebuilt} {a}"
                );
            }
        }
        for pair in 0..STAGES / 2 {
            assert!(t.eigenvalues[2 * pair].im > 0.0);
            assert_eq!(t.eigenvalues[2 * pair + 1], t.eigenvalues[2 * pair].conj());
        }
        // The nodes are symmetric about the step's middle.
        for i in 0..STAGES {
            assert!((c[i] + c[STAGES - 1 - i] - 1.0).abs() < 1e-15);
        }
    }
}
