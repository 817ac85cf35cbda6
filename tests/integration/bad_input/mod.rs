//! Bad input, singular physics and blow-ups, as tables: every case gets an
//! answer a person understands. From the command line (run as a process):
//! the status, one line on stderr, never a panic, never NaN in the output.
//! From the library: an error naming the parameter, or a result with its
//! caveat. The README's table "Bad input and extremes" lists the same cases.

use std::io::Read as _;
use std::process::{Child, Command, Output, Stdio};
use std::time::Duration;

use zieglerlab::analysis::{
    AffinePencil, bracketing_locus, critical_loads_along, resolution_warning,
};
use zieglerlab::model::{Model, apply_assignments, parse_assignment, preset};
use zieglerlab::sim::{EngineKind, SimError, Simulation, Status, initial_state};

mod cli_bounds;
mod cli_cases;
mod cli_extremes;
mod cli_maps;
mod files_and_text;
mod lesson_files;
mod outputs;

use cli_bounds::CLI_BOUNDS;
use cli_cases::CLI;
use cli_extremes::CLI_EXTREMES;
use cli_maps::CLI_MAPS;

/// Longest a command line case may run: a hang fails the test instead of
/// freezing CI.
const CASE_LIMIT: Duration = Duration::from_mins(1);

/// The binary started on `args`, its standard output and error piped.
fn spawn(args: &[&str]) -> Child {
    Command::new(env!("CARGO_BIN_EXE_zieglerlab"))
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary runs")
}

pub(super) use crate::common::wait_within;

/// Runs the binary with `args`, killed after [`CASE_LIMIT`].
pub(super) fn run_limited(args: &[&str]) -> Output {
    crate::common::output_within(
        Command::new(env!("CARGO_BIN_EXE_zieglerlab")).args(args),
        CASE_LIMIT,
        &format!("{args:?}"),
        "the binary runs",
    )
}

#[test]
fn every_command_line_case_gets_its_answer() {
    for case in CLI
        .iter()
        .chain(CLI_MAPS)
        .chain(CLI_EXTREMES)
        .chain(CLI_BOUNDS)
    {
        let out = run_limited(case.args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        let stdout = String::from_utf8_lossy(&out.stdout);
        let args = case.args;
        assert_eq!(out.status.code(), Some(case.status), "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
        assert!(stderr.contains(case.stderr), "{args:?}: {stderr}");
        if case.status != 0 {
            assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
            assert!(stdout.is_empty(), "{args:?}");
        } else {
            assert!(stderr.lines().count() <= 1, "{args:?}: {stderr}");
            if case.stderr.is_empty() {
                assert!(stderr.is_empty(), "{args:?}: {stderr}");
            }
            assert!(!stdout.is_empty(), "{args:?}");
            let lower = stdout.to_lowercase();
            assert!(!lower.contains("nan") && !lower.contains("inf"), "{args:?}");
        }
    }
}

/// The preset with `key=value` assignments, through the library's parser.
fn model(name: &str, sets: &[&str]) -> Result<Model, Option<String>> {
    let mut model = preset(name)
        .map_err(|e| e.parameter().map(str::to_owned))?
        .model();
    let mut assignments = Vec::new();
    for set in sets {
        assignments.push(parse_assignment(set).map_err(|e| e.parameter().map(str::to_owned))?);
    }
    apply_assignments(&mut model, &assignments).map_err(|e| e.parameter().map(str::to_owned))?;
    Ok(model)
}

/// Values the model refuses, each by the parameter it names.
const MODEL_REFUSALS: &[(&str, &str, &str)] = &[
    ("roller", "m1=nan", "m1"),
    ("roller", "m2=inf", "m2"),
    ("ziegler-1952", "m_tip=-1", "m_tip"),
    ("roller", "m3=-1", "m3"),
    ("roller", "nu=-1", "nu"),
    ("roller", "l1=0", "l1"),
    ("roller", "l2=-1", "l2"),
    ("uniform-rods", "k1=0", "k1"),
    ("uniform-rods", "k2=nan", "k2"),
    ("uniform-rods", "c1=-1", "c1"),
    ("roller", "r=0", "r"),
    ("roller", "r=3", "r"),
    ("roller", "rho=5", "r"),
    ("roller", "mu=0", "mu"),
    ("roller", "mu=inf", "mu"),
    ("roller", "R=-1", "R"),
    ("roller", "V=-1", "V"),
    ("roller", "V=nan", "V"),
    ("roller", "load=-1", "load"),
    ("roller", "load=inf", "load"),
    ("uniform-rods", "R=1", "R"),
    ("roller", "colour=1", "colour"),
];

#[test]
fn the_model_refuses_bad_values_naming_the_parameter() {
    for &(name, set, parameter) in MODEL_REFUSALS {
        let refused = model(name, &[set]).expect_err(set);
        assert_eq!(refused.as_deref(), Some(parameter), "{name} {set}");
    }
    // No mass at all: the mass matrix is singular, and says so.
    let refused = model("uniform-rods", &["m1=0", "m2=0"]).expect_err("massless");
    assert_eq!(refused.as_deref(), Some("mass matrix"));
}

/// The linear analysis: refused (naming the parameter), answered, or
/// answered with a warning that its stability is not resolved.
#[derive(Debug, PartialEq)]
enum Analysis {
    Refused(&'static str),
    Answered,
    Unresolved,
}

const ANALYSIS: &[(&str, &[&str], Analysis)] = &[
    ("roller", &["V=0"], Analysis::Refused("V")),
    ("roller", &[], Analysis::Answered),
    ("roller", &["load=1e6"], Analysis::Answered),
    ("roller", &["nu=1e3"], Analysis::Answered),
    ("roller", &["nu=1e-6"], Analysis::Answered),
    ("roller", &["nu=0"], Analysis::Answered),
    ("roller", &["R=0"], Analysis::Answered),
    ("roller", &["V=10"], Analysis::Answered),
    ("roller", &["nu=1e-9"], Analysis::Unresolved),
    ("roller", &["V=1e-5"], Analysis::Unresolved),
    ("roller", &["V=1e-6"], Analysis::Unresolved),
    ("roller", &["V=1e-12"], Analysis::Unresolved),
    ("ziegler-1952", &["c1=1e6"], Analysis::Unresolved),
    ("ziegler-1952", &[], Analysis::Answered),
    ("midpoint-masses", &["load=1e6"], Analysis::Answered),
];

#[test]
fn the_analysis_answers_or_says_why_not() {
    for (name, sets, expected) in ANALYSIS {
        let model = model(name, sets).expect("a valid model");
        let answer = match AffinePencil::new(&model) {
            Err(error) => Analysis::Refused(match error.parameter() {
                Some("V") => "V",
                other => panic!("{name} {sets:?}: {other:?} {error}"),
            }),
            Ok(pencil) => {
                let locus = bracketing_locus(&pencil, 0.0, 10.0).unwrap();
                let transitions = critical_loads_along(&pencil, &locus).unwrap();
                assert!(transitions.iter().all(|t| t.load.is_finite()));
                let spectrum = pencil.spectrum(model.load_p()).unwrap();
                assert!(spectrum.all().all(|z| z.re.is_finite() && z.im.is_finite()));
                match resolution_warning(&pencil, &locus).unwrap() {
                    None => Analysis::Answered,
                    Some(_) => Analysis::Unresolved,
                }
            }
        };
        assert_eq!(&answer, expected, "{name} {sets:?}");
    }
}

/// How a run of 2 s ends: with a status, or refused naming the parameter.
type RunEnd = Result<&'static str, &'static str>;

const RUNS: &[(&str, &[&str], EngineKind, RunEnd)] = &[
    // The band's friction mu R = P holds the contact in stick and drags the
    // column at the band's pace: rapier's implicit friction follows that.
    ("roller", &["load=1e6"], EngineKind::Rapier, Ok("running")),
    (
        "roller",
        &["load=1e6"],
        EngineKind::Reference,
        Ok("too stiff"),
    ),
    ("roller", &["V=0"], EngineKind::Rapier, Ok("running")),
    ("roller", &["V=0"], EngineKind::Reference, Ok("running")),
    ("roller", &["nu=1e-9"], EngineKind::Rapier, Ok("running")),
    ("roller", &["nu=1e3"], EngineKind::Rapier, Ok("running")),
    ("roller", &["nu=1e3"], EngineKind::Reference, Ok("running")),
    ("roller", &["c1=1e6"], EngineKind::Rapier, Err("dt")),
    ("roller", &["c1=1e6"], EngineKind::Reference, Ok("running")),
    ("uniform-rods", &["k1=1e9"], EngineKind::Rapier, Err("dt")),
    (
        "ziegler-1952",
        &["load=1e6"],
        EngineKind::Rapier,
        Ok("too fast"),
    ),
];

#[test]
fn runs_end_with_a_status_and_finite_states() {
    for (name, sets, engine, expected) in RUNS {
        let model = model(name, sets).expect("a valid model");
        let run = Simulation::new(model, *engine, initial_state(&model, 1e-3), 1.0 / 240.0);
        let answer = match run {
            Err(error @ SimError::TooStiffForRapier { .. }) => {
                Err(error.parameter().unwrap_or_default().to_owned())
            }
            Err(error) => panic!("{name} {sets:?}: {error}"),
            Ok(mut sim) => {
                let status = sim.run(2.0, |o| {
                    assert!(o.phi1_rad.is_finite() && o.phi2_rad.is_finite());
                    assert!(o.energy_j().is_finite());
                });
                assert!(sim.state().iter().all(|v| v.is_finite()), "{name} {sets:?}");
                Ok(match status {
                    Status::Running => "running",
                    Status::Diverged { .. } => "diverged",
                    Status::TooStiff { .. } => "too stiff",
                    Status::TooFast { .. } => "too fast",
                })
            }
        };
        assert_eq!(
            answer,
            expected.map_err(str::to_owned),
            "{name} {sets:?} {engine:?}"
        );
    }
}

/// A refused or failed write leaves an existing file as it was: the output
/// is checked before any work and written beside its destination, renamed
/// into place only when complete.
#[test]
fn a_refused_output_leaves_the_existing_file_alone() {
    let dir = std::env::temp_dir().join(format!("zl-keep-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let jpg = dir.join("existing.jpg");
    std::fs::write(&jpg, "the user's picture").unwrap();
    let out = run_limited(&[
        "snapshot",
        "--preset",
        "roller",
        "--out",
        jpg.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(std::fs::read_to_string(&jpg).unwrap(), "the user's picture");
    // A completed map replaces the file whole, leaving no temporary behind.
    let csv = dir.join("map.csv");
    std::fs::write(&csv, "old").unwrap();
    let out = run_limited(&[
        "map",
        "--preset",
        "roller",
        "--x",
        "load:0:8:4",
        "--y",
        "nu:0.1:0.2:2",
        "--out",
        csv.to_str().unwrap(),
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&csv).unwrap();
    assert!(text.starts_with("load,nu,state,growth_rate\n"), "{text}");
    assert_eq!(text.lines().count(), 1 + 4 * 2);
    let names: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names.len(), 2, "{names:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A reader that stops early (`simulate | head -1`) ends the command quietly
/// with status 0, as Unix tools do, instead of "error: Broken pipe", and
/// at once: 40000 s of a chain of 16 rods (several minutes of computing)
/// are not run to the end for nobody (the case limit of a minute fails a
/// run that goes on).
#[test]
fn a_closed_pipe_ends_quietly() {
    let with_ramp = ["--ramp", "0:0.1:0.000001"];
    for extra in [&[][..], &with_ramp[..]] {
        let args = [
            &["simulate", "--preset", "beck", "--duration", "40000"],
            extra,
        ]
        .concat();
        let mut child = spawn(&args);
        let mut first = [0u8; 64];
        child
            .stdout
            .as_mut()
            .unwrap()
            .read_exact(&mut first)
            .unwrap();
        drop(child.stdout.take());
        let why = format!("{extra:?}: still computing for a closed pipe");
        wait_within(&mut child, CASE_LIMIT, &why);
        let out = child.wait_with_output().unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(0), "{extra:?}: {stderr}");
        assert!(stderr.is_empty(), "{extra:?}: {stderr}");
    }
}

/// A reader that goes before anything is written: a command whose answer
/// comes only at the end of a long computation (the critical loads of 64
/// rods up to p = 1e150: more than a minute; a long bench; a map written
/// to standard output) ends quietly
/// within a second of the pipe's closing, not when it would first write.
#[test]
fn a_reader_gone_before_the_first_line_ends_the_work() {
    let cases: [&[&str]; 3] = [
        &[
            "critical",
            "--preset",
            "beck",
            "--set",
            "rods=64",
            "--load-max",
            "1e150",
        ],
        &["bench", "--frames", "10000", "--no-window"],
        &[
            "map",
            "--preset",
            "beck",
            "--x",
            "load:0:0.15:200",
            "--y",
            "mass_ratio:0.01:1:200",
            "--out",
            "/dev/stdout",
        ],
    ];
    for args in cases {
        let mut child = spawn(args);
        std::thread::sleep(Duration::from_millis(300));
        assert!(
            child.try_wait().unwrap().is_none(),
            "{args:?} still at work"
        );
        drop(child.stdout.take());
        let why = format!("{args:?}: still computing since its reader went");
        wait_within(&mut child, Duration::from_secs(5), &why);
        let out = child.wait_with_output().unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(0), "{args:?}: {stderr}");
        // (A debug build of bench notes that its numbers are not representative.)
        assert!(!stderr.contains("error"), "{args:?}: {stderr}");
    }
}

/// The standard output of a command that must succeed.
fn answer(args: &[&str]) -> String {
    let out = run_limited(args);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

/// Data files carry no negative zero: a rate or an angle that rounds to
/// zero is written `0` (`-0` reads as negative to a sign test).
#[test]
fn data_files_write_zero_without_a_sign() {
    let map = answer(&[
        "map",
        "--preset",
        "beck",
        "--x",
        "load:0:0.1:2",
        "--y",
        "mass_ratio:0.05:0.1:2",
        "--out",
        "/dev/stdout",
    ]);
    let locus = answer(&[
        "locus",
        "--preset",
        "roller",
        "--load-min",
        "0",
        "--load-max",
        "1",
        "--samples",
        "3",
    ]);
    for text in [map, locus] {
        assert!(text.lines().count() > 2, "{text}");
        for line in text.lines() {
            assert!(!line.split(',').any(|field| field == "-0"), "{line}");
        }
    }
}

/// `--out` through a symbolic link writes the file the link names and
/// keeps the link (it used to replace the link by the file).
#[cfg(unix)]
#[test]
fn an_output_through_a_link_writes_the_file_it_names() {
    let dir = tempfile::tempdir().unwrap();
    let (target, link) = (dir.path().join("data.csv"), dir.path().join("link.csv"));
    std::fs::write(&target, "old").unwrap();
    std::os::unix::fs::symlink(&target, &link).unwrap();
    let out = run_limited(&[
        "map",
        "--preset",
        "roller",
        "--x",
        "load:0:1:2",
        "--y",
        "nu:0.1:0.2:2",
        "--out",
        link.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink()
    );
    assert!(
        std::fs::read_to_string(&target)
            .unwrap()
            .starts_with("load")
    );
}

/// Ctrl-C or SIGTERM stops a long command at once with status 130, and no
/// file is left where the output would have gone.
#[cfg(unix)]
#[test]
fn a_stopping_signal_ends_a_long_command_at_once() {
    let folder = tempfile::tempdir().expect("a temporary folder");
    let out = folder.path().join("never.png");
    let mut child = Command::new(env!("CARGO_BIN_EXE_zieglerlab"))
        .args([
            "snapshot", "--preset", "roller", "--time", "100000", "--out",
        ])
        .arg(&out)
        .spawn()
        .expect("the binary runs");
    std::thread::sleep(std::time::Duration::from_millis(500));
    let sent = Command::new("kill")
        .args(["-TERM", &child.id().to_string()])
        .status()
        .expect("kill runs");
    assert!(sent.success());
    // 100000 simulated seconds would take hours: 130 is the handler's.
    let status = wait_within(
        &mut child,
        Duration::from_secs(30),
        "SIGTERM: still running",
    );
    assert_eq!(status.code(), Some(130));
    assert_eq!(
        std::fs::read_dir(folder.path())
            .expect("the folder")
            .count(),
        0
    );
}
