//! The status card: the stability at the current load in words and numbers,
//! and the eigenvalue measured from the run.

use eframe::egui::{self, RichText};

use crate::analysis::{C64, Hopf, HopfKind, NoHopf, Stability, State, classify};
use crate::app::View;
use crate::app::action::Actions;
use crate::app::state::AppState;
use crate::app::theme::Theme;
use crate::format::{
    duration_text, load_text, measured_text, number_text, percent_text, rate_text, secs_text,
};

/// An e-folding time beyond this is a growth nobody sees in a lesson: even
/// at the fastest speed (10x) it takes over five minutes to grow by e.
const TOO_SLOW_TO_SEE_SECS: f64 = 3000.0;

/// What each word of the card means, in plain words (its tooltip).
fn meaning(state: State, weak: bool) -> &'static str {
    match (state, weak) {
        (State::Stable, _) => {
            "stable: a small nudge stays small (it dies away, or with no damping at all keeps its size)"
        }
        (State::Flutter, true) => {
            "weak flutter: the swing grows, but by less than 1% of its frequency: slowly, over many swings"
        }
        (State::Flutter, false) => {
            "flutter: the column swings back and forth, wider and wider (a pair of eigenvalues right of the axis)"
        }
        (State::Divergence, _) => {
            "divergence: the column bends away to one side without swinging (a real eigenvalue right of the axis)"
        }
    }
}

const GROWTH_RATE: &str = "growth rate: how fast the motion grows (positive) or dies away (negative), per second: the real part of the eigenvalue furthest right";
const E_FOLDING: &str =
    "e-folding time: the time in which the swing grows by a factor e = 2.72 (1 / growth rate)";
const DECAY: &str = "decay time: the time in which the swing shrinks by a factor e = 2.72";
/// What the measured line means, on hover.
const MEASURED_TIP: &str = "the eigenvalue fitted to the run's own motion (a matrix pencil of the angles): at least 20 s of small swings (below 0.05 rad) since the last kick, release or change, each mode once the run holds a whole period of it; 'mode 2 of 2' counts the column's modes of swinging from the slowest. The ± is the fit's own uncertainty: how far fits over the run's first and last three quarters fall from the whole run's. The engine's time step dt moves the run itself from the linear model too, its frequency by about ω³dt²/24";

const FREQUENCY_AND_MODES: &str = "frequency: how fast the column swings, in radians per second (the eigenvalue's height); the period is one full swing. A column of n rods has n modes of swinging, counted here from the slowest; the card describes the one that grows fastest (or dies away slowest), and the run's measurement is shown for that same mode";

/// The frequency of the mode the card describes, named among the column's
/// modes (slowest first), and the eigenvalue measured from the run for
/// that same mode (or the one measured, said to be another).
fn frequency_and_measured_ui(
    ui: &mut egui::Ui,
    state: &AppState,
    s: &Stability,
    eigenvalues: &[C64],
) {
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
            format!("mode {} of {}", k + 1, modes.len())
        } else {
            "the mode".to_owned()
        }
    };
    if frequency > s.tolerance_per_s {
        let period = std::f64::consts::TAU / frequency;
        let which = card_mode
            .filter(|_| named)
            .map(|k| format!(", {}", mode_name(k)))
            .unwrap_or_default();
        ui.label(format!(
            "frequency  {frequency:.4} rad/s  (period {} s{which})",
            secs_text(period)
        ))
        .on_hover_text(FREQUENCY_AND_MODES);
    } else {
        ui.label("non-oscillatory: the dominant eigenvalue is real");
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
        (Some(&(z, k, uncertainty)), _) => ui.label(format!(
            "measured from the run{}  {}",
            k.filter(|_| named)
                .map(|k| format!(" ({})", mode_name(k)))
                .unwrap_or_default(),
            measurement_text(z, uncertainty)
        )),
        (None, Some(&(z, k, uncertainty))) => {
            let (measured_one, cards) = match (named, k, card_mode) {
                (true, Some(k), Some(card)) => (mode_name(k), format!("the card's {}", mode_name(card))),
                _ => ("another eigenvalue".to_owned(), "the card's".to_owned()),
            };
            ui.label(format!(
                "measured from the run: {measured_one} only, {} ({cards} too weak in this run to fit)",
                measurement_text(z, uncertainty)
            ))
        }
        (None, None) => ui.label(
            RichText::new(if state.model().column.rods == 2 {
                "measured: after 20 s of small-amplitude motion (|φ| < 0.05 rad)"
            } else {
                "measured: for two rods only (a chain's many slow modes need a longer run than a fit can use)"
            })
            .small(),
        ),
    };
    measured_label.on_hover_text(MEASURED_TIP);
}

/// A measured eigenvalue `z` as its growth rate and frequency, each with
/// its uncertainty where the run tells it (the fits over the first and the
/// last three quarters of the run), else said to be unknown.
fn measurement_text(z: C64, uncertainty: Option<C64>) -> String {
    match uncertainty {
        Some(u) => format!(
            "growth {} 1/s, frequency {} rad/s",
            measured_text(z.re, u.re, true),
            measured_text(z.im, u.im, false)
        ),
        None => format!(
            "growth {:+.5} 1/s, frequency {:.4} rad/s (uncertainty unknown: too few periods in the run)",
            z.re, z.im
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
    let at = load_text(onset);
    let sticking_tip = if sliding {
        " On the roller the slip at the contact falls as the cycle grows; where it nears zero the friction is no longer smooth and the motion turns to stick-slip, which this analysis does not follow: the post-critical tab's branch ends there."
    } else {
        ""
    };
    let (words, more) = match hopf {
        Ok(hopf) => {
            let amplitude = hopf
                .amplitude_per_sqrt_load_rad
                .first()
                .map(|a| format!(" Near it the cycle's |phi1| is about {} sqrt(p - {at}) rad.", number_text(*a)))
                .unwrap_or_default();
            let tip = format!(
                "Soft: past the onset the swing grows from zero to a small steady cycle, larger as the load rises; hard: it jumps to a large one, which stays when the load is lowered a little. Sticking: the roller stops slipping on the band, where the friction changes its law.\n\nFirst Lyapunov coefficient {} at the onset p = {at} (Hopf point, frequency {} rad/s).{amplitude}{sticking_tip}",
                number_text(hopf.first_lyapunov),
                number_text(hopf.frequency_rad_per_s)
            );
            match hopf.kind {
                HopfKind::Supercritical if sliding => (
                    format!("soft onset at p = {at}: a cycle grows from zero, until the roller nears sticking"),
                    tip,
                ),
                HopfKind::Supercritical => (
                    format!("soft onset at p = {at}: the swing settles on a limit cycle that grows from zero"),
                    tip,
                ),
                HopfKind::Subcritical => (
                    format!("hard onset at p = {at}: the swing jumps to a large cycle, which persists below the onset"),
                    tip,
                ),
                HopfKind::Degenerate => (
                    format!("onset at p = {at} neither soft nor hard to first order"),
                    tip,
                ),
            }
        }
        Err(NoHopf::Reversible) => (
            "no damping: no limit cycle to settle on (a reversible column)".to_owned(),
            "Without damping the column is reversible: flutter starts where two pairs of eigenvalues meet on the imaginary axis, and there is no attractor, so no limit cycle the swing could settle on.".to_owned(),
        ),
    };
    ui.label(RichText::new(words).small()).on_hover_text(more);
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
        if state.answer_hidden() {
            ui.label(RichText::new("stable or not?").heading().color(theme.info));
            ui.weak("The verdict is hidden until the lesson reveals it: watch the column.");
            return;
        }
        let (Some(analysis), Some(spectrum)) = (state.analysis(), state.current_spectrum()) else {
            if let Some(error) = state.analysis_failure() {
                ui.colored_label(theme.warning, format!("no stability figures: {error}"));
            }
            return;
        };
        let s = classify(&spectrum.eigenvalues, spectrum.scale_per_s);
        let growth = s.growth_rate_per_s();
        let frequency = s.frequency_rad_per_s();
        let weak = s.state == State::Flutter && growth < 0.01 * frequency;
        let title = match (s.state, weak) {
            (State::Flutter, true) => "weak flutter".to_owned(),
            (stability, _) => stability.name().to_owned(),
        };
        ui.label(
            RichText::new(title)
                .heading()
                .color(theme.state_color(s.state)),
        )
        .on_hover_text(meaning(s.state, weak));
        if growth.abs() <= s.tolerance_per_s {
            // Rounding's share of the real part: say zero, and to what accuracy.
            ui.label(format!(
                "growth rate  0 (to within {:.0e} 1/s)",
                s.tolerance_per_s
            ))
            .on_hover_text(GROWTH_RATE);
        } else {
            ui.label(format!("growth rate  {} 1/s", rate_text(growth)))
                .on_hover_text(GROWTH_RATE);
        }
        if analysis.warning.is_some() {
            ui.colored_label(
                theme.warning,
                "not resolved at these parameters: see the warning under the load",
            );
        }
        match s.e_folding_secs() {
            Some(secs) => ui
                .label(format!("e-folding time  {}", duration_text(secs)))
                .on_hover_text(E_FOLDING),
            // Within the resolution the rate is zero: no decay time of
            // millions of years beside "growth rate 0".
            None if growth < -s.tolerance_per_s => ui
                .label(format!("decay time  {}", duration_text(-1.0 / growth)))
                .on_hover_text(DECAY),
            None => ui.label("neutral: no growth, no decay"),
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
            let pace = if s
                .e_folding_secs()
                .is_some_and(|secs| secs > TOO_SLOW_TO_SEE_SECS)
            {
                "too slow to see in a lesson"
            } else {
                "watch for minutes, not seconds"
            };
            ui.label(
                RichText::new(format!(
                    "grows by {} per period: {pace}",
                    percent_text(per_period)
                ))
                .small(),
            );
        }
    }
}
