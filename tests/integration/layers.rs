//! The layers of ARCHITECTURE.md as the source files keep them: the
//! physics, the analysis and the plots' descriptions name no UI, engine,
//! drawing crate, clock or core count; the figures name nothing of the
//! window; rapier2d is named in one file; no file is over 600 lines.

use std::path::{Path, PathBuf};

/// Every `.rs` file under `dir`, with its code (comment lines left out).
fn sources(dir: &Path) -> Vec<(PathBuf, String)> {
    let mut found = Vec::new();
    let mut folders = vec![dir.to_path_buf()];
    while let Some(folder) = folders.pop() {
        for entry in std::fs::read_dir(&folder).expect("a source folder") {
            let path = entry.expect("an entry").path();
            if path.is_dir() {
                folders.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let text = std::fs::read_to_string(&path).expect("a source file");
                let code: Vec<&str> = text
                    .lines()
                    .filter(|line| !line.trim_start().starts_with("//"))
                    .collect();
                found.push((path, code.join("\n")));
            }
        }
    }
    assert!(!found.is_empty(), "no sources under {}", dir.display());
    found
}

/// The files under `src/<layer>` that name any of `forbidden` in code.
fn naming(layer: &str, forbidden: &[&str]) -> Vec<String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("src")
        .join(layer);
    sources(&root)
        .into_iter()
        .flat_map(|(path, code)| {
            forbidden
                .iter()
                .filter(|name| code.contains(*name))
                .map(|name| format!("{} names {name}", path.display()))
                .collect::<Vec<_>>()
        })
        .collect()
}

/// What the pure layers may not name: the window, the engine, a drawing
/// crate, the layers above, the clock, the machine's core count (its
/// callers give the threads).
const IMPURE: [&str; 12] = [
    "egui",
    "eframe",
    "rapier2d",
    "plotters",
    "crate::app",
    "crate::figure",
    "crate::sim",
    "crate::cli",
    "Instant",
    "SystemTime",
    "crate::lesson",
    "available_parallelism",
];

#[test]
fn the_model_the_analysis_and_the_plots_are_pure() {
    for layer in ["model", "analysis", "plot"] {
        let found = naming(layer, &IMPURE);
        assert!(found.is_empty(), "{found:#?}");
    }
}

#[test]
fn the_figures_name_nothing_of_the_window() {
    let found = naming("figure", &["crate::app", "egui::", "eframe", "egui_plot"]);
    assert!(found.is_empty(), "{found:#?}");
}

#[test]
fn rapier2d_is_named_in_one_file() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let naming: Vec<PathBuf> = sources(&root)
        .into_iter()
        .filter(|(_, code)| code.contains("rapier2d::") || code.contains("use rapier2d"))
        .map(|(path, _)| path)
        .collect();
    assert_eq!(naming, [root.join("sim").join("rapier.rs")]);
}

/// ARCHITECTURE.md's rule: no source file over 600 lines.
#[test]
fn no_source_file_is_over_600_lines() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let long: Vec<String> = sources(&root)
        .into_iter()
        .filter_map(|(path, _)| {
            let lines = std::fs::read_to_string(&path)
                .expect("a source")
                .lines()
                .count();
            (lines > 600).then(|| format!("{}: {lines} lines", path.display()))
        })
        .collect();
    assert!(long.is_empty(), "{long:#?}");
}
