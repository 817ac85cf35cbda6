//! The mass matrix of a deformed chain, `M(phi)_jk = mu_jk cos(phi_j -
//! phi_k)`, factored and solved in O(N) by its rank-two structure.
//!
//! Off the diagonal `mu_jk = l_j g_k` for `j < k` (see `ChainInertia`), and
//! `cos(phi_j - phi_k) = e_j . e_k` with `e_i = (cos phi_i, sin phi_i)`:
//! `M_jk = u_j . v_k` with `u_j = l_j e_j`, `v_k = g_k e_k`. The Cholesky
//! factor of such a matrix keeps the structure, `L_jk = v_j . w_k` below
//! the diagonal, with
//!
//! ```text
//! L_kk^2 = M_kk - v_k^T P_k v_k,   w_k = (u_k - P_k v_k) / L_kk,
//! P_k = sum_{i<k} w_i w_i^T
//! ```
//!
//! (the same entries as the dense factorization, summed in another order),
//! so the factor is `N` numbers and `N` 2-vectors, and each triangular solve
//! carries one 2-vector along the chain. The dense factorization of a
//! 32-rod chain took `N^3 / 3` operations per evaluation of the equations
//! of motion; this takes about `20 N`.

use super::mass::ChainInertia;

/// The Cholesky factor `L` of a deformed chain's mass matrix, by its
/// generators.
#[derive(Clone, Debug)]
pub struct MassFactor {
    /// `1 / L_kk` (the solves multiply: a division's latency is on the
    /// sweeps' critical path).
    inverse_diagonal: Vec<f64>,
    /// `v_j`: row j's generator, `L_jk = v_j . w_k` for `j > k`.
    rows: Vec<[f64; 2]>,
    /// `w_k`: column k's generator.
    columns: Vec<[f64; 2]>,
}

fn dot(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}

impl MassFactor {
    /// The factor of `inertia`'s matrix deformed to the angles whose
    /// `(sin, cos)` are `trig`. `None` where the matrix is not positive
    /// definite (a pivot not above zero, or not finite).
    #[must_use]
    pub fn new(inertia: &ChainInertia, trig: &[(f64, f64)]) -> Option<Self> {
        let [factor] = Self::new_lanes(inertia, [trig]);
        factor
    }

    /// [`Self::new`] for `L` deformations of the same chain at once, their
    /// operations interleaved, each lane's those of one factorization (so
    /// each factor is the same to the bit): a factorization is a chain of
    /// dependent square roots and divisions, and `L` of them side by side
    /// keep the CPU busy while each waits.
    #[must_use]
    pub fn new_lanes<const L: usize>(
        inertia: &ChainInertia,
        trigs: [&[(f64, f64)]; L],
    ) -> [Option<Self>; L] {
        let n = inertia.diagonal_kg_m2.len();
        let mut factors: [Self; L] = std::array::from_fn(|_| Self {
            inverse_diagonal: Vec::with_capacity(n),
            rows: Vec::with_capacity(n),
            columns: Vec::with_capacity(n),
        });
        // Each lane's P = sum of w_i w_i^T so far: (xx, xy, yy).
        let mut p = [[0.0; 3]; L];
        let mut positive = [true; L];
        let generators = (inertia.lever_m.iter())
            .zip(&inertia.moment_kg_m)
            .zip(&inertia.diagonal_kg_m2);
        for (k, ((&lever, &moment), &diagonal_kg_m2)) in generators.enumerate() {
            for lane in 0..L {
                let (sin, cos) = trigs[lane][k];
                let [pxx, pxy, pyy] = p[lane];
                let v = [moment * cos, moment * sin];
                let pv = [pxx * v[0] + pxy * v[1], pxy * v[0] + pyy * v[1]];
                let pivot = diagonal_kg_m2 - dot(v, pv);
                positive[lane] &= pivot > 0.0 && pivot.is_finite();
                let inverse = pivot.sqrt().recip();
                let w = [
                    (lever * cos - pv[0]) * inverse,
                    (lever * sin - pv[1]) * inverse,
                ];
                p[lane] = [pxx + w[0] * w[0], pxy + w[0] * w[1], pyy + w[1] * w[1]];
                let factor = &mut factors[lane];
                factor.inverse_diagonal.push(inverse);
                factor.rows.push(v);
                factor.columns.push(w);
            }
        }
        let mut factors = factors.into_iter();
        std::array::from_fn(|lane| factors.next().filter(|_| positive[lane]))
    }

    /// Solves `M a = b` in place (`b` of the chain's length).
    pub fn solve_in_place(&self, b: &mut [f64]) {
        Self::solve_lanes([Some(self)], &mut [b]);
    }

    /// [`Self::solve_in_place`] for `L` factors and right sides at once,
    /// interleaved as in [`Self::new_lanes`] (each lane to the bit as
    /// alone); a lane without a factor is left as it is.
    #[expect(
        clippy::needless_range_loop,
        reason = "every lane is taken at the same row"
    )]
    pub fn solve_lanes<const L: usize>(factors: [Option<&Self>; L], bs: &mut [&mut [f64]; L]) {
        let n = bs.first().map_or(0, |b| b.len());
        // L y = b, carrying s = sum_{k<j} w_k y_k.
        let mut carried = [[0.0; 2]; L];
        for j in 0..n {
            for lane in 0..L {
                let Some(factor) = factors[lane] else {
                    continue;
                };
                let value = &mut bs[lane][j];
                let y = (*value - dot(factor.rows[j], carried[lane])) * factor.inverse_diagonal[j];
                *value = y;
                carried[lane][0] += factor.columns[j][0] * y;
                carried[lane][1] += factor.columns[j][1] * y;
            }
        }
        // L^T a = y, carrying t = sum_{j>k} v_j a_j.
        let mut carried = [[0.0; 2]; L];
        for k in (0..n).rev() {
            for lane in 0..L {
                let Some(factor) = factors[lane] else {
                    continue;
                };
                let value = &mut bs[lane][k];
                let a =
                    (*value - dot(factor.columns[k], carried[lane])) * factor.inverse_diagonal[k];
                *value = a;
                carried[lane][0] += factor.rows[k][0] * a;
                carried[lane][1] += factor.rows[k][1] * a;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::PresetId;
    use crate::model::mass::chain_inertia;
    use nalgebra::{DMatrix, DVector};

    /// The deformed mass matrix written out entry by entry.
    fn dense(inertia: &ChainInertia, phi: &[f64]) -> DMatrix<f64> {
        let mu = inertia.matrix();
        DMatrix::from_fn(phi.len(), phi.len(), |j, k| {
            mu[(j, k)] * (phi[j] - phi[k]).cos()
        })
    }

    /// On chains of 3 to 32 rods with a tip mass, a heavier second rod and
    /// the roller's yaw inertia, at large scattered angles: the solve agrees
    /// with the dense Cholesky solve to rounding, and the factor's product
    /// is the dense matrix.
    #[test]
    fn the_structured_solve_is_the_dense_one() {
        for (preset, rods) in [
            (PresetId::UniformRods, 3),
            (PresetId::UniformRods, 32),
            (PresetId::Roller, 7),
        ] {
            let mut model = preset.model();
            model.column.rods = rods;
            model.column.tip_mass_kg = 0.3;
            model.column.rod2.mass_kg *= 1.7;
            let inertia = chain_inertia(&model);
            #[expect(clippy::cast_precision_loss, reason = "a few rods")]
            let phi: Vec<f64> = (0..rods)
                .map(|i| 2.5 * (1.3 * i as f64 + 0.4).sin())
                .collect();
            let trig: Vec<(f64, f64)> = phi.iter().map(|a| a.sin_cos()).collect();
            let factor = MassFactor::new(&inertia, &trig).expect("positive definite");
            let m = dense(&inertia, &phi);
            #[expect(clippy::cast_precision_loss, reason = "a few rods")]
            let b = DVector::from_fn(rods, |i, _| (0.9 * i as f64).cos() - 0.2);
            let mut a = b.clone();
            factor.solve_in_place(a.as_mut_slice());
            let reference = m.clone().cholesky().expect("positive definite").solve(&b);
            let off = (&a - &reference).amax();
            assert!(off < 1e-12 * reference.amax(), "{rods} rods: {off}");
            let residual = (&m * &a - &b).amax();
            assert!(residual < 1e-12 * b.amax() * m.amax(), "{residual}");
            let lower = DMatrix::from_fn(rods, rods, |j, k| match j.cmp(&k) {
                std::cmp::Ordering::Less => 0.0,
                std::cmp::Ordering::Equal => factor.inverse_diagonal[j].recip(),
                std::cmp::Ordering::Greater => dot(factor.rows[j], factor.columns[k]),
            });
            let product = (&lower * lower.transpose() - &m).amax();
            assert!(product < 1e-13 * m.amax(), "{product}");
        }
    }

    /// Factors and solves side by side are each the same to the bit as
    /// alone, and a lane whose matrix has no factor leaves the others be.
    #[test]
    fn lanes_are_each_the_same_as_alone() {
        let mut model = PresetId::Roller.model();
        model.column.rods = 9;
        let inertia = chain_inertia(&model);
        let trigs: Vec<Vec<(f64, f64)>> = (0..3)
            .map(|lane| {
                (0..9)
                    .map(|i| {
                        (1.7 * (0.9 * f64::from(i) + f64::from(lane)))
                            .sin()
                            .sin_cos()
                    })
                    .collect()
            })
            .collect();
        #[expect(clippy::cast_precision_loss, reason = "a few rods")]
        let rhs =
            |lane: usize| -> Vec<f64> { (0..9).map(|i| (0.4 * (i + lane) as f64).cos()).collect() };
        let lanes = MassFactor::new_lanes(&inertia, [&trigs[0], &trigs[1], &trigs[2]]);
        let factors: Vec<&MassFactor> = lanes
            .iter()
            .map(|f| f.as_ref().expect("a factor"))
            .collect();
        let (mut b0, mut b1, mut b2) = (rhs(0), rhs(1), rhs(2));
        MassFactor::solve_lanes(
            [Some(factors[0]), Some(factors[1]), Some(factors[2])],
            &mut [&mut b0, &mut b1, &mut b2],
        );
        for (lane, solved) in [b0, b1, b2].iter().enumerate() {
            let mut alone = rhs(lane);
            MassFactor::new(&inertia, &trigs[lane])
                .expect("a factor")
                .solve_in_place(&mut alone);
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(solved), bits(&alone), "lane {lane}");
        }
        // A lane at an angle that is not a number has no factor; the
        // other's is its own, and solved beside the empty lane, which is
        // left as it was, it is the same as alone.
        let mut broken = trigs[1].clone();
        broken[4] = (f64::NAN, f64::NAN);
        let [first, second] = MassFactor::new_lanes(&inertia, [&trigs[0], &broken]);
        assert!(second.is_none());
        let (mut with, mut untouched, mut alone) = (rhs(0), rhs(1), rhs(0));
        MassFactor::solve_lanes(
            [first.as_ref(), second.as_ref()],
            &mut [&mut with, &mut untouched],
        );
        factors[0].solve_in_place(&mut alone);
        assert_eq!(with, alone);
        assert_eq!(untouched, rhs(1));
    }

    /// A matrix that is not positive definite has no factor: a pivot of
    /// zero, or not a number.
    #[test]
    fn a_singular_matrix_has_no_factor() {
        let mut model = PresetId::UniformRods.model();
        model.column.rods = 4;
        let mut inertia = chain_inertia(&model);
        inertia.diagonal_kg_m2[2] = 0.0;
        let trig = vec![(0.0, 1.0); 4];
        assert!(MassFactor::new(&inertia, &trig).is_none());
        inertia.diagonal_kg_m2[2] = f64::NAN;
        assert!(MassFactor::new(&inertia, &trig).is_none());
    }
}
