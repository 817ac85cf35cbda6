//! The paradox curves described once: the first critical load against the
//! swept ratio on a log axis, one curve per damping level (or band speed),
//! the undamped (or massless) reference dashed, and the model's own point.

use std::sync::atomic::AtomicBool;

use super::spec::{Entry, Ink, Mark, OffView, Plot, Sheet, Size, Swatch, Ticks, View, Weight};
use crate::analysis::{
    CurveName, Curves, DampingKind, ReferenceName, SweptRatio, own_point, paradox_curves,
};
use crate::format::{load_text, number_text};
use crate::i18n::Words;
use crate::model::Model;
use crate::tr;

/// The plot's height over its highest point.
const HEADROOM: f64 = 1.1;

/// Room left and right of the curves, as a fraction of their extent (the
/// first decade's label clear of the load axis's zero).
const SIDE_ROOM: f64 = 0.02;

/// The explorer's curves and the model's own point `[log10 ratio, load]`,
/// gathered as a figure gathers them (the window's tab finds the same two
/// in the background).
#[derive(Clone, Debug)]
pub struct ParadoxData {
    pub curves: Curves,
    pub here: Option<[f64; 2]>,
}

impl ParadoxData {
    /// The curves of `model` for damping of `kind` (the roller's: its mass
    /// ratio and band speed), and the model's own first critical load,
    /// computed on `threads`.
    #[must_use]
    pub fn new(model: &Model, kind: DampingKind, threads: usize) -> Self {
        let curves = paradox_curves(model, kind, threads, &AtomicBool::new(false));
        let here = own_point(model, kind, None, threads);
        Self { curves, here }
    }

    /// The curves' sheet in `words`.
    #[must_use]
    pub fn sheet(&self, words: &'static Words) -> Sheet {
        Paradox {
            curves: &self.curves,
            here: self.here,
            words,
        }
        .sheet()
    }
}

/// The curves and the model's own point `[log10 ratio, load]`, if it has one.
#[derive(Clone, Copy, Debug)]
pub struct Paradox<'a> {
    pub curves: &'a Curves,
    pub here: Option<[f64; 2]>,
    /// The language of the axes and the legend.
    pub words: &'static Words,
}

impl Paradox<'_> {
    /// A curve's name in the legend's language.
    fn curve_name(&self, name: &CurveName) -> String {
        let words = self.words;
        let speed = |v: f64| tr!(words, "paradox-curve-speed", speed = number_text(v));
        match name {
            CurveName::DampingLevel(level) => {
                tr!(words, "paradox-curve-damping", level = number_text(*level))
            }
            CurveName::BandSpeed(v) => speed(*v),
            CurveName::AllBandSpeeds(speeds) => tr!(
                words,
                "paradox-curve-all-speeds",
                speeds = speeds
                    .iter()
                    .map(|&v| speed(v))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        }
    }

    /// The reference line's name in the legend, with its load, and said to
    /// lie above the axis unless `within` (the second answer of
    /// [`crate::analysis::Curves::fitted_top`]).
    fn reference_label(&self, within: bool) -> Option<String> {
        let words = self.words;
        let (name, p) = self.curves.reference.as_ref()?;
        let name = words.get(match name {
            ReferenceName::Undamped => "paradox-reference-undamped",
            ReferenceName::MasslessRoller => "paradox-reference-massless",
        });
        let load = load_text(*p);
        Some(if within {
            tr!(words, "paradox-reference", name = name, load = load)
        } else {
            tr!(words, "paradox-reference-above", name = name, load = load)
        })
    }

    /// The legend and the plot; no plot when the curves have no extent
    /// along the ratio.
    #[must_use]
    pub fn sheet(&self) -> Sheet {
        Sheet {
            legend: self.legend(),
            plots: self.plot().into_iter().collect(),
        }
    }

    /// The plot, fitted to the curves and the model's point (the reference
    /// line only when it lies near them: [`Curves::fitted_top`]); `None`
    /// when the curves have no extent along the ratio.
    fn plot(&self) -> Option<Plot> {
        let curves = self.curves;
        let (x0, x1) = curves
            .lines
            .iter()
            .flat_map(|(_, points)| points.iter().map(|p| p[0]))
            .chain(self.here.map(|h| h[0]))
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| {
                (lo.min(x), hi.max(x))
            });
        if !(x0.is_finite() && x1 > x0) {
            return None;
        }
        let (highest, reference_within) = curves.fitted_top(self.here.map(|h| h[1]));
        let mut marks = Vec::new();
        if let Some((_, p)) = curves.reference.as_ref().filter(|_| reference_within) {
            marks.push(Mark::Horizontal {
                y: *p,
                ink: Ink::Reference,
                weight: Weight::Fine,
                dashed: true,
            });
        }
        marks.extend(
            curves
                .lines
                .iter()
                .enumerate()
                .map(|(k, (_, points))| Mark::Line {
                    points: points.clone(),
                    ink: Ink::Series(k),
                    weight: Weight::Layered(k),
                    dashed: false,
                }),
        );
        if let Some(here) = self.here {
            marks.push(Mark::Markers {
                points: vec![here],
                ink: Ink::Now,
                size: Size::Regular,
                filled: true,
                off_view: OffView::Hidden,
            });
        }
        Some(Plot {
            id: "paradox",
            x_label: tr!(
                self.words,
                "axis-log-scale",
                axis = self.words.get(match curves.ratio {
                    SweptRatio::JointDampers => "paradox-ratio-joints",
                    SweptRatio::ExternalOverInternal => "paradox-ratio-external",
                    SweptRatio::RollerMass => "paradox-ratio-roller-mass",
                })
            ),
            y_label: tr!(self.words, "axis-first-critical-load"),
            x_ticks: Ticks::Decades,
            view: View::Ranges {
                x: (x0 - SIDE_ROOM * (x1 - x0), x1 + SIDE_ROOM * (x1 - x0)),
                y: (0.0, HEADROOM * highest.max(1e-9)),
            },
            marks,
            far_left: Vec::new(),
        })
    }

    /// The legend: each curve, the reference (said to lie above the axis
    /// when it is not drawn) and the model's own load.
    fn legend(&self) -> Vec<Entry> {
        let curves = self.curves;
        let mut entries: Vec<Entry> = curves
            .lines
            .iter()
            .enumerate()
            .map(|(k, (name, _))| Entry::new(Swatch::Line(Ink::Series(k)), self.curve_name(name)))
            .collect();
        let (_, reference_within) = curves.fitted_top(self.here.map(|h| h[1]));
        if let Some(name) = self.reference_label(reference_within) {
            entries.push(Entry::new(Swatch::Dashed(Ink::Reference), name));
        }
        if let Some([_, p]) = self.here {
            entries.push(Entry::new(
                Swatch::Marker(Ink::Now, true),
                tr!(self.words, "legend-this-model", load = load_text(p)),
            ));
        }
        entries
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::i18n::{Language, words};

    /// The legend names each curve and the reference in the language
    /// asked for, and says when the reference lies above the axis.
    #[test]
    fn the_legend_names_the_curves_and_the_reference_in_its_language() {
        let curves = Curves {
            ratio: SweptRatio::RollerMass,
            lines: vec![(
                CurveName::AllBandSpeeds(vec![0.01, 0.1, 1.0]),
                vec![[-2.0, 0.01], [0.0, 0.02]],
            )],
            reference: Some((ReferenceName::MasslessRoller, 2.0858)),
            note: None,
        };
        let legend = |language| {
            let paradox = Paradox {
                curves: &curves,
                here: None,
                words: words(language),
            };
            paradox
                .legend()
                .into_iter()
                .map(|e| e.text)
                .collect::<Vec<_>>()
        };
        assert_eq!(
            legend(Language::English),
            [
                "V = 0.01 m/s, V = 0.1 m/s, V = 1 m/s: one curve, the first critical load does not depend on V",
                "nu = 0: the ideal follower: p = 2.0858 (above the axis)",
            ]
        );
        let french = legend(Language::French);
        assert!(french[0].contains("ne dépend pas de V"), "{french:?}");
        assert!(french[1].ends_with("(au-dessus de l'axe)"), "{french:?}");
    }
}
