//! The two-stage Gauss-Legendre method (implicit Runge-Kutta of order 4,
//! the collocation AUTO's periodic orbits are built on) for the flow of a
//! [`Field`], with the derivative of each step for the monodromy matrix.
//!
//! Why an implicit method: a chain's fastest modes are far faster than its
//! flutter (their rates grow like the square of the number of rods), and an
//! explicit method must step at their pace to stay stable. Gauss-Legendre is
//! A-stable and maps the imaginary axis onto the unit circle
//! (`R(z) = (1 + z/2 + z^2/12) / (1 - z/2 + z^2/12)`): a step of any size
//! keeps every decaying linear mode decaying and every undamped one neither
//! growing nor decaying, so a multiplier's side of the unit circle is the
//! equations', not the step's. The step is then set by the flutter's
//! accuracy alone.
//!
//! Each step solves its stage equations `K_i = f(x + h sum_j a_ij K_j)` by
//! Newton's method with the field's Jacobian at the step's start (its
//! matrix `I - h (A ⊗ J)` factored once); the monodromy is carried by the
//! derivative of the step, `dK_i = J_i (dx + h sum_j a_ij dK_j)`, with `J_i`
//! at the stages (the exact derivative of the computed flow) or `J` at the
//! start held over both (cheaper, for Newton's iterations of the shooting).
//! Pure: no UI, no clock.

use nalgebra::allocator::Allocator;
use nalgebra::{DMatrix, DVector, DefaultAllocator, Dim, Dyn, LU, OMatrix};

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

/// `sqrt(3) / 6`.
const S: f64 = 0.288_675_134_594_812_9;
/// The Butcher matrix `A`; the weights are `1/2, 1/2`.
const A: [[f64; 2]; 2] = [[0.25, 0.25 - S], [0.25 + S, 0.25]];
/// Most Newton iterations of one step's stage equations.
const STAGE_ITERATIONS: usize = 12;
/// Most iterations with the last step's Jacobian before it is taken afresh.
const KEPT_JACOBIAN_ITERATIONS: usize = 4;
/// Difference step of the Jacobians.
const JACOBIAN_STEP: f64 = 1e-7;

/// Steps of one field with a fixed step, keeping the last stages to start
/// the next step's Newton iterations from, and the last Jacobian.
pub struct Stepper<'a> {
    field: &'a Field,
    h: f64,
    /// The last step's stage derivatives `K_1, K_2`.
    stages: Option<[DVector<f64>; 2]>,
    /// The Jacobian the last step was solved with and its stage matrix,
    /// factored.
    newton: Option<(DMatrix<f64>, LU<f64, Dyn, Dyn>)>,
    /// Room for a stage point and the field there, reused by every
    /// iteration (the inner loop allocates nothing).
    point: DVector<f64>,
    at_point: DVector<f64>,
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
            point: DVector::zeros(d),
            at_point: DVector::zeros(d),
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
        let (h, d) = (self.h, x.len());
        let kept = if monodromy == Monodromy::None {
            self.solve_stages(x, KEPT_JACOBIAN_ITERATIONS, false)
        } else {
            None
        };
        let k = if let Some(k) = kept {
            k
        } else {
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
            let lu = stage_matrix(&jacobian, &jacobian, h).lu();
            self.newton = Some((jacobian, lu));
            self.solve_stages(x, STAGE_ITERATIONS, true)?
        };
        let (k1, k2) = (k.rows(0, d).into_owned(), k.rows(d, d).into_owned());
        if let Some(y) = y {
            let dk = match (monodromy, &self.newton) {
                (Monodromy::Exact | Monodromy::Multipliers, _) => {
                    let [j1, j2] = [0, 1].map(|i| {
                        self.field
                            .jacobian_extrapolated(&stage_point(x, &k1, &k2, h, i), JACOBIAN_STEP)
                    });
                    let rhs = stack(&(&j1 * &*y), &(&j2 * &*y));
                    stage_matrix(&j1, &j2, h).lu().solve(&rhs)?
                }
                (Monodromy::HeldPerStep | Monodromy::None, Some((jacobian, lu))) => {
                    let jy = jacobian * &*y;
                    lu.solve(&stack(&jy, &jy))?
                }
                (_, None) => return None,
            };
            *y += (dk.rows(0, d) + dk.rows(d, d)) * (h / 2.0);
        }
        *x += (&k1 + &k2) * (h / 2.0);
        self.stages = Some([k1, k2]);
        Some(())
    }

    /// The stage derivatives of the step from `x` by at most `iterations`
    /// of Newton's method with the kept stage matrix, or `None` where they
    /// do not converge within them to a few units in the state's last
    /// place, or, where `fresh` (the matrix is this step's own, so that the
    /// iterations contract fast), until they stop shrinking near that. A
    /// kept matrix contracts more slowly: stopping where it stalls would
    /// leave an error that varies from one flow to the next and stalls
    /// Newton's iterations of the shooting.
    fn solve_stages(
        &mut self,
        x: &DVector<f64>,
        iterations: usize,
        fresh: bool,
    ) -> Option<DVector<f64>> {
        self.newton.as_ref()?;
        let mut k = self.first_guess(x);
        let mut change = DVector::zeros(k.len());
        let scale = x.amax().max(f64::MIN_POSITIVE);
        let mut last_change = f64::INFINITY;
        for _ in 0..iterations {
            self.residual(x, &k, &mut change);
            let (_, lu) = self.newton.as_ref()?;
            if !lu.solve_mut(&mut change) {
                return None;
            }
            k -= &change;
            let size = self.h * change.amax();
            if !size.is_finite() {
                return None;
            }
            // Done at rounding, relative to the state: a few units in its
            // last place, or no longer shrinking near that.
            let stalled = fresh && size <= 1e-13 * scale && size > 0.5 * last_change;
            if size <= 1e-15 * scale || stalled {
                return Some(k);
            }
            last_change = size;
        }
        None
    }

    /// The stage derivatives to start from: the last step's, extrapolated
    /// along the line through them to this step's stage times (the stage
    /// times are `1/2 -+ sqrt(3)/6` of a step, `1/sqrt(3)` apart); at the
    /// first step, the field at the start.
    fn first_guess(&self, x: &DVector<f64>) -> DVector<f64> {
        if let Some([k1, k2]) = &self.stages {
            let slope = (k2 - k1) * 3.0_f64.sqrt();
            stack(&(k1 + &slope), &(k2 + &slope))
        } else {
            let f = self.field.at(x);
            stack(&f, &f)
        }
    }

    /// The stage equations' residual `K_i - f(x + h sum_j a_ij K_j)`, into
    /// `out`.
    fn residual(&mut self, x: &DVector<f64>, k: &DVector<f64>, out: &mut DVector<f64>) {
        let d = x.len();
        for (i, a) in A.iter().enumerate() {
            for r in 0..d {
                self.point[r] = x[r] + k[r] * (self.h * a[0]) + k[d + r] * (self.h * a[1]);
            }
            self.field.at_into(&self.point, &mut self.at_point);
            for r in 0..d {
                out[i * d + r] = k[i * d + r] - self.at_point[r];
            }
        }
    }
}

/// Stage `i`'s point `x + h sum_j a_ij K_j`.
fn stage_point(
    x: &DVector<f64>,
    k1: &DVector<f64>,
    k2: &DVector<f64>,
    h: f64,
    i: usize,
) -> DVector<f64> {
    x + k1 * (h * A[i][0]) + k2 * (h * A[i][1])
}

/// `I - h [[a11 J1, a12 J1], [a21 J2, a22 J2]]`.
fn stage_matrix(j1: &DMatrix<f64>, j2: &DMatrix<f64>, h: f64) -> DMatrix<f64> {
    let d = j1.nrows();
    let mut m = DMatrix::identity(2 * d, 2 * d);
    for (i, j) in [(0, j1), (1, j2)] {
        for (col, a) in A[i].iter().enumerate() {
            let mut block = m.view_mut((i * d, col * d), (d, d));
            block -= j * (h * a);
        }
    }
    m
}

/// `[top; bottom]`: two stages' vectors, or two blocks of rows.
fn stack<C: Dim>(top: &OMatrix<f64, Dyn, C>, bottom: &OMatrix<f64, Dyn, C>) -> OMatrix<f64, Dyn, C>
where
    DefaultAllocator: Allocator<Dyn, C>,
{
    let d = top.nrows();
    OMatrix::from_fn_generic(Dyn(2 * d), top.shape_generic().1, |r, c| {
        if r < d {
            top[(r, c)]
        } else {
            bottom[(r - d, c)]
        }
    })
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
    /// divides the error by 2^4 (order 4), and the exact monodromy is the
    /// derivative of the computed flow (against central differences of it).
    #[test]
    fn the_steps_are_of_order_four_and_the_monodromy_is_their_derivative() {
        let mut model = PresetId::Ziegler1952.model().at_load(2.2);
        model.column.c1_nms_per_rad = 0.3;
        model.column.c2_nms_per_rad = 0.3;
        let field = Field::new(&model);
        let x0 = DVector::from_vec(vec![0.5, 0.9, 0.0, 0.0]);
        let duration = 10.0;
        let (fine, _) = flow(&field, &x0, duration, 1600, Monodromy::None);
        let errors: Vec<f64> = [50, 100, 200]
            .iter()
            .map(|&n| (flow(&field, &x0, duration, n, Monodromy::None).0 - &fine).amax())
            .collect();
        for pair in errors.windows(2) {
            let ratio = pair[0] / pair[1];
            assert!((13.0..19.0).contains(&ratio), "{errors:?}");
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
