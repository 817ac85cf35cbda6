//! The stability map as the window shows it (`egui_kittest`): the cell
//! under the pointer read out, checked against the map's own row computed
//! here.

use eframe::egui;
use egui_kittest::kittest::{NodeT as _, Queryable as _};
use zieglerlab::app::{Action, Settings, Tab, ZieglerApp};

/// The number after `name = ` in `text` (up to a comma, colon or space).
fn number_after(text: &str, name: &str) -> f64 {
    let start = text
        .find(name)
        .unwrap_or_else(|| panic!("{name} in {text}"))
        + name.len();
    text[start..]
        .split([',', ':', ' '])
        .next()
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("a number after {name} in {text}"))
}

/// Pointing at the roller's map reads out the cell there: its load, its
/// mass ratio, its state and growth rate, those of the map's row at that
/// mass ratio as the analysis computes it.
#[test]
fn the_cell_under_the_pointer_is_read_out() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    app.apply(Action::Tab(Tab::Map));
    app.complete_background_work(Tab::Map);
    let mut harness = crate::app_input::harness(&mut app);
    let hint = harness.get_by_label_contains("point at the map").rect();
    harness.hover_at(egui::pos2(hint.left() + 400.0, hint.bottom() + 120.0));
    harness.run();
    // The readout is a row of labels: gather it from its parts.
    let parts: Vec<String> = harness
        .query_all_by_label_contains("")
        .filter_map(|node| node.accesskit_node().value())
        .collect();
    let place = parts
        .iter()
        .find(|t| t.starts_with("p = ") && t.contains(", nu = "))
        .unwrap_or_else(|| panic!("no readout among {parts:?}"));
    let load = number_after(place, "p = ");
    let nu = number_after(place, "nu = ");
    let growth_text = parts
        .iter()
        // (the status card's line has two spaces after the words)
        .find(|t| t.starts_with("growth rate ") && !t.starts_with("growth rate  "))
        .expect("the readout's growth rate");
    let growth = number_after(growth_text, "growth rate ");
    // The same cell from the analysis.
    let spec = zieglerlab::bench::roller_map_spec();
    let values = spec.value_grid().unwrap();
    let j = (0..values.len())
        .min_by(|&a, &b| (values[a] - nu).abs().total_cmp(&(values[b] - nu).abs()))
        .unwrap();
    let loads = spec.load_grid().unwrap();
    let i = (0..loads.len())
        .min_by(|&a, &b| (loads[a] - load).abs().total_cmp(&(loads[b] - load).abs()))
        .unwrap();
    assert!((loads[i] - load).abs() < 1e-4 && (values[j] - nu).abs() < 1e-4);
    let row = spec.row(values[j]).unwrap();
    let cell = row.cells[i];
    assert!(
        // As shown: five decimals, or four significant digits when small.
        (cell.growth_per_s - growth).abs() <= 5e-6_f64.max(5e-4 * cell.growth_per_s.abs()),
        "{growth} against {}",
        cell.growth_per_s
    );
    assert!(
        parts.iter().any(|t| t == cell.state.name()),
        "{} not among {parts:?}",
        cell.state.name()
    );
}
