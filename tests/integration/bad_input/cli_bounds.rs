//! The command-line cases of the bad-input tests for bounds and words: load
//! ranges held to what the analysis resolves in every command, figure pages
//! that hold their legend, values that would give meaningless answers, and
//! messages that name what the user typed.

use super::cli_cases::{Cli, refused, stopped};

/// The cases of bounds and words (the table goes on from
/// [`super::cli_extremes::CLI_EXTREMES`]).
pub const CLI_BOUNDS: &[Cli] = &[
    // Load ranges: the rule of `critical` (at most 1e150) in every command.
    refused(
        &[
            "figure",
            "--preset",
            "roller",
            "--kind",
            "locus",
            "--load-max",
            "1e300",
            "--out",
            "/tmp/zl-never.svg",
        ],
        "load-max = 1e300: must be at most 1e150",
    ),
    refused(
        &[
            "locus",
            "--preset",
            "roller",
            "--load-min",
            "0",
            "--load-max",
            "1e300",
            "--samples",
            "3",
        ],
        "load-max = 1e300: must be at most 1e150",
    ),
    // Pages that hold no plot beside their legend and labels.
    refused(
        &[
            "figure",
            "--preset",
            "ziegler-1952",
            "--kind",
            "re-im",
            "--width-mm",
            "30",
            "--height-mm",
            "30",
            "--out",
            "/tmp/zl-never.svg",
        ],
        "a 30 x 30 mm page at 8 pt leaves no room for the plots: its legend and the axes' words need about 30 x ",
    ),
    refused(
        &[
            "figure",
            "--preset",
            "ziegler-1952",
            "--kind",
            "locus",
            "--font-pt",
            "24",
            "--out",
            "/tmp/zl-never.svg",
        ],
        "at 24 pt leaves no room for the plot: ",
    ),
    // The height not typed is the width's: the width is named.
    refused(
        &[
            "figure",
            "--preset",
            "ziegler-1952",
            "--kind",
            "re-im",
            "--width-mm",
            "500",
            "--out",
            "/tmp/zl-never.svg",
        ],
        "--width-mm 500: a re-im figure is 1.1 times as tall as it is wide unless --height-mm is given, here 550 mm",
    ),
    // The axes' words, not `critical`'s options.
    refused(
        &[
            "map",
            "--preset",
            "ziegler-1952",
            "--x",
            "load:0:1e300:8",
            "--y",
            "damping:0:1:4",
            "--out",
            "/tmp/zl-never.csv",
        ],
        "--x load:0:1e300:8: MAX = 1e300: must be at most 1e150",
    ),
    refused(
        &[
            "map",
            "--preset",
            "ziegler-1952",
            "--x",
            "load:0:4:1",
            "--y",
            "damping:0:1:4",
            "--out",
            "/tmp/zl-never.csv",
        ],
        "--x load:0:4:1: N = 1: must be >= 2 unless MIN equals MAX",
    ),
    refused(
        &[
            "map",
            "--preset",
            "ziegler-1952",
            "--x",
            "load:0:4:8",
            "--y",
            "damping:0:1e300:4",
            "--out",
            "/tmp/zl-never.csv",
        ],
        "--y damping:0:1e300:4: the damper c1 = ",
    ),
    refused(
        &[
            "bifurcation",
            "--preset",
            "ziegler-1952",
            "--set",
            "c2=0.05",
            "--x",
            "load:0:1e300:8",
        ],
        "--x load:0:1e300:8: MAX = 1e300: must be at most 1e150",
    ),
    // Values that would give meaningless answers.
    refused(
        &[
            "bifurcation",
            "--preset",
            "ziegler-1952",
            "--set",
            "c2=0.05",
            "--x",
            "load:2:3:4",
            "--sweep",
            "--measure-periods",
            "1e-300",
        ],
        "--measure-periods 1e-300: must be a number of periods from 1 to",
    ),
    refused(
        &[
            "simulate",
            "--preset",
            "tabletop",
            "--duration",
            "1",
            "--ramp",
            "0:4:1e-320",
        ],
        "ramp rate = 1e-320: must be at least 1e-6 load per second",
    ),
    refused(
        &[
            "simulate",
            "--preset",
            "tabletop",
            "--duration",
            "1",
            "--ramp",
            "0:1000:1e-5",
        ],
        "ramp from 0 to 1000 at 1e-5 per second takes 1e8 s of simulated time; at most 1e7 s",
    ),
    // No input runs without end: a wide range on a long chain takes about
    // 20 s; the time limit stops it with one line (and the limit itself is
    // checked).
    stopped(
        &[
            "critical",
            "--preset",
            "beck",
            "--set",
            "rods=32",
            "--load-max",
            "1e150",
            "--time-limit",
            "2",
        ],
        "error: stopped after 2 s, the time limit of a command (--time-limit SECS allows more)",
    ),
    refused(
        &["presets", "--time-limit", "0"],
        "--time-limit 0: must be 1 to 604800 seconds",
    ),
    // An option that takes negative numbers, followed by another option
    // instead of its value: named (it said "unexpected argument 'load=1'").
    refused(
        &[
            "critical",
            "--preset",
            "roller",
            "--time-limit",
            "--set",
            "load=1",
        ],
        "error: --time-limit needs a value, but the next word is the option --set",
    ),
    refused(
        &[
            "simulate",
            "--preset",
            "roller",
            "--duration",
            "--set",
            "load=1",
        ],
        "error: --duration needs a value, but the next word is the option --set",
    ),
    // A mu so small that R = P / mu overflows: mu is named with its value
    // (it said "the load P = inf").
    refused(
        &["critical", "--preset", "roller", "--set", "mu=1e-320"],
        "error: mu = 1e-320: too small",
    ),
];
