//! The status card: the stability at the current load in words and numbers,
//! and the eigenvalue measured from the run.

use eframe::egui::{self, RichText};

use crate::analysis::{C64, Hopf, HopfKind, NoHopf, Stability, State, classify};
use crate::app::View;
use crate::app::action::Actions;
use crate::app::speak::Speak as _;
use crate::app::state::AppState;
use crate::app::theme::{Theme, color};
use crate::format::{load_text, measured_text, number_text, percent_text, rate_text, secs_text};
use crate::i18n::Words;
use crate::i18n::{duration_words, state_name};
use crate::tr;

/// An e-folding time beyond this is a growth nobody sees in a lesson: even
/// at the fastest speed (10x) it takes over five minutes to grow by e.
const TOO_SLOW_TO_SEE_SECS: f64 = 3000.0;

/// What each word of the card means, in plain words (its tooltip).
fn meaning(words: &'static Words, state: State, weak: bool) -> String {
    match (state, weak) {
        (State::Flutter, true) => tr!(words, "card-weak-flutter.meaning"),
        (state, _) => words
            .get(&format!("card-{}.meaning", state.name()))
            .into_owned(),
    }
}

/// The frequency of the mode the card describes, named among the column's
/// modes (slowest first), and the eigenvalue measured from the run for
/// that same mode (or the one measured, said to be another).
fn frequency_and_measured_ui(
    ui: &mut egui::Ui,
    state: &AppState,
    s: &Stability,
    eigenvalues: &[C64],
) {
    let words = ui.words();
    let frequency = s.frequency_rad_per_s();
    // The modes by frequency, slowest first: the card names the one it
    // describes, and shows the measured eigenvalue of that same mode.
    let modes = oscillating_modes(eigenvalues, s.tolerance_per_s);
    let card_mode = (frequency > s.tolerance_per_s)
        .then(|| nearest_mode(s.dominant, &modes))
        .flatten();
    // Modes are named by their rank in frequency only while the
    // frequencies differ: past a flutter onset two modes have merged into
    // one pair, one growing and one dying away at the same frequency.
    let named = modes.len() > 1
        && modes
            .windows(2)
            .all(|pair| pair[1].im - pair[0].im > 1e-6 * pair[1].im);
    let mode_name = |k: usize| {
        if named {
            tr!(words, "card-mode", k = k + 1, n = modes.len())
        } else {
            tr!(words, "card-the-mode")
        }
    };
    if frequency > s.tolerance_per_s {
        let period = std::f64::consts::TAU / frequency;
        let which = card_mode
            .filter(|_| named)
            .map(|k| format!(", {}", mode_name(k)))
            .unwrap_or_default();
        ui.label(tr!(
            words,
            "card-frequency",
            frequency = format!("{frequency:.4}"),
            period = secs_text(period),
            which = which
        ))
        .on_hover_text(tr!(words, "card-frequency.tooltip"));
    } else {
        ui.label(tr!(words, "card-non-oscillatory"));
    }
    let measured: Vec<(C64, Option<usize>, Option<C64>)> = state
        .measured()
        .unwrap_or_default()
        .iter()
        .enumerate()
        .filter(|(_, z)| z.im > 0.0)
        .map(|(k, &z)| (z, nearest_mode(z, &modes), state.measured_uncertainty(k)))
        .collect();
    // The measurement of the card's mode; any one when the card's mode
    // does not swing (a divergence).
    let like_for_like = match card_mode {
        Some(_) => measured.iter().find(|(_, k, _)| *k == card_mode),
        None => measured.first(),
    };
    let measured_label = match (like_for_like, measured.first()) {
        (Some(&(z, k, uncertainty)), _) => ui.label(tr!(
            words,
            "card-measured",
            mode = k
                .filter(|_| named)
                .map(|k| format!(" ({})", mode_name(k)))
                .unwrap_or_default(),
            measurement = measurement_text(words, z, uncertainty)
        )),
        (None, Some(&(z, k, uncertainty))) => ui.label(match (named, k, card_mode) {
            (true, Some(k), Some(card)) => tr!(
                words,
                "card-measured-other-mode",
                mode = mode_name(k),
                card = mode_name(card),
                measurement = measurement_text(words, z, uncertainty)
            ),
            _ => tr!(
                words,
                "card-measured-other",
                measurement = measurement_text(words, z, uncertainty)
            ),
        }),
        (None, None) => ui.label(
            RichText::new(if state.model().column.rods == 2 {
                tr!(words, "card-measured-after")
            } else {
                tr!(words, "card-measured-two-rods")
            })
            .small(),
        ),
    };
    measured_label.on_hover_text(tr!(words, "card-measured.tooltip"));
}

/// A measured eigenvalue `z` as its growth rate and frequency, each with
/// its uncertainty where the run tells it (the fits over the first and the
/// last three quarters of the run), else said to be unknown.
fn measurement_text(words: &'static Words, z: C64, uncertainty: Option<C64>) -> String {
    match uncertainty {
        Some(u) => tr!(
            words,
            "card-measurement",
            growth = measured_text(z.re, u.re, true),
            frequency = measured_text(z.im, u.im, false)
        ),
        None => tr!(
            words,
            "card-measurement-unknown",
            growth = format!("{:+.5}", z.re),
            frequency = format!("{:.4}", z.im)
        ),
    }
}

/// The oscillating modes of a spectrum, slowest first: of each pair, the
/// eigenvalue above the real axis.
fn oscillating_modes(eigenvalues: &[C64], tolerance_per_s: f64) -> Vec<C64> {
    let mut modes: Vec<C64> = eigenvalues
        .iter()
        .copied()
        .filter(|z| z.im > tolerance_per_s)
        .collect();
    modes.sort_by(|a, b| a.im.total_cmp(&b.im));
    modes
}

/// The mode (from 0, slowest first) whose eigenvalue is nearest to `z` or
/// its conjugate.
fn nearest_mode(z: C64, modes: &[C64]) -> Option<usize> {
    let z = C64::new(z.re, z.im.abs());
    (0..modes.len()).min_by(|&a, &b| (modes[a] - z).norm().total_cmp(&(modes[b] - z).norm()))
}

/// How the flutter set in at `onset`: soft or hard (the first Lyapunov
/// coefficient), or that an undamped column has no cycle to settle on. On
/// the roller (`sliding`) the smooth analysis holds only while the contact
/// slides: the card says where that ends.
fn onset_ui(ui: &mut egui::Ui, onset: f64, hopf: &Result<Hopf, NoHopf>, sliding: bool) {
    let words = ui.words();
    let at = load_text(onset);
    let (line, more) = match hopf {
        Ok(hopf) => {
            let amplitude = hopf
                .amplitude_per_sqrt_load_rad
                .first()
                .map(|a| {
                    format!(
                        " {}",
                        tr!(
                            words,
                            "onset-amplitude",
                            a = number_text(*a),
                            at = at.clone()
                        )
                    )
                })
                .unwrap_or_default();
            let sticking = if sliding {
                format!(" {}", tr!(words, "onset-sticking"))
            } else {
                String::new()
            };
            let tip = tr!(
                words,
                "onset.tooltip",
                lyapunov = number_text(hopf.first_lyapunov),
                at = at.clone(),
                frequency = number_text(hopf.frequency_rad_per_s),
                amplitude = amplitude,
                sticking = sticking
            );
            let line = match hopf.kind {
                HopfKind::Supercritical if sliding => tr!(words, "onset-soft-roller", at = at),
                HopfKind::Supercritical => tr!(words, "onset-soft", at = at),
                HopfKind::Subcritical => tr!(words, "onset-hard", at = at),
                HopfKind::Degenerate => tr!(words, "onset-degenerate", at = at),
            };
            (line, tip)
        }
        Err(NoHopf::Reversible) => (
            tr!(words, "onset-reversible"),
            tr!(words, "onset-reversible.tooltip"),
        ),
    };
    ui.label(RichText::new(line).small()).on_hover_text(more);
}

/// The card. `compact`: the verdict, the growth and its time only, for a
/// lesson on a projector, where the card stays in view at the sidebar's
/// foot under the step's text (the frequency, the measurement and the
/// onset's kind are in the full card, on the projector outside a lesson).
pub struct StatusSection {
    pub compact: bool,
}

impl View for StatusSection {
    fn ui(&mut self, ui: &mut egui::Ui, state: &AppState, _actions: &mut Actions, theme: &Theme) {
        let words = ui.words();
        if state.answer_hidden() {
            ui.label(
                RichText::new(tr!(words, "card-hidden"))
                    .heading()
                    .color(color(theme.palette.info)),
            );
            ui.weak(tr!(words, "card-hidden.why"));
            return;
        }
        let (Some(analysis), Some(spectrum)) = (state.analysis(), state.current_spectrum()) else {
            if let Some(error) = state.analysis_failure() {
                ui.colored_label(
                    color(theme.palette.warning),
                    tr!(words, "card-no-figures", why = error.to_string()),
                );
            }
            return;
        };
        let s = classify(&spectrum.eigenvalues, spectrum.scale_per_s);
        let growth = s.growth_rate_per_s();
        let frequency = s.frequency_rad_per_s();
        let weak = s.state == State::Flutter && growth < 0.01 * frequency;
        let title = match (s.state, weak) {
            (State::Flutter, true) => tr!(words, "card-weak-flutter"),
            (stability, _) => state_name(words, stability),
        };
        ui.label(
            RichText::new(title)
                .heading()
                .color(theme.state_color(s.state)),
        )
        .on_hover_text(meaning(words, s.state, weak));
        if growth.abs() <= s.tolerance_per_s {
            // Rounding's share of the real part: say zero, and to what accuracy.
            ui.label(tr!(
                words,
                "card-growth-zero",
                tolerance = format!("{:.0e}", s.tolerance_per_s)
            ))
            .on_hover_text(tr!(words, "card-growth.tooltip"));
        } else {
            ui.label(tr!(words, "card-growth", rate = rate_text(growth)))
                .on_hover_text(tr!(words, "card-growth.tooltip"));
        }
        if analysis.warning.is_some() {
            ui.colored_label(
                color(theme.palette.warning),
                tr!(words, "card-not-resolved"),
            );
        }
        match s.e_folding_secs() {
            Some(secs) => ui
                .label(tr!(
                    words,
                    "card-e-folding",
                    time = duration_words(words, secs)
                ))
                .on_hover_text(tr!(words, "card-e-folding.tooltip")),
            // Within the resolution the rate is zero: no decay time of
            // millions of years beside "growth rate 0".
            None if growth < -s.tolerance_per_s => ui
                .label(tr!(
                    words,
                    "card-decay",
                    time = duration_words(words, -1.0 / growth)
                ))
                .on_hover_text(tr!(words, "card-decay.tooltip")),
            None => ui.label(tr!(words, "card-neutral")),
        };
        if !self.compact {
            frequency_and_measured_ui(ui, state, &s, &spectrum.eigenvalues);
        }
        if !self.compact
            && s.state == State::Flutter
            && let Some((onset, Some(hopf))) = analysis.onset_below(state.settings().model.load_p())
        {
            let sliding = state.settings().model.roller().is_some();
            onset_ui(ui, *onset, hopf, sliding);
        }
        if weak {
            let per_period = 100.0 * (growth * std::f64::consts::TAU / frequency).exp_m1();
            let percent = percent_text(per_period);
            let line = if s
                .e_folding_secs()
                .is_some_and(|secs| secs > TOO_SLOW_TO_SEE_SECS)
            {
                tr!(words, "card-grows-too-slowly", percent = percent)
            } else {
                tr!(words, "card-grows-slowly", percent = percent)
            };
            ui.label(RichText::new(line).small());
        }
    }
}
