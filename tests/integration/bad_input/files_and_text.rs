//! Bad input that needs more than a command line's status and its one
//! line: a path naming the shell's stream, figure pages and load ranges
//! checked on the figure itself, settings text too long to read, and a
//! huge paste into the window; numbers far from 1 in data files, and
//! changes of state that rounding makes, not listed as found.

use crate::common::message_line;
use crate::common::{analysed_to, paper_loci};
use eframe::egui;
use egui_kittest::kittest::Queryable as _;
use zieglerlab::app::{Settings, ZieglerApp};
use zieglerlab::figure::{Format, Page, render};
use zieglerlab::model::PresetId;
use zieglerlab::plot::locus::Part;

use crate::app_input::harness_at;
use crate::app_tools::paste_from_clipboard;
use crate::cli::{run, stdout};
use crate::common::model;

/// `--out /dev/stdout` (or a link to it) with the shell's `>> file` appends
/// to what the file held, and with `> file` writes where the shell opened
/// it; neither renames over the file behind the stream. Every command with
/// `--out` writes through the same function; `map` and `locus`-like CSV
/// from `bifurcation` stand for them.
#[cfg(unix)]
#[test]
fn a_stream_named_by_a_path_is_written_where_the_shell_opened_it() {
    use std::io::Write as _;
    let folder = tempfile::tempdir().expect("a temporary folder");
    let results = folder.path().join("results.csv");
    let link = folder.path().join("to-stdout");
    std::os::unix::fs::symlink("/dev/stdout", &link).expect("a link");
    let map = |out: &str| {
        vec![
            "map".to_owned(),
            "--preset".to_owned(),
            "ziegler-1952".to_owned(),
            "--x".to_owned(),
            "load:0:4:3".to_owned(),
            "--y".to_owned(),
            "damping:0:0.5:2".to_owned(),
            "--out".to_owned(),
            out.to_owned(),
        ]
    };
    let run_into = |args: &[String], append: bool| {
        let file = std::fs::File::options()
            .write(true)
            .create(true)
            .append(append)
            .truncate(!append)
            .open(&results)
            .expect("the shell's file");
        let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_zieglerlab"))
            .args(args)
            .stdout(file)
            .spawn()
            .expect("runs");
        let why = format!("{args:?}: no answer");
        let status = super::wait_within(&mut child, std::time::Duration::from_mins(1), &why);
        assert!(status.success(), "{args:?}");
    };
    let alone = {
        let out = folder.path().join("alone.csv");
        run_into(&map(out.to_str().expect("a path")), false);
        std::fs::read_to_string(out).expect("written")
    };
    assert!(alone.starts_with("load,"), "{alone}");
    for out in ["/dev/stdout", "/dev/fd/1", link.to_str().expect("a path")] {
        std::fs::File::create(&results)
            .and_then(|mut f| f.write_all(b"earlier results\n"))
            .expect("written");
        run_into(&map(out), true);
        let held = std::fs::read_to_string(&results).expect("read");
        assert_eq!(held, format!("earlier results\n{alone}"), "{out} >>");
        run_into(&map(out), false);
        let held = std::fs::read_to_string(&results).expect("read");
        assert_eq!(held, alone, "{out} >");
        run_into(&map(out), true);
        run_into(&map(out), true);
        let held = std::fs::read_to_string(&results).expect("read");
        assert_eq!(held, alone.repeat(3), "{out}: twice more >>");
    }
    // A FIFO by its own path is a stream too: read as it is written.
    let fifo = folder.path().join("fifo");
    let made = std::process::Command::new("mkfifo").arg(&fifo).status();
    assert!(
        made.expect("mkfifo runs (coreutils: apt-get install coreutils)")
            .success()
    );
    // The reader answers on a channel: were the FIFO replaced by a file,
    // its open() would wait for a writer forever, and the test fails on
    // the time limit instead of hanging.
    let (send, read) = std::sync::mpsc::channel();
    {
        let fifo = fifo.clone();
        std::thread::spawn(move || send.send(std::fs::read_to_string(fifo)));
    }
    let out = crate::common::output_within(
        std::process::Command::new(env!("CARGO_BIN_EXE_zieglerlab"))
            .args(map(fifo.to_str().expect("a path"))),
        std::time::Duration::from_mins(1),
        "map into a FIFO",
        "the binary runs",
    );
    assert!(out.status.success());
    let text = read
        .recv_timeout(std::time::Duration::from_secs(10))
        .expect("the FIFO's reader got the map (or the FIFO was replaced by a file)");
    assert_eq!(text.expect("read"), alone);
    assert!(fifo.exists(), "the FIFO is not replaced by a file");
}

/// A figure takes the loads and the range rules of `critical`: over beck's
/// 0 to 1e6 it finds the eight changes `critical` finds (the divergence
/// windows from p = 4.75 to 5.22, which an even grid of the range misses),
/// on a page whose legend still holds (the rest counted); past 1e150 it is
/// refused as `critical` refuses; where rounding decides the states it
/// marks none (thousands were drawn, and a second rod 1e74 times the first
/// aborted on a 4 GB legend) and says so on stderr.
#[test]
fn figures_take_the_loads_and_the_range_rules_of_critical() {
    let beck = model("beck", &[]);
    let wide = analysed_to("beck", &beck, 1e6).expect("an analysis");
    let found = zieglerlab::analysis::critical_loads(
        &zieglerlab::analysis::AffinePencil::new(&beck).unwrap(),
        0.0,
        1e6,
    )
    .unwrap();
    assert_eq!(wide.transitions.len(), found.len());
    assert!(found.len() >= 8, "{found:?}");
    assert!(
        wide.transitions
            .iter()
            .any(|t| (4.7..4.8).contains(&t.load))
    );
    for (drawn, found) in wide.transitions.iter().zip(&found) {
        assert_eq!(drawn.load, found.load);
    }
    assert!(wide.warning.is_none());
    let content = paper_loci(&wide, &[], Part::VersusLoad);
    let page = Page {
        width_mm: 85.0,
        height_mm: 93.5,
        font_pt: 8.0,
        dpi: 150.0,
    };
    render(&content, &page, Format::Png).expect("the legend fits");
    let refused = analysed_to("beck", &beck, 1e300).unwrap_err().to_string();
    assert!(
        refused.contains("load-max = 1e300: must be at most 1e150"),
        "{refused}"
    );
    for (name, sets) in [
        ("roller", &["nu=1e-50"][..]),
        ("ziegler-1952", &["l2=1e74"][..]),
    ] {
        let m = model(name, sets);
        let unresolved = analysed_to(name, &m, m.load_bar_max_p()).expect("an analysis");
        assert!(unresolved.warning.is_some(), "{name}");
        assert!(unresolved.transitions.is_empty() && unresolved.ranges.is_empty());
        let folder = tempfile::tempdir().unwrap();
        let out = folder.path().join("f.png");
        let mut args = vec!["figure", "--preset", name, "--kind", "re-im"];
        for set in sets {
            args.extend(["--set", set]);
        }
        args.extend(["--out", out.to_str().unwrap()]);
        let done = run(&args);
        assert!(done.status.success(), "{name}");
        let said = String::from_utf8_lossy(&done.stderr);
        assert!(
            said.contains("the stability is not resolved")
                && said.contains("no critical load is drawn"),
            "{said}"
        );
    }
}

/// A page too small for its legend and labels is refused with a page that
/// fits, and that page draws.
#[test]
fn a_page_too_small_for_its_legend_is_refused_with_one_that_fits() {
    let m = model("ziegler-1952", &[]);
    let main = analysed_to("ziegler-1952", &m, m.load_bar_max_p()).expect("an analysis");
    let content = paper_loci(&main, &[], Part::VersusLoad);
    let small = Page {
        width_mm: 30.0,
        height_mm: 30.0,
        font_pt: 8.0,
        dpi: 300.0,
    };
    let why = render(&content, &small, Format::Svg)
        .unwrap_err()
        .to_string();
    let size = why
        .split("need about ")
        .nth(1)
        .and_then(|rest| rest.split(" mm").next())
        .expect(&why);
    let (w, h) = size.split_once(" x ").expect(&why);
    let fits = Page {
        width_mm: w.parse().unwrap(),
        height_mm: h.parse().unwrap(),
        ..small
    };
    assert!(fits.height_mm > small.height_mm, "{why}");
    render(&content, &fits, Format::Svg).expect("the page it names fits");
}

/// Stored settings of many lines (300,000, 5 MB: no window came within
/// 30 s) are refused by their size at once and said so; 16 kB of repeated
/// lines are read in one pass, naming ten and counting the rest; a stored
/// speed of 1e300 is named in exponent form, not in 301 digits.
#[test]
fn long_stored_settings_are_bounded_and_named_briefly() {
    let huge = format!("preset = roller\n{}", "speed = 2\n".repeat(300_000));
    let app = ZieglerApp::from_stored_text(Some(&huge));
    let said = message_line(&app);
    assert!(
        said.contains(
            "stored settings ignored (the text holds 3000016 bytes; settings text is at most 16384"
        ),
        "{said}"
    );
    assert_eq!(app.settings(), &Settings::default());
    let repeated = format!("preset = beck\n{}", "speed = 2\n".repeat(1500));
    let app = ZieglerApp::from_stored_text(Some(&repeated));
    assert_eq!(app.settings().preset, PresetId::Beck);
    assert_eq!(app.settings().speed, 2.0);
    let said = message_line(&app);
    assert!(said.contains("1489 more"), "{said}");
    assert!(said.len() < 1000, "{} characters", said.len());
    let app = ZieglerApp::from_stored_text(Some("preset = roller\nspeed = 1e300\n"));
    let said = message_line(&app);
    assert!(said.contains("speed (1e300 is outside"), "{said}");
}

/// A 10 MB paste (from the clipboard, or into the share box) is refused
/// by its size with a message, before any text field lays it out: it froze
/// the window. Nothing changes, and the window goes on answering.
#[test]
fn a_huge_paste_is_refused_by_its_size() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    let huge = "speed = 2\n".repeat(1_000_000);
    paste_from_clipboard(&mut app, Some(&huge));
    let said = message_line(&app);
    assert!(
        said.starts_with("paste refused, nothing changed: the text holds 10000000 bytes"),
        "{said}"
    );
    assert_eq!(app.state().settings(), &Settings::default());
    // Typed into the box (a paste with the box focused): the same.
    let mut harness = harness_at(&mut app, [1280.0, 800.0]);
    harness.get_by_label("share").click();
    harness.run();
    harness
        .get_by_role(egui::accesskit::Role::MultilineTextInput)
        .click();
    harness.run();
    harness.event(egui::Event::Paste(huge.clone()));
    harness.run();
    let typed = harness
        .get_by_role(egui::accesskit::Role::MultilineTextInput)
        .value()
        .unwrap_or_default();
    assert!(typed.len() < 100, "the box holds {} bytes", typed.len());
    drop(harness);
    let said = message_line(&app);
    assert!(said.starts_with("paste refused"), "{said}");
}

/// Data files too write numbers far from 1 in exponent form, still to the
/// last bit: a locus and a map to p = 1e150 have no field of 151 digits,
/// and every field reads back to a finite number.
#[test]
fn data_files_write_extreme_numbers_in_exponent_form() {
    let locus = stdout(&[
        "locus",
        "--preset",
        "ziegler-1952",
        "--load-min",
        "0",
        "--load-max",
        "1e150",
        "--samples",
        "3",
    ]);
    let folder = tempfile::tempdir().unwrap();
    let out = folder.path().join("map.csv");
    stdout(&[
        "map",
        "--preset",
        "ziegler-1952",
        "--x",
        "load:0:1e150:3",
        "--y",
        "damping:0:0.5:2",
        "--out",
        out.to_str().unwrap(),
    ]);
    let map = std::fs::read_to_string(&out).unwrap();
    for (what, text) in [("locus", &locus), ("map", &map)] {
        assert!(text.contains("1e150"), "{what}: {text}");
        for field in text.lines().skip(1).flat_map(|l| l.split(',')) {
            assert!(field.len() <= 25, "{what}: {field}");
            if let Ok(number) = field.parse::<f64>() {
                assert!(number.is_finite(), "{what}: {field}");
            }
        }
    }
}

/// Where rounding decides the states (a roller of mass nu = 1e-50, a second
/// rod 1e74 times the first), `critical` lists no change as if it were
/// found: it counts them under its warning, and the JSON lists none and
/// says how many it left out. It once printed thousands of lines made by
/// rounding, then the first 20.
#[test]
fn unresolved_changes_are_counted_not_listed() {
    for set in ["nu=1e-50", "l2=1e74"] {
        let preset = if set.starts_with("nu") {
            "roller"
        } else {
            "ziegler-1952"
        };
        let out = run(&["critical", "--preset", preset, "--set", set]);
        assert!(out.status.success());
        assert!(String::from_utf8_lossy(&out.stderr).contains("the stability is not resolved"));
        let text = String::from_utf8(out.stdout).unwrap();
        let listed = text.lines().filter(|l| l.starts_with("  p = ")).count();
        assert_eq!(listed, 0, "{text}");
        let last = text.lines().last().unwrap();
        assert!(last.starts_with("  not resolved: the "), "{last}");
        let json: serde_json::Value = serde_json::from_str(&stdout(&[
            "critical", "--preset", preset, "--set", set, "--json",
        ]))
        .unwrap();
        assert_eq!(json["resolved"], false);
        assert_eq!(json["transitions"].as_array().unwrap().len(), 0);
        assert!(
            json["transitions_not_listed"].as_u64().unwrap() > 10,
            "{set}"
        );
    }
}
