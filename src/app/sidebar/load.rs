//! The load typed, the critical loads in words, and a ramp's onsets (seen
//! and predicted); the slider is the wide load bar under the scene.

use eframe::egui::{self, RichText};

use super::number_field::{NumberFields, refusal_ui};
use crate::app::View;
use crate::app::action::Actions;
use crate::app::state::{AppState, VISIBLE_FRACTION};
use crate::app::theme::Theme;
use crate::format::{load_text, number_text};
use crate::model::Key;

/// The load's number field.
#[derive(Default)]
pub struct LoadSection {
    field: NumberFields,
}

impl View for LoadSection {
    fn ui(&mut self, ui: &mut egui::Ui, state: &AppState, actions: &mut Actions, theme: &Theme) {
        self.field.prune(ui, state);
        ui.horizontal(|ui| {
            // The wide bar under the scene is the slider; this field takes a
            // typed load, also beyond the bar's range (not clamped).
            self.field
                .show(ui, state, actions, theme, Key::Load)
                .on_hover_text(
                    "type a load (Enter applies, Escape restores); beyond the bar's end too",
                );
            ui.label("load p = P l/k").on_hover_text(
                "the load without units: the tip force P times the rod's length l over the springs' stiffness k (Ziegler's column flutters from p = 2.09)",
            );
        });
        refusal_ui(ui, state, theme, Key::Load);
        let p = state.model().load_p();
        if let Some(roller) = state.model().roller() {
            ui.label(format!(
                "roller: q = R l/k = p/μ = {:.3}   (μ = {})",
                p / roller.mu,
                roller.mu
            ))
            .on_hover_text(
                "the roller's own load: the force R pressing it on the band, in the units of p; the band's friction pushes with μ R, so p = μ q",
            );
        }
        // The notes below the field (the critical loads, a ramp's onsets,
        // warnings) take a fixed number of lines whatever their count, so
        // the fields under them stay where the hand is.
        let notes = notes(state, p, theme, ui.visuals().weak_text_color());
        let row_height = ui.text_style_height(&egui::TextStyle::Body);
        let spacing = ui.spacing().item_spacing.y;
        let shown = notes.len().min(NOTE_LINES);
        let top = ui.cursor().top();
        for (i, note) in notes.iter().take(shown).enumerate() {
            let last_of_more = i + 1 == NOTE_LINES && notes.len() > NOTE_LINES;
            if last_of_more {
                let rest: Vec<&str> = notes[i..].iter().map(|n| n.text.as_str()).collect();
                ui.add(egui::Label::new(format!("... and {} more (hover)", rest.len())).truncate())
                    .on_hover_text(rest.join("\n"));
            } else {
                let label = ui
                    .add(egui::Label::new(RichText::new(&note.text).color(note.color)).truncate());
                // A cut line shows itself whole on hover (egui's own): a
                // second tooltip of the same words stacked under it.
                if let Some(more) = &note.more {
                    label.on_hover_text(more);
                }
            }
        }
        // Up to the same bottom every frame, whatever was drawn above it.
        #[expect(clippy::cast_precision_loss, reason = "a few lines")]
        let bottom = top + NOTE_LINES as f32 * (row_height + spacing);
        let left = bottom - ui.cursor().top();
        if left > 0.0 {
            ui.add_space(left);
        }
    }
}

/// Lines kept for the notes under the load field.
const NOTE_LINES: usize = 4;

/// One line under the load field: its words, colour, and what its hover
/// adds.
struct Note {
    text: String,
    color: egui::Color32,
    more: Option<String>,
}

impl Note {
    fn new(text: impl Into<String>, color: egui::Color32) -> Self {
        Self {
            text: text.into(),
            color,
            more: None,
        }
    }
}

/// What a critical load means, for its tooltip (the line itself says the
/// load and the states).
fn transition_meaning(t: &crate::analysis::Transition) -> String {
    use crate::analysis::State;
    let how = match t.to {
        State::Flutter => {
            "past this load a pair of eigenvalues lies right of the imaginary axis: a kick grows into a growing swing"
        }
        State::Divergence => {
            "past this load a real eigenvalue is positive: the column leans away without swinging"
        }
        State::Stable => {
            "past this load no eigenvalue lies right of the imaginary axis: a kick no longer grows"
        }
    };
    format!(
        "p = {}: the column goes from {} to {}; {how}",
        crate::format::load_text(t.load),
        t.from.name(),
        t.to.name()
    )
}

/// The notes under the load field, in order: the load beyond the plotted
/// range, the critical loads (or that a lesson hides them), a ramp's
/// onsets, the resolution warning.
fn notes(state: &AppState, p: f64, theme: &Theme, weak: egui::Color32) -> Vec<Note> {
    let mut notes = Vec::new();
    if p > state.load_max() {
        notes.push(Note::new(
            format!(
                "p = {} is beyond the plotted range (0 to {}); the status below is at p",
                number_text(p),
                number_text(state.load_max())
            ),
            theme.warning,
        ));
    }
    if state.answer_hidden() {
        notes.push(Note::new(
            "The critical loads are hidden until the lesson reveals them.",
            weak,
        ));
        if let Some(run) = state.ramp() {
            ramp_onset_notes(&mut notes, run.seen_at_p, None, theme);
        }
        return notes;
    }
    let Some(analysis) = state.analysis() else {
        return notes;
    };
    for t in &analysis.transitions {
        let mut note = Note::new(t.to_string(), theme.state_color(t.to));
        note.more = Some(transition_meaning(t));
        notes.push(note);
    }
    if let Some(run) = state.ramp() {
        ramp_onset_notes(
            &mut notes,
            run.seen_at_p,
            analysis.first_instability(),
            theme,
        );
    }
    if let Some(warning) = &analysis.warning {
        notes.push(Note {
            text: "the stability is not resolved here (hover for why)".to_owned(),
            color: theme.warning,
            more: Some(warning.clone()),
        });
    }
    notes
}

/// The ramp's onsets in words: where the motion was seen against where the
/// theory puts it, and why the first lags (on hover).
fn ramp_onset_notes(notes: &mut Vec<Note>, seen: Option<f64>, theory: Option<f64>, theme: &Theme) {
    let visible = format!(
        "the tip off by {:.0}% of the length",
        100.0 * VISIBLE_FRACTION
    );
    if let Some(theory) = theory {
        notes.push(Note::new(
            format!(
                "theory (white mark): unstable from p = {}",
                load_text(theory)
            ),
            theme.text,
        ));
    }
    match seen {
        Some(seen) => notes.push(Note {
            text: format!(
                "seen (mark): motion visible at p = {}{} ({visible})",
                load_text(seen),
                if theory.is_some_and(|theory| seen > theory) {
                    ", late: hover for why"
                } else {
                    ""
                }
            ),
            color: theme.measured,
            more: theory.filter(|&theory| seen > theory).map(|_| {
                "It shows late: past the onset the motion needs time to grow to a visible size, and the ramp moves on meanwhile. A slower ramp shows it closer to the theory.".to_owned()
            }),
        }),
        None => notes.push(Note::new(
            format!("watching for the motion to become visible ({visible})"),
            theme.text,
        )),
    }
}
