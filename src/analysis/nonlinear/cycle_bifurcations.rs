//! The bifurcations of the limit cycles themselves along a branch, read
//! from their Floquet multipliers: a fold of cycles (a real multiplier
//! through +1, where the branch turns back in the load), a period doubling
//! (a real multiplier through -1) and a Neimark-Sacker (torus) bifurcation
//! (a complex pair through the unit circle), each placed between the two
//! cycles it lies between where the multiplier's modulus passes 1.

use serde::Serialize;

use super::cycle::Cycle;
use crate::analysis::C64;

/// A multiplier is real when its imaginary part is at most this share of
/// its modulus.
const REAL: f64 = 1e-8;

/// What changes at a bifurcation of the cycles.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum CycleBifurcationKind {
    /// A real multiplier through +1: the branch folds back in the load.
    Fold,
    /// A real multiplier through -1: a cycle of twice the period is born.
    PeriodDoubling,
    /// A complex pair through the unit circle: a torus is born.
    NeimarkSacker,
}

/// A bifurcation of the cycles along a branch.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct CycleBifurcation {
    pub kind: CycleBifurcationKind,
    /// The load, interpolated between the two cycles.
    pub load: f64,
    /// The largest angle's amplitude there, interpolated, in rad.
    pub amplitude_rad: f64,
}

/// The class of a multiplier other than the trivial one.
fn class_of(m: C64) -> CycleBifurcationKind {
    if m.im.abs() > REAL * m.norm() {
        CycleBifurcationKind::NeimarkSacker
    } else if m.re > 0.0 {
        CycleBifurcationKind::Fold
    } else {
        CycleBifurcationKind::PeriodDoubling
    }
}

/// How many multipliers of `kind` lie outside the unit circle, and the
/// distance `|m| - 1` of the one of that kind nearest the circle.
fn outside(cycle: &Cycle, kind: CycleBifurcationKind) -> (usize, Option<f64>) {
    let of_kind: Vec<f64> = cycle
        .nontrivial_multipliers()
        .filter(|m| class_of(*m) == kind)
        .map(|m| m.norm() - 1.0)
        .collect();
    let count = of_kind.iter().filter(|&&r| r > 0.0).count();
    let nearest = of_kind
        .into_iter()
        .min_by(|a, b| a.abs().total_cmp(&b.abs()));
    (count, nearest)
}

/// Every bifurcation along `cycles` (in the order of the continuation):
/// where the count of multipliers of a kind outside the unit circle
/// changes between two cycles, placed where the modulus of the one
/// nearest the circle passes 1, linearly between them.
#[must_use]
pub fn cycle_bifurcations(cycles: &[Cycle]) -> Vec<CycleBifurcation> {
    use CycleBifurcationKind::{Fold, NeimarkSacker, PeriodDoubling};
    let mut out = Vec::new();
    for pair in cycles.windows(2) {
        let [a, b] = pair else { continue };
        for kind in [Fold, PeriodDoubling, NeimarkSacker] {
            let ((count_a, near_a), (count_b, near_b)) = (outside(a, kind), outside(b, kind));
            if count_a == count_b {
                continue;
            }
            let t = match (near_a, near_b) {
                (Some(ra), Some(rb)) if ra * rb < 0.0 => ra / (ra - rb),
                _ => 0.5,
            };
            let along = |x: f64, y: f64| x + t * (y - x);
            out.push(CycleBifurcation {
                kind,
                load: along(a.load, b.load),
                amplitude_rad: along(a.largest_amplitude_rad(), b.largest_amplitude_rad()),
            });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::DVector;

    /// A cycle at `load` with the trivial multiplier and `others`.
    fn cycle(load: f64, others: &[C64]) -> Cycle {
        let mut multipliers = vec![C64::new(1.0, 0.0)];
        multipliers.extend_from_slice(others);
        Cycle {
            load,
            period_secs: 1.0,
            start: DVector::zeros(2),
            amplitude_rad: vec![load],
            multipliers,
            stable: true,
            closest_slip_m_per_s: None,
        }
    }

    /// Each kind is read where its multiplier's modulus passes 1 (the
    /// moduli here change linearly with the load, so the placement is
    /// exact): a real one through -1 at p = 1.25, a complex pair through
    /// the circle at p = 2.5, a real one through +1 at p = 3.75.
    #[test]
    fn each_kind_is_read_where_its_multiplier_leaves_the_circle() {
        let pd = |p: f64| C64::new(-(0.5 + 0.4 * p), 0.0);
        let ns = |p: f64| C64::from_polar(0.5 + 0.2 * p, 1.0);
        let fold = |p: f64| C64::new(0.25 + 0.2 * p, 0.0);
        let cycles: Vec<Cycle> = [1.0, 1.5, 2.0, 3.0, 3.5, 4.0]
            .iter()
            .map(|&p| {
                cycle(
                    p,
                    &[pd(p.min(1.5)), ns(p.clamp(2.0, 3.0)), fold(p.max(3.5))],
                )
            })
            .collect();
        let found = cycle_bifurcations(&cycles);
        let kinds: Vec<_> = found.iter().map(|b| b.kind).collect();
        assert_eq!(
            kinds,
            [
                CycleBifurcationKind::PeriodDoubling,
                CycleBifurcationKind::NeimarkSacker,
                CycleBifurcationKind::Fold
            ]
        );
        for (b, at) in found.iter().zip([1.25, 2.5, 3.75]) {
            assert!((b.load - at).abs() < 1e-12, "{b:?}");
            assert!((b.amplitude_rad - at).abs() < 1e-12, "{b:?}");
        }
    }

    /// Where the constructed field below has its period doubling.
    const DOUBLING_P: f64 = 0.61;

    /// The cycle's angular frequency at `p`, rad/s.
    fn omega(p: f64) -> f64 {
        0.8 + 0.4 * p
    }

    /// A field in four dimensions with a period doubling at a known load:
    /// the circle `x^2 + y^2 = 1` run round at `omega(p)` attracts `(x,
    /// y)`, and `w = (u, v)` obeys
    ///
    /// ```text
    /// w' = (l I + d S(x, y) + omega/2 J) w - |w|^2 w,
    /// S = [[x, y], [y, -x]],  J = [[0, -1], [1, 0]],
    /// ```
    ///
    /// with `l +- d = l1, l2`, `l1 = p - DOUBLING_P`, `l2 = -1`. On the
    /// circle `S(theta)` is the reflection `R(theta/2) diag(1, -1)
    /// R(-theta/2)`, so in the frame turned by `theta/2` the linear part is
    /// `diag(l1, l2)`, and over a period the frame turns by half a turn:
    /// `w`'s multipliers are `-exp(l1 T)` and `-exp(l2 T)`, the first
    /// through -1 exactly at `p = DOUBLING_P` (the band of a Moebius strip
    /// flipping its stability). The circle's own are 1 and `exp(-2 T)`.
    fn doubling_field(s: &DVector<f64>, p: f64, out: &mut DVector<f64>) {
        let (x, y, u, v) = (s[0], s[1], s[2], s[3]);
        let (l1, l2, w) = (p - DOUBLING_P, -1.0, omega(p));
        let (l, d) = (f64::midpoint(l1, l2), (l1 - l2) / 2.0);
        let (radial, cubic) = (1.0 - x * x - y * y, u * u + v * v);
        out[0] = x * radial - w * y;
        out[1] = y * radial + w * x;
        out[2] = l * u + d * (x * u + y * v) - w / 2.0 * v - cubic * u;
        out[3] = l * v + d * (y * u - x * v) + w / 2.0 * u - cubic * v;
    }

    /// The shooting, its multipliers and the reading of the bifurcations
    /// on a field whose period doubling is known in closed form (above):
    /// every cycle's multipliers are the closed form's to 1e-8, and the
    /// doubling is read at `DOUBLING_P` to the linear placement's own
    /// error, `T h^2 / 8` for loads `h` apart (the modulus
    /// `exp((p - DOUBLING_P) T)` is not linear in the load).
    #[test]
    fn a_constructed_period_doubling_is_found_where_it_is() {
        use crate::analysis::nonlinear::shooting::{Constraint, Shooting};
        let field = crate::analysis::field::Field::constructed(doubling_field, 2, 0.3);
        let shooting = Shooting::on(field);
        let h = 0.02;
        let cycles: Vec<Cycle> = (0..30)
            .map(|i| {
                let p = 0.3 + h * f64::from(i);
                let period = std::f64::consts::TAU / omega(p);
                let guess = DVector::from_vec(vec![1.0, 0.0, 0.0, 0.0, period, p]);
                let cycle = shooting
                    .solve(&guess, &Constraint::Load(p))
                    .expect("a cycle")
                    .cycle;
                assert!((cycle.period_secs - period).abs() < 1e-9 * period);
                let expected = [1.0, (-2.0 * period).exp()]
                    .into_iter()
                    .chain([-((p - DOUBLING_P) * period).exp(), -(-period).exp()]);
                for m in expected {
                    let off = cycle
                        .multipliers
                        .iter()
                        .map(|z| (z - m).norm())
                        .fold(f64::INFINITY, f64::min);
                    assert!(off < 1e-8, "p = {p}: {m} against {:?}", cycle.multipliers);
                }
                cycle
            })
            .collect();
        let found = cycle_bifurcations(&cycles);
        assert_eq!(found.len(), 1, "{found:?}");
        let period = std::f64::consts::TAU / omega(DOUBLING_P);
        assert_eq!(found[0].kind, CycleBifurcationKind::PeriodDoubling);
        let off = (found[0].load - DOUBLING_P).abs();
        assert!(off < period * h * h / 8.0, "{:?}: {off}", found[0]);
    }
}
