//! What a kick does to the column at a point of the plane of the load and
//! a second parameter, read off the boundaries there: it dies out; it dies
//! out or, if large, leaves the column swinging (in the band of hysteresis
//! between a fold of cycles and a hard onset); the swing grows softly from
//! a soft onset; or the column jumps to a large swing past a hard one.
//! Pure: no UI, no clock.

use serde::Serialize;

use super::boundary::Boundaries;
use super::curve::{BoundaryKind, load_on_chord};
use crate::analysis::State;

/// What a kick does.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Kick {
    /// At rest and stable, no large swing to reach: a kick dies out.
    Settles,
    /// At rest and stable, between a fold of cycles and a hard onset: a
    /// small kick dies out, a large one leaves the column swinging.
    Hysteresis,
    /// Past a soft onset: a small swing grows, small near the onset.
    GrowsSoftly,
    /// Past a hard onset: the column jumps to a large swing.
    Jumps,
}

impl Boundaries {
    /// What a kick does at `load` and the second parameter's `value`, the
    /// column's state there being `state`; `None` where the boundaries do
    /// not say (divergence, or flutter with no onset followed at `value`).
    #[must_use]
    pub fn kick_at(&self, value: f64, load: f64, state: State) -> Option<Kick> {
        let onsets = self.onsets_at(value);
        match state {
            State::Stable => {
                let above = onsets
                    .iter()
                    .filter(|(p, _)| *p >= load)
                    .min_by(|a, b| a.0.total_cmp(&b.0));
                let hard_above = above.is_some_and(|(_, l1)| l1.is_some_and(|l1| l1 > 0.0));
                let past_fold = self
                    .folds
                    .iter()
                    .filter_map(|fold| {
                        fold.points.windows(2).find_map(|w| {
                            load_on_chord((w[0].value, w[0].load), (w[1].value, w[1].load), value)
                        })
                    })
                    .any(|fold_load| fold_load <= load);
                Some(if hard_above && past_fold {
                    Kick::Hysteresis
                } else {
                    Kick::Settles
                })
            }
            State::Flutter => {
                // The onset passed; next to the boundary, where a cell may
                // lie either side of it, the nearest.
                let passed = onsets
                    .iter()
                    .filter(|(p, _)| *p <= load)
                    .max_by(|a, b| a.0.total_cmp(&b.0))
                    .or_else(|| {
                        onsets
                            .iter()
                            .min_by(|a, b| (a.0 - load).abs().total_cmp(&(b.0 - load).abs()))
                    })?;
                match passed.1? {
                    l1 if l1 < 0.0 => Some(Kick::GrowsSoftly),
                    _ => Some(Kick::Jumps),
                }
            }
            State::Divergence => None,
        }
    }

    /// Every flutter onset at `value`: its load and the first Lyapunov
    /// coefficient there (the nearer point's), along the Hopf curves'
    /// chords.
    fn onsets_at(&self, value: f64) -> Vec<(f64, Option<f64>)> {
        self.curves
            .iter()
            .filter(|c| c.kind == BoundaryKind::Flutter)
            .flat_map(|c| c.points.windows(2))
            .filter_map(|w| {
                let (a, b) = (&w[0], &w[1]);
                let load = load_on_chord((a.value, a.load), (b.value, b.load), value)?;
                let nearer = if (value - a.value).abs() <= (value - b.value).abs() {
                    a
                } else {
                    b
                };
                Some((load, nearer.first_lyapunov))
            })
            .collect()
    }
}
