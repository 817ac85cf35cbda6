//! Speed, measured in this process: the analysis core, both engines and the
//! app's frame time, as the numbers `zieglerlab bench` prints.
//!
//! Wall times on a shared machine wander; every figure but the frame
//! quantiles is the median of several repetitions, so one busy moment does
//! not move it.

#![expect(
    clippy::cast_precision_loss,
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    reason = "repetition counts and quantile indices are small"
)]

use std::hint::black_box;
use std::time::Instant;

use anyhow::Result;
use eframe::egui::{self, RawInput, Rect, pos2};
use serde::Serialize;

use std::sync::atomic::{AtomicBool, AtomicUsize};

use crate::analysis::{AffinePencil, MapSpec, compute_map, critical_loads, load_grid, locus};
use crate::app::{Action, Settings, Tab, ZieglerApp};
use crate::model::{AsValid as _, Assignment, Axis, Key, Model, PresetId, apply_assignments};
use crate::plot::locus::{Layer, Loci, Part, Present};
use crate::plot::spec::Medium;
use crate::sim::{DEFAULT_STEP_SECS, EngineKind, Simulation, initial_state};

mod numpy;
use numpy::{numpy_chain_scan_ms, numpy_eig_us_per_pencil};

/// Loads of the benchmarked root loci, over the column's analysis range
/// (`Model::analysis_max_p`).
pub const LOCUS_LOADS: usize = 1000;
/// Pencils solved for the bare eigenvalue throughput.
pub const EIG_PENCILS: usize = 100_000;
/// Simulated time per engine run, in s.
const SIM_SECS: f64 = 10.0;
/// The default launch: roller in weak flutter at p = 1.
const SIM_LOAD_P: f64 = 1.0;
/// Frames timed by default, after [`WARMUP_FRAMES`] untimed ones.
pub const FRAMES: usize = 300;
const WARMUP_FRAMES: usize = 10;
/// The window size of the timed frames, in points.
const FRAME_SIZE: [f32; 2] = [1280.0, 800.0];

/// What `zieglerlab bench` reports (the JSON keys are the field names).
#[derive(Clone, Copy, Debug, Serialize)]
pub struct Report {
    /// Tracked root locus of `roller`, 1000 loads: µs per load.
    pub locus_us_per_load: f64,
    /// The same for `midpoint-masses`.
    pub locus2_us_per_load: f64,
    /// Eigenvalues alone of 100000 `roller` pencils: µs per pencil.
    pub eig_us_per_pencil: f64,
    /// Critical loads of `roller` for p in [0, 10]: ms.
    pub critical_ms: f64,
    /// Critical loads of a chain of 32 uniform rods over `critical`'s
    /// default range (P L^2/EI from 0 to 40), locus and all: ms.
    pub critical_chain32_ms: f64,
    /// Simulated seconds per wall second, reference engine, app's step.
    pub sim_reference_x_realtime: f64,
    /// The same for the rapier engine.
    pub sim_rapier_x_realtime: f64,
    /// Headless frame time of the app at 1280x800, nu moving every frame.
    pub frame_ms_p50: f64,
    pub frame_ms_p99: f64,
    /// The stability-map tab open with rho dragged (nu is its own axis; rho
    /// restarts it every frame): 99th percentile.
    pub frame_ms_p99_map: f64,
    /// The same drag with the paradox tab open: 99th percentile.
    pub frame_ms_p99_paradox: f64,
    /// The `beck` preset (16 rods, reference engine), its load dragged: p99.
    pub frame_ms_p99_chain16: f64,
    /// The locus tab's sheet of the `beck` preset (32 branches) built whole,
    /// as every frame built it before the analysis's part was kept: ms.
    pub locus_sheet_ms_chain16: f64,
    /// The same sheet as a frame makes it now: the kept part copied and the
    /// present added: ms.
    pub locus_sheet_kept_ms_chain16: f64,
    /// The 256x256 roller map (load 0-8 against nu 0.005-1) on every core: ms.
    pub map_ms: f64,
    /// numpy's batched `eigvals` on the roller's 6x6 companion matrices at
    /// the locus's 1000 loads, measured in this run: µs per matrix (null
    /// without python3 and numpy).
    pub numpy_eig_us_per_pencil: Option<f64>,
    /// `numpy_eig_us_per_pencil / locus_us_per_load`.
    pub locus_speedup_vs_numpy: Option<f64>,
    /// A plain numpy scan for the first flutter load of the same 32-rod
    /// chain, measured in this run: 400 loads' eigenvalues of `M^-1 K` in one
    /// batched call, then 50 bisection steps; ms (null without numpy).
    pub numpy_chain32_scan_ms: Option<f64>,
    /// `critical_chain32_ms / numpy_chain32_scan_ms`: at most 1 when every
    /// change of stability comes as fast as numpy's first one.
    pub critical_chain32_over_numpy: Option<f64>,
    /// The real window (the default launch, the default renderer) at
    /// 1280x800, repainted continuously: frames drawn per second, drawing
    /// and buffer swap included (null without a display, or when skipped).
    pub window_fps: Option<f64>,
    /// The same window's frame interval: 99th percentile, ms.
    pub window_frame_ms_p99: Option<f64>,
    /// The window at 1920x1080: frames drawn per second.
    pub window_fps_1920x1080: Option<f64>,
    /// The window at 1920x1080: frame interval, 99th percentile, ms.
    pub window_frame_ms_p99_1920x1080: Option<f64>,
    /// The window at 1920x1080 in projector mode with the `beck` preset
    /// (16 rods on the reference engine): frames drawn per second.
    pub window_fps_chain16_projector_1920x1080: Option<f64>,
    /// Its frame interval, 99th percentile, ms.
    pub window_frame_ms_p99_chain16_projector_1920x1080: Option<f64>,
    /// The limit cycles of `bifurcation` for a chain of 16 uniform rods
    /// with joint dampers 0.05 over its load bar: every branch followed,
    /// s (null when skipped).
    pub bifurcation_chain16_s: Option<f64>,
}

/// Frames timed in each real window.
pub const WINDOW_FRAMES: usize = 240;

/// Frames per second and the p99 frame interval (ms) of the default launch
/// in a real window of `size` points drawn by `renderer`; `None` when there
/// is no display to open it on.
///
/// # Errors
/// A display that is there but gives no window or graphics context.
pub fn window_figures(
    renderer: crate::app::Renderer,
    size: [f32; 2],
    frames: usize,
    settings: Settings,
) -> Result<Option<(f64, f64)>> {
    let has_display = ["DISPLAY", "WAYLAND_DISPLAY"]
        .iter()
        .any(|var| std::env::var_os(var).is_some_and(|v| !v.is_empty()));
    if !has_display {
        return Ok(None);
    }
    let timed = crate::app::time_window_frames(renderer, size, frames, settings)
        .map_err(|why| anyhow::anyhow!("the timed window: {why}"))?;
    let total_secs: f64 = timed.intervals_ms.iter().sum::<f64>() / 1e3;
    Ok(Some((
        timed.intervals_ms.len() as f64 / total_secs,
        quantile(&timed.intervals_ms, 0.99),
    )))
}

/// Runs every measurement; `frames` frames are timed headless, the real
/// window too when `window` is set and there is a display, and the 16-rod
/// chain's limit cycles when `cycles` is set.
///
/// # Errors
/// A preset or a computation that fails (none should), or a display that
/// gives no window.
pub fn run(frames: usize, window: bool, cycles: bool) -> Result<Report> {
    let (small, large, chain_window) = if window {
        let renderer = crate::app::Renderer::default();
        let large = [1920.0, 1080.0];
        (
            window_figures(renderer, FRAME_SIZE, WINDOW_FRAMES, Settings::default())?,
            window_figures(renderer, large, WINDOW_FRAMES, Settings::default())?,
            window_figures(renderer, large, WINDOW_FRAMES, chain16_projector())?,
        )
    } else {
        (None, None, None)
    };
    let bifurcation_s = if cycles {
        Some(bifurcation_chain16_s()?)
    } else {
        None
    };
    let roller = pencil(PresetId::Roller)?;
    let midpoint = pencil(PresetId::MidpointMasses)?;
    let frame_ms = frame_times_ms(frames, Tab::Locus)?;
    let frame_ms_map = frame_times_ms(frames, Tab::Map)?;
    let frame_ms_paradox = frame_times_ms(frames, Tab::Paradox)?;
    let frame_ms_chain = chain_frame_times_ms(frames)?;
    let (sheet_ms, kept_ms) = locus_sheet_ms_chain16()?;
    let locus_us = locus_us_per_load(&roller)?;
    let numpy_us = numpy_eig_us_per_pencil(&roller)?;
    let chain = chain32()?;
    let chain_ms = critical_chain32_ms(&chain)?;
    let numpy_chain_ms = numpy_chain_scan_ms(&chain)?;
    Ok(Report {
        locus_us_per_load: locus_us,
        locus2_us_per_load: locus_us_per_load(&midpoint)?,
        eig_us_per_pencil: eig_us_per_pencil(&roller)?,
        critical_ms: critical_ms(&roller)?,
        critical_chain32_ms: chain_ms,
        sim_reference_x_realtime: x_realtime(EngineKind::Reference)?,
        sim_rapier_x_realtime: x_realtime(EngineKind::Rapier)?,
        frame_ms_p50: quantile(&frame_ms, 0.5),
        frame_ms_p99: quantile(&frame_ms, 0.99),
        frame_ms_p99_map: quantile(&frame_ms_map, 0.99),
        frame_ms_p99_paradox: quantile(&frame_ms_paradox, 0.99),
        frame_ms_p99_chain16: quantile(&frame_ms_chain, 0.99),
        locus_sheet_ms_chain16: sheet_ms,
        locus_sheet_kept_ms_chain16: kept_ms,
        map_ms: map_ms()?,
        numpy_eig_us_per_pencil: numpy_us,
        locus_speedup_vs_numpy: numpy_us.map(|numpy| numpy / locus_us),
        numpy_chain32_scan_ms: numpy_chain_ms,
        critical_chain32_over_numpy: numpy_chain_ms.map(|numpy| chain_ms / numpy),
        window_fps: small.map(|(fps, _)| fps),
        window_frame_ms_p99: small.map(|(_, p99)| p99),
        window_fps_1920x1080: large.map(|(fps, _)| fps),
        window_frame_ms_p99_1920x1080: large.map(|(_, p99)| p99),
        window_fps_chain16_projector_1920x1080: chain_window.map(|(fps, _)| fps),
        window_frame_ms_p99_chain16_projector_1920x1080: chain_window.map(|(_, p99)| p99),
        bifurcation_chain16_s: bifurcation_s,
    })
}

/// The `beck` preset (16 rods on the reference engine) in projector mode.
#[must_use]
pub fn chain16_projector() -> Settings {
    Settings {
        preset: PresetId::Beck,
        model: PresetId::Beck.model(),
        engine: EngineKind::Reference,
        projector: true,
        ..Settings::default()
    }
}

/// The time `bifurcation` spends on the limit cycles of a chain of 16
/// uniform rods with joint dampers 0.05 over its load bar (every branch
/// from every flutter onset, followed by shooting and continuation), s.
fn bifurcation_chain16_s() -> Result<f64> {
    let mut model = PresetId::UniformRods.model();
    model.column.rods = 16;
    model.column.c1_nms_per_rad = 0.05;
    model.column.c2_nms_per_rad = 0.05;
    let load_max = model.load_bar_max_p();
    let start = Instant::now();
    let branches = crate::analysis::cycle_branches(&model, 0.0, load_max, &AtomicBool::new(false))?;
    let secs = start.elapsed().as_secs_f64();
    if !branches.iter().any(|onset| onset.branch.is_ok()) {
        anyhow::bail!("the 16-rod chain gave no branch of cycles");
    }
    Ok(secs)
}

/// The map of the app's stability-map tab for `roller`: 256 loads in
/// [0, 8] against 256 values of nu in [0.005, 1].
#[must_use]
pub fn roller_map_spec() -> MapSpec {
    MapSpec {
        axis: Axis::Key(Key::Nu),
        model: PresetId::Roller.model(),
        load_range: (0.0, 8.0),
        loads: 256,
        axis_range: (0.005, 1.0),
        values: 256,
    }
}

/// [`roller_map_spec`] on every core.
fn map_ms() -> Result<f64> {
    let spec = roller_map_spec();
    let threads = crate::machine_threads();
    let secs = median_secs(3, || {
        let (cancel, done) = (AtomicBool::new(false), AtomicUsize::new(0));
        compute_map(&spec, threads, &cancel, &done, &|_, row| {
            drop(black_box(row));
        })?;
        Ok(())
    })?;
    Ok(secs * 1e3)
}

fn pencil(id: PresetId) -> Result<AffinePencil> {
    Ok(AffinePencil::new(&id.model())?.with_threads(crate::machine_threads()))
}

/// The locus tab's sheet of the `beck` preset (16 rods: 32 branches, the
/// window's locus of it) at half its load bar, ms: built whole with the
/// present, and made as a frame makes it from the kept part (a copy, the
/// present added). Medians of 50 each.
///
/// # Errors
/// The preset's analysis failing (it should not).
fn locus_sheet_ms_chain16() -> Result<(f64, f64)> {
    let model = PresetId::Beck.model().into_valid()?;
    let (pencil, along) = crate::app::window_locus(&model)?;
    let words = crate::i18n::words(crate::i18n::Language::English);
    let loci = Loci {
        main: Layer {
            name: "",
            locus: &along.locus,
            transitions: &along.transitions,
            ranges: &along.ranges,
            at_transitions: &[],
        },
        others: Vec::new(),
        medium: Medium::Window,
        words,
    };
    let load = 0.5 * model.load_bar_max_p();
    let now = pencil.spectrum(load)?.eigenvalues;
    let present = Present {
        load,
        eigenvalues: &now,
        measured: None,
    };
    let whole = median_secs(50, || {
        let mut sheet = loci.sheet(Part::All);
        present.mark(&mut sheet, words);
        black_box(sheet);
        Ok(())
    })?;
    let kept = loci.sheet(Part::All);
    let frame = median_secs(50, || {
        let mut sheet = kept.clone();
        present.mark(&mut sheet, words);
        black_box(sheet);
        Ok(())
    })?;
    Ok((whole * 1e3, frame * 1e3))
}

/// The median wall time of `repeats` calls of `f`, in s.
fn median_secs(repeats: usize, mut f: impl FnMut() -> Result<()>) -> Result<f64> {
    // One untimed call: caches, lazy statics, page faults.
    f()?;
    let mut secs = Vec::with_capacity(repeats);
    for _ in 0..repeats {
        let start = Instant::now();
        f()?;
        secs.push(start.elapsed().as_secs_f64());
    }
    Ok(quantile(&secs, 0.5))
}

/// The `q` quantile of `values` (nearest rank); NaN for none.
#[must_use]
pub fn quantile(values: &[f64], q: f64) -> f64 {
    let mut sorted = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    match sorted.len() {
        0 => f64::NAN,
        n => sorted[(q.clamp(0.0, 1.0) * (n - 1) as f64).round() as usize],
    }
}

fn locus_us_per_load(pencil: &AffinePencil) -> Result<f64> {
    let secs = median_secs(31, || {
        black_box(locus(pencil, 0.0, pencil.natural_load_max(), LOCUS_LOADS)?);
        Ok(())
    })?;
    Ok(secs * 1e6 / LOCUS_LOADS as f64)
}

fn eig_us_per_pencil(pencil: &AffinePencil) -> Result<f64> {
    let loads = load_grid(0.0, pencil.natural_load_max(), EIG_PENCILS)?;
    let secs = median_secs(3, || {
        for &p in &loads {
            black_box(pencil.spectrum(black_box(p))?);
        }
        Ok(())
    })?;
    Ok(secs * 1e6 / EIG_PENCILS as f64)
}

fn critical_ms(pencil: &AffinePencil) -> Result<f64> {
    let secs = median_secs(31, || {
        black_box(critical_loads(pencil, 0.0, pencil.natural_load_max())?);
        Ok(())
    })?;
    Ok(secs * 1e3)
}

/// Rods of the benchmarked chain.
const CHAIN_RODS: f64 = 32.0;

/// The benchmarked chain's pencil and `critical`'s default load range.
struct Chain {
    pencil: AffinePencil,
    load_max: f64,
}

fn chain32() -> Result<Chain> {
    let mut chain = PresetId::UniformRods.model();
    apply_assignments(
        &mut chain,
        &[Assignment {
            key: Key::Rods,
            value: CHAIN_RODS,
        }],
    )?;
    Ok(Chain {
        pencil: AffinePencil::new(&chain)?.with_threads(crate::machine_threads()),
        load_max: chain.analysis_max_p(),
    })
}

fn critical_chain32_ms(chain: &Chain) -> Result<f64> {
    let secs = median_secs(5, || {
        black_box(critical_loads(&chain.pencil, 0.0, chain.load_max)?);
        Ok(())
    })?;
    Ok(secs * 1e3)
}

/// Simulated seconds per wall second of `engine` for the default launch.
fn x_realtime(engine: EngineKind) -> Result<f64> {
    let model: Model = PresetId::Roller.model().at_load(SIM_LOAD_P);
    let secs = median_secs(5, || {
        let x0 = initial_state(&model, 1e-3);
        let mut sim = Simulation::new(model, engine, x0, DEFAULT_STEP_SECS)?;
        black_box(sim.run(SIM_SECS, |_| ()));
        Ok(())
    })?;
    Ok(SIM_SECS / secs)
}

/// The wall time of `frames` headless frames of the whole app at 1280x800
/// with `tab` open below, in ms, with nu swept 0.05 .. 0.35 and back as a
/// dragged slider does (so the locus and the critical loads are recomputed
/// every frame, and the paradox curves restart off the UI thread): the
/// simulation's advance by 1/60 s, the egui pass and tessellation. The
/// GPU's share (a few thousand triangles) is not included. With the map
/// open rho is swept 0.05 .. 0.35 instead: nu is the map's own axis (a drag
/// along it only moves the map's marker), rho restarts the map every frame
/// and its rows come in as the frames go on.
///
/// # Errors
/// The app refusing its defaults or a swept value (neither should happen).
pub fn frame_times_ms(frames: usize, tab: Tab) -> Result<Vec<f64>> {
    let key = if tab == Tab::Map { Key::Rho } else { Key::Nu };
    drag_frame_times_ms(frames, Settings::default(), tab, (key, 0.05, 0.35))
}

/// The same for the `beck` preset (16 rods on the reference engine) with
/// the load swept over its slider as a dragged load bar does.
///
/// # Errors
/// The app refusing the preset or a load (neither should happen).
pub fn chain_frame_times_ms(frames: usize) -> Result<Vec<f64>> {
    let model = PresetId::Beck.model();
    let settings = Settings {
        preset: PresetId::Beck,
        model,
        engine: EngineKind::Reference,
        ..Settings::default()
    };
    let load_max = model.load_bar_max_p();
    drag_frame_times_ms(frames, settings, Tab::Locus, (Key::Load, 0.0, load_max))
}

/// Frame times of the app from `settings` with `tab` open, with `key`
/// swept from `low` to `high` and back over 120 frames.
fn drag_frame_times_ms(
    frames: usize,
    settings: Settings,
    tab: Tab,
    (key, low, high): (Key, f64, f64),
) -> Result<Vec<f64>> {
    let ctx = egui::Context::default();
    let mut app = ZieglerApp::new(settings)?;
    // As in the window: new parameters are analysed on their own thread.
    app.state_mut().analyse_in_background();
    app.show_tab(tab);
    let mut times_ms = Vec::with_capacity(frames);
    for frame in 0..frames + WARMUP_FRAMES {
        let phase = (frame % 120) as f64 / 120.0;
        let value = low + (high - low) * (1.0 - (2.0 * phase - 1.0).abs());
        let input = RawInput {
            screen_rect: Some(Rect::from_min_max(
                pos2(0.0, 0.0),
                pos2(FRAME_SIZE[0], FRAME_SIZE[1]),
            )),
            ..Default::default()
        };
        let start = Instant::now();
        app.apply(Action::Enter { key, value });
        if let Some(why) = app.state().refusal(key) {
            anyhow::bail!("setting {key}: {why}");
        }
        app.advance(1.0 / 60.0);
        app.state_mut().receive_analysis();
        let mut output = ctx.run_ui(input, |ui| app.contents_ui(ui));
        // No renderer takes the font atlas here.
        output.textures_delta.clear();
        black_box(ctx.tessellate(output.shapes, output.pixels_per_point));
        let elapsed_ms = start.elapsed().as_secs_f64() * 1e3;
        // The first frames lay out fonts and fill caches once.
        if frame >= WARMUP_FRAMES {
            times_ms.push(elapsed_ms);
        }
    }
    Ok(times_ms)
}
