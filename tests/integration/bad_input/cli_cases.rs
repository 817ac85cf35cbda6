//! The command-line cases of the bad-input tests: each command line with
//! the exit status and the piece of stderr it must answer with.

/// A command line and what it must answer: the exit status and a piece of
/// stderr (for status 2 or 124, its only line; for status 0, "" means
/// silence).
pub struct Cli {
    pub args: &'static [&'static str],
    pub status: i32,
    pub stderr: &'static str,
}

pub const fn refused(args: &'static [&'static str], stderr: &'static str) -> Cli {
    Cli {
        args,
        status: 2,
        stderr,
    }
}

/// A command stopped by its time limit: status 124 and one line.
pub const fn stopped(args: &'static [&'static str], stderr: &'static str) -> Cli {
    Cli {
        args,
        status: 124,
        stderr,
    }
}

pub const fn answered(args: &'static [&'static str], stderr: &'static str) -> Cli {
    Cli {
        args,
        status: 0,
        stderr,
    }
}

pub const CLI: &[Cli] = &[
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
];
