//! The cycles between two neighbouring cycles of a branch: each solved on
//! the plane across the chord between them at a share `s` of it, with the
//! load's rate `dp/ds` along the branch there (zero at a fold of cycles);
//! or, where the mirror symmetry breaks between them, the symmetric cycles
//! on those planes (`symmetric`).
//!
//! For the cycles' unknowns `u_a`, `u_b` (`u = (x0, T, p)`) and the
//! continuation's scales `w`, the chord is `c = u_b - u_a` and the plane
//!
//! ```text
//! t . (u - u_a) = s,    t = (c / w^2) / |c / w|^2,
//! ```
//!
//! so `s` is 0 at `u_a`, 1 at `u_b`, and measures the branch between them
//! as the continuation's own arclength equation does (it never turns more
//! than 25 degrees from a step's direction, so each plane meets the branch
//! once). With `t . u` as the last equation Newton's matrix `J` stays
//! regular through a fold in the load, and the branch's rate `du/ds =
//! J⁻¹ e` (`e` the last unit vector) has its load entry zero exactly at a
//! fold. Pure: no UI, no clock.

use std::sync::atomic::{AtomicBool, Ordering};

use nalgebra::DVector;

use super::cycle::Cycle;
use super::falsi::{Stop, illinois};
use super::shooting::{Constraint, Phase, Shooting, Solved, Update};
use super::symmetric::{Symmetric, solve_symmetric};

/// The chord between two cycles of a branch.
pub(super) struct Chord<'a> {
    shooting: &'a Shooting,
    from: DVector<f64>,
    along: DVector<f64>,
    tangent: DVector<f64>,
}

/// A cycle on the chord's plane at `share`, and the phase plane its start
/// was held on.
pub(super) struct OnChord {
    pub(super) share: f64,
    pub(super) solved: Solved,
    phase: Phase,
}

impl<'a> Chord<'a> {
    /// The chord from `a` to `b` in the unknowns scaled by `scales`;
    /// `None` where the two cycles are one.
    pub(super) fn new(
        shooting: &'a Shooting,
        (a, b): (&Cycle, &Cycle),
        scales: &DVector<f64>,
    ) -> Option<Self> {
        let from = a.unknowns();
        let along = b.unknowns() - &from;
        let scaled = along.component_div(scales);
        let length_sq = scaled.norm_squared();
        if length_sq.is_nan() || length_sq <= 0.0 {
            return None;
        }
        let tangent = scaled.component_div(scales) / length_sq;
        Some(Self {
            shooting,
            from,
            along,
            tangent,
        })
    }

    /// The cycle at `share` of the chord, from the guess on the chord and,
    /// when given, a nearby cycle's monodromy; `None` where Newton fails.
    pub(super) fn solve(&self, share: f64, near: Option<&Solved>) -> Option<OnChord> {
        let predicted = &self.from + &self.along * share;
        let phase = self.shooting.phase_through(&predicted);
        let first = near.map(|n| Update::Broyden(Some(&n.monodromy)));
        let solved =
            self.shooting
                .solve_on(&predicted, &self.constraint(&predicted), &phase, first)?;
        Some(OnChord {
            share,
            solved,
            phase,
        })
    }

    /// The symmetric cycle at `share` of the chord (see `symmetric`), from
    /// the guess on the chord; `None` where Newton fails.
    fn symmetric(&self, share: f64) -> Option<Symmetric> {
        let predicted = &self.from + &self.along * share;
        let phase = self.shooting.phase_through(&predicted);
        solve_symmetric(self.shooting, &predicted, &self.tangent, &phase)
    }

    /// The symmetric cycle where the mirror symmetry breaks on the chord: the symmetric cycles on it are solved for at both ends,
    /// and regula falsi (stopping at `stop`) drives `det(I + R)` of their
    /// half-period map `R` to zero, whose sign changes where a real
    /// multiplier goes through -1 (a simple root, where the whole period's
    /// Newton matrix is singular; the multiplier may have been one of a
    /// complex pair at the other end). `None` where a solve fails, the sign
    /// does not change between the ends, or once `cancel` is set.
    pub(super) fn symmetry_break(&self, stop: Stop, cancel: &AtomicBool) -> Option<Symmetric> {
        let at = |share: f64| {
            if cancel.load(Ordering::Relaxed) {
                return None;
            }
            let cycle = self.symmetric(share)?;
            Some((share, cycle.shifted_determinant, cycle))
        };
        Some(illinois(at(0.0)?, at(1.0)?, stop, |share, _| at(share))?.2)
    }

    /// The load's rate `dp/ds` along the branch at `on`, from Newton's
    /// matrix at its exact monodromy; `None` where that matrix is singular.
    pub(super) fn load_rate(&self, on: &OnChord) -> Option<f64> {
        let predicted = &self.from + &self.along * on.share;
        let cycle = &on.solved.cycle;
        let d = cycle.start.len();
        let matrix = self.shooting.newton_matrix(
            (&cycle.start, cycle.period_secs, cycle.load),
            on.solved.steps,
            (&cycle.start, &on.solved.monodromy),
            &on.phase.normal,
            &self.constraint(&predicted),
        )?;
        let last = DVector::from_fn(d + 2, |i, _| if i == d + 1 { 1.0 } else { 0.0 });
        Some(matrix.lu().solve(&last)?[d + 1])
    }

    /// The chord's plane through `predicted`.
    fn constraint<'c>(&'c self, predicted: &'c DVector<f64>) -> Constraint<'c> {
        Constraint::Arclength {
            tangent: &self.tangent,
            predicted,
        }
    }
}
