//! Eigenvalues of a real square matrix without its Schur vectors: reduction
//! to upper Hessenberg form by elimination with pivoting, then Francis's
//! double-shift QR iteration on the active block only (the classic EISPACK
//! `elmhes` and `hqr`). For a long chain's undamped pencil this is a few
//! times faster than a general Schur decomposition, which also builds the
//! vectors' reflectors and guards every 3-vector norm against overflow.
//! nalgebra's eigenvalue routine is not used here: it is that general
//! decomposition (`Schur`, the vectors accumulated) and, without
//! exceptional shifts, it stalls on a long chain's many imaginary pairs.

use crate::analysis::C64;

/// Iterations allowed per eigenvalue before giving up (EISPACK's limit).
const MAX_ITERATIONS_PER_EIGENVALUE: usize = 30;

/// A dense square matrix, row-major, indexed `(row, column)`.
struct Square {
    n: usize,
    entries: Vec<f64>,
}

impl std::ops::Index<(usize, usize)> for Square {
    type Output = f64;
    fn index(&self, (i, j): (usize, usize)) -> &f64 {
        &self.entries[i * self.n + j]
    }
}

impl std::ops::IndexMut<(usize, usize)> for Square {
    fn index_mut(&mut self, (i, j): (usize, usize)) -> &mut f64 {
        &mut self.entries[i * self.n + j]
    }
}

/// The eigenvalues of the `n` x `n` matrix whose entry `(i, j)` is
/// `entry(i, j)`, or `None` when the QR iteration does not converge (or the
/// matrix holds a non-finite entry).
pub(crate) fn eigenvalues(n: usize, entry: impl Fn(usize, usize) -> f64) -> Option<Vec<C64>> {
    let mut columns = Vec::with_capacity(n * n);
    for j in 0..n {
        columns.extend((0..n).map(|i| entry(i, j)));
    }
    if !columns.iter().all(|v| v.is_finite()) {
        return None;
    }
    to_hessenberg(n, &mut columns);
    let mut entries = Vec::with_capacity(n * n);
    for i in 0..n {
        entries.extend(columns.iter().skip(i).step_by(n));
    }
    hessenberg_eigenvalues(&mut Square { n, entries })
}

/// Reduces the `n` x `n` matrix `a`, stored column by column, to upper
/// Hessenberg form by Gaussian elimination with partial pivoting
/// (similarity transformations), zeroing what lies below the subdiagonal.
///
/// Each elimination `m` subtracts multiples of row `m` from the rows below
/// it and adds the same multiples of their columns to column `m`, one row
/// `i` after another. The row operations are applied here a column at a
/// time (contiguous, so vectorized) at the moment the column is read: rows
/// up to `i` before column `i` is added to column `m`, the rest after.
/// Every entry therefore receives the same operations in the same order as
/// in EISPACK's `elmhes`, so the result is the same to the last bit.
fn to_hessenberg(n: usize, a: &mut [f64]) {
    let mut multipliers = vec![0.0; n];
    for m in 1..n.saturating_sub(1) {
        // The pivot: the largest entry of column m - 1 at or below row m.
        let mut pivot = 0.0_f64;
        let mut row = m;
        for (j, &v) in a[(m - 1) * n..m * n].iter().enumerate().skip(m) {
            if v.abs() > pivot.abs() {
                pivot = v;
                row = j;
            }
        }
        if row != m {
            for j in m - 1..n {
                a.swap(j * n + row, j * n + m);
            }
            let (left, right) = a.split_at_mut(row * n);
            left[m * n..(m + 1) * n].swap_with_slice(&mut right[..n]);
        }
        if pivot == 0.0 {
            continue;
        }
        // The multiplier of each row below m (zero: the row is left alone).
        multipliers.fill(0.0);
        for (y, &v) in multipliers
            .iter_mut()
            .zip(&a[(m - 1) * n..m * n])
            .skip(m + 1)
        {
            *y = v / pivot;
        }
        let y = &multipliers;
        for i in m + 1..n {
            let (left, right) = a.split_at_mut(i * n);
            let (before_m, from_m) = left.split_at_mut(m * n);
            let (column_m, column_i) = (&mut from_m[..n], &mut right[..n]);
            // Row m's entry in column i: what the rows below m subtract.
            let from = column_i[m];
            // Rows m + 1..=i of column i, before it is read.
            subtract_rows(&mut column_i[m + 1..=i], &y[m + 1..=i], from);
            let y_i = y[i];
            if y_i != 0.0 {
                before_m[(m - 1) * n + i] = 0.0;
                // Row i's entry in column m, against row m's so far.
                column_m[i] -= y_i * column_m[m];
                // Column m += y_i column i.
                for (to, &v) in column_m.iter_mut().zip(column_i.iter()) {
                    *to += y_i * v;
                }
            }
            // The rows below i, once column i has been read.
            subtract_rows(&mut column_i[i + 1..], &y[i + 1..], from);
        }
    }
}

/// `v_r -= y_r from` for each `r` whose multiplier `y_r` is not zero (a
/// zero multiplier leaves the entry exactly as it is, its zero's sign too).
fn subtract_rows(column: &mut [f64], multipliers: &[f64], from: f64) {
    for (v, &y) in column.iter_mut().zip(multipliers) {
        let updated = *v - y * from;
        *v = if y == 0.0 { *v } else { updated };
    }
}

/// The eigenvalues of the upper Hessenberg matrix `a` (destroyed) by the
/// double-shift QR iteration, with exceptional shifts after 10 and 20
/// iterations on one eigenvalue; `None` after 30.
#[expect(
    clippy::many_single_char_names,
    reason = "the algorithm's own names (EISPACK's hqr), kept to be checked against it"
)]
#[expect(
    clippy::too_many_lines,
    reason = "one iteration: deflation, shifts and the bulge chase share its state"
)]
fn hessenberg_eigenvalues(a: &mut Square) -> Option<Vec<C64>> {
    let n = a.n;
    let mut found = vec![C64::new(0.0, 0.0); n];
    let mut norm = 0.0;
    for i in 0..n {
        for j in i.saturating_sub(1)..n {
            norm += a[(i, j)].abs();
        }
    }
    // The active block is rows and columns l..=last (0-based).
    let mut remaining = n;
    let mut shift = 0.0;
    while remaining > 0 {
        let last = remaining - 1;
        let mut iterations = 0;
        loop {
            // Look for a negligible subdiagonal entry.
            let mut l = last;
            while l > 0 {
                let mut s = a[(l - 1, l - 1)].abs() + a[(l, l)].abs();
                if s == 0.0 {
                    s = norm;
                }
                if a[(l, l - 1)].abs() + s == s {
                    a[(l, l - 1)] = 0.0;
                    break;
                }
                l -= 1;
            }
            let mut x = a[(last, last)];
            if l == last {
                // One root found.
                found[last] = C64::new(x + shift, 0.0);
                remaining -= 1;
                break;
            }
            let mut y = a[(last - 1, last - 1)];
            let mut w = a[(last, last - 1)] * a[(last - 1, last)];
            if l + 1 == last {
                // Two roots found.
                let p = 0.5 * (y - x);
                let q = p * p + w;
                let z = q.abs().sqrt();
                x += shift;
                if q >= 0.0 {
                    let z = p + z.copysign(p);
                    let second = if z == 0.0 { x + z } else { x - w / z };
                    found[last - 1] = C64::new(x + z, 0.0);
                    found[last] = C64::new(second, 0.0);
                } else {
                    found[last - 1] = C64::new(x + p, -z);
                    found[last] = C64::new(x + p, z);
                }
                remaining -= 2;
                break;
            }
            if iterations == MAX_ITERATIONS_PER_EIGENVALUE {
                return None;
            }
            if iterations == 10 || iterations == 20 {
                // An exceptional shift.
                shift += x;
                for i in 0..=last {
                    a[(i, i)] -= x;
                }
                let s = a[(last, last - 1)].abs() + a[(last - 1, last - 2)].abs();
                x = 0.75 * s;
                y = x;
                w = -0.4375 * s * s;
            }
            iterations += 1;
            // Two consecutive small subdiagonal entries: where the bulge starts.
            let mut m = last - 2;
            let (mut p, mut q, mut r);
            loop {
                let z = a[(m, m)];
                let r0 = x - z;
                let s0 = y - z;
                p = (r0 * s0 - w) / a[(m + 1, m)] + a[(m, m + 1)];
                q = a[(m + 1, m + 1)] - z - r0 - s0;
                r = a[(m + 2, m + 1)];
                let s = p.abs() + q.abs() + r.abs();
                p /= s;
                q /= s;
                r /= s;
                if m == l {
                    break;
                }
                let u = a[(m, m - 1)].abs() * (q.abs() + r.abs());
                let v = p.abs() * (a[(m - 1, m - 1)].abs() + z.abs() + a[(m + 1, m + 1)].abs());
                if u + v == v {
                    break;
                }
                m -= 1;
            }
            for i in m + 2..=last {
                a[(i, i - 2)] = 0.0;
                if i != m + 2 {
                    a[(i, i - 3)] = 0.0;
                }
            }
            // The double QR step on rows l..=last and columns m..=last.
            for k in m..last {
                if k != m {
                    p = a[(k, k - 1)];
                    q = a[(k + 1, k - 1)];
                    r = if k + 1 == last {
                        0.0
                    } else {
                        a[(k + 2, k - 1)]
                    };
                    x = p.abs() + q.abs() + r.abs();
                    if x != 0.0 {
                        p /= x;
                        q /= x;
                        r /= x;
                    }
                }
                let s = (p * p + q * q + r * r).sqrt().copysign(p);
                if s == 0.0 {
                    continue;
                }
                if k == m {
                    if l != m {
                        a[(k, k - 1)] = -a[(k, k - 1)];
                    }
                } else {
                    a[(k, k - 1)] = -s * x;
                }
                p += s;
                x = p / s;
                y = q / s;
                let z = r / s;
                q /= p;
                r /= p;
                // Rows k, k + 1 (and k + 2), columns k..=last.
                let (upper, lower) = a.entries.split_at_mut((k + 1) * n);
                let row_0 = &mut upper[k * n + k..=k * n + last];
                if k + 1 == last {
                    for (a0, a1) in row_0.iter_mut().zip(&mut lower[k..=last]) {
                        let h = *a0 + q * *a1;
                        *a1 -= h * y;
                        *a0 -= h * x;
                    }
                } else {
                    let (row_1, row_2) = lower.split_at_mut(n);
                    let rows_12 = row_1[k..=last].iter_mut().zip(&mut row_2[k..=last]);
                    for (a0, (a1, a2)) in row_0.iter_mut().zip(rows_12) {
                        let h = *a0 + q * *a1 + r * *a2;
                        *a2 -= h * z;
                        *a1 -= h * y;
                        *a0 -= h * x;
                    }
                }
                // Columns k, k + 1 (and k + 2), rows l..=min(last, k + 3).
                for row in a
                    .entries
                    .chunks_exact_mut(n)
                    .take(last.min(k + 3) + 1)
                    .skip(l)
                {
                    if k + 1 == last {
                        let h = x * row[k] + y * row[k + 1];
                        row[k + 1] -= h * q;
                        row[k] -= h;
                    } else {
                        let h = x * row[k] + y * row[k + 1] + z * row[k + 2];
                        row[k + 2] -= h * r;
                        row[k + 1] -= h * q;
                        row[k] -= h;
                    }
                }
            }
        }
    }
    found
        .iter()
        .all(|z| z.re.is_finite() && z.im.is_finite())
        .then_some(found)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A companion matrix's eigenvalues are its polynomial's roots: real,
    /// complex pairs and a repeated pair of moduli (the case that stalls
    /// shifts without exceptional ones).
    #[test]
    fn a_companion_matrix_gives_its_polynomial_s_roots() {
        // (x - 1)(x + 2)(x^2 + 1)(x^2 + 4)(x^2 - 2x + 5)
        let roots = [
            C64::new(1.0, 0.0),
            C64::new(-2.0, 0.0),
            C64::new(0.0, 1.0),
            C64::new(0.0, -1.0),
            C64::new(0.0, 2.0),
            C64::new(0.0, -2.0),
            C64::new(1.0, 2.0),
            C64::new(1.0, -2.0),
        ];
        let mut coeffs = vec![C64::new(1.0, 0.0)];
        for &r in &roots {
            let mut next = vec![C64::new(0.0, 0.0); coeffs.len() + 1];
            for (k, &c) in coeffs.iter().enumerate() {
                next[k + 1] += c;
                next[k] -= c * r;
            }
            coeffs = next;
        }
        let n = roots.len();
        // Companion: ones on the subdiagonal, -c_k in the last column.
        let found = eigenvalues(n, |i, j| {
            if j == n - 1 {
                -coeffs[i].re
            } else if i == j + 1 {
                1.0
            } else {
                0.0
            }
        })
        .unwrap();
        assert_eq!(found.len(), n);
        for r in roots {
            let miss = found
                .iter()
                .map(|f| (f - r).norm())
                .fold(f64::INFINITY, f64::min);
            assert!(miss < 1e-12, "{r}: {found:?}");
        }
    }

    /// EISPACK's `elmhes` as written there, a row `i` at a time on a
    /// row-major matrix: what [`to_hessenberg`] must equal bit for bit.
    fn elmhes(n: usize, a: &mut [f64]) {
        for m in 1..n.saturating_sub(1) {
            let (mut pivot, mut row) = (0.0_f64, m);
            for j in m..n {
                if a[j * n + m - 1].abs() > pivot.abs() {
                    pivot = a[j * n + m - 1];
                    row = j;
                }
            }
            if row != m {
                for j in m - 1..n {
                    a.swap(row * n + j, m * n + j);
                }
                for j in 0..n {
                    a.swap(j * n + row, j * n + m);
                }
            }
            if pivot == 0.0 {
                continue;
            }
            for i in m + 1..n {
                let y = a[i * n + m - 1] / pivot;
                if y != 0.0 {
                    a[i * n + m - 1] = 0.0;
                    for j in m..n {
                        a[i * n + j] -= y * a[m * n + j];
                    }
                    for r in 0..n {
                        a[r * n + m] += y * a[r * n + i];
                    }
                }
            }
        }
    }

    /// The reduction column by column gives `elmhes`'s Hessenberg matrix to
    /// the last bit, signs of zeros included: on dense matrices, on ones
    /// with exact zeros below the diagonal (zero multipliers, zero pivots)
    /// and on a 32-rod chain's `M^-1 K` at loads past its flutter.
    #[test]
    fn the_reduction_is_elmhes_to_the_last_bit() {
        let mut model = crate::model::PresetId::UniformRods.model();
        model.column.rods = 32;
        let pencil = crate::analysis::AffinePencil::new(&model).unwrap();
        // Each case: its order and its entries, row by row.
        let mut cases: Vec<(usize, Vec<f64>)> = Vec::new();
        let rows_of = |n: usize, entry: &dyn Fn(usize, usize) -> f64| {
            (n, (0..n * n).map(|k| entry(k / n, k % n)).collect())
        };
        for n in [1, 2, 3, 7, 12, 33] {
            #[expect(clippy::cast_precision_loss, reason = "small indices")]
            cases.push(rows_of(n, &|i, j| {
                ((1.7 * i as f64 + 0.3 * (j * j) as f64).sin() - 0.25).max(-0.5)
            }));
            // Sparse: zeros below the diagonal, some negative.
            cases.push(rows_of(n, &|i, j| match (i + 2 * j) % 5 {
                0 => 0.0,
                1 => -0.0,
                k => f64::from(u8::try_from(k).unwrap()) - 2.5,
            }));
        }
        for p in [0.0, 3.0, 12.0, 40.0] {
            let lin = pencil.at(p);
            let a = lin.mass.clone().cholesky().unwrap().solve(&lin.stiffness);
            cases.push(rows_of(a.nrows(), &|i, j| a[(i, j)]));
        }
        for (n, mut rows) in cases {
            let mut columns: Vec<f64> = (0..n * n).map(|k| rows[(k % n) * n + k / n]).collect();
            elmhes(n, &mut rows);
            to_hessenberg(n, &mut columns);
            for i in 0..n {
                for j in 0..n {
                    assert_eq!(
                        rows[i * n + j].to_bits(),
                        columns[j * n + i].to_bits(),
                        "n = {n}, entry ({i}, {j})"
                    );
                }
            }
        }
    }

    /// A random-looking dense matrix: the eigenvalues' sum is the trace and
    /// their product the determinant (by elimination), to rounding.
    #[test]
    fn eigenvalues_keep_the_trace_and_the_determinant() {
        let n = 12;
        let entry = |i: usize, j: usize| {
            #[expect(clippy::cast_precision_loss, reason = "small indices")]
            let (x, y) = (i as f64, j as f64);
            (1.7 * x + 0.3 * y * y).sin() + if i == j { 2.0 } else { 0.0 }
        };
        let found = eigenvalues(n, entry).unwrap();
        let trace: f64 = (0..n).map(|i| entry(i, i)).sum();
        let sum: C64 = found.iter().sum();
        assert!((sum - trace).norm() < 1e-12 * trace.abs().max(1.0));
        let product: C64 = found.iter().product();
        let m = nalgebra::DMatrix::from_fn(n, n, entry);
        let det = m.determinant();
        assert!(
            (product - det).norm() < 1e-10 * det.abs(),
            "{product} vs {det}"
        );
    }
}
