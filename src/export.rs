//! The command line's CSV tables as text, for the window's exports too: a
//! run's time history and a root locus, every number written exactly.

use std::fmt::Write as _;

use crate::analysis::{C64, Locus};
use crate::format::Exact;
use crate::sim::Observables;

/// The header of a root locus table.
pub const LOCUS_HEADER: &str = "load,branch,re,im";

/// The header of a run's table: the time, every rod's angle, the roller's
/// spin angle, every rate, the spin rate, the band force's angle and the
/// energy, and the load when it moves (a ramp).
#[must_use]
pub fn history_header(rods: usize, with_load: bool) -> String {
    let angles: Vec<String> = (1..=rods).map(|i| format!("phi{i}")).collect();
    let rates: Vec<String> = (1..=rods).map(|i| format!("phi{i}_dot")).collect();
    let load = if with_load { ",load" } else { "" };
    format!(
        "t,{},psi,{},psi_dot,delta,energy{load}",
        angles.join(","),
        rates.join(",")
    )
}

/// One row of a run's table (see [`history_header`]), without its newline.
#[must_use]
pub fn history_row(o: &Observables, load: Option<f64>) -> String {
    let join = |values: &[f64]| {
        values
            .iter()
            .map(|&x| Exact(x).to_string())
            .collect::<Vec<_>>()
            .join(",")
    };
    let load = load.map(|p| format!(",{}", Exact(p))).unwrap_or_default();
    format!(
        "{},{},{},{},{},{},{}{load}",
        Exact(o.t_secs),
        join(&o.angles_rad),
        Exact(o.psi_rad),
        join(&o.rates_rad_per_s),
        Exact(o.psi_dot_rad_per_s),
        Exact(o.delta_rad),
        Exact(o.energy_j())
    )
}

/// The rows of a locus table at one load: one per branch, each with its
/// newline.
#[must_use]
pub fn locus_rows(load: f64, row: &[C64]) -> String {
    let mut text = String::new();
    for (branch, z) in row.iter().enumerate() {
        // Writing to a String cannot fail.
        let _ = writeln!(
            text,
            "{},{branch},{},{}",
            Exact(load),
            Exact(z.re),
            Exact(z.im)
        );
    }
    text
}

/// A whole locus as a table: the header, then every sample's rows.
#[must_use]
pub fn locus_csv(locus: &Locus) -> String {
    let mut text = format!("{LOCUS_HEADER}\n");
    for (i, &load) in locus.loads.iter().enumerate() {
        let row: Vec<C64> = locus.at(i).collect();
        text.push_str(&locus_rows(load, &row));
    }
    text
}

/// A run's samples as a table, oldest first.
#[must_use]
pub fn history_csv<'a>(rods: usize, samples: impl IntoIterator<Item = &'a Observables>) -> String {
    let mut text = history_header(rods, false);
    text.push('\n');
    for o in samples {
        text.push_str(&history_row(o, None));
        text.push('\n');
    }
    text
}
