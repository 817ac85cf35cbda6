//! A small complex system factored once by faer (`P M = L U`) and solved
//! for one right-hand side at a time by plain vector loops: the stage
//! iterations' solve, where faer's solver (made for many columns) spent
//! more on its setup than on a 32 x 32 system's sweeps.

use faer::linalg::solvers::PartialPivLu;

use crate::analysis::C64;

/// The factors of `P M = L U` with real and imaginary parts apart, by
/// columns, so that the sweeps are loops over contiguous `f64` slices.
pub(super) struct ColumnLu {
    n: usize,
    /// Row `i` of `P b` is `b[forward[i]]`.
    forward: Vec<usize>,
    /// `L` (unit diagonal, strictly below it) and `U` (on and above it),
    /// column-major `n x n`.
    l_re: Vec<f64>,
    l_im: Vec<f64>,
    u_re: Vec<f64>,
    u_im: Vec<f64>,
    /// `1 / U_jj`.
    inverse_diagonal: Vec<C64>,
}

impl ColumnLu {
    /// The same factors as faer's `lu`.
    pub(super) fn new(lu: &PartialPivLu<C64>) -> Self {
        let (l, u) = (lu.L(), lu.U());
        let n = l.nrows();
        Self {
            n,
            forward: lu.P().arrays().0.to_vec(),
            l_re: parts_by_columns(l, |z| z.re),
            l_im: parts_by_columns(l, |z| z.im),
            u_re: parts_by_columns(u, |z| z.re),
            u_im: parts_by_columns(u, |z| z.im),
            inverse_diagonal: (0..n).map(|j| u[(j, j)].inv()).collect(),
        }
    }

    /// The system's size.
    pub(super) fn size(&self) -> usize {
        self.n
    }

    /// `(re, im) <- M^-1 (re, im)` where `(re, im)` holds `b`'s parts
    /// gathered by the pivoting already (see [`Self::gather`]).
    #[expect(
        clippy::inline_always,
        reason = "inlined into pulp's dispatch, whose body is compiled for the vector units"
    )]
    #[inline(always)]
    pub(super) fn sweep(&self, re: &mut [f64], im: &mut [f64]) {
        let n = self.n;
        // L y = P b, by columns of L.
        for j in 0..n {
            let y = C64::new(re[j], im[j]);
            let column = j * n + j + 1..(j + 1) * n;
            let l = (&self.l_re[column.clone()], &self.l_im[column]);
            sub_product((&mut re[j + 1..], &mut im[j + 1..]), l, y);
        }
        // U x = y, by columns of U from the last.
        for j in (0..n).rev() {
            let z = C64::new(re[j], im[j]) * self.inverse_diagonal[j];
            (re[j], im[j]) = (z.re, z.im);
            let column = j * n..j * n + j;
            let u = (&self.u_re[column.clone()], &self.u_im[column]);
            sub_product((&mut re[..j], &mut im[..j]), u, z);
        }
    }

    /// `P b` into `(re, im)`, from `b`'s parts `(b_re, b_im)`.
    #[expect(
        clippy::inline_always,
        reason = "inlined into pulp's dispatch, whose body is compiled for the vector units"
    )]
    #[inline(always)]
    pub(super) fn gather(&self, b_re: &[f64], b_im: &[f64], re: &mut [f64], im: &mut [f64]) {
        for ((x, y), &from) in re.iter_mut().zip(im.iter_mut()).zip(&self.forward) {
            (*x, *y) = (b_re[from], b_im[from]);
        }
    }
}

/// `x -= p z` over vectors given by their parts `(re, im)`, elementwise.
#[expect(
    clippy::inline_always,
    reason = "inlined into pulp's dispatch, whose body is compiled for the vector units"
)]
#[inline(always)]
pub(super) fn sub_product(
    (x_re, x_im): (&mut [f64], &mut [f64]),
    (p_re, p_im): (&[f64], &[f64]),
    z: C64,
) {
    for ((x, y), (p, q)) in x_re
        .iter_mut()
        .zip(x_im.iter_mut())
        .zip(p_re.iter().zip(p_im))
    {
        *x -= p * z.re - q * z.im;
        *y -= p * z.im + q * z.re;
    }
}

/// `part` of each of `m`'s entries, column by column.
pub(super) fn parts_by_columns(m: faer::MatRef<'_, C64>, part: fn(C64) -> f64) -> Vec<f64> {
    let mut out = Vec::with_capacity(m.nrows() * m.ncols());
    for c in 0..m.ncols() {
        out.extend(m.col(c).iter().map(|&z| part(z)));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// On a complex system whose diagonal is small (so that the pivoting
    /// reorders every column), the sweeps solve it: against faer's own
    /// solve and by the residual.
    #[test]
    fn the_sweeps_solve_the_pivoted_system() {
        use faer::linalg::solvers::Solve;
        let n = 9;
        let entry = |r: usize, c: usize| {
            let (r, c) = (
                f64::from(u8::try_from(r).unwrap()),
                f64::from(u8::try_from(c).unwrap()),
            );
            if r == c {
                C64::new(1e-3, -2e-3)
            } else {
                C64::new((1.3 * r + 0.7 * c).sin(), (0.4 * r - 1.1 * c).cos())
            }
        };
        let m = faer::Mat::from_fn(n, n, entry);
        let lu = m.partial_piv_lu();
        assert!(
            lu.P().arrays().0.iter().enumerate().any(|(i, &p)| i != p),
            "the test needs pivoting"
        );
        let b: Vec<C64> = (0..n)
            .map(|k| {
                let k = f64::from(u8::try_from(k).unwrap());
                C64::new(k - 4.0, 0.5 * k)
            })
            .collect();
        let column = ColumnLu::new(&lu);
        let (b_re, b_im): (Vec<f64>, Vec<f64>) = b.iter().map(|z| (z.re, z.im)).unzip();
        let (mut re, mut im) = (vec![0.0; n], vec![0.0; n]);
        column.gather(&b_re, &b_im, &mut re, &mut im);
        column.sweep(&mut re, &mut im);
        let mut reference = faer::Mat::from_fn(n, 1, |r, _| b[r]);
        lu.solve_in_place(reference.as_mut());
        let scale = (0..n).map(|k| reference[(k, 0)].norm()).fold(0.0, f64::max);
        for k in 0..n {
            let off = (C64::new(re[k], im[k]) - reference[(k, 0)]).norm();
            assert!(off < 1e-13 * scale, "{k}: {off}");
        }
        for (r, b_r) in b.iter().enumerate() {
            let row: C64 = (0..n).map(|c| entry(r, c) * C64::new(re[c], im[c])).sum();
            assert!((row - b_r).norm() < 1e-12 * scale, "row {r}");
        }
    }
}
