//! Bad input, singular physics and blow-ups, as tables: every case gets an
//! answer a person understands. From the command line (run as a process):
//! the status, one line on stderr, never a panic, never NaN in the output.
//! From the library: an error naming the parameter, or a result with its
//! caveat. The README's table "Bad input and extremes" lists the same cases.

use std::io::Read as _;
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

use zieglerlab::analysis::{
    AffinePencil, bracketing_locus, critical_loads_along, resolution_warning,
};
use zieglerlab::model::{Model, apply_assignments, parse_assignment, preset};
use zieglerlab::sim::{EngineKind, SimError, Simulation, Status, initial_state};

/// A command line and what it must answer: the exit status and a piece of
/// stderr (for status 2, its only line; for status 0, "" means silence).
struct Cli {
    args: &'static [&'static str],
    status: i32,
    stderr: &'static str,
}

const fn refused(args: &'static [&'static str], stderr: &'static str) -> Cli {
    Cli {
        args,
        status: 2,
        stderr,
    }
}

const fn answered(args: &'static [&'static str], stderr: &'static str) -> Cli {
    Cli {
        args,
        status: 0,
        stderr,
    }
}

const CLI: &[Cli] = &[
    // Masses: NaN, infinite, negative; all zero (no inertia at all).
    refused(
        &["critical", "--preset", "roller", "--set", "m1=nan"],
        "m1 = NaN",
    ),
    refused(
        &["critical", "--preset", "roller", "--set", "m2=inf"],
        "m2 = inf",
    ),
    refused(
        &["critical", "--preset", "ziegler-1952", "--set", "m_tip=-1"],
        "m_tip = -1",
    ),
    refused(
        &["critical", "--preset", "roller", "--set", "nu=NaN"],
        "nu = NaN",
    ),
    refused(
        &[
            "critical",
            "--preset",
            "uniform-rods",
            "--set",
            "m1=0",
            "--set",
            "m2=0",
        ],
        "mass matrix",
    ),
    // Lengths, stiffnesses, radius.
    refused(
        &["critical", "--preset", "roller", "--set", "l1=0"],
        "l1 = 0",
    ),
    refused(
        &["critical", "--preset", "roller", "--set", "l2=-1"],
        "l2 = -1",
    ),
    refused(
        &["critical", "--preset", "roller", "--set", "l1=inf"],
        "l1 = inf",
    ),
    refused(
        &["critical", "--preset", "uniform-rods", "--set", "k1=0"],
        "k1 = 0",
    ),
    refused(
        &["critical", "--preset", "uniform-rods", "--set", "k2=-3"],
        "k2 = -3",
    ),
    refused(&["critical", "--preset", "roller", "--set", "a=0"], "a = 0"),
    refused(&["critical", "--preset", "roller", "--set", "r=0"], "r = 0"),
    refused(
        &["critical", "--preset", "roller", "--set", "r=nan"],
        "r = NaN",
    ),
    // r larger than the rod.
    refused(&["critical", "--preset", "roller", "--set", "r=3"], "r = 3"),
    refused(
        &["critical", "--preset", "roller", "--set", "rho=5"],
        "r = 5",
    ),
    // Friction: mu = 0 is no load at all; R.
    refused(
        &["critical", "--preset", "roller", "--set", "mu=0"],
        "mu = 0",
    ),
    refused(
        &["critical", "--preset", "roller", "--set", "mu=-0.1"],
        "mu = -0.1",
    ),
    refused(
        &["critical", "--preset", "roller", "--set", "R=-1"],
        "R = -1",
    ),
    refused(
        &["critical", "--preset", "roller", "--set", "R=inf"],
        "R = inf",
    ),
    // The band stopped: the linear model is singular (physics.md section 2).
    refused(&["critical", "--preset", "roller", "--set", "V=0"], "V = 0"),
    refused(
        &["critical", "--preset", "roller", "--set", "V=-1"],
        "V = -1",
    ),
    refused(
        &["critical", "--preset", "roller", "--set", "load=-1"],
        "load = -1",
    ),
    refused(
        &["critical", "--preset", "roller", "--set", "load=nan"],
        "load = NaN",
    ),
    // Unknown names, malformed numbers, conflicts.
    refused(&["critical", "--preset", "nope"], "unknown preset 'nope'"),
    refused(
        &["critical", "--preset", "roller", "--set", "colour=3"],
        "unknown key 'colour'",
    ),
    refused(
        &["critical", "--preset", "uniform-rods", "--set", "R=3"],
        "unknown key 'R'",
    ),
    refused(
        &["critical", "--preset", "uniform-rods", "--set", "load=abc"],
        "'abc' is not a number",
    ),
    refused(
        &["critical", "--preset", "uniform-rods", "--set", "load"],
        "no '='",
    ),
    refused(
        &[
            "critical", "--preset", "roller", "--set", "m3=1", "--set", "nu=1",
        ],
        "m3 and nu",
    ),
    refused(
        &["critical", "--preset", "uniform-rods", "--load-max", "-1"],
        "load-max",
    ),
    refused(
        &[
            "locus",
            "--preset",
            "roller",
            "--load-min",
            "0",
            "--load-max",
            "1",
            "--samples",
            "1",
        ],
        "samples",
    ),
    refused(
        &[
            "locus",
            "--preset",
            "roller",
            "--load-min",
            "0",
            "--load-max",
            "1",
            "--samples",
            "0",
        ],
        "samples",
    ),
    refused(
        &[
            "locus",
            "--preset",
            "roller",
            "--load-min",
            "0",
            "--load-max",
            "x",
            "--samples",
            "3",
        ],
        "invalid value 'x'",
    ),
    refused(
        &["critical", "--preset", "roller", "--bogus"],
        "unexpected argument '--bogus'",
    ),
    refused(&["frobnicate"], "unrecognized subcommand 'frobnicate'"),
    // Output that cannot be written, sizes and times that make no picture.
    refused(
        &[
            "snapshot",
            "--preset",
            "roller",
            "--out",
            "/nonexistent-dir/x.png",
        ],
        "the folder /nonexistent-dir does not exist",
    ),
    refused(
        &[
            "snapshot",
            "--preset",
            "roller",
            "--size",
            "10x10",
            "--out",
            "/tmp/zl-never.png",
        ],
        "invalid value '10x10' for '--size",
    ),
    refused(
        &[
            "snapshot",
            "--preset",
            "roller",
            "--time",
            "-3",
            "--out",
            "/tmp/zl-never.png",
        ],
        "time = -3",
    ),
    // Simulation arguments.
    refused(
        &["simulate", "--preset", "roller", "--duration", "-1"],
        "duration = -1",
    ),
    refused(
        &[
            "simulate",
            "--preset",
            "roller",
            "--duration",
            "1",
            "--dt",
            "0",
        ],
        "dt = 0",
    ),
    refused(
        &[
            "simulate",
            "--preset",
            "roller",
            "--duration",
            "1",
            "--perturb",
            "nan",
        ],
        "perturb = NaN",
    ),
    refused(
        &[
            "simulate",
            "--preset",
            "roller",
            "--duration",
            "1e9",
            "--dt",
            "0.001",
        ],
        "at most",
    ),
    // Huge damping: rapier's explicit step cannot follow; it says which engine can.
    refused(
        &[
            "simulate",
            "--preset",
            "roller",
            "--set",
            "c1=1e6",
            "--duration",
            "1",
        ],
        "use the reference engine",
    ),
    // Stability maps: axes, ranges, values without analysis, output.
    refused(
        &[
            "map",
            "--preset",
            "roller",
            "--x",
            "nu:0:1:3",
            "--y",
            "V:0.1:1:3",
            "--out",
            "/tmp/zl-never.csv",
        ],
        "the map's first axis is the load",
    ),
    refused(
        &[
            "map",
            "--preset",
            "roller",
            "--x",
            "load:0:8:3",
            "--y",
            "nu:0:1",
            "--out",
            "/tmp/zl-never.csv",
        ],
        "must be NAME:MIN:MAX:N",
    ),
    refused(
        &[
            "map",
            "--preset",
            "roller",
            "--x",
            "load:0:8:3",
            "--y",
            "nu:1:0:3",
            "--out",
            "/tmp/zl-never.csv",
        ],
        "MAX must be above MIN",
    ),
    refused(
        &[
            "map",
            "--preset",
            "roller",
            "--x",
            "load:0:8:3",
            "--y",
            "nu:0:1:0",
            "--out",
            "/tmp/zl-never.csv",
        ],
        "N = 0",
    ),
    refused(
        &[
            "map",
            "--preset",
            "roller",
            "--x",
            "load:0:8:3",
            "--y",
            "nu:0:x:3",
            "--out",
            "/tmp/zl-never.csv",
        ],
        "'x' is not a finite number",
    ),
    refused(
        &[
            "map",
            "--preset",
            "roller",
            "--x",
            "load:0:8:3",
            "--y",
            "colour:0:1:3",
            "--out",
            "/tmp/zl-never.csv",
        ],
        "unknown key 'colour'",
    ),
    refused(
        &[
            "map",
            "--preset",
            "roller",
            "--x",
            "load:0:8:3",
            "--y",
            "V:0:1:3",
            "--out",
            "/tmp/zl-never.csv",
        ],
        "V = 0",
    ),
    refused(
        &[
            "map",
            "--preset",
            "ziegler-1952",
            "--x",
            "load:0:8:3",
            "--y",
            "c1/c2:0.5:2:3",
            "--out",
            "/tmp/zl-never.csv",
        ],
        "needs a damped joint 2",
    ),
    refused(
        &[
            "map",
            "--preset",
            "roller",
            "--x",
            "load:0:8:3",
            "--y",
            "nu:0:1:3",
            "--out",
            "/nonexistent-dir/m.csv",
        ],
        "the folder /nonexistent-dir does not exist",
    ),
    refused(
        &["bench", "--frames", "0"],
        "frames = 0: must be 1 to 10000",
    ),
    refused(&["bench", "--frames", "many"], "invalid value"),
    // Extremes with an answer.
    answered(&["critical", "--preset", "roller", "--set", "load=1e6"], ""),
    answered(&["critical", "--preset", "roller", "--set", "nu=1e3"], ""),
    answered(&["critical", "--preset", "roller", "--set", "R=0"], ""),
    answered(
        &["critical", "--preset", "roller", "--set", "nu=1e-9"],
        "warning: the stability is not resolved",
    ),
    answered(
        &["critical", "--preset", "roller", "--set", "V=1e-6"],
        "warning: the stability is not resolved",
    ),
    answered(
        &[
            "simulate",
            "--preset",
            "roller",
            "--set",
            "load=1e6",
            "--duration",
            "2",
        ],
        "run stopped: too fast for the rapier engine at t = ",
    ),
    answered(
        &[
            "simulate",
            "--preset",
            "roller",
            "--set",
            "load=1e6",
            "--duration",
            "2",
            "--engine",
            "reference",
        ],
        "run stopped: too stiff for the reference integrator",
    ),
    // A step size that collapses while the state is bounded is stiffness,
    // not divergence (this once said "diverged at t = 0.000 s").
    answered(
        &[
            "simulate",
            "--preset",
            "ziegler-1952",
            "--set",
            "a=1e12",
            "--set",
            "load=1e15",
            "--duration",
            "1",
            "--engine",
            "reference",
        ],
        "run stopped: too stiff for the reference integrator at t = 0.000 s: a very light roller or a stopped band (the rapier engine handles those), or a load or stiffness so large",
    ),
    answered(
        &[
            "simulate",
            "--preset",
            "roller",
            "--set",
            "V=0",
            "--duration",
            "2",
        ],
        "",
    ),
    answered(
        &[
            "simulate",
            "--preset",
            "roller",
            "--set",
            "nu=1e-9",
            "--duration",
            "2",
        ],
        "",
    ),
    answered(
        &[
            "simulate",
            "--preset",
            "roller",
            "--set",
            "c1=1e6",
            "--duration",
            "2",
            "--engine",
            "reference",
        ],
        "",
    ),
    // Degenerate load intervals: a few units in the last place wide. These
    // once halved the step forever (p + step == p) and grew without bound.
    refused(
        &[
            "critical",
            "--preset",
            "ziegler-1952",
            "--load-min",
            "1",
            "--load-max",
            "1.0000000000000002",
        ],
        "load-max = 1.0000000000000002: must exceed load-min by more than the resolution",
    ),
    answered(
        &[
            "critical",
            "--preset",
            "ziegler-1952",
            "--load-min",
            "1",
            "--load-max",
            "1.00000000000002",
        ],
        "",
    ),
    refused(
        &[
            "locus",
            "--preset",
            "roller",
            "--load-min",
            "1",
            "--load-max",
            "1.0000000000000002",
            "--samples",
            "100",
        ],
        "samples = 100: too many for so narrow a range",
    ),
    refused(
        &[
            "map",
            "--preset",
            "roller",
            "--x",
            "load:1:1.0000000000000002:16",
            "--y",
            "nu:0.1:0.2:4",
            "--out",
            "/dev/null",
        ],
        "too many for so narrow a range",
    ),
    // Messages that name what is wrong, on one readable line.
    refused(
        &["critical"],
        "required arguments were not provided: --preset <PRESET>",
    ),
    refused(
        &[
            "snapshot", "--preset", "roller", "--size", "-640x480", "--out", "x.png",
        ],
        "invalid value '-640x480' for '--size <SIZE>': must be WIDTHxHEIGHT",
    ),
    refused(
        &["critical", "--preset", "roller", "--set", "n\x1bu\tx=1"],
        "unknown key",
    ),
    refused(
        &["critical", "--preset", "roller", "--set", "n\u{1b}u=1"],
        "unknown key 'n\\u{1b}u'",
    ),
    // Values whose derived quantities the analysis cannot square: refused,
    // naming the key, numbers in exponent form (never inf, never 300 digits).
    refused(
        &[
            "critical", "--preset", "roller", "--set", "mu=1e308", "--set", "R=1e308",
        ],
        "mu = 1e308: makes the load P beyond what the analysis can square",
    ),
    refused(
        &["critical", "--preset", "roller", "--set", "V=1e-300"],
        "V = 1e-300: makes the slip damping mu R l^2 / V beyond",
    ),
    refused(
        &["critical", "--preset", "ziegler-1952", "--set", "k1=1e300"],
        "k1 = 1e300: makes the stiffness k1 beyond",
    ),
    refused(
        &["critical", "--preset", "roller", "--set", "r=1e-300"],
        "r = 1e-300: makes the roller's spin inertia m3 r^2 / 2 beyond",
    ),
    refused(
        &[
            "snapshot", "--preset", "roller", "--set", "nu=1e-9", "--set", "V=1e-300", "--out",
            "x.png",
        ],
        "V = 1e-300: makes the slip damping",
    ),
    // A roller of tiny mass: its spin mode is so fast that rounding decides
    // the slow modes' states; every command that shows states says so.
    answered(
        &["critical", "--preset", "roller", "--set", "nu=1e-16"],
        "the stability is not resolved",
    ),
    answered(
        &["critical", "--preset", "roller", "--set", "nu=1e-100"],
        "a ratio beyond 1e12",
    ),
    answered(
        &[
            "locus",
            "--preset",
            "roller",
            "--set",
            "nu=1e-16",
            "--load-min",
            "0",
            "--load-max",
            "8",
            "--samples",
            "50",
        ],
        "the stability is not resolved",
    ),
    answered(
        &[
            "map",
            "--preset",
            "roller",
            "--x",
            "load:0:8:8",
            "--y",
            "nu:1e-16:2e-16:2",
            "--out",
            "/dev/stdout",
        ],
        "warning: at nu = 1e-16: the stability is not resolved",
    ),
    // Counts that would exhaust memory.
    refused(
        &["bench", "--frames", "18446744073709551615"],
        "frames = 18446744073709551615: must be 1 to 10000",
    ),
    refused(
        &["bench", "--frames", "1000000000000"],
        "must be 1 to 10000",
    ),
    // Output checked before any work: only PNG pictures, an existing folder.
    refused(
        &["snapshot", "--preset", "roller", "--out", "picture.jpg"],
        "pictures are written as PNG; name the file *.png",
    ),
    refused(
        &[
            "map",
            "--preset",
            "roller",
            "--x",
            "load:0:8:8",
            "--y",
            "nu:0.1:0.2:2",
            "--format",
            "png",
            "--out",
            "/no/such/folder/map.png",
        ],
        "the folder /no/such/folder does not exist",
    ),
];

/// Longest a command line case may run: a hang fails the test instead of
/// freezing CI.
const CASE_LIMIT: Duration = Duration::from_mins(1);

/// Runs the binary with `args`, killed after [`CASE_LIMIT`].
fn run_limited(args: &[&str]) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_zieglerlab"))
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary runs");
    // Readers on their own threads, so a full pipe cannot stall the child.
    let mut stdout = child.stdout.take().unwrap();
    let mut stderr = child.stderr.take().unwrap();
    let out_reader = std::thread::spawn(move || {
        let mut bytes = Vec::new();
        stdout.read_to_end(&mut bytes).map(|_| bytes)
    });
    let err_reader = std::thread::spawn(move || {
        let mut bytes = Vec::new();
        stderr.read_to_end(&mut bytes).map(|_| bytes)
    });
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if start.elapsed() > CASE_LIMIT {
            child.kill().unwrap();
            panic!("{args:?}: no answer within {CASE_LIMIT:?}");
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    Output {
        status,
        stdout: out_reader.join().unwrap().unwrap(),
        stderr: err_reader.join().unwrap().unwrap(),
    }
}

#[test]
fn every_command_line_case_gets_its_answer() {
    for case in CLI {
        let out = run_limited(case.args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        let stdout = String::from_utf8_lossy(&out.stdout);
        let args = case.args;
        assert_eq!(out.status.code(), Some(case.status), "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
        assert!(stderr.contains(case.stderr), "{args:?}: {stderr}");
        if case.status == 2 {
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
    ("roller", &["load=1e6"], EngineKind::Rapier, Ok("too fast")),
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
/// with status 0, as Unix tools do, instead of "error: Broken pipe".
#[test]
fn a_closed_pipe_ends_quietly() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_zieglerlab"))
        .args(["simulate", "--preset", "roller", "--duration", "200"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = [0u8; 64];
    child
        .stdout
        .as_mut()
        .unwrap()
        .read_exact(&mut first)
        .unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(stderr.is_empty(), "{stderr}");
}
