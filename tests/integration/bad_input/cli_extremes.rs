//! The command-line cases of the bad-input tests at the extremes: values
//! with an answer, stiffness, degenerate intervals, singular limits,
//! resource bounds and output checks.

use super::cli_cases::{Cli, answered, refused};

/// The cases at the extremes (the table goes on from [`super::cli_cases::CLI`]).
pub const CLI_EXTREMES: &[Cli] = &[
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
    // A chain whose first damper is 1e149 times the others': the modes span
    // beyond resolution, and the bounded iteration answers in seconds
    // (faer's Schur decomposition ran for minutes on one of its loads).
    answered(
        &[
            "critical",
            "--preset",
            "pflueger-roller",
            "--set",
            "rods=64",
            "--set",
            "c1=1e149",
        ],
        "warning: the stability is not resolved: at p = 0.0098 the modes span 1.6e149 1/s",
    ),
    answered(
        &[
            "simulate",
            "--preset",
            "ziegler-1952",
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
    // Load ranges the analysis cannot resolve: refused by name. A range as
    // wide as the load itself allows is bracketed decade by decade.
    refused(
        &[
            "critical",
            "--preset",
            "ziegler-1952",
            "--load-max",
            "1e300",
        ],
        "load-max = 1e300: must be at most 1e150",
    ),
    refused(
        &[
            "critical",
            "--preset",
            "ziegler-1952",
            "--load-min",
            "0",
            "--load-max",
            "5e-324",
        ],
        "load-max = 5e-324: must exceed load-min by more than the resolution",
    ),
    refused(
        &[
            "critical",
            "--preset",
            "ziegler-1952",
            "--load-min",
            "2",
            "--load-max",
            "2",
        ],
        "load-max = 2: must exceed load-min",
    ),
    answered(
        &[
            "critical",
            "--preset",
            "ziegler-1952",
            "--load-max",
            "1e150",
        ],
        "the stability is not resolved: at p = 1.0000e150",
    ),
    // Chains: the memory a locus holds is bounded by its arguments, and a
    // stiff first joint (a mode the load cancels to rounding) once halved
    // the locus's step to its floor everywhere (7 s on 8 rods, 75 s on 32).
    refused(
        &[
            "locus",
            "--preset",
            "beck",
            "--set",
            "rods=64",
            "--load-min",
            "0",
            "--load-max",
            "0.01",
            "--samples",
            "1000000",
        ],
        "samples = 1000000: at most 131072 loads for a locus of 128 eigenvalues",
    ),
    // That cancelled mode is below double precision: in 60-digit arithmetic
    // of the same matrices its mu = lambda^2 is -5.8e-12 beside the fastest
    // 6.8e6 (|lambda| = 2.4e-6 1/s), so a double-precision solver returns
    // rounding, 5e-6 to 4e-5 1/s as the algorithm goes, and the state there
    // is rounding's: the answer comes with the warning that says so.
    answered(
        &[
            "critical", "--preset", "beck", "--set", "rods=8", "--set", "k1=1e6",
        ],
        "warning: the stability is not resolved: at p = 0.6250",
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
