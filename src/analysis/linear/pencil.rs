//! Eigenvalues of the quadratic pencil `lambda^2 M + lambda D + K`, any number
//! of degrees of freedom, and the pencil as an affine function of the load.

use nalgebra::DMatrix;

use super::characteristic::CharacteristicPolynomial;
use super::dense::{
    NALGEBRA_MAX_ORDER, balance, companion, eigenvalues_from_squares, eigenvalues_of,
};
use crate::analysis::roots::{MAX_DEGREE, Poly, aberth};
use crate::analysis::{AnalysisError, C64};
use crate::model::{AsValid, LinearModel, linearize};

/// The eigenvalues of one pencil.
#[derive(Clone, Debug, PartialEq)]
pub struct Spectrum {
    /// The eigenvalues that move with the parameters.
    pub eigenvalues: Vec<C64>,
    /// Exact zero roots from free coordinates (the roller's spin angle appears
    /// only through its rate: the third column of K is zero). Not in `eigenvalues`.
    pub structural_zeros: usize,
    /// The pencil's frequency scale in 1/s, `sqrt(|K|/|M|) + |D|/|M|`
    /// (Frobenius norms): what tolerances are relative to.
    pub scale_per_s: f64,
}

impl Spectrum {
    /// All `2n` eigenvalues, the structural zeros last.
    pub fn all(&self) -> impl Iterator<Item = C64> + '_ {
        self.eigenvalues.iter().copied().chain(std::iter::repeat_n(
            C64::new(0.0, 0.0),
            self.structural_zeros,
        ))
    }
}

/// Indices of coordinates that enter only through their rates (zero K column).
pub(crate) fn cyclic_coordinates(stiffness: &DMatrix<f64>) -> Vec<usize> {
    (0..stiffness.ncols())
        .filter(|&j| stiffness.column(j).iter().all(|&v| v == 0.0))
        .collect()
}

/// The frequency scale of a pencil in 1/s.
pub(crate) fn frequency_scale(lin: &LinearModel) -> f64 {
    scale_of_norms(lin.stiffness.norm(), lin.damping.norm(), lin.mass.norm())
}

/// The frequency scale from the Frobenius norms of K, D and M.
fn scale_of_norms(stiffness: f64, damping: f64, mass: f64) -> f64 {
    (stiffness / mass).sqrt() + damping / mass
}

/// `M^-1 K` of `lin` by a Cholesky solve; `None` when M is not positive
/// definite.
fn squares_matrix(lin: &LinearModel) -> Option<DMatrix<f64>> {
    Some(lin.mass.clone().cholesky()?.solve(&lin.stiffness))
}

/// All eigenvalues of the pencil by a balanced real Schur decomposition of its
/// companion matrix: the general, robust path (any n). nalgebra's QR
/// iteration has no exceptional shifts and can stall (seen on a balanced
/// matrix next to a double eigenvalue); the unbalanced matrix is tried then.
///
/// # Errors
/// Non-finite entries, a mass matrix that is not positive definite, or a
/// QR iteration that converges for neither matrix.
pub fn spectrum(lin: &LinearModel, load: f64) -> Result<Spectrum, AnalysisError> {
    spectrum_from(lin, load, || squares_matrix(lin))
}

/// [`spectrum`], with `squares` giving `M^-1 K` where the squares' matrix
/// is taken (see [`takes_squares`]).
fn spectrum_from(
    lin: &LinearModel,
    load: f64,
    squares: impl FnOnce() -> Option<DMatrix<f64>>,
) -> Result<Spectrum, AnalysisError> {
    let finite = [&lin.mass, &lin.damping, &lin.stiffness]
        .iter()
        .all(|m| m.iter().all(|v| v.is_finite()));
    let not_converged = AnalysisError::NotConverged { load };
    if !finite {
        return Err(not_converged);
    }
    let cyclic = cyclic_coordinates(&lin.stiffness);
    let eigenvalues = if takes_squares(lin, &cyclic) {
        squares()
            .and_then(eigenvalues_from_squares)
            .ok_or(not_converged)?
    } else {
        let a = companion(lin, &cyclic).ok_or(not_converged.clone())?;
        let mut balanced = a.clone();
        balance(&mut balanced);
        eigenvalues_of(&balanced, &a).ok_or(not_converged)?
    };
    Ok(Spectrum {
        eigenvalues,
        structural_zeros: cyclic.len() + lin.extra_zero_roots,
        scale_per_s: frequency_scale(lin),
    })
}

/// Whether the spectrum of `lin` comes from the squares' matrix `M^-1 K`:
/// an undamped pencil with no cyclic coordinate, too large for nalgebra.
fn takes_squares(lin: &LinearModel, cyclic: &[usize]) -> bool {
    cyclic.is_empty()
        && lin.damping.iter().all(|&d| d == 0.0)
        && 2 * lin.mass.nrows() > NALGEBRA_MAX_ORDER
}

/// The linearization as an affine function of the load p: M is fixed and
/// `D = D0 + p D1`, `K = K0 + p K1` (every load here is proportional to p).
#[derive(Clone, Debug, PartialEq)]
pub struct AffinePencil {
    at_zero: LinearModel,
    per_unit_load: LinearModel,
    /// Coordinates that are cyclic at every load (zero K column).
    cyclic: usize,
    norms: NormQuadratics,
    /// The characteristic polynomial as polynomials in the load, for 2 or 3
    /// degrees of freedom.
    characteristic: Option<CharacteristicPolynomial>,
    /// `M^-1 K0` and `M^-1 K1` of a pencil undamped at every load: the
    /// squares' matrix at p is `M^-1 K0 + p M^-1 K1` (see [`takes_squares`]),
    /// without a Cholesky solve per load.
    squares: Option<[DMatrix<f64>; 2]>,
    natural_load_max: f64,
    /// Threads a long chain's locus may compute its spectra on (the
    /// caller's choice: [`Self::with_threads`]; one by default).
    threads: usize,
    /// No damping at any load.
    undamped: bool,
}

impl AffinePencil {
    /// Linearizes `model` at p = 0 and p = 1.
    ///
    /// # Errors
    /// Whatever [`linearize`] rejects.
    pub fn new(model: &impl AsValid) -> Result<Self, AnalysisError> {
        let model = model.as_valid()?;
        let at_zero = linearize(&model.at_load(0.0)?)?;
        let at_one = linearize(&model.at_load(1.0)?)?;
        let per_unit_load = LinearModel {
            mass: DMatrix::zeros(at_zero.mass.nrows(), at_zero.mass.ncols()),
            damping: &at_one.damping - &at_zero.damping,
            stiffness: &at_one.stiffness - &at_zero.stiffness,
            extra_zero_roots: 0,
        };
        let always_cyclic = cyclic_coordinates(&at_zero.stiffness)
            .into_iter()
            .filter(|j| cyclic_coordinates(&per_unit_load.stiffness).contains(j))
            .count();
        let characteristic = CharacteristicPolynomial::new(&at_zero, &per_unit_load);
        let undamped = [&at_zero.damping, &per_unit_load.damping]
            .iter()
            .all(|d| d.iter().all(|&v| v == 0.0));
        let squares = undamped
            .then(|| at_zero.mass.clone().cholesky())
            .flatten()
            .map(|mass| {
                [
                    mass.solve(&at_zero.stiffness),
                    mass.solve(&per_unit_load.stiffness),
                ]
            });
        Ok(Self {
            squares,
            norms: NormQuadratics::new(&at_zero, &per_unit_load),
            at_zero,
            per_unit_load,
            cyclic: always_cyclic,
            characteristic,
            natural_load_max: model.analysis_max_p(),
            threads: 1,
            undamped,
        })
    }

    /// Whether the pencil has no damping at any load.
    #[must_use]
    pub fn undamped(&self) -> bool {
        self.undamped
    }

    /// Degrees of freedom of the pencil.
    #[must_use]
    pub fn dof(&self) -> usize {
        self.at_zero.mass.nrows()
    }

    /// The pencil at load p.
    #[must_use]
    pub fn at(&self, p: f64) -> LinearModel {
        LinearModel {
            mass: self.at_zero.mass.clone(),
            damping: &self.at_zero.damping + p * &self.per_unit_load.damping,
            stiffness: &self.at_zero.stiffness + p * &self.per_unit_load.stiffness,
            extra_zero_roots: self.at_zero.extra_zero_roots,
        }
    }

    /// Number of exact zero roots at every load (cyclic coordinates and the
    /// massless roller's spin angle).
    #[must_use]
    pub fn structural_zeros(&self) -> usize {
        self.cyclic + self.at_zero.extra_zero_roots
    }

    /// Zero roots that are factors of the pencil's determinant (cyclic coordinates).
    #[must_use]
    pub fn cyclic_zeros(&self) -> usize {
        self.cyclic
    }

    /// The spectrum at load p by the robust (Schur) path.
    ///
    /// # Errors
    /// See [`spectrum`].
    pub fn spectrum(&self, p: f64) -> Result<Spectrum, AnalysisError> {
        if let Some(spectrum) = self.squares_spectrum(p) {
            return spectrum;
        }
        // The products formed once serve wherever the squares' matrix is
        // taken with them (`squares_spectrum`); here it is solved for.
        let lin = self.at(p);
        let squares = || squares_matrix(&lin);
        let mut spectrum = match spectrum_from(&lin, p, squares) {
            Ok(spectrum) => spectrum,
            Err(error) => self.polynomial_spectrum(p, &lin).ok_or(error)?,
        };
        // A coordinate that is cyclic only at this load (the roller at p = 0)
        // is not structural: report its zero among the moving eigenvalues.
        let structural = self.structural_zeros();
        let extra = spectrum.structural_zeros - structural;
        spectrum
            .eigenvalues
            .extend(std::iter::repeat_n(C64::new(0.0, 0.0), extra));
        spectrum.structural_zeros = structural;
        Ok(spectrum)
    }

    /// [`Self::spectrum`] where it comes from the squares' matrix formed
    /// once (see [`takes_squares`]), without the pencil's matrices at p:
    /// only `K(p)`, for the general path's checks and the frequency scale,
    /// which are the same here to the last bit (the damping is zero at a
    /// finite load). `None` where the general path decides.
    fn squares_spectrum(&self, p: f64) -> Option<Result<Spectrum, AnalysisError>> {
        let [own, per_load] = self.squares.as_ref()?;
        if !p.is_finite() || 2 * self.dof() <= NALGEBRA_MAX_ORDER {
            return None;
        }
        let stiffness = &self.at_zero.stiffness + p * &self.per_unit_load.stiffness;
        let finite = [&self.at_zero.mass, &stiffness]
            .iter()
            .all(|m| m.iter().all(|v| v.is_finite()));
        if !finite || !cyclic_coordinates(&stiffness).is_empty() {
            return None;
        }
        let eigenvalues = eigenvalues_from_squares(own + p * per_load)
            .ok_or(AnalysisError::NotConverged { load: p });
        Some(eigenvalues.map(|eigenvalues| Spectrum {
            eigenvalues,
            structural_zeros: self.structural_zeros(),
            scale_per_s: scale_of_norms(stiffness.norm(), 0.0, self.norms.mass),
        }))
    }

    /// `det(lambda^2 M + lambda D + K)` at load p for 2 or 3 degrees of
    /// freedom, with the structural zero roots divided out (their
    /// coefficients are exact zeros: every term carries an entry of a zero
    /// column). `None` for other sizes or a vanishing leading coefficient.
    /// Allocation-free: 2n + 1 cubics in p.
    #[must_use]
    pub fn char_poly(&self, p: f64) -> Option<Poly> {
        let characteristic = self.characteristic.as_ref()?;
        let n = self.dof();
        let zeros = self.cyclic;
        let full = characteristic.at(p);
        let degree = 2 * n - zeros;
        if full[..zeros].iter().any(|&c| c != 0.0) || full[2 * n] == 0.0 {
            return None;
        }
        let mut coeffs = [0.0; MAX_DEGREE + 1];
        coeffs[..=degree].copy_from_slice(&full[zeros..=2 * n]);
        Some(Poly { coeffs, degree })
    }

    /// The last resort when Schur fails: the characteristic polynomial's roots
    /// by Aberth iteration from points on a circle of the pencil's frequency
    /// scale (globally convergent in practice).
    fn polynomial_spectrum(&self, p: f64, lin: &LinearModel) -> Option<Spectrum> {
        let poly = self.char_poly(p)?;
        let radius = frequency_scale(lin).max(f64::MIN_POSITIVE);
        #[expect(clippy::cast_precision_loss, reason = "degree <= 6")]
        let step = std::f64::consts::TAU / poly.degree as f64;
        // Off the real axis and not symmetric about it, so no two starts coincide.
        let mut roots: Vec<C64> = (0..poly.degree)
            .map(|k| {
                #[expect(clippy::cast_precision_loss, reason = "k < 6")]
                let angle = 0.4 + step * k as f64;
                C64::from_polar(radius, angle)
            })
            .collect();
        aberth(&poly, &mut roots, 500).then(|| Spectrum {
            eigenvalues: roots,
            structural_zeros: self.cyclic + lin.extra_zero_roots,
            scale_per_s: frequency_scale(lin),
        })
    }

    /// The load at which the load's stiffness matches the column's own in
    /// norm (`|K1| p = |K0|`). Infinite when the load adds no stiffness.
    #[must_use]
    pub fn stiffness_matching_load(&self) -> f64 {
        let [own, _, per_load] = self.norms.stiffness;
        if per_load > 0.0 {
            (own / per_load).sqrt()
        } else {
            f64::INFINITY
        }
    }

    /// This pencil, its loci computing a long chain's spectra on `threads`
    /// threads (at least one).
    #[must_use]
    pub fn with_threads(mut self, threads: usize) -> Self {
        self.threads = threads.max(1);
        self
    }

    /// The threads a locus of this pencil computes its spectra on.
    #[must_use]
    pub fn threads(&self) -> usize {
        self.threads
    }

    /// The upper end of the column's own load range (see `Model::analysis_max_p`).
    #[must_use]
    pub fn natural_load_max(&self) -> f64 {
        self.natural_load_max
    }

    /// The frequency scale at load p (see [`Spectrum::scale_per_s`]),
    /// from the squared norms of `K(p)` and `D(p)` as quadratics in p.
    #[must_use]
    pub fn scale_per_s(&self, p: f64) -> f64 {
        let NormQuadratics {
            stiffness,
            damping,
            mass,
        } = self.norms;
        let at = |[c0, c1, c2]: [f64; 3]| ((c2 * p + c1) * p + c0).max(0.0).sqrt();
        (at(stiffness) / mass).sqrt() + at(damping) / mass
    }
}

/// `|A0 + p A1|^2 = |A0|^2 + 2 p <A0, A1> + p^2 |A1|^2` (Frobenius), lowest
/// degree first, for the stiffness and the damping; the mass norm.
#[derive(Clone, Copy, Debug, PartialEq)]
struct NormQuadratics {
    stiffness: [f64; 3],
    damping: [f64; 3],
    mass: f64,
}

impl NormQuadratics {
    fn new(at_zero: &LinearModel, per_unit_load: &LinearModel) -> Self {
        let quadratic = |a: &DMatrix<f64>, b: &DMatrix<f64>| {
            [a.norm_squared(), 2.0 * a.dot(b), b.norm_squared()]
        };
        Self {
            stiffness: quadratic(&at_zero.stiffness, &per_unit_load.stiffness),
            damping: quadratic(&at_zero.damping, &per_unit_load.damping),
            mass: at_zero.mass.norm(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::dense::faer_eigenvalues;
    use super::*;
    use crate::model::{Assignment, Key, PresetId, apply_assignments};

    /// A long damped chain's spectrum (the EISPACK iteration on the
    /// balanced companion matrix) is faer's Schur decomposition's, pair for
    /// pair, for joint dampers, drag along the rods and a roller chain,
    /// below and past flutter; and a chain whose modes span 1e149 (a first
    /// damper of 1e149 on eight rods) keeps its slow modes: 1/s of the
    /// others' order, not rounding of the fast one.
    #[test]
    fn a_damped_chain_s_eigenvalues_are_faer_s() {
        let pencil_of = |id: PresetId, sets: &[(Key, f64)]| {
            let mut model = id.model();
            let sets: Vec<Assignment> = sets
                .iter()
                .map(|&(key, value)| Assignment { key, value })
                .collect();
            apply_assignments(&mut model, &sets).unwrap();
            (AffinePencil::new(&model).unwrap(), model)
        };
        let cases = [
            (
                PresetId::UniformRods,
                vec![(Key::Rods, 16.0), (Key::C1, 0.05), (Key::C2, 0.05)],
            ),
            (
                PresetId::UniformRods,
                vec![(Key::Rods, 8.0), (Key::CExt, 0.05)],
            ),
            (
                PresetId::PfluegerRoller,
                vec![(Key::Rods, 6.0), (Key::C1, 0.01)],
            ),
        ];
        for (id, sets) in cases {
            let (pencil, model) = pencil_of(id, &sets);
            let p_max = model.analysis_max_p();
            for p in [0.0, 0.3 * p_max, 0.7 * p_max] {
                let ours = pencil.spectrum(p).unwrap().eigenvalues;
                let lin = pencil.at(p);
                let mut balanced = companion(&lin, &cyclic_coordinates(&lin.stiffness)).unwrap();
                balance(&mut balanced);
                let theirs = faer_eigenvalues(&balanced).unwrap();
                let scale = theirs.iter().map(|z| z.norm()).fold(0.0, f64::max);
                let nearest = |z: &C64, among: &[C64]| {
                    among
                        .iter()
                        .map(|w| (w - z).norm())
                        .fold(f64::INFINITY, f64::min)
                };
                for z in &theirs {
                    let miss = nearest(z, &ours);
                    assert!(
                        miss < 1e-10 * scale,
                        "{id:?} {sets:?} p = {p}: faer's {z} is {miss:e} from ours"
                    );
                }
                // Ours beyond faer's: only the zero of a coordinate cyclic at this load.
                for z in ours.iter().filter(|z| z.norm() > 0.0) {
                    let miss = nearest(z, &theirs);
                    assert!(miss < 1e-10 * scale, "{id:?} {sets:?} p = {p}: {z}");
                }
                assert!(ours.len() >= theirs.len());
            }
        }
        let (huge, _) = pencil_of(
            PresetId::PfluegerRoller,
            &[(Key::Rods, 8.0), (Key::C1, 1e149)],
        );
        let spectrum = huge.spectrum(0.001).unwrap();
        let (fastest, slowest) = crate::analysis::stability::mode_span(&spectrum.eigenvalues);
        assert!(fastest > 1e148 && slowest < 10.0, "{fastest:e} {slowest:e}");
    }

    /// The half-order path of an undamped chain (the double-shift QR
    /// iteration on `M^-1 K`, and on the pencil's `M^-1 K0 + p M^-1 K1`)
    /// gives the eigenvalues of faer's Schur decomposition of the companion
    /// matrix, pair for pair, in flutter and before it, for 6, 24 and 64
    /// rods.
    #[test]
    fn an_undamped_chain_s_half_order_eigenvalues_are_the_companion_s() {
        for (rods, p) in [
            (6.0, 0.0),
            (6.0, 0.3),
            (6.0, 0.9),
            (24.0, 0.0),
            (24.0, 0.05),
        ] {
            let mut chain = PresetId::UniformRods.model();
            let rods = Assignment {
                key: Key::Rods,
                value: rods,
            };
            apply_assignments(&mut chain, &[rods]).unwrap();
            let lin = linearize(&chain.at_load(p)).unwrap();
            let from_pencil = AffinePencil::new(&chain).unwrap().spectrum(p).unwrap();
            let half = squares_matrix(&lin)
                .and_then(eigenvalues_from_squares)
                .unwrap();
            let a = companion(&lin, &[]).unwrap();
            let full = faer_eigenvalues(&a).unwrap();
            let scale = full.iter().map(|z| z.norm()).fold(0.0, f64::max);
            assert_eq!(half.len(), full.len());
            assert_eq!(from_pencil.eigenvalues.len(), full.len());
            for z in half.iter().chain(&from_pencil.eigenvalues) {
                let nearest = full
                    .iter()
                    .map(|w| (w - z).norm())
                    .fold(f64::INFINITY, f64::min);
                assert!(
                    nearest < 1e-9 * scale,
                    "p = {p}: {z} is {nearest:e} from the companion's"
                );
            }
        }
    }
}
