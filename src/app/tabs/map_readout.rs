//! The values of the stability map's cell under the pointer (its readout),
//! and where that cell is.

use crate::app::speak::Speak as _;
use crate::i18n::state_name;
use crate::tr;
use eframe::egui;

use crate::analysis::{Kick, MapSpec, RowResult, State};
use crate::app::theme::Theme;
use crate::format::{number_text, rate_text};

/// The cell under the pointer: where it is and what the analysis says there.
#[derive(Clone, Debug, PartialEq)]
pub struct Readout {
    pub load: f64,
    pub value: f64,
    pub state: State,
    pub growth_per_s: f64,
    /// What a kick does at the pointer, where the boundaries followed say.
    pub kick: Option<Kick>,
}

/// The computed cell nearest to `(load, value)` on the map of `spec`, or
/// `None` outside the map or on a row not computed (or without analysis).
#[must_use]
pub fn cell_at(
    spec: &MapSpec,
    rows: &[Option<RowResult>],
    load: f64,
    value: f64,
) -> Option<Readout> {
    let ((p0, p1), (y0, y1)) = (spec.load_range, spec.axis_range);
    let index = |x: f64, lo: f64, hi: f64, n: usize| -> Option<usize> {
        if n < 2 || hi <= lo {
            return (n == 1).then_some(0);
        }
        #[expect(clippy::cast_precision_loss, reason = "cell counts")]
        let (step, last) = ((hi - lo) / (n - 1) as f64, (n - 1) as f64);
        let k = ((x - lo) / step).round();
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "checked to lie in 0..n"
        )]
        (0.0..=last).contains(&k).then_some(k as usize)
    };
    let i = index(load, p0, p1, spec.loads)?;
    let j = index(value, y0, y1, spec.values)?;
    let row = rows.get(j)?.as_ref()?.as_ref().ok()?;
    let cell = row.cells.get(i)?;
    let loads = spec.load_grid().ok()?;
    Some(Readout {
        load: *loads.get(i)?,
        value: row.value,
        state: cell.state,
        growth_per_s: cell.growth_per_s,
        kick: None,
    })
}

/// One line in a fixed place: the cell under the pointer (and what a kick
/// does there, where the boundaries followed say), or how to read one.
pub fn readout_ui(ui: &mut egui::Ui, readout: Option<&Readout>, axis_name: &str, theme: &Theme) {
    match readout {
        Some(cell) => {
            let words = ui.words();
            ui.horizontal(|ui| {
                ui.label(format!(
                    "p = {}, {axis_name} = {}:",
                    number_text(cell.load),
                    number_text(cell.value)
                ));
                ui.colored_label(theme.state_color(cell.state), state_name(words, cell.state));
                ui.label(tr!(
                    words,
                    "map-readout-growth",
                    rate = rate_text(cell.growth_per_s)
                ));
                if let Some(kick) = cell.kick {
                    ui.label(kick_words(words, kick));
                }
            });
        }
        None => {
            ui.weak(tr!(ui.words(), "map-readout-hint"));
        }
    }
}

/// What a kick does, in `words`.
#[must_use]
pub fn kick_words(words: &'static crate::i18n::Words, kick: Kick) -> String {
    match kick {
        Kick::Settles => tr!(words, "map-kick-settles"),
        Kick::Hysteresis => tr!(words, "map-kick-hysteresis"),
        Kick::GrowsSoftly => tr!(words, "map-kick-grows-softly"),
        Kick::Jumps => tr!(words, "map-kick-jumps"),
    }
}
