//! Hopf criticality at a flutter onset of a dissipative column: the first
//! Lyapunov coefficient of the nonlinear equations of motion (soft flutter
//! growing from zero amplitude, or hard flutter jumping to a large cycle),
//! and the normal form's amplitude of each angle against the load.
//!
//! The method is Kuznetsov's (Elements of Applied Bifurcation Theory, 3rd
//! ed., eq. 3.20): at the critical load the Jacobian `A` of `x' = f(x)` has
//! the pair `±iω`; with `A q = iω q`, `Aᵀ p = -iω p`, `<q, q> = <p, q> = 1`,
//!
//! ```text
//! l1 = Re[ <p, C(q,q,q̄)> - 2 <p, B(q, A⁻¹ B(q,q̄))> + <p, B(q̄, (2iω - A)⁻¹ B(q,q))> ] / (2ω)
//! ```
//!
//! where `B` and `C` are the second and third derivatives of `f` at rest.
//! They are taken by central differences of the equations of motion
//! (`model::state_derivative`), with complex arguments by multilinearity
//! ([`Steps`] are the difference steps), or, for the follower columns
//! without drag, exactly by automatic differentiation of the equations
//! written a second time (`jet`): two independent means. Pure: no UI, no
//! clock.

use nalgebra::{DMatrix, DVector};
use serde::Serialize;

use crate::analysis::{AffinePencil, AnalysisError, C64};
use crate::model::Model;

/// Difference steps: for the Jacobian, the second and the third derivatives.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Steps {
    pub jacobian: f64,
    pub second: f64,
    pub third: f64,
}

impl Steps {
    /// Steps balancing truncation against rounding in double precision.
    pub const DEFAULT: Self = Self {
        jacobian: 1e-6,
        second: 1e-4,
        third: 1e-3,
    };
}

/// How the derivatives of the equations of motion are taken.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Derivatives {
    /// Central differences of the equations with these steps (every column).
    Differences(Steps),
    /// Exactly, by truncated Taylor arithmetic on the equations written a
    /// second time (`jet`): the follower columns without drag.
    Automatic,
}

impl From<Steps> for Derivatives {
    fn from(steps: Steps) -> Self {
        Self::Differences(steps)
    }
}

/// Whether flutter sets in softly or with a jump.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum HopfKind {
    /// `l1 < 0`: a small stable cycle grows from zero past the onset.
    Supercritical,
    /// `l1 > 0`: an unstable cycle shrinks to the onset; past it the motion
    /// jumps to a large cycle (hysteresis).
    Subcritical,
    /// `l1` is zero within its accuracy: higher terms decide.
    Degenerate,
}

/// The Hopf point at a flutter onset.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Hopf {
    /// The critical load p.
    pub load: f64,
    /// The frequency of the pair on the imaginary axis, rad/s.
    pub frequency_rad_per_s: f64,
    /// The first Lyapunov coefficient (1/s, for the eigenvectors normalized
    /// as above in the state's units: only its sign is physical).
    pub first_lyapunov: f64,
    pub kind: HopfKind,
    /// d Re(lambda)/dp of the critical pair at the onset, 1/s per unit load.
    pub growth_per_load: f64,
    /// The normal form's amplitude of each rod's angle: the cycle's largest
    /// `|phi_i|` is this times `sqrt(|p - load|)`, rad, on the side of the
    /// onset where the cycle exists (above it when supercritical, below it
    /// when subcritical, for a pair that becomes unstable as p grows).
    pub amplitude_per_sqrt_load_rad: Vec<f64>,
}

/// `|l1|` below this fraction of its largest term is zero within accuracy.
const DEGENERATE: f64 = 1e-6;

/// Why there is no Hopf coefficient at a flutter onset.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum NoHopf {
    /// No damping at all: the column is reversible, the flutter onset is a
    /// collision of two pairs on the imaginary axis, and there is no
    /// attractor for a cycle to be.
    Reversible,
}

/// The Hopf point of `model` at the flutter onset `load`, or why there is none.
///
/// # Errors
/// A model that cannot be analysed, or no pair on the imaginary axis at `load`.
pub fn hopf_at(
    model: &Model,
    load: f64,
    derivatives: impl Into<Derivatives>,
) -> Result<Result<Hopf, NoHopf>, AnalysisError> {
    Ok(hopf_point(model, load, derivatives.into())?.map(|point| point.hopf))
}

/// A Hopf point with the critical eigenvector: where the limit cycles start.
#[derive(Clone, Debug)]
pub(crate) struct HopfPoint {
    pub hopf: Hopf,
    /// `q`, `A q = i omega q` on the reduced state (see `field`), `|q| = 1`.
    pub eigenvector: DVector<C64>,
    /// `p`, `Aᵀ p = -i omega p` with `<p, q> = 1`: the normal form's
    /// coordinate is `z = <p, x>` (to the orders its transformation keeps).
    pub adjoint: DVector<C64>,
    /// The normal form's radius per sqrt of the load's distance from the
    /// onset: the cycle is `2 r Re(q e^{i omega t})` to leading order.
    pub radius_per_sqrt_load: f64,
}

/// Whether anything in `model` dissipates energy: a damper, drag along the
/// rods or a roller with mass (whose spin slips on the band). Without, the
/// column is reversible (a massless roller is exactly the ideal follower).
pub(crate) fn dissipative(model: &Model) -> bool {
    let c = &model.column;
    c.c1_nms_per_rad != 0.0
        || c.c2_nms_per_rad != 0.0
        || c.drag_ns_per_m2 != 0.0
        || model.roller().is_some_and(|r| r.mass_kg > 0.0)
}

/// [`hopf_at`] with the critical eigenvector and the normal form's radius.
pub(crate) fn hopf_point(
    model: &Model,
    load: f64,
    derivatives: Derivatives,
) -> Result<Result<HopfPoint, NoHopf>, AnalysisError> {
    if !dissipative(model) {
        return Ok(Err(NoHopf::Reversible));
    }
    if derivatives == Derivatives::Automatic && !crate::analysis::jet::covers(model) {
        return Err(AnalysisError::NotCovered(
            "the automatic derivatives cover the follower columns with joint springs and dampers, without drag along the rods",
        ));
    }
    let at = model.at_load(load);
    let pencil = AffinePencil::new(&at)?;
    let critical = critical_pair(&pencil, load)?;
    let field = Field {
        reduced: crate::analysis::field::Field::new(&at),
        derivatives,
    };
    let n = field.reduced.dimension();
    let a = field.jacobian();
    let not_found = AnalysisError::NotConverged { load };
    let (lambda, q) = eigenvector(&a, critical).ok_or(not_found.clone())?;
    let omega = lambda.im;
    let (_, adjoint) = eigenvector(&a.transpose(), lambda.conj()).ok_or(not_found.clone())?;
    // <p, q> = 1.
    let overlap = adjoint.dotc(&q);
    let p = adjoint.map(|v| v / overlap.conj());
    let b = |x: &DVector<C64>, y: &DVector<C64>| field.second(x, y);
    let cubic = field.third(&q);
    let qq_bar = b(&q, &q.conjugate());
    let qq = b(&q, &q);
    let complex_a = a.map(|v| C64::new(v, 0.0));
    let solve = |m: DMatrix<C64>, rhs: &DVector<C64>| m.lu().solve(rhs).ok_or(not_found.clone());
    let zero_mode = solve(complex_a.clone(), &qq_bar)?;
    let shifted = DMatrix::<C64>::identity(n, n) * C64::new(0.0, 2.0 * omega) - &complex_a;
    let double_mode = solve(shifted, &qq)?;
    let terms = [
        p.dotc(&cubic),
        -2.0 * p.dotc(&b(&q, &zero_mode)),
        p.dotc(&b(&q.conjugate(), &double_mode)),
    ];
    let sum: C64 = terms.iter().sum();
    let first_lyapunov = sum.re / (2.0 * omega);
    let largest = terms.iter().map(|t| t.norm()).fold(0.0, f64::max) / (2.0 * omega);
    let kind = if first_lyapunov.abs() <= DEGENERATE * largest {
        HopfKind::Degenerate
    } else if first_lyapunov < 0.0 {
        HopfKind::Supercritical
    } else {
        HopfKind::Subcritical
    };
    let growth_per_load = growth_per_load(&pencil, load, critical)?;
    // r^2 = -mu' eps / (omega l1) for z' = lambda z + c1 z |z|^2, x = 2 Re(z q).
    let radius_per_sqrt_load = (growth_per_load.abs() / (omega * first_lyapunov.abs())).sqrt();
    let amplitude_per_sqrt_load_rad = (0..field.reduced.rods())
        .map(|i| 2.0 * q[i].norm() * radius_per_sqrt_load)
        .collect();
    Ok(Ok(HopfPoint {
        hopf: Hopf {
            load,
            frequency_rad_per_s: omega,
            first_lyapunov,
            kind,
            growth_per_load,
            amplitude_per_sqrt_load_rad,
        },
        eigenvector: q,
        adjoint: p,
        radius_per_sqrt_load,
    }))
}

/// The eigenvalue of the pair nearest the imaginary axis at `load`, Im > 0.
fn critical_pair(pencil: &AffinePencil, load: f64) -> Result<C64, AnalysisError> {
    pencil
        .spectrum(load)?
        .eigenvalues
        .into_iter()
        .filter(|z| z.im > 0.0)
        .min_by(|a, b| a.re.abs().total_cmp(&b.re.abs()))
        .ok_or(AnalysisError::NotConverged { load })
}

/// d Re(lambda)/dp of the eigenvalue nearest `critical` at `load`, by a
/// central difference of the pencil's spectrum.
fn growth_per_load(pencil: &AffinePencil, load: f64, critical: C64) -> Result<f64, AnalysisError> {
    let delta = 1e-6 * load.max(1e-3);
    let nearest = |p: f64| -> Result<f64, AnalysisError> {
        pencil
            .spectrum(p)?
            .eigenvalues
            .into_iter()
            .min_by(|a, b| (a - critical).norm().total_cmp(&(b - critical).norm()))
            .map(|z| z.re)
            .ok_or(AnalysisError::NotConverged { load: p })
    };
    Ok((nearest(load + delta)? - nearest(load - delta)?) / (2.0 * delta))
}

/// The eigenvalue near `guess` of `a` and its unit eigenvector, by inverse
/// iteration with the Rayleigh quotient as the shift.
fn eigenvector(a: &DMatrix<f64>, guess: C64) -> Option<(C64, DVector<C64>)> {
    let n = a.nrows();
    let complex = a.map(|v| C64::new(v, 0.0));
    let mut lambda = guess;
    // A start with a part along every eigenvector (not a symmetric one).
    let mut x = DVector::<C64>::from_iterator(
        n,
        std::iter::successors(Some(1.0), |v| Some(v * 0.9))
            .take(n)
            .map(|v| C64::new(1.0, v)),
    );
    let tolerance = 1e-9 * a.norm().max(1.0);
    let residual = |lambda: C64, x: &DVector<C64>| (&complex * x - x * lambda).norm();
    for _ in 0..8 {
        if residual(lambda, &x) <= tolerance {
            break;
        }
        let shifted = &complex - DMatrix::<C64>::identity(n, n) * lambda;
        // At an exact eigenvalue the solve may fail: the last vector stands.
        let Some(y) = shifted.lu().solve(&x) else {
            break;
        };
        let norm = y.norm();
        if !(norm.is_finite() && norm > 0.0) {
            break;
        }
        x = y / C64::new(norm, 0.0);
        lambda = x.dotc(&(&complex * &x));
    }
    let residual = residual(lambda, &x);
    (residual <= 1e-6 * a.norm().max(1.0)).then_some((lambda, x))
}

/// The derivatives of the reduced field at rest, by the means asked for.
struct Field {
    reduced: crate::analysis::field::Field,
    derivatives: Derivatives,
}

impl Field {
    fn at(&self, x: &DVector<f64>) -> DVector<f64> {
        self.reduced.at(x)
    }

    /// The first, second and third directional derivatives along `v` by
    /// jets (only called for [`Derivatives::Automatic`], on a covered model).
    fn jets(&self, v: &DVector<f64>) -> [DVector<f64>; 3] {
        crate::analysis::jet::directional_derivatives(self.reduced.model(), v)
            .unwrap_or_else(|| std::array::from_fn(|_| DVector::from_element(v.len(), f64::NAN)))
    }

    /// The Jacobian at rest.
    fn jacobian(&self) -> DMatrix<f64> {
        let n = self.reduced.dimension();
        match self.derivatives {
            Derivatives::Differences(steps) => {
                self.reduced.jacobian(&DVector::zeros(n), steps.jacobian)
            }
            Derivatives::Automatic => {
                let mut a = DMatrix::zeros(n, n);
                for j in 0..n {
                    let [first, ..] =
                        self.jets(&DVector::from_fn(n, |i, _| f64::from(u8::from(i == j))));
                    a.set_column(j, &first);
                }
                a
            }
        }
    }

    /// The second derivative `B(x, y)` at rest for real `x`, `y`.
    fn second_real(&self, x: &DVector<f64>, y: &DVector<f64>) -> DVector<f64> {
        match self.derivatives {
            Derivatives::Differences(steps) => {
                let h = steps.second;
                let (s, d) = ((x + y) * h, (x - y) * h);
                (self.at(&s) - self.at(&d) - self.at(&-&d) + self.at(&-&s)) / (4.0 * h * h)
            }
            // B(x, y) = (D²[x + y] - D²[x - y]) / 4.
            Derivatives::Automatic => {
                let [_, plus, _] = self.jets(&(x + y));
                let [_, minus, _] = self.jets(&(x - y));
                (plus - minus) / 4.0
            }
        }
    }

    /// `B(x, y)` for complex `x`, `y`, by bilinearity.
    fn second(&self, x: &DVector<C64>, y: &DVector<C64>) -> DVector<C64> {
        let (xr, xi) = (x.map(|v| v.re), x.map(|v| v.im));
        let (yr, yi) = (y.map(|v| v.re), y.map(|v| v.im));
        let re = self.second_real(&xr, &yr) - self.second_real(&xi, &yi);
        let im = self.second_real(&xr, &yi) + self.second_real(&xi, &yr);
        DVector::from_fn(re.len(), |i, _| C64::new(re[i], im[i]))
    }

    /// The third directional derivative `C(v, v, v)` at rest, real `v`.
    fn cube(&self, v: &DVector<f64>) -> DVector<f64> {
        match self.derivatives {
            Derivatives::Differences(steps) => {
                // The stencil is off by h^2/4 of the fifth derivative:
                // Richardson's (4 D(h/2) - D(h)) / 3 cancels that. Without,
                // the drag column's first Lyapunov coefficient near its
                // Bautin point, where its terms cancel to 1e-4 of
                // themselves, was off by 1e-5 (as much as it is there), by
                // an amount that turned with the eigenvector's phase.
                let stencil = |h: f64| {
                    (self.at(&(v * (2.0 * h))) - self.at(&(v * h)) * 2.0 + self.at(&(v * -h)) * 2.0
                        - self.at(&(v * (-2.0 * h))))
                        / (2.0 * h * h * h)
                };
                let h = steps.third;
                (stencil(h / 2.0) * 4.0 - stencil(h)) / 3.0
            }
            Derivatives::Automatic => {
                let [_, _, third] = self.jets(v);
                third
            }
        }
    }

    /// `C(q, q, q̄)` for complex `q = a + ib`: `C(a,a,a) + C(a,b,b) +
    /// i (C(a,a,b) + C(b,b,b))`, the mixed terms by polarization along
    /// `a + t b` for t = 0, 1, -1, 2.
    fn third(&self, q: &DVector<C64>) -> DVector<C64> {
        let (a, b) = (q.map(|v| v.re), q.map(|v| v.im));
        let along = |t: f64| self.cube(&(&a + &b * t));
        let (c0, c1, cm, c2) = (along(0.0), along(1.0), along(-1.0), along(2.0));
        // c(t) = aaa + 3t aab + 3t^2 abb + t^3 bbb.
        let aaa = c0.clone();
        let even = (&c1 + &cm) / 2.0 - &aaa; // 3 abb
        let odd = (&c1 - &cm) / 2.0; // 3 aab + bbb
        // c(2) = aaa + 6 aab + 12 abb + 8 bbb.
        let rest = &c2 - &aaa - &even * 4.0; // 6 aab + 8 bbb
        let bbb = (&rest - &odd * 2.0) / 6.0;
        let aab = (&odd - &bbb) / 3.0;
        let abb = even / 3.0;
        let re = &aaa + &abb;
        let im = &aab + &bbb;
        DVector::from_fn(re.len(), |i, _| C64::new(re[i], im[i]))
    }
}

/// Whether a transition between `from` and `to` is a flutter onset or end
/// (a pair crossing the imaginary axis): stable on one side, flutter on
/// the other.
#[must_use]
pub fn is_hopf(from: crate::analysis::State, to: crate::analysis::State) -> bool {
    use crate::analysis::State::{Flutter, Stable};
    matches!((from, to), (Stable, Flutter) | (Flutter, Stable))
}
