//! The load typed, the critical loads in words, and a ramp's onsets (seen
//! and predicted); the slider is the wide load bar under the scene.

use eframe::egui::{self, RichText};

use super::number_field::{NumberFields, refusal_ui};
use crate::app::View;
use crate::app::action::Actions;
use crate::app::speak::Speak as _;
use crate::app::state::{AppState, VISIBLE_FRACTION};
use crate::app::theme::{Theme, color};
use crate::format::{load_text, number_text};
use crate::i18n::Words;
use crate::i18n::{state_name, transition_text};
use crate::model::Key;
use crate::tr;

/// The load's number field.
#[derive(Default)]
pub struct LoadSection {
    field: NumberFields,
}

impl View for LoadSection {
    fn ui(&mut self, ui: &mut egui::Ui, state: &AppState, actions: &mut Actions, theme: &Theme) {
        self.field.prune(ui, state);
        let words = ui.words();
        ui.horizontal(|ui| {
            // The wide bar under the scene is the slider; this field takes a
            // typed load, also beyond the bar's range (not clamped).
            self.field
                .show(ui, state, actions, theme, Key::Load)
                .on_hover_text(tr!(words, "load-field.tooltip"));
            ui.label(tr!(words, "load-field"))
                .on_hover_text(tr!(words, "load-field.meaning"));
        });
        refusal_ui(ui, state, theme, Key::Load);
        let p = state.model().load_p();
        if let Some(roller) = state.model().roller() {
            ui.label(tr!(
                words,
                "roller-load",
                q = format!("{:.3}", p / roller.mu),
                mu = roller.mu.to_string()
            ))
            .on_hover_text(tr!(words, "roller-load.tooltip"));
        }
        // The notes below the field (the critical loads, a ramp's onsets,
        // warnings) take a fixed number of lines whatever their count, so
        // the fields under them stay where the hand is.
        let notes = notes(state, p, theme, ui.visuals().weak_text_color(), words);
        let row_height = ui.text_style_height(&egui::TextStyle::Body);
        let spacing = ui.spacing().item_spacing.y;
        let shown = notes.len().min(NOTE_LINES);
        let top = ui.cursor().top();
        for (i, note) in notes.iter().take(shown).enumerate() {
            let last_of_more = i + 1 == NOTE_LINES && notes.len() > NOTE_LINES;
            if last_of_more {
                let rest: Vec<&str> = notes[i..].iter().map(|n| n.text.as_str()).collect();
                ui.add(egui::Label::new(tr!(words, "notes-more", count = rest.len())).truncate())
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
fn transition_meaning(words: &'static Words, t: &crate::analysis::Transition) -> String {
    tr!(
        words,
        "transition-meaning",
        load = crate::format::load_text(t.load),
        from = state_name(words, t.from),
        to = state_name(words, t.to),
        how = words.get(&format!("transition-meaning.to-{}", t.to.name()))
    )
}

/// The notes under the load field, in order: the load beyond the plotted
/// range, the critical loads (or that a lesson hides them), a ramp's
/// onsets, the resolution warning.
fn notes(
    state: &AppState,
    p: f64,
    theme: &Theme,
    weak: egui::Color32,
    words: &'static Words,
) -> Vec<Note> {
    let mut notes = Vec::new();
    if p > state.load_max() {
        notes.push(Note::new(
            tr!(
                words,
                "load-beyond-range",
                load = number_text(p),
                end = number_text(state.load_max())
            ),
            color(theme.palette.warning),
        ));
    }
    if state.answer_hidden() {
        notes.push(Note::new(tr!(words, "critical-loads-hidden"), weak));
        if let Some(run) = state.ramp() {
            ramp_onset_notes(&mut notes, run.seen_at_p, None, theme, words);
        }
        return notes;
    }
    let Some(analysis) = state.analysis() else {
        return notes;
    };
    for t in &analysis.transitions {
        let mut note = Note::new(transition_text(words, t), theme.state_color(t.to));
        note.more = Some(transition_meaning(words, t));
        notes.push(note);
    }
    if let Some(run) = state.ramp() {
        ramp_onset_notes(
            &mut notes,
            run.seen_at_p,
            analysis.first_instability(),
            theme,
            words,
        );
    }
    if let Some(warning) = &analysis.warning {
        notes.push(Note {
            text: tr!(words, "not-resolved"),
            color: color(theme.palette.warning),
            more: Some(crate::i18n::not_resolved_words(words, warning)),
        });
    }
    notes
}

/// The ramp's onsets in words: where the motion was seen against where the
/// theory puts it, and why the first lags (on hover).
fn ramp_onset_notes(
    notes: &mut Vec<Note>,
    seen: Option<f64>,
    theory: Option<f64>,
    theme: &Theme,
    words: &'static Words,
) {
    let visible = tr!(
        words,
        "ramp-visible",
        percent = format!("{:.0}", 100.0 * VISIBLE_FRACTION)
    );
    if let Some(theory) = theory {
        notes.push(Note::new(
            tr!(words, "ramp-theory", load = load_text(theory)),
            color(theme.palette.text),
        ));
    }
    match seen {
        Some(seen) => {
            let late = theory.is_some_and(|theory| seen > theory);
            let load = load_text(seen);
            notes.push(Note {
                text: if late {
                    tr!(words, "ramp-seen-late", load = load, visible = visible)
                } else {
                    tr!(words, "ramp-seen", load = load, visible = visible)
                },
                color: color(theme.palette.measured),
                more: late.then(|| tr!(words, "ramp-seen-late.why")),
            });
        }
        None => notes.push(Note::new(
            tr!(words, "ramp-watching", visible = visible),
            color(theme.palette.text),
        )),
    }
}
