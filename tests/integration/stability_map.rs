//! Stability maps and the paradox explorer against independent answers: a
//! map's rows against `critical` at the row's value, its columns against a
//! bisection in the second parameter at a fixed load, its cells against the
//! Schur path; the vanishing-damping flutter load against Semler's closed
//! form and its limits (physics.md section 7).

use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, AtomicUsize};

use zieglerlab::analysis::{
    AffinePencil, MapSpec, Row, State, classify, compute_map, critical_loads, flutter_load_damped,
};
use zieglerlab::model::{Axis, preset};

fn roller_map(axis: &str, range: (f64, f64), loads: usize, values: usize) -> MapSpec {
    let model = preset("roller").unwrap().model();
    MapSpec {
        axis: Axis::parse(axis, &model).unwrap(),
        model,
        load_range: (0.0, 8.0),
        loads,
        axis_range: range,
        values,
    }
}

fn rows(spec: &MapSpec) -> Vec<Row> {
    let out: Mutex<Vec<Option<Row>>> = Mutex::new(vec![None; spec.values]);
    let (cancel, done) = (AtomicBool::new(false), AtomicUsize::new(0));
    compute_map(spec, 2, &cancel, &done, &|j, row| {
        out.lock().unwrap()[j] = Some(row.unwrap());
    })
    .unwrap();
    assert_eq!(done.into_inner(), spec.values);
    out.into_inner()
        .unwrap()
        .into_iter()
        .map(Option::unwrap)
        .collect()
}

fn schur_state(spec: &MapSpec, value: f64, load: f64) -> State {
    let model = spec.axis.apply(&spec.model, value).unwrap();
    let spectrum = AffinePencil::new(&model).unwrap().spectrum(load).unwrap();
    classify(&spectrum.eigenvalues, spectrum.scale_per_s).state
}

#[test]
fn rows_are_critical_at_their_value_and_cells_are_the_schur_state() {
    let spec = roller_map("nu", (0.02, 0.5), 41, 12);
    let loads = spec.load_grid().unwrap();
    for row in rows(&spec) {
        let model = spec.axis.apply(&spec.model, row.value).unwrap();
        let expected = critical_loads(&AffinePencil::new(&model).unwrap(), 0.0, 8.0).unwrap();
        // The row brackets on a grid that holds its cells, `critical` on
        // its own: the same changes, each polished to the root of the
        // growth rate (which rounding blurs at 1e-13 of the load).
        assert_eq!(row.transitions.len(), expected.len(), "nu = {}", row.value);
        for (found, critical) in row.transitions.iter().zip(&expected) {
            assert_eq!((found.from, found.to), (critical.from, critical.to));
            assert!(
                (found.load - critical.load).abs() <= 1e-12 * critical.load,
                "nu = {}: {found:?} vs {critical:?}",
                row.value
            );
        }
        for (cell, &p) in row.cells.iter().zip(&loads) {
            // Away from the critical loads, the Schur path's own verdict.
            let near = row.transitions.iter().any(|t| (t.load - p).abs() < 1e-9);
            if !near {
                assert_eq!(
                    cell.state,
                    schur_state(&spec, row.value, p),
                    "nu {} p {p}",
                    row.value
                );
            }
            assert!(cell.growth_per_s.is_finite());
        }
    }
}

/// Along a column (fixed load), where the state changes between two rows,
/// bisection in the second parameter finds the value at which `critical`
/// has a critical load at exactly that load.
#[test]
fn columns_cross_the_boundary_where_critical_says() {
    for (axis, range, loads) in [("nu", (0.05, 5.0), 17), ("V", (0.02, 0.6), 401)] {
        let spec = roller_map(axis, range, loads, 16);
        let loads = spec.load_grid().unwrap();
        let rows = rows(&spec);
        let mut crossings = 0;
        for (i, &p) in loads.iter().enumerate().skip(1) {
            for pair in rows.windows(2) {
                let (sa, sb) = (pair[0].cells[i].state, pair[1].cells[i].state);
                if sa == sb {
                    continue;
                }
                let (mut lo, mut hi) = (pair[0].value, pair[1].value);
                for _ in 0..60 {
                    let mid = 0.5 * (lo + hi);
                    if schur_state(&spec, mid, p) == sa {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                let model = spec.axis.apply(&spec.model, 0.5 * (lo + hi)).unwrap();
                let t = critical_loads(&AffinePencil::new(&model).unwrap(), 0.0, 8.0).unwrap();
                let nearest = t
                    .iter()
                    .map(|t| (t.load - p).abs())
                    .fold(f64::INFINITY, f64::min);
                assert!(nearest < 1e-6 * p.max(1.0), "{axis} p = {p}: {nearest}");
                crossings += 1;
            }
        }
        assert!(crossings > 0, "{axis}: the map has boundaries to check");
    }
}

/// Semler et al.: Ziegler 1952 with g1 = ratio level, g2 = level.
fn semler(g1: f64, g2: f64) -> f64 {
    (4.0 * g1 * g1 + 33.0 * g1 * g2 + 4.0 * g2 * g2)
        / (2.0 * (g1 * g1 + 7.0 * g1 * g2 + 6.0 * g2 * g2))
        + 0.5 * g1 * g2
}

#[test]
fn the_paradox_curve_is_semlers_formula_and_its_limits() {
    let model = preset("ziegler-1952").unwrap().model();
    for ratio in [0.01, 0.1, 0.5, 1.0, 2.0, 10.0, 100.0] {
        for level in [0.3, 0.1, 1e-2, 1e-3] {
            let p = flutter_load_damped(&model, ratio, level, 10.0)
                .unwrap()
                .unwrap();
            let expected = semler(ratio * level, level);
            assert!(
                (p - expected).abs() < 1e-9,
                "ratio {ratio} level {level}: {p} vs {expected}"
            );
        }
    }
    // Vanishing damping: 41/28 for equal dampers, far below the undamped
    // 7/2 - sqrt 2; from 1/3 to 2 over the ratio.
    let limit = |ratio| {
        flutter_load_damped(&model, ratio, 1e-4, 10.0)
            .unwrap()
            .unwrap()
    };
    assert!((limit(1.0) - 41.0 / 28.0).abs() < 1e-6);
    assert!((limit(1e-4) - 1.0 / 3.0).abs() < 1e-3);
    assert!((limit(1e4) - 2.0).abs() < 1e-3);
    let undamped = critical_loads(&AffinePencil::new(&model).unwrap(), 0.0, 10.0).unwrap()[0].load;
    assert!((undamped - (3.5 - 2f64.sqrt())).abs() < 1e-12);
}

#[test]
fn the_other_columns_reach_their_equal_damper_limits() {
    for (name, limit) in [
        ("uniform-rods", 74.0 / 45.0),
        ("midpoint-masses", 39.0 / 22.0),
    ] {
        let model = preset(name).unwrap().model();
        let p = flutter_load_damped(&model, 1.0, 1e-4, 10.0)
            .unwrap()
            .unwrap();
        assert!((p - limit).abs() < 1e-6, "{name}: {p} vs {limit}");
    }
}

/// The mass-ratio axis on the 1952 column (point masses r m at A and m at
/// the tip, equal l and k): physics.md section 7's general formula gives
/// p = (r + 5 -/+ 2 sqrt r) / 2.
#[test]
fn the_mass_ratio_axis_moves_the_closed_form_loads() {
    let model = preset("ziegler-1952").unwrap().model();
    let axis = Axis::parse("mass_ratio", &model).unwrap();
    assert!((axis.get(&model) - 2.0).abs() < 1e-12);
    for r in [0.25, 1.0, 2.0, 4.0] {
        let m = axis.apply(&model, r).unwrap();
        let t = critical_loads(&AffinePencil::new(&m).unwrap(), 0.0, 10.0).unwrap();
        let (flutter, divergence) = (
            (r + 5.0 - 2.0 * r.sqrt()) / 2.0,
            (r + 5.0 + 2.0 * r.sqrt()) / 2.0,
        );
        assert_eq!(t.len(), 2, "r = {r}");
        assert!(
            (t[0].load - flutter).abs() < 1e-9,
            "r = {r}: {} vs {flutter}",
            t[0].load
        );
        assert!(
            (t[1].load - divergence).abs() < 1e-9,
            "r = {r}: {} vs {divergence}",
            t[1].load
        );
    }
}

/// A cancelled map stops at the next row: before it starts, nothing is
/// computed; cancelled as its first row arrives, it returns long before the
/// end.
#[test]
fn a_cancelled_map_stops() {
    let spec = roller_map("nu", (0.01, 1.0), 64, 256);
    let (cancel, done) = (AtomicBool::new(true), AtomicUsize::new(0));
    compute_map(&spec, 2, &cancel, &done, &|_, _| {
        panic!("no row after a cancel")
    })
    .unwrap();
    assert_eq!(done.into_inner(), 0);
    let (cancel, done) = (AtomicBool::new(false), AtomicUsize::new(0));
    compute_map(&spec, 2, &cancel, &done, &|_, _| {
        cancel.store(true, std::sync::atomic::Ordering::Relaxed);
    })
    .unwrap();
    let rows = done.into_inner();
    assert!((1..=4).contains(&rows), "{rows} rows after the cancel");
}

#[test]
fn map_rows_hold_no_subnormal_numbers() {
    let normal = |x: f64| x == 0.0 || x.is_normal();
    for row in rows(&roller_map("nu", (0.005, 1.0), 64, 8)) {
        for cell in &row.cells {
            assert!(normal(cell.growth_per_s), "nu = {}: {cell:?}", row.value);
        }
        for t in &row.transitions {
            assert!(normal(t.load), "nu = {}: {t:?}", row.value);
        }
    }
}

/// On a chain the mass beyond joint A is every rod after the first (rod 2
/// repeated), the tip and the roller: Beck's 16 equal rods have the mass
/// ratio 1/15, and that value gives the preset back. A map over `rods`
/// samples whole numbers, each row a chain that exists.
#[test]
fn a_chain_counts_every_rod_beyond_the_joint_and_its_rods_are_whole() {
    let model = preset("beck").unwrap().model();
    assert_eq!(model.column.rods, 16);
    let axis = Axis::parse("mass_ratio", &model).unwrap();
    assert!((axis.get(&model) - 1.0 / 15.0).abs() < 1e-15);
    let back = axis.apply(&model, 1.0 / 15.0).unwrap();
    assert!((back.column.rod1.mass_kg - model.column.rod1.mass_kg).abs() < 1e-15);
    let spec = MapSpec {
        axis: Axis::parse("rods", &model).unwrap(),
        model,
        load_range: (0.0, 0.5),
        loads: 3,
        axis_range: (2.0, 16.0),
        values: 5,
    };
    assert_eq!(spec.value_grid().unwrap(), [2.0, 6.0, 9.0, 13.0, 16.0]);
    for row in rows(&spec) {
        assert_eq!(row.value.fract(), 0.0);
        assert_eq!(
            row.cells.len(),
            3,
            "rods = {}: every cell computed",
            row.value
        );
    }
}
