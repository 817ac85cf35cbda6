//! The Gauss-Legendre method of four stages (implicit Runge-Kutta of
//! order 8: collocation at the Gauss points, as AUTO's periodic orbits
//! are built on) for the flow of a [`Field`], with the derivative of each
//! step for the monodromy matrix.
//!
//! Why an implicit method: a chain's fastest modes are far faster than its
//! flutter (their rates grow like the square of the number of rods), and an
//! explicit method must step at their pace to stay stable. Gauss-Legendre is
//! A-stable and maps the imaginary axis onto the unit circle (its
//! stability function is the diagonal Pade approximant of `exp`): a step of
//! any size keeps every decaying linear mode decaying and every undamped one
//! neither growing nor decaying, so a multiplier's side of the unit circle
//! is the equations', not the step's. The step is then set by the flutter's
//! accuracy alone, and the order 8 lets a period take a hundred steps where
//! the order 4 took eight hundred.
//!
//! Each step solves its stage equations `K_i = f(x + h sum_j a_ij K_j)` by
//! Newton's method with the field's Jacobian at the step's start, its
//! matrix `I - h (A ⊗ J)` split by `A`'s eigenvalues into two complex
//! systems of the state's size, or of half of it for a column's state of
//! angles and rates (see [`SplitStages`]); the monodromy is
//! carried by the derivative of the step, `dK_i = J_i (dx + h sum_j a_ij
//! dK_j)`, with `J_i` at the stages (the exact derivative of the computed
//! flow) or `J` at the start held over them (cheaper, for Newton's
//! iterations of the shooting). Pure: no UI, no clock.

use nalgebra::{DMatrix, DVector};

use super::split_stages::SplitStages;
use super::tableau::{GAUSS, STAGES};
use crate::analysis::field::Field;

/// How much of the flow's derivative (the monodromy) a step carries.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Monodromy {
    /// None: the end point only.
    None,
    /// The field's Jacobian at both stages (in closed form or by
    /// extrapolated differences, [`Field::jacobian_extrapolated`]): the
    /// exact derivative of the computed flow, for Newton's method proper.
    Exact,
    /// The same for a flow whose end point no Newton iteration compares
    /// (a converged cycle's multipliers): its stage iterations may take
    /// their Newton matrix in closed form too, which is cheaper.
    Multipliers,
    /// The Jacobian at the step's start held over its stages: off by the
    /// step's change of the Jacobian, which slows Newton's convergence from
    /// quadratic to fast linear but not where it ends.
    HeldPerStep,
}

/// The stage iterations are done when their change of the step is within
/// this many units in the last place of the state and the step's
/// increments (a step's stages were seen to stall at 5 to 15 of them).
const ROUNDING_ULPS: f64 = 16.0;
/// Most Newton iterations of one step's stage equations.
const STAGE_ITERATIONS: usize = 12;
/// Most iterations with the last step's Jacobian before it is taken afresh,
/// plus one for every `2 * STAGES` entries of the state: a kept iteration
/// costs `STAGES` evaluations of the field, a fresh Jacobian (by
/// differences) as many as the state has entries, and its factorization.
const KEPT_JACOBIAN_ITERATIONS: usize = 4;
/// Difference step of the Jacobians.
const JACOBIAN_STEP: f64 = 1e-7;

/// Steps of one field with a fixed step, keeping the last stages to start
/// the next step's Newton iterations from, and the last Jacobian.
pub struct Stepper<'a> {
    field: &'a Field,
    h: f64,
    /// The last step's stage derivatives `K_1 .. K_s`, stacked.
    stages: Option<DVector<f64>>,
    /// The Jacobian the last step was solved with and its stage matrix,
    /// factored.
    newton: Option<(DMatrix<f64>, SplitStages)>,
    /// Room for the stage points and the field there, reused by every
    /// iteration.
    points: [DVector<f64>; STAGES],
    at_points: [DVector<f64>; STAGES],
}

impl<'a> Stepper<'a> {
    #[must_use]
    pub fn new(field: &'a Field, h: f64) -> Self {
        let d = field.dimension();
        Self {
            field,
            h,
            stages: None,
            newton: None,
            points: std::array::from_fn(|_| DVector::zeros(d)),
            at_points: std::array::from_fn(|_| DVector::zeros(d)),
        }
    }

    /// The step, s.
    #[must_use]
    pub fn step_secs(&self) -> f64 {
        self.h
    }

    /// Advances `x` by one step and, when given, the monodromy `y` by the
    /// step's derivative. A step without the monodromy keeps the last
    /// step's Jacobian while its Newton iterations converge quickly with it
    /// (the Jacobian changes little from one step to the next); a step with
    /// it takes the Jacobian afresh. `None` where the stage equations do
    /// not converge or the field is not finite (the state is then left
    /// unchanged).
    pub fn step(
        &mut self,
        x: &mut DVector<f64>,
        y: Option<&mut DMatrix<f64>>,
        monodromy: Monodromy,
    ) -> Option<()> {
        let (h, d, t) = (self.h, x.len(), &*GAUSS);
        // With the kept matrix first where no monodromy is asked; where it
        // does not converge within a few iterations, on from where it got
        // (if anywhere) with the matrix anew.
        let mut k = self.first_guess(x);
        let kept = monodromy == Monodromy::None && {
            let mut tried = k.clone();
            let most = KEPT_JACOBIAN_ITERATIONS + d / (2 * STAGES);
            match self.solve_stages(x, &mut tried, most, false) {
                Some(converged) => {
                    k = tried;
                    converged
                }
                None => false,
            }
        };
        if !kept {
            // Newton's matrix for the stages only: where they converge
            // does not depend on its accuracy, but how the iterations end
            // does, and with it the flow's rounding: by differences, with
            // which the shooting's tolerances were set (see
            // `Field::jacobian_one_sided`).
            let jacobian = match monodromy {
                Monodromy::Exact => self.field.central_differences(x, JACOBIAN_STEP),
                Monodromy::Multipliers => self.field.jacobian(x, JACOBIAN_STEP),
                Monodromy::None | Monodromy::HeldPerStep => {
                    self.field.jacobian_one_sided(x, JACOBIAN_STEP)
                }
            };
            let split = SplitStages::new(&jacobian, h, self.field.mechanical());
            self.newton = Some((jacobian, split));
            if self.solve_stages(x, &mut k, STAGE_ITERATIONS, true) != Some(true) {
                return None;
            }
        }
        if let Some(y) = y {
            let dk = match (monodromy, &mut self.newton) {
                (Monodromy::Exact | Monodromy::Multipliers, _) => {
                    let jacobians: [DMatrix<f64>; STAGES] = std::array::from_fn(|i| {
                        stage_point_into(x, &k, h, i, &mut self.points[i]);
                        self.field
                            .jacobian_extrapolated(&self.points[i], JACOBIAN_STEP)
                    });
                    stage_derivatives(&jacobians.each_ref(), y, h, self.field.mechanical())?
                }
                (Monodromy::HeldPerStep | Monodromy::None, Some((jacobian, split))) => {
                    let jy = &*jacobian * &*y;
                    let mut dk = DMatrix::zeros(STAGES * d, d);
                    for i in 0..STAGES {
                        dk.rows_mut(i * d, d).copy_from(&jy);
                    }
                    if !split.solve_columns_mut(dk.as_mut_slice(), d) {
                        return None;
                    }
                    dk
                }
                (_, None) => return None,
            };
            for (j, b) in t.b.iter().enumerate() {
                y.zip_apply(&dk.rows(j * d, d), |y, dk| *y += dk * (h * b));
            }
        }
        for (j, b) in t.b.iter().enumerate() {
            x.axpy(h * b, &k.rows(j * d, d), 1.0);
        }
        self.stages = Some(k);
        Some(())
    }

    /// Newton's iterations on the stage derivatives `k` of the step from
    /// `x`, at most `iterations` of them with the kept stage matrix:
    /// `Some(true)` where they converge to a few units in the state's last
    /// place, or, where `fresh` (the matrix is this step's own, so that the
    /// iterations contract fast), until they stop shrinking near that;
    /// `Some(false)` where they have not within the iterations, `None` where
    /// there is no matrix or the iterations leave the finite numbers. A
    /// kept matrix contracts more slowly: stopping where it stalls would
    /// leave an error that varies from one flow to the next and stalls
    /// Newton's iterations of the shooting.
    fn solve_stages(
        &mut self,
        x: &DVector<f64>,
        k: &mut DVector<f64>,
        iterations: usize,
        fresh: bool,
    ) -> Option<bool> {
        self.newton.as_ref()?;
        let mut change = DVector::zeros(k.len());
        let scale = x.amax().max(f64::MIN_POSITIVE);
        let mut last_change = f64::INFINITY;
        for _ in 0..iterations {
            self.residual(x, k, &mut change);
            let (_, split) = self.newton.as_mut()?;
            if !split.solve_mut(change.as_mut_slice()) {
                return None;
            }
            *k -= &change;
            let size = self.h * change.amax();
            if !size.is_finite() {
                return None;
            }
            // Done at rounding: within a few units in the last place of the
            // state and of the step's increments, or no longer shrinking
            // near that.
            let floor = ROUNDING_ULPS * f64::EPSILON * (scale + self.h * k.amax());
            let stalled = fresh && size <= 100.0 * floor && size > 0.5 * last_change;
            if size <= floor || stalled {
                return Some(true);
            }
            last_change = size;
        }
        Some(false)
    }

    /// The stage derivatives to start from: the last step's, extrapolated
    /// by the polynomial through them to this step's stage times; at the
    /// first step, the field at the start.
    fn first_guess(&self, x: &DVector<f64>) -> DVector<f64> {
        let d = x.len();
        let mut guess = DVector::zeros(STAGES * d);
        if let Some(last) = &self.stages {
            for (i, weights) in GAUSS.next.iter().enumerate() {
                let mut stage = guess.rows_mut(i * d, d);
                for (j, &w) in weights.iter().enumerate() {
                    stage.axpy(w, &last.rows(j * d, d), 1.0);
                }
            }
        } else {
            let f = self.field.at(x);
            for i in 0..STAGES {
                guess.rows_mut(i * d, d).copy_from(&f);
            }
        }
        guess
    }

    /// The stage equations' residual `K_i - f(x + h sum_j a_ij K_j)`, into
    /// `out`. The stages' fields are evaluated side by side
    /// ([`Field::at_into_each`]).
    fn residual(&mut self, x: &DVector<f64>, k: &DVector<f64>, out: &mut DVector<f64>) {
        let d = x.len();
        for (i, point) in self.points.iter_mut().enumerate() {
            stage_point_into(x, k, self.h, i, point);
        }
        self.field
            .at_into_each(self.points.each_ref(), self.at_points.each_mut());
        for (i, at_point) in self.at_points.iter().enumerate() {
            for r in 0..d {
                out[i * d + r] = k[i * d + r] - at_point[r];
            }
        }
    }
}

/// Stage `i`'s point `x + h sum_j a_ij K_j` (`k` the stacked stages), into
/// `point` (of the state's length).
fn stage_point_into(
    x: &DVector<f64>,
    k: &DVector<f64>,
    h: f64,
    i: usize,
    point: &mut DVector<f64>,
) {
    let d = x.len();
    point.copy_from(x);
    for (j, &a_ij) in GAUSS.a[i].iter().enumerate() {
        point.axpy(h * a_ij, &k.rows(j * d, d), 1.0);
    }
}

/// Solves `matrix x = rhs` in place by faer's LU decomposition with
/// partial pivoting (blocked and vectorized: at four stages of a 16-rod
/// chain the matrix is 128 x 128, and nalgebra's unblocked LU took a
/// fifth of a branch's time); `None` where the solution is not finite
/// (a singular matrix).
fn solve_dense(matrix: &DMatrix<f64>, rhs: &mut DMatrix<f64>) -> Option<()> {
    use faer::linalg::solvers::Solve;
    let n = matrix.nrows();
    let columns = rhs.ncols();
    let lu = faer::MatRef::from_column_major_slice(matrix.as_slice(), n, n).partial_piv_lu();
    lu.solve_in_place(faer::MatMut::from_column_major_slice_mut(
        rhs.as_mut_slice(),
        n,
        columns,
    ));
    rhs.iter().all(|v| v.is_finite()).then_some(())
}

/// The stages' derivatives `dK` (stacked, `s d x d`) of a step from the
/// monodromy `y` so far, with stage `i`'s Jacobian `J_i`: the solution of
/// `dK_i = J_i (y + h sum_j a_ij dK_j)`. For a `mechanical` state `(q,
/// q')` (`J_i = [[0, I], [A_i, B_i]]`, taken so whatever its first half of
/// rows holds) the angles' halves `dU_i = Y' + h sum_j a_ij dV_j` are
/// eliminated (`y = [Y; Y']`), leaving for the rates' halves
///
/// ```text
/// dV_i - h^2 A_i sum_k (a^2)_ik dV_k - h B_i sum_k a_ik dV_k
///     = A_i (Y + h c_i Y') + B_i Y',     c_i = sum_j a_ij,
/// ```
///
/// a system of half the size (an eighth of the work to factor). `None`
/// where the solution is not finite.
fn stage_derivatives(
    jacobians: &[&DMatrix<f64>; STAGES],
    y: &DMatrix<f64>,
    h: f64,
    mechanical: bool,
) -> Option<DMatrix<f64>> {
    let d = y.nrows();
    let mut dk = DMatrix::zeros(STAGES * d, y.ncols());
    if !(mechanical && d.is_multiple_of(2)) {
        for (i, j) in jacobians.iter().enumerate() {
            dk.rows_mut(i * d, d).copy_from(&(*j * y));
        }
        solve_dense(&stage_matrix(jacobians, h), &mut dk)?;
        return Some(dk);
    }
    let (n, a) = (d / 2, &GAUSS.a);
    let a2 = |i: usize, k: usize| (0..STAGES).map(|j| a[i][j] * a[j][k]).sum::<f64>();
    let (upper, lower) = (y.rows(0, n), y.rows(n, n));
    let mut matrix = DMatrix::identity(STAGES * n, STAGES * n);
    let mut dv = DMatrix::zeros(STAGES * n, y.ncols());
    let mut shifted = upper.clone_owned();
    for (i, j) in jacobians.iter().enumerate() {
        let (a_i, b_i) = (j.view((n, 0), (n, n)), j.view((n, n), (n, n)));
        for (k, a_ik) in a[i].iter().enumerate() {
            let (x, z) = (h * h * a2(i, k), h * a_ik);
            matrix
                .view_mut((i * n, k * n), (n, n))
                .zip_zip_apply(&a_i, &b_i, |m, a, b| *m -= a * x + b * z);
        }
        let c_i: f64 = a[i].iter().sum();
        shifted.copy_from(&upper);
        shifted.zip_apply(&lower, |s, l| *s += l * (h * c_i));
        let mut dv_i = dv.rows_mut(i * n, n);
        dv_i.gemm(1.0, &a_i, &shifted, 0.0);
        dv_i.gemm(1.0, &b_i, &lower, 1.0);
    }
    solve_dense(&matrix, &mut dv)?;
    for (i, row) in a.iter().enumerate() {
        dk.rows_mut(i * d + n, n).copy_from(&dv.rows(i * n, n));
        let mut du = dk.rows_mut(i * d, n);
        du.copy_from(&lower);
        for (j, a_ij) in row.iter().enumerate() {
            du.zip_apply(&dv.rows(j * n, n), |u, v| *u += v * (h * a_ij));
        }
    }
    Some(dk)
}

/// `I - h [a_ij J_i]`: the stage equations' matrix with stage `i`'s
/// Jacobian `J_i`.
fn stage_matrix(jacobians: &[&DMatrix<f64>; STAGES], h: f64) -> DMatrix<f64> {
    let d = jacobians[0].nrows();
    let mut m = DMatrix::identity(STAGES * d, STAGES * d);
    for (i, j) in jacobians.iter().enumerate() {
        for (col, a) in GAUSS.a[i].iter().enumerate() {
            let mut block = m.view_mut((i * d, col * d), (d, d));
            block -= *j * (h * a);
        }
    }
    m
}

/// A damped Ziegler column (p = 2.2, joint dampers 0.3) and a start far
/// from rest (angles 0.5 and 0.9 rad): a swing at large amplitude, for the
/// flows' tests.
#[cfg(test)]
pub(in crate::analysis) fn swinging_column() -> (Field, DVector<f64>) {
    let mut model = crate::model::PresetId::Ziegler1952.model().at_load(2.2);
    model.column.c1_nms_per_rad = 0.3;
    model.column.c2_nms_per_rad = 0.3;
    (
        Field::new(&model),
        DVector::from_vec(vec![0.5, 0.9, 0.0, 0.0]),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::PresetId;

    /// `steps` steps over `duration` from `x0`, with the monodromy as asked.
    fn flow(
        field: &Field,
        x0: &DVector<f64>,
        duration: f64,
        steps: u32,
        monodromy: Monodromy,
    ) -> (DVector<f64>, DMatrix<f64>) {
        let mut stepper = Stepper::new(field, duration / f64::from(steps));
        let (mut x, mut y) = (x0.clone(), DMatrix::identity(x0.len(), x0.len()));
        for _ in 0..steps {
            stepper
                .step(&mut x, Some(&mut y), monodromy)
                .expect("a step");
        }
        (x, y)
    }

    /// A damped column swinging at large amplitude: halving the step
    /// divides the error by 2^8 (order 8), and the exact monodromy is the
    /// derivative of the computed flow (against central differences of it).
    #[test]
    fn the_steps_are_of_order_eight_and_the_monodromy_is_their_derivative() {
        let (field, x0) = swinging_column();
        let duration = 10.0;
        let (fine, _) = flow(&field, &x0, duration, 400, Monodromy::None);
        let errors: Vec<f64> = [3, 6, 12]
            .iter()
            .map(|&n| (flow(&field, &x0, duration, n, Monodromy::None).0 - &fine).amax())
            .collect();
        for pair in errors.windows(2) {
            let ratio = pair[0] / pair[1];
            assert!((150.0..400.0).contains(&ratio), "{errors:?}");
        }
        let (_, monodromy) = flow(&field, &x0, duration, 200, Monodromy::Exact);
        let h = 1e-6;
        for j in 0..4 {
            let mut plus = x0.clone();
            plus[j] += h;
            let mut minus = x0.clone();
            minus[j] -= h;
            let column = (flow(&field, &plus, duration, 200, Monodromy::None).0
                - flow(&field, &minus, duration, 200, Monodromy::None).0)
                / (2.0 * h);
            let off = (column - monodromy.column(j)).amax();
            assert!(off < 1e-6 * monodromy.amax(), "column {j}: {off}");
        }
    }

    /// The split solve is the stage matrix's: against a dense solve of
    /// `I - h (A ⊗ J)` for a Jacobian with real and complex eigenvalues,
    /// whole and, for a mechanical state's `J = [[0, I], [A, B]]`, by
    /// halves, for one right-hand side and for several.
    #[test]
    fn the_split_stages_solve_the_stage_matrix() {
        let entry = |r: usize, c: usize| {
            f64::from(u8::try_from((r * 7 + c * 3) % 11).unwrap()) / 3.0 - 1.5
                + if r == c { -2.0 } else { 0.0 }
        };
        let general = DMatrix::from_fn(5, 5, entry);
        let n = 4;
        let mechanical = DMatrix::from_fn(2 * n, 2 * n, |r, c| match (r < n, c < n) {
            (true, true) => 0.0,
            (true, false) => f64::from(u8::from(c - n == r)),
            (false, _) => entry(r, c),
        });
        let h = 0.4;
        for (jacobian, halves) in [(&general, false), (&mechanical, true)] {
            let rows = STAGES * jacobian.nrows();
            for columns in [1, 3] {
                let rhs = DMatrix::from_fn(rows, columns, |i, c| {
                    f64::from(u8::try_from((i * 5 + c * 3) % 13).unwrap()) - 6.0
                });
                let mut split = rhs.clone();
                let mut stages = SplitStages::new(jacobian, h, halves);
                assert!(stages.solve_columns_mut(split.as_mut_slice(), columns));
                let mut dense = rhs.clone();
                solve_dense(&stage_matrix(&[jacobian; STAGES], h), &mut dense).expect("regular");
                let off = (&dense - &split).amax();
                assert!(off < 1e-12 * split.amax(), "{halves} {columns}: {off}");
            }
        }
    }

    /// The stages' derivatives by halves are the dense solve's: four
    /// different mechanical Jacobians `[[0, I], [A_i, B_i]]` and a full
    /// monodromy so far.
    #[test]
    fn the_stage_derivatives_by_halves_are_the_dense_ones() {
        let n = 3;
        let jacobians: [DMatrix<f64>; STAGES] = std::array::from_fn(|stage| {
            DMatrix::from_fn(2 * n, 2 * n, |r, c| match (r < n, c < n) {
                (true, true) => 0.0,
                (true, false) => f64::from(u8::from(c - n == r)),
                (false, _) => {
                    f64::from(u8::try_from((r * 7 + c * 3 + stage * 5) % 11).unwrap()) / 3.0 - 1.5
                }
            })
        });
        let y = DMatrix::from_fn(2 * n, 2 * n, |r, c| {
            f64::from(u8::try_from((r * 5 + c * 2) % 7).unwrap()) / 4.0
                + f64::from(u8::from(r == c))
        });
        let h = 0.3;
        let halves = stage_derivatives(&jacobians.each_ref(), &y, h, true).expect("regular");
        let dense = stage_derivatives(&jacobians.each_ref(), &y, h, false).expect("regular");
        let off = (&halves - &dense).amax();
        assert!(off < 1e-12 * dense.amax(), "{off}");
    }

    /// At rest the flow is linear, and the step maps each undamped mode's
    /// eigenvalue onto the unit circle whatever its size: an undamped
    /// column's monodromy keeps every eigenvalue's modulus 1, with steps
    /// five times longer than its fastest mode's period over 2 pi (where
    /// the classical Runge-Kutta method grows by a factor 21 a step).
    #[test]
    fn an_undamped_mode_neither_grows_nor_decays_at_any_step() {
        let model = PresetId::Ziegler1952.model().at_load(1.0);
        let field = Field::new(&model);
        let rest = DVector::zeros(4);
        let fastest = field
            .jacobian(&rest, 1e-6)
            .complex_eigenvalues()
            .iter()
            .map(|z| z.norm())
            .fold(0.0, f64::max);
        let (_, monodromy) = flow(&field, &rest, 50.0 * 5.0 / fastest, 50, Monodromy::Exact);
        for z in monodromy.complex_eigenvalues().iter() {
            assert!((z.norm() - 1.0).abs() < 1e-9, "{z}");
        }
    }
}
