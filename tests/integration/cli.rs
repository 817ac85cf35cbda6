//! The command line as a user runs it: output formats (the JSON and CSV
//! layouts other tools read), the numbers in them, and bad input answered by
//! status 2 and one line naming the problem, never a panic. (The pictures
//! and files it writes: `cli_files.rs`.)

use std::process::{Command, Output};

/// The slowest command a test runs takes about a minute in a debug build.
const COMMAND_LIMIT: std::time::Duration = std::time::Duration::from_mins(5);

pub(crate) fn run(args: &[&str]) -> Output {
    crate::common::output_within(
        Command::new(env!("CARGO_BIN_EXE_zieglerlab"))
            .args(args)
            // Pictures in English whatever this machine's language.
            .env_remove("LANGUAGE")
            .env("LC_ALL", "C.UTF-8"),
        COMMAND_LIMIT,
        &format!("{args:?}"),
        "the binary runs",
    )
}

pub(crate) fn stdout(args: &[&str]) -> String {
    let out = run(args);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("utf-8")
}

/// The rows of a CSV of numbers whose first line must be `header`.
fn csv_rows(text: &str, header: &str) -> Vec<Vec<f64>> {
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some(header));
    lines
        .map(|l| l.split(',').map(|x| x.parse().expect("number")).collect())
        .collect()
}

#[test]
fn critical_json_layout_and_values() {
    let text = stdout(&["critical", "--preset", "ziegler-1952", "--json"]);
    let json: serde_json::Value = serde_json::from_str(&text).expect("json");
    assert_eq!(json["preset"], "ziegler-1952");
    assert_eq!(json["load_axis"], "p = P l/k");
    let t = json["transitions"].as_array().expect("array");
    assert_eq!(t.len(), 2);
    assert_eq!(
        (t[0]["from"].as_str(), t[0]["to"].as_str()),
        (Some("stable"), Some("flutter"))
    );
    assert_eq!(
        (t[1]["from"].as_str(), t[1]["to"].as_str()),
        (Some("flutter"), Some("divergence"))
    );
    let flutter = t[0]["load"].as_f64().expect("number");
    assert!((flutter - (3.5 - 2f64.sqrt())).abs() < 1e-9 * flutter);
}

#[test]
fn critical_respects_set_and_load_max() {
    // With the springs' ratio and a lower search limit.
    let text = stdout(&[
        "critical",
        "--preset",
        "midpoint-masses",
        "--load-max",
        "4",
        "--json",
    ]);
    let json: serde_json::Value = serde_json::from_str(&text).expect("json");
    assert_eq!(
        json["transitions"].as_array().expect("array").len(),
        1,
        "divergence at 13/3 is beyond 4"
    );
    let text = stdout(&[
        "critical",
        "--preset",
        "ziegler-1952",
        "--set",
        "c1=0.0316227766",
        "--set",
        "c2=0.0316227766",
        "--json",
    ]);
    let json: serde_json::Value = serde_json::from_str(&text).expect("json");
    let flutter = json["transitions"][0]["load"].as_f64().expect("number");
    assert!(flutter < 2.0, "damping lowers the flutter load: {flutter}");
}

#[test]
fn locus_csv_has_every_eigenvalue_at_evenly_spaced_loads() {
    let text = stdout(&[
        "locus",
        "--preset",
        "roller",
        "--load-min",
        "0",
        "--load-max",
        "5",
        "--samples",
        "11",
    ]);
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("load,branch,re,im"));
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|x| x.parse().expect("number")).collect())
        .collect();
    assert_eq!(
        rows.len(),
        11 * 6,
        "six eigenvalues per load, the zero root included"
    );
    for (i, chunk) in rows.chunks(6).enumerate() {
        let expected = 0.5 * f64::from(u8::try_from(i).expect("small"));
        assert!(chunk.iter().all(|r| (r[0] - expected).abs() < 1e-12));
        assert_eq!(
            chunk.iter().map(|r| r[1]).collect::<Vec<_>>(),
            vec![0.0, 1.0, 2.0, 3.0, 4.0, 5.0]
        );
        assert!(
            chunk.iter().any(|r| r[2] == 0.0 && r[3] == 0.0),
            "the structural zero root"
        );
    }
}

#[test]
fn one_sample_gives_the_spectrum_at_that_load() {
    let text = stdout(&[
        "locus",
        "--preset",
        "uniform-rods",
        "--load-min",
        "3",
        "--load-max",
        "3",
        "--samples",
        "1",
        "--format",
        "json",
    ]);
    let json: serde_json::Value = serde_json::from_str(&text).expect("json");
    let rows = json["rows"].as_array().expect("rows");
    assert_eq!(rows.len(), 4);
    // p = 3 is in the flutter range of uniform rods: a pair with Re > 0.
    assert!(rows.iter().any(|r| r["re"].as_f64().expect("re") > 1e-3));
}

#[test]
fn presets_lists_every_preset_with_units() {
    let text = stdout(&["presets"]);
    for name in [
        "ziegler-1952",
        "uniform-rods",
        "midpoint-masses",
        "roller",
        "roller-as-printed",
        "tabletop",
        "tabletop-roller",
        "beck",
        "pflueger",
        "beck-roller",
        "pflueger-roller",
    ] {
        assert!(text.contains(name), "{name}");
    }
    for unit in ["N m/rad", "kg m^2", "m/s", "1/s^2"] {
        assert!(text.contains(unit), "{unit}");
    }
    let json: serde_json::Value =
        serde_json::from_str(&stdout(&["presets", "--json"])).expect("json");
    assert_eq!(json.as_array().expect("array").len(), 11);
}

#[test]
fn simulate_csv_layout() {
    let text = stdout(&[
        "simulate",
        "--preset",
        "roller",
        "--duration",
        "1",
        "--dt",
        "0.01",
        "--engine",
        "reference",
    ]);
    let rows = csv_rows(
        &text,
        "t,phi1,phi2,psi,phi1_dot,phi2_dot,psi_dot,delta,energy",
    );
    assert_eq!(rows.len(), 101, "t = 0 and 100 steps");
    assert_eq!(rows[0][..3], [0.0, 0.001, 0.001]);
    assert!((rows[100][0] - 1.0).abs() < 1e-12);
    // A 2-DOF preset has no spin: its psi columns are zero.
    let text = stdout(&[
        "simulate",
        "--preset",
        "ziegler-1952",
        "--duration",
        "0.1",
        "--dt",
        "0.05",
    ]);
    for line in text.lines().skip(1) {
        let v: Vec<f64> = line
            .split(',')
            .map(|x| x.parse().expect("number"))
            .collect();
        assert_eq!((v[3], v[6]), (0.0, 0.0));
    }
}

/// `bench --json` (a debug build here, so the figures are slow; only their
/// layout and sanity are checked): the keys in the documented order,
/// each a positive finite number, with the frame quantiles ordered.
#[test]
fn bench_json_has_every_figure() {
    let out = run(&[
        "bench",
        "--json",
        "--frames",
        "3",
        "--no-window",
        "--no-cycles",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).expect("utf-8");
    let keys: Vec<&str> = text
        .lines()
        .filter_map(|line| line.trim().strip_prefix('"')?.split('"').next())
        .collect();
    assert_eq!(
        keys,
        [
            "locus_us_per_load",
            "locus2_us_per_load",
            "eig_us_per_pencil",
            "critical_ms",
            "critical_chain32_ms",
            "sim_reference_x_realtime",
            "sim_rapier_x_realtime",
            "frame_ms_p50",
            "frame_ms_p99",
            "frame_ms_p99_map",
            "frame_ms_p99_paradox",
            "frame_ms_p99_chain16",
            "locus_sheet_ms_chain16",
            "locus_sheet_kept_ms_chain16",
            "map_ms",
            "numpy_eig_us_per_pencil",
            "locus_speedup_vs_numpy",
            "numpy_chain32_scan_ms",
            "critical_chain32_over_numpy",
            "window_fps",
            "window_frame_ms_p99",
            "window_fps_1920x1080",
            "window_frame_ms_p99_1920x1080",
            "window_fps_chain16_projector_1920x1080",
            "window_frame_ms_p99_chain16_projector_1920x1080",
            "bifurcation_chain16_s",
        ]
    );
    let json: serde_json::Value = serde_json::from_str(&text).expect("json");
    for key in keys {
        // numpy's figures are null on a machine without numpy, the
        // window's and the cycles' when they are skipped (as here).
        let skipped = key.starts_with("window_") || key == "bifurcation_chain16_s";
        if (key.contains("numpy") || skipped) && json[key].is_null() {
            continue;
        }
        let figure = json[key].as_f64().expect("a number");
        assert!(figure.is_finite() && figure > 0.0, "{key} = {figure}");
    }
    assert!(json["frame_ms_p50"].as_f64() <= json["frame_ms_p99"].as_f64());
}

/// `map` CSV: the header, one row per cell in rows of the second axis, and
/// each row's changes of state where `critical` puts them at that value.
#[test]
fn map_csv_rows_agree_with_critical() {
    let path = std::env::temp_dir().join(format!("zl-map-{}.csv", std::process::id()));
    let path_text = path.to_str().unwrap();
    let out = run(&[
        "map",
        "--preset",
        "roller",
        "--x",
        "load:0:8:161",
        "--y",
        "nu:0.05:0.8:4",
        "--out",
        path_text,
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&path).unwrap();
    std::fs::remove_file(&path).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("load,nu,state,growth_rate"));
    let cells: Vec<(f64, f64, String)> = lines
        .map(|line| {
            let f: Vec<&str> = line.split(',').collect();
            assert_eq!(f.len(), 4, "{line}");
            let growth: f64 = f[3].parse().unwrap();
            assert!(growth.is_finite(), "{line}");
            (
                f[0].parse().unwrap(),
                f[1].parse().unwrap(),
                f[2].to_owned(),
            )
        })
        .collect();
    assert_eq!(cells.len(), 161 * 4);
    for row in cells.chunks(161) {
        let nu = row[0].1;
        let json = stdout(&[
            "critical",
            "--preset",
            "roller",
            "--set",
            &format!("nu={nu}"),
            "--load-max",
            "8",
            "--json",
        ]);
        let json: serde_json::Value = serde_json::from_str(&json).unwrap();
        let transitions = json["transitions"].as_array().unwrap();
        for (load, _, state) in row {
            // The state `critical` gives at this load: the last change at or below it.
            let expected = transitions
                .iter()
                .rev()
                .find(|t| t["load"].as_f64().unwrap() <= *load)
                .map_or("stable", |t| t["to"].as_str().unwrap());
            assert_eq!(state, expected, "nu = {nu}, p = {load}");
        }
    }
}

/// `locus --format json` is streamed row by row; it must hold exactly the
/// CSV's rows, with the document's other keys.
#[test]
fn locus_json_and_csv_hold_the_same_rows() {
    let args = |format: &'static str| {
        [
            "locus",
            "--preset",
            "roller",
            "--load-min",
            "0",
            "--load-max",
            "8",
            "--samples",
            "30",
            "--format",
            format,
        ]
    };
    let json: serde_json::Value =
        serde_json::from_str(&stdout(&args("json"))).expect("one JSON document");
    assert_eq!(json["preset"], "roller");
    assert_eq!(json["load_axis"], "p = P l/k");
    // The spin angle psi enters only through its rate: one exact zero root.
    assert_eq!(json["structural_zero_branches"], 1);
    let rows = json["rows"].as_array().expect("rows");
    let csv = stdout(&args("csv"));
    let lines: Vec<&str> = csv.lines().skip(1).collect();
    assert_eq!(rows.len(), lines.len());
    assert_eq!(rows.len(), 30 * 6);
    for (row, line) in rows.iter().zip(lines) {
        let fields: Vec<f64> = line.split(',').map(|f| f.parse().unwrap()).collect();
        let from_json = [
            row["load"].as_f64().unwrap(),
            row["branch"].as_f64().unwrap(),
            row["re"].as_f64().unwrap(),
            row["im"].as_f64().unwrap(),
        ];
        // serde_json's default parser may miss the last bit of a float.
        for (a, b) in fields.iter().zip(from_json) {
            assert!((a - b).abs() <= 4.0 * f64::EPSILON * a.abs(), "{line}: {b}");
        }
    }
}

/// `simulate --ramp FROM:TO:RATE`: a `load` column, the load of each step
/// from FROM at RATE per simulated second, held at TO; a `--set load` beside
/// it is refused (the ramp sets the load).
#[test]
fn simulate_with_a_ramp_adds_the_load_of_each_step() {
    let text = stdout(&[
        "simulate",
        "--preset",
        "tabletop",
        "--duration",
        "3",
        "--dt",
        "0.01",
        "--ramp",
        "0.5:1.5:0.5",
    ]);
    let rows = csv_rows(
        &text,
        "t,phi1,phi2,psi,phi1_dot,phi2_dot,psi_dot,delta,energy,load",
    );
    assert_eq!(rows.len(), 301);
    for row in &rows {
        // The row at t closes the step that started at t - dt.
        let started = (row[0] - 0.01).max(0.0);
        let expected = (0.5 + 0.5 * started).min(1.5);
        assert!(
            (row[9] - expected).abs() < 1e-9,
            "t = {}: load {}",
            row[0],
            row[9]
        );
    }
    let refused = run(&[
        "simulate",
        "--preset",
        "tabletop",
        "--duration",
        "1",
        "--set",
        "load=2",
        "--ramp",
        "0:1:0.5",
    ]);
    assert_eq!(refused.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&refused.stderr).contains("leave out --set load"));
    let bad = run(&[
        "simulate",
        "--preset",
        "tabletop",
        "--duration",
        "1",
        "--ramp",
        "0:1:0",
    ]);
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("ramp rate = 0"));
}

/// `lesson --check`: every shipped lesson, in every language, passes; a
/// broken one is refused with status 2, its line and what was expected.
#[test]
fn lesson_check_passes_the_shipped_lessons_and_names_the_line_of_a_broken_one() {
    // English's, and each language's folder of translations.
    let mut checked = 0;
    let mut folders = vec![std::path::PathBuf::from("assets/lessons")];
    while let Some(folder) = folders.pop() {
        for entry in std::fs::read_dir(folder).expect("a lessons folder") {
            let path = entry.expect("an entry").path();
            if path.is_dir() {
                folders.push(path);
                continue;
            }
            let text = stdout(&["lesson", "--check", path.to_str().expect("a path")]);
            assert!(text.contains(": ok: "), "{text}");
            checked += 1;
        }
    }
    assert_eq!(checked, 18, "three lessons in six languages");
    let folder = tempfile::tempdir().expect("a temporary folder");
    let broken = folder.path().join("broken.ron");
    std::fs::write(
        &broken,
        "Lesson(\n    title: \"t\",\n    steps: [\n        Step(text: \"a\"),\n        Step(text: \"b\", speed: 50.0),\n    ],\n)\n",
    )
    .expect("written");
    let refused = run(&["lesson", "--check", broken.to_str().expect("a path")]);
    assert_eq!(refused.status.code(), Some(2));
    let said = String::from_utf8_lossy(&refused.stderr);
    assert!(
        said.contains("line 5: step 2: speed = 50: expected 0.1 to 10"),
        "{said}"
    );
}

/// The renderer is the window's: beside a subcommand the flag is refused,
/// and an unknown name in the environment is refused before any window
/// opens (no display is needed to see either).
#[test]
fn the_renderer_choice_is_checked_before_anything_opens() {
    let beside = run(&["--renderer", "wgpu", "presets"]);
    assert_eq!(beside.status.code(), Some(2));
    let text = String::from_utf8_lossy(&beside.stderr);
    assert!(
        text.contains("--renderer chooses what draws the window"),
        "{text}"
    );
    // No display: were the name taken, the window would fail to open.
    let with_unknown_renderer = |args: &[&str]| {
        crate::common::output_within(
            Command::new(env!("CARGO_BIN_EXE_zieglerlab"))
                .args(args)
                .env("ZIEGLERLAB_RENDERER", "vulkan")
                .env_remove("DISPLAY")
                .env_remove("WAYLAND_DISPLAY"),
            COMMAND_LIMIT,
            &format!("{args:?} with an unknown renderer"),
            "the binary runs",
        )
    };
    let unknown = with_unknown_renderer(&[]);
    assert_eq!(unknown.status.code(), Some(2));
    let text = String::from_utf8_lossy(&unknown.stderr);
    assert!(
        text.contains("ZIEGLERLAB_RENDERER=vulkan: must be glow or wgpu"),
        "{text}"
    );
    // Subcommands draw headlessly and ignore the variable.
    let presets = with_unknown_renderer(&["presets"]);
    assert!(presets.status.success());
}

/// Loads far from 1 are written in exponent form: a range to 1e150 gives
/// no line of 150 digits, nor a range to 1e-300 one of 300.
#[test]
fn extreme_loads_are_printed_in_exponent_form() {
    for load_max in ["1e150", "1e-300"] {
        let text = stdout(&[
            "critical",
            "--preset",
            "ziegler-1952",
            "--load-max",
            load_max,
        ]);
        assert!(text.lines().all(|l| l.len() < 120), "{text}");
        assert!(text.contains(&format!(", {load_max}]")), "{text}");
    }
}

/// The README's example of `critical` is what the command prints, line for
/// line (it had drifted in the last digits).
#[test]
fn the_readme_example_of_critical_is_what_it_prints() {
    let readme = std::fs::read_to_string("README.md").expect("the README");
    let command = "    $ zieglerlab critical --preset ziegler-1952\n";
    let start = readme.find(command).expect("the example") + command.len();
    let shown: Vec<&str> = readme[start..]
        .lines()
        .take_while(|line| line.starts_with("    ") && !line.trim_start().starts_with('#'))
        .map(|line| &line[4..])
        .collect();
    let printed = stdout(&["critical", "--preset", "ziegler-1952"]);
    assert_eq!(shown, printed.lines().collect::<Vec<_>>());
}

/// A program that outlives its limit is killed and fails the test, naming
/// it, instead of hanging the suite.
#[test]
fn a_hung_program_fails_the_test_in_time() {
    let started = std::time::Instant::now();
    let caught = std::panic::catch_unwind(|| {
        crate::common::output_within(
            Command::new("sleep").arg("30"),
            std::time::Duration::from_millis(300),
            "sleep 30",
            "sleep runs",
        )
    });
    let message = caught.expect_err("killed").downcast::<String>().unwrap();
    assert!(message.contains("sleep 30: no answer"), "{message}");
    assert!(started.elapsed() < std::time::Duration::from_secs(10));
}
