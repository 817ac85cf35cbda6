//! The paradox curves as a figure: the first critical load against the
//! swept ratio on a log axis, one curve per damping level (or band speed),
//! the undamped (or massless) reference as a dashed line, the model's own
//! point.

use std::sync::atomic::AtomicBool;

use plotters::coord::Shift;
use plotters::prelude::*;

use super::style::Ink;
use super::{Drawn, FigureError, plots};
use crate::analysis::{Curves, DampingKind, own_point, paradox_curves};
use crate::model::Model;
use crate::plot::paradox::Paradox;

/// The explorer's curves and the model's own point `(log10 ratio, load)`.
#[derive(Clone, Debug)]
pub struct ParadoxData {
    pub curves: Curves,
    pub here: Option<(f64, f64)>,
}

impl ParadoxData {
    /// The curves of `model` for damping of `kind` (the roller's: its mass
    /// ratio and band speed), and the model's own first critical load.
    #[must_use]
    pub fn new(model: &Model, kind: DampingKind) -> Self {
        let threads = crate::machine_threads();
        let curves = paradox_curves(model, kind, threads, &AtomicBool::new(false));
        let here = own_point(model, kind, None, threads).map(|[x, p]| (x, p));
        Self { curves, here }
    }
}

/// The curves ([`Paradox`]) with their legend above.
pub(super) fn draw<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    data: &ParadoxData,
    ink: &Ink,
) -> Result<Drawn, FigureError>
where
    DB::ErrorType: 'static,
{
    if let Some(note) = &data.curves.note {
        return Err(FigureError::Empty(note.to_string()));
    }
    let paradox = Paradox {
        curves: &data.curves,
        here: data.here.map(|(x, p)| [x, p]),
        words: ink.words,
    };
    let plot = paradox
        .plot()
        .ok_or_else(|| FigureError::Empty("the curves have no extent".to_owned()))?;
    plots::draw(root, &paradox.legend(), &[plot], ink)
}
