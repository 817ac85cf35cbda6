//! The Ziegler paradox: the load at which a column first loses stability,
//! with joint dampers of a given ratio, or with external drag and equal
//! joint dampers in a given ratio, as their level goes to zero (or a roller
//! as its mass goes to zero), next to the undamped value.

use std::sync::atomic::{AtomicBool, Ordering};

use crate::analysis::AnalysisError;
use crate::analysis::critical::first_loss_within;
use crate::analysis::crossing::Transition;
use crate::analysis::pencil::AffinePencil;
use crate::analysis::stability::State;
use crate::format::number_text;
use crate::model::{Axis, Key, Load, Model};

/// The lowest load in `[0, load_max]` at which `model` goes from stable to
/// unstable, if it does.
///
/// # Errors
/// A model the linear analysis refuses.
pub fn first_instability(model: &Model, load_max: f64) -> Result<Option<f64>, AnalysisError> {
    first_instability_on(model, load_max, 1)
}

/// [`first_instability`], a long chain's spectra computed on `threads`.
fn first_instability_on(
    model: &Model,
    load_max: f64,
    threads: usize,
) -> Result<Option<f64>, AnalysisError> {
    let pencil = AffinePencil::new(model)?.with_threads(threads);
    Ok(first_loss_within(&pencil, load_max)?.map(|t| t.load))
}

/// The load of the first change from stable to unstable among
/// `transitions` (in increasing load), if there is one.
#[must_use]
pub fn first_loss_of_stability(transitions: &[Transition]) -> Option<f64> {
    transitions
        .iter()
        .find(|t| t.from == State::Stable)
        .map(|t| t.load)
}

/// [`first_instability`] with joint dampers `g1 = ratio level`,
/// `g2 = level` (`g_i = c_i / sqrt(k m l^2)`, physics.md section 7).
///
/// # Errors
/// A ratio or level the model refuses, or a failed analysis.
pub fn flutter_load_damped(
    model: &Model,
    ratio: f64,
    level: f64,
    load_max: f64,
) -> Result<Option<f64>, AnalysisError> {
    first_instability(&damped(model, ratio, level)?, load_max)
}

/// `model` with joint dampers `g1 = ratio level`, `g2 = level`.
fn damped(model: &Model, ratio: f64, level: f64) -> Result<Model, AnalysisError> {
    let damped = Axis::DampingLevel.apply(model, level)?;
    Ok(Axis::DamperRatio.apply(&damped, ratio)?)
}

/// [`first_instability`] with equal joint dampers `g1 = g2 = level`
/// (the internal damping) and the external drag in the ratio `ratio` to
/// them: `c_ext l^3 = ratio c2`, with `l` the reference length. For
/// Ziegler's column its limit as `level` vanishes is in physics.md
/// section 7.
///
/// # Errors
/// A ratio or level the model refuses, or a failed analysis.
pub fn flutter_load_external(
    model: &Model,
    ratio: f64,
    level: f64,
    load_max: f64,
) -> Result<Option<f64>, AnalysisError> {
    first_instability(&externally_damped(model, ratio, level)?, load_max)
}

/// `model` with equal joint dampers `g1 = g2 = level` and the external
/// drag `c_ext l^3 = ratio c2`.
fn externally_damped(model: &Model, ratio: f64, level: f64) -> Result<Model, AnalysisError> {
    if !(ratio.is_finite() && ratio >= 0.0) {
        return Err(crate::model::ModelError::invalid(
            crate::model::Quantity::DragRatio,
            ratio,
            crate::model::Allowed::NonNegative,
        )
        .into());
    }
    let mut undamped = *model;
    undamped.column.c1_nms_per_rad = 0.0;
    undamped.column.c2_nms_per_rad = 0.0;
    let mut damped = Axis::DampingLevel.apply(&undamped, level)?;
    damped.column.drag_ns_per_m2 =
        ratio * damped.column.c2_nms_per_rad / damped.reference_length_m().powi(3);
    damped.validate()?;
    Ok(damped)
}

/// Points per curve.
const POINTS: usize = 41;
/// Joint damping levels g2 of the column curves, down to "vanishing".
const LEVELS: [f64; 3] = [0.1, 0.01, 1e-4];
/// log10 of the damper ratio c1/c2, and of the external to internal
/// damping ratio `c_ext l^3 / c`, shown.
const RATIO_DECADES: (f64, f64) = (-2.0, 2.0);
/// log10 of the roller's mass ratio nu shown.
const NU_DECADES: (f64, f64) = (-6.0, 1.0);
/// Curves closer than this, relative to their loads, are one curve.
const SAME_CURVE: f64 = 1e-6;
/// Which damping of a column with a tip force vanishes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum DampingKind {
    /// The joint dampers, in the ratio c1/c2.
    #[default]
    Joints,
    /// External drag along the rods and equal joint dampers (internal
    /// damping), in the ratio `c_ext l^3 / c`.
    External,
}

impl DampingKind {
    /// The current model's ratio, when it has this kind of damping.
    #[must_use]
    pub fn ratio(self, model: &Model) -> f64 {
        let c = &model.column;
        match self {
            Self::Joints if c.c2_nms_per_rad > 0.0 => c.c1_nms_per_rad / c.c2_nms_per_rad,
            Self::External if c.c2_nms_per_rad > 0.0 && c.c1_nms_per_rad == c.c2_nms_per_rad => {
                c.drag_ns_per_m2 * model.reference_length_m().powi(3) / c.c2_nms_per_rad
            }
            Self::Joints | Self::External => f64::NAN,
        }
    }
}

/// The ratio the explorer's x axis sweeps, for `model` itself: the
/// roller's mass ratio nu, or the damping ratio of `kind` (NaN when the
/// model has no such damping).
#[must_use]
pub fn swept_ratio(model: &Model, kind: DampingKind) -> f64 {
    match model.load {
        Load::Roller(_) => Axis::Key(Key::Nu).get(model),
        Load::Follower { .. } => kind.ratio(model),
    }
}

/// The model's own point on the explorer's plot: log10 of its swept ratio
/// and its first critical load (`known`, when the caller has found it
/// already; else found with a long chain's spectra on `threads`), or
/// `None` when it has no such ratio or never loses stability.
#[must_use]
pub fn own_point(
    model: &Model,
    kind: DampingKind,
    known: Option<f64>,
    threads: usize,
) -> Option<[f64; 2]> {
    let x = swept_ratio(model, kind);
    (x > 0.0 && x.is_finite())
        .then(|| {
            known.or_else(|| {
                first_instability_on(model, model.analysis_max_p(), threads)
                    .ok()
                    .flatten()
            })
        })
        .flatten()
        .map(|p| [x.log10(), p])
}

/// What a curve is, for its name in a legend (in the legend's language).
#[derive(Clone, Debug, PartialEq)]
pub enum CurveName {
    /// Damping at level `g2`.
    DampingLevel(f64),
    /// The band at this speed, in m/s.
    BandSpeed(f64),
    /// One curve for all these band speeds: the first critical load does
    /// not depend on V.
    AllBandSpeeds(Vec<f64>),
}

/// What the reference line is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ReferenceName {
    /// The column without damping.
    Undamped,
    /// The massless roller: the ideal follower force.
    MasslessRoller,
}

/// The ratio swept along the curves.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum SweptRatio {
    /// c1/c2.
    #[default]
    JointDampers,
    /// External drag over internal damping.
    ExternalOverInternal,
    /// The roller's mass, nu = m3/m.
    RollerMass,
}

/// What the explorer draws: curves of the first critical load against
/// log10 of the swept ratio, and the undamped (or massless) reference.
#[derive(Clone, Debug, Default)]
pub struct Curves {
    pub ratio: SweptRatio,
    pub lines: Vec<(CurveName, Vec<[f64; 2]>)>,
    pub reference: Option<(ReferenceName, f64)>,
    /// Why there is nothing to draw, if so.
    pub note: Option<NoCurve>,
}

/// Why the explorer has no curve to draw; its `Display` says it in English.
#[derive(Clone, Debug, PartialEq)]
pub enum NoCurve {
    /// A dead load never flutters: no paradox.
    DeadLoad,
    /// No point of any curve loses its stability up to `load_max`.
    StableThroughout { load_max: f64 },
    /// The first failure met on the curves.
    Failed(AnalysisError),
}

impl std::fmt::Display for NoCurve {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::DeadLoad => f.write_str(
                "A dead load (eta = 0) is conservative: it never flutters, so there is no paradox to show.",
            ),
            Self::StableThroughout { load_max } => write!(
                f,
                "No curve to draw: at every ratio shown the column keeps its stability up to p = {}.",
                number_text(*load_max)
            ),
            Self::Failed(error) => write!(f, "No curve to draw: {error}."),
        }
    }
}

impl Curves {
    /// Curves with `reference`; with a note instead when no line has a point.
    fn new(
        ratio: SweptRatio,
        lines: Vec<(CurveName, Vec<[f64; 2]>)>,
        failures: Vec<Option<AnalysisError>>,
        reference: Option<(ReferenceName, f64)>,
        load_max: f64,
    ) -> Self {
        let note = lines
            .iter()
            .all(|(_, points)| points.is_empty())
            .then(|| empty_reason(failures, load_max));
        Self {
            ratio,
            lines,
            reference,
            note,
        }
    }

    /// The height a plot of the curves fits: their highest point (and
    /// `here`, the model's own load), and the reference line's load only
    /// when it lies within `REFERENCE_REACH` times that. A reference far
    /// above (the massless roller's p = 2.09 over a roller whose curves
    /// stand near 0.1) would press the curves onto the axis's floor; it is
    /// then left above the axis and named with its value in the legend.
    /// Returns the height and whether the reference is within it.
    #[must_use]
    pub fn fitted_top(&self, here: Option<f64>) -> (f64, bool) {
        let curves = self
            .lines
            .iter()
            .flat_map(|(_, points)| points.iter().map(|p| p[1]))
            .chain(here)
            .fold(0.0, f64::max);
        match self.reference {
            Some((_, p)) if curves <= 0.0 || p <= REFERENCE_REACH * curves => (curves.max(p), true),
            _ => (curves, self.reference.is_none()),
        }
    }
}

/// How far above the curves a reference line may lie and still set the
/// plot's height: the curves then fill at least a third of it.
pub const REFERENCE_REACH: f64 = 3.0;

/// The points `(log10 x, first critical load)` of `load_at(x)` over
/// `decades`, leaving out values where the column never loses stability or
/// cannot be analysed (the first such reason is returned with them). Stops
/// computing (the rest left out) once `cancel` is set.
fn curve(
    decades: (f64, f64),
    cancel: &AtomicBool,
    load_at: impl Fn(f64) -> Result<Option<f64>, AnalysisError>,
) -> (Vec<[f64; 2]>, Option<AnalysisError>) {
    #[expect(clippy::cast_precision_loss, reason = "point counts")]
    let step = (decades.1 - decades.0) / (POINTS - 1) as f64;
    let mut failure = None;
    let points = (0..POINTS)
        .take_while(|_| !cancel.load(Ordering::Relaxed))
        .filter_map(|i| {
            #[expect(clippy::cast_precision_loss, reason = "point counts")]
            let e = decades.0 + step * i as f64;
            match load_at(10f64.powf(e)) {
                Ok(load) => load.map(|p| [e, p]),
                Err(error) => {
                    failure.get_or_insert(error);
                    None
                }
            }
        })
        .collect();
    (points, failure)
}

/// Why a plot with no point at all is empty: the first failure, or that
/// no point loses stability below `load_max`.
fn empty_reason(
    failures: impl IntoIterator<Item = Option<AnalysisError>>,
    load_max: f64,
) -> NoCurve {
    failures
        .into_iter()
        .flatten()
        .next()
        .map_or(NoCurve::StableThroughout { load_max }, NoCurve::Failed)
}

/// The explorer's curves for `model` (its load and the swept parameters are
/// set by the curves themselves), a long chain's spectra computed on
/// `threads`. Once `cancel` is set the curves end early: a cancelled result
/// is for no one.
#[must_use]
pub fn curves(model: &Model, kind: DampingKind, threads: usize, cancel: &AtomicBool) -> Curves {
    // The first loss of stability is sought over the column's own range, as
    // `critical` does by default (a chain of 16 rods searched over two rods' range, 64
    // times its own, took ten minutes per picture).
    let load_max = model.analysis_max_p();
    let first_on = |m: &Model| first_instability_on(m, load_max, threads);
    let first = |m: &Model| first_on(m).ok().flatten();
    match model.load {
        Load::Follower { eta: 0.0, .. } => Curves {
            note: Some(NoCurve::DeadLoad),
            ..Curves::default()
        },
        Load::Follower { .. } => {
            let undamped = Axis::DampingLevel
                .apply(model, 0.0)
                .ok()
                .and_then(|m| first(&m));
            let (lines, failures): (Vec<_>, Vec<_>) = LEVELS
                .iter()
                .map(|&level| {
                    let (points, failure) = curve(RATIO_DECADES, cancel, |ratio| match kind {
                        DampingKind::Joints => first_on(&damped(model, ratio, level)?),
                        DampingKind::External => first_on(&externally_damped(model, ratio, level)?),
                    });
                    ((CurveName::DampingLevel(level), points), failure)
                })
                .unzip();
            let ratio = match kind {
                DampingKind::Joints => SweptRatio::JointDampers,
                DampingKind::External => SweptRatio::ExternalOverInternal,
            };
            Curves::new(
                ratio,
                lines,
                failures,
                undamped.map(|p| (ReferenceName::Undamped, p)),
                load_max,
            )
        }
        Load::Roller(roller) => {
            let v = roller.band_speed_m_per_s;
            let massless = Axis::Key(Key::Nu)
                .apply(model, 0.0)
                .ok()
                .and_then(|m| first(&m));
            let (lines, failures): (Vec<_>, Vec<_>) = [0.1 * v, v, 10.0 * v]
                .iter()
                .map(|&speed| {
                    let (points, failure) = curve(NU_DECADES, cancel, |nu| {
                        let m = Axis::Key(Key::V).apply(model, speed)?;
                        let m = Axis::Key(Key::Nu).apply(&m, nu)?;
                        first_on(&m)
                    });
                    ((speed, points), failure)
                })
                .unzip();
            Curves::new(
                SweptRatio::RollerMass,
                merge_if_one_curve(lines),
                failures,
                massless.map(|p| (ReferenceName::MasslessRoller, p)),
                load_max,
            )
        }
    }
}

/// The band speeds' `lines`, each named by its speed, or the one curve
/// they all draw (the same points, loads within [`SAME_CURVE`]) named by
/// them all.
fn merge_if_one_curve(lines: Vec<(f64, Vec<[f64; 2]>)>) -> Vec<(CurveName, Vec<[f64; 2]>)> {
    let by_speed = |lines: Vec<(f64, Vec<[f64; 2]>)>| {
        lines
            .into_iter()
            .map(|(speed, points)| (CurveName::BandSpeed(speed), points))
            .collect()
    };
    let Some((_, first)) = lines.first() else {
        return by_speed(lines);
    };
    let same = |points: &Vec<[f64; 2]>| {
        points.len() == first.len()
            && points.iter().zip(first).all(|(a, b)| {
                a[0] == b[0] && (a[1] - b[1]).abs() <= SAME_CURVE * a[1].abs().max(b[1].abs())
            })
    };
    if lines.len() < 2 || first.is_empty() || !lines.iter().all(|(_, points)| same(points)) {
        return by_speed(lines);
    }
    let speeds = lines.iter().map(|(speed, _)| *speed).collect();
    let points = first.clone();
    vec![(CurveName::AllBandSpeeds(speeds), points)]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::PresetId;

    fn roller_with(key: Key, value: f64) -> Model {
        Axis::Key(key)
            .apply(&PresetId::Roller.model(), value)
            .unwrap()
    }

    /// The roller's first critical load is the same at every band speed
    /// (computed, not assumed): the three curves are drawn as one, and the
    /// legend says so; curves that differ stay apart.
    #[test]
    fn the_roller_s_band_speeds_draw_one_curve_and_say_why() {
        let curves = curves(
            &PresetId::Roller.model(),
            DampingKind::Joints,
            1,
            &AtomicBool::new(false),
        );
        assert_eq!(curves.lines.len(), 1, "{:?}", curves.lines);
        let (name, points) = &curves.lines[0];
        assert!(
            matches!(name, CurveName::AllBandSpeeds(v) if v.len() == 3),
            "{name:?}"
        );
        assert_eq!(points.len(), POINTS);
        let apart = vec![
            (0.1, vec![[0.0, 1.0], [1.0, 2.0]]),
            (1.0, vec![[0.0, 1.0], [1.0, 2.001]]),
        ];
        assert_eq!(merge_if_one_curve(apart).len(), 2);
    }

    /// A stopped band has no linear analysis: the panel says so instead of
    /// claiming that the column never loses stability.
    #[test]
    fn a_stopped_band_leaves_the_plot_empty_with_the_reason() {
        let curves = curves(
            &roller_with(Key::V, 0.0),
            DampingKind::Joints,
            1,
            &AtomicBool::new(false),
        );
        let note = curves.note.unwrap().to_string();
        assert!(note.contains("V = 0"), "{note}");
    }

    /// External and internal damping vanishing together: the curve of the
    /// smallest level follows the Routh-Hurwitz limit (physics.md section
    /// 7), from near internal damping's 41/28 at small ratios toward
    /// external damping's 2 at large ones, below the undamped 7/2 - sqrt 2
    /// that the reference line shows.
    #[test]
    fn external_damping_curves_follow_the_vanishing_damping_limit() {
        let limit = |r: f64| {
            let a = 15.0 * r * r + 210.0 * r;
            let b = -(104.0 * r * r + 1467.0 * r + 504.0);
            let c = 148.0 * r * r + 2214.0 * r + 738.0;
            (-b - (b * b - 4.0 * a * c).sqrt()) / (2.0 * a)
        };
        let curves = curves(
            &PresetId::Ziegler1952.model(),
            DampingKind::External,
            1,
            &AtomicBool::new(false),
        );
        let (_, vanishing) = curves.lines.last().unwrap();
        assert_eq!(vanishing.len(), POINTS);
        for point in vanishing {
            let expected = limit(10f64.powf(point[0]));
            assert!(
                (point[1] - expected).abs() < 1e-3,
                "{point:?} vs {expected}"
            );
        }
        assert!((vanishing[0][1] - 41.0 / 28.0).abs() < 0.02);
        assert!((vanishing[POINTS - 1][1] - 2.0).abs() < 0.03);
        let undamped = curves.reference.as_ref().unwrap().1;
        assert!((undamped - (3.5 - 2f64.sqrt())).abs() < 1e-9);
        // The undamped 2.09 lies among the curves (up to 3.5): it is within
        // the plot's height, and its name says no more.
        let (top, within) = curves.fitted_top(None);
        assert!(within && top >= undamped, "{top}");
    }

    /// The plain roller's curves stand far below the massless roller's
    /// load (the ideal follower's 2.09): the plot's height follows the
    /// curves and the reference is named above the axis, with its value;
    /// a model's own point above the curves still fits.
    #[test]
    fn a_reference_far_above_the_curves_is_left_above_the_axis() {
        let curves = curves(
            &PresetId::Roller.model(),
            DampingKind::Joints,
            1,
            &AtomicBool::new(false),
        );
        let highest = curves
            .lines
            .iter()
            .flat_map(|(_, points)| points.iter().map(|p| p[1]))
            .fold(0.0, f64::max);
        let massless = curves.reference.as_ref().unwrap().1;
        assert!(massless > REFERENCE_REACH * highest, "{massless} {highest}");
        assert_eq!(curves.fitted_top(None), (highest, false));
        assert!(curves.fitted_top(Some(2.0 * highest)).0 >= 2.0 * highest);
    }
}
