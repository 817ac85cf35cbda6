//! The stage equations' Newton matrix of the Gauss-Legendre steps
//! (`gauss`), factored by pairs of the method's eigenvalues and, for a
//! column's state of angles and rates, by halves of the state.

use nalgebra::DMatrix;

use super::column_lu::{ColumnLu, parts_by_columns, sub_product};
use super::tableau::{GAUSS, STAGES};
use crate::analysis::C64;

/// The stage equations' matrix `I - h (A ⊗ J)` for one Jacobian `J`,
/// split by `A`'s eigenvalues (Butcher's transformation, as Radau codes
/// do): with `A = V diag(lambda) V^-1` it is
/// `(V ⊗ I) diag(I - h lambda_k J) (V^-1 ⊗ I)`, so a solve is one complex
/// `d x d` solve per conjugate pair of eigenvalues (the pair's other half
/// is its conjugate for a real right-hand side) instead of one real
/// `s d x s d` solve: for four stages an eighth of the operations to
/// factor, about half to solve.
pub(super) struct SplitStages {
    /// Each pair's `I - h lambda J`, factored.
    pairs: Vec<PairLu>,
    /// Each pair's transformed right-hand sides (column-major), reused.
    scratch: Vec<Vec<C64>>,
    /// Room for a single column's solve by halves, reused.
    parts: Vec<f64>,
}

/// One conjugate pair's `I - mu J` (`mu = h lambda`), factored by faer.
#[expect(
    clippy::large_enum_variant,
    reason = "two per Newton matrix, each holding kilobytes of factors"
)]
enum PairLu {
    /// The whole matrix.
    Whole(faer::linalg::solvers::PartialPivLu<C64>),
    /// For a mechanical state `(q, q')`, whose field's first half is the
    /// second (`J = [[0, I], [A, B]]`): `(u, v)` solves
    /// `u - mu v = r_1`, `-mu A u + (I - mu B) v = r_2`, so
    /// `(I - mu B - mu^2 A) v = r_2 + mu A r_1` and `u = r_1 + mu v`: one
    /// factorization of half the size (an eighth of the operations) and
    /// solves of a quarter, for one product with `mu A`. The factors
    /// twice: faer's for many right-hand sides, and laid out for one
    /// ([`ColumnLu`], with `mu A`'s parts apart likewise).
    Half {
        mu: C64,
        mu_a: faer::Mat<C64>,
        lu: faer::linalg::solvers::PartialPivLu<C64>,
        single: ColumnLu,
        mu_a_parts: [Vec<f64>; 2],
    },
}

impl PairLu {
    /// `I - mu J` factored; by halves where `mechanical` (see [`Self::Half`]:
    /// `J`'s first half of rows is then taken as `[0, I]`, whatever it holds).
    fn new(jacobian: &DMatrix<f64>, mu: C64, mechanical: bool) -> Self {
        let d = jacobian.nrows();
        let delta = |r: usize, c: usize| C64::new(f64::from(u8::from(r == c)), 0.0);
        if mechanical && d.is_multiple_of(2) {
            let n = d / 2;
            let (a, b) = (
                |r: usize, c: usize| jacobian[(n + r, c)],
                |r: usize, c: usize| jacobian[(n + r, n + c)],
            );
            let schur =
                faer::Mat::from_fn(n, n, |r, c| delta(r, c) - mu * b(r, c) - mu * mu * a(r, c));
            let mu_a = faer::Mat::from_fn(n, n, |r, c| mu * a(r, c));
            let part = |of: fn(C64) -> f64| parts_by_columns(mu_a.as_ref(), of);
            let lu = schur.partial_piv_lu();
            Self::Half {
                mu,
                single: ColumnLu::new(&lu),
                mu_a_parts: [part(|z| z.re), part(|z| z.im)],
                mu_a,
                lu,
            }
        } else {
            Self::Whole(
                faer::Mat::from_fn(d, d, |r, c| delta(r, c) - mu * jacobian[(r, c)])
                    .partial_piv_lu(),
            )
        }
    }

    /// Solves in place for the `d x columns` right-hand sides `rho`
    /// (column-major), with room `parts` for a single column's.
    fn solve_in_place(&self, rho: &mut [C64], d: usize, columns: usize, parts: &mut Vec<f64>) {
        use faer::linalg::solvers::Solve;
        use faer::reborrow::{Reborrow, ReborrowMut};
        match self {
            Self::Half {
                mu,
                single,
                mu_a_parts,
                ..
            } if columns == 1 => solve_half_column(*mu, single, mu_a_parts, rho, parts),
            Self::Whole(lu) => {
                lu.solve_in_place(faer::MatMut::from_column_major_slice_mut(rho, d, columns));
            }
            Self::Half { mu, mu_a, lu, .. } => {
                let all = faer::MatMut::from_column_major_slice_mut(rho, d, columns);
                let (top, mut bottom) = all.split_at_row_mut(d / 2);
                faer::linalg::matmul::matmul(
                    bottom.rb_mut(),
                    faer::Accum::Add,
                    mu_a.as_ref(),
                    top.rb(),
                    C64::new(1.0, 0.0),
                    faer::Par::Seq,
                );
                lu.solve_in_place(bottom.rb_mut());
                for column in rho.chunks_exact_mut(d) {
                    let (u, v) = column.split_at_mut(d / 2);
                    for (u, v) in u.iter_mut().zip(v.iter()) {
                        *u += mu * v;
                    }
                }
            }
        }
    }
}

/// [`PairLu::Half`]'s solve of one column `(r_1, r_2)` in place, by plain
/// loops over the parts (`mu A` as `mu_a_parts`, re and im by columns),
/// compiled for the machine's vector units by pulp's dispatch.
fn solve_half_column(
    mu: C64,
    lu: &ColumnLu,
    mu_a_parts: &[Vec<f64>; 2],
    column: &mut [C64],
    parts: &mut Vec<f64>,
) {
    parts.clear();
    parts.resize(6 * lu.size(), 0.0);
    pulp::Arch::new().dispatch(HalfColumn {
        mu,
        lu,
        mu_a_parts,
        column,
        parts,
    });
}

/// The work of [`solve_half_column`], for pulp's dispatch (a closure is
/// not inlined into its vectorized body).
struct HalfColumn<'a> {
    mu: C64,
    lu: &'a ColumnLu,
    mu_a_parts: &'a [Vec<f64>; 2],
    column: &'a mut [C64],
    parts: &'a mut [f64],
}

impl pulp::WithSimd for HalfColumn<'_> {
    type Output = ();

    #[expect(
        clippy::inline_always,
        reason = "inlined into pulp's dispatch, whose body is compiled for the vector units"
    )]
    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _simd: S) {
        let Self {
            mu,
            lu,
            mu_a_parts,
            column,
            parts,
        } = self;
        let n = lu.size();
        let (u, rest) = parts.split_at_mut(2 * n);
        let (r, v) = rest.split_at_mut(2 * n);
        let ((u_re, u_im), (r_re, r_im), (v_re, v_im)) =
            (u.split_at_mut(n), r.split_at_mut(n), v.split_at_mut(n));
        for (k, z) in column[..n].iter().enumerate() {
            (u_re[k], u_im[k]) = (z.re, z.im);
        }
        for (k, z) in column[n..].iter().enumerate() {
            (r_re[k], r_im[k]) = (z.re, z.im);
        }
        // r_2 + mu A r_1, by columns of mu A (less the product with
        // -r_1, the same in every bit).
        for j in 0..n {
            let column = j * n..(j + 1) * n;
            let m = (&mu_a_parts[0][column.clone()], &mu_a_parts[1][column]);
            sub_product((&mut *r_re, &mut *r_im), m, -C64::new(u_re[j], u_im[j]));
        }
        lu.gather(r_re, r_im, v_re, v_im);
        lu.sweep(v_re, v_im);
        for k in 0..n {
            let v = C64::new(v_re[k], v_im[k]);
            column[n + k] = v;
            column[k] = C64::new(u_re[k], u_im[k]) + mu * v;
        }
    }
}

impl SplitStages {
    /// The split matrix for `jacobian` at step `h`, by halves where the
    /// state is `mechanical` (see [`PairLu::Half`]).
    pub(super) fn new(jacobian: &DMatrix<f64>, h: f64, mechanical: bool) -> Self {
        let pairs = (0..STAGES / 2)
            .map(|pair| PairLu::new(jacobian, GAUSS.eigenvalues[2 * pair] * h, mechanical))
            .collect();
        Self {
            pairs,
            scratch: (0..STAGES / 2)
                .map(|_| Vec::with_capacity(jacobian.nrows()))
                .collect(),
            parts: Vec::new(),
        }
    }

    /// Solves the stage equations' matrix for the stacked stages `r`, in
    /// place; `false` where the solution is not finite (a singular matrix).
    pub(super) fn solve_mut(&mut self, r: &mut [f64]) -> bool {
        self.solve_columns_mut(r, 1)
    }

    /// [`Self::solve_mut`] for `columns` right-hand sides at once, `r`
    /// column-major (the monodromy's step: one blocked solve of all its
    /// columns, where one solve per column is bound by each column's
    /// pass over the factors).
    pub(super) fn solve_columns_mut(&mut self, r: &mut [f64], columns: usize) -> bool {
        let t = &*GAUSS;
        let rows = r.len() / columns;
        let d = rows / STAGES;
        for (pair, (lu, rho)) in self.pairs.iter().zip(&mut self.scratch).enumerate() {
            let row: [C64; STAGES] = std::array::from_fn(|j| t.eigenvectors_inverse[(2 * pair, j)]);
            rho.clear();
            rho.resize(d * columns, C64::new(0.0, 0.0));
            for (rho_c, r_c) in rho.chunks_exact_mut(d).zip(r.chunks_exact(rows)) {
                for (w, r_j) in row.iter().zip(r_c.chunks_exact(d)) {
                    for (rho_e, &x) in rho_c.iter_mut().zip(r_j) {
                        *rho_e += w * x;
                    }
                }
            }
            lu.solve_in_place(rho, d, columns, &mut self.parts);
        }
        for (c, r_c) in r.chunks_exact_mut(rows).enumerate() {
            for (i, r_i) in r_c.chunks_exact_mut(d).enumerate() {
                let back: [C64; STAGES / 2] =
                    std::array::from_fn(|pair| t.eigenvectors[(i, 2 * pair)]);
                for (e, r_e) in r_i.iter_mut().enumerate() {
                    let mut sum = 0.0;
                    for (v, w) in back.iter().zip(&self.scratch) {
                        sum += 2.0 * (v * w[c * d + e]).re;
                    }
                    *r_e = sum;
                }
            }
        }
        r.iter().all(|v| v.is_finite())
    }
}
