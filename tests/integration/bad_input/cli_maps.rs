//! The command-line cases of the bad-input tests, continued: stability
//! maps, output that cannot be written, numbers at the edges of what a flag
//! takes, lesson files that are no files, picture sizes and ramps.

use super::cli_cases::{Cli, refused};

/// The cases of maps, outputs, flags and ramps (the table goes on from
/// [`super::cli_cases::CLI`]).
pub const CLI_MAPS: &[Cli] = &[
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
    // A folder that exists but takes no file is found before any work.
    refused(
        &["record", "--preset", "roller", "--out", "/proc/x.gif"],
        "out = /proc/x.gif: the folder /proc takes no new file",
    ),
    // Negative numbers and -inf reach the flag's own check, which names it
    // (clap once answered "unexpected argument '-1' found", naming none).
    refused(
        &[
            "record",
            "--preset",
            "roller",
            "--fps",
            "-1",
            "--out",
            "/tmp/x.gif",
        ],
        "invalid value '-1' for '--fps <FPS>'",
    ),
    refused(
        &[
            "record",
            "--preset",
            "roller",
            "--duration",
            "-inf",
            "--out",
            "/tmp/x.gif",
        ],
        "duration = -inf: must be a positive number of seconds",
    ),
    // clap repeats a value as typed: a long one is clipped with its length.
    refused(
        &[
            "critical",
            "--preset",
            "xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx",
        ],
        "... (102 characters) for '--preset <PRESET>'",
    ),
    // Huge and tiny numbers are repeated in exponent form, not with 300 digits.
    refused(
        &[
            "record",
            "--preset",
            "roller",
            "--duration",
            "1e308",
            "--out",
            "/tmp/zl-never.gif",
        ],
        "duration = 1e308: must be a positive number of seconds",
    ),
    refused(
        &[
            "snapshot",
            "--preset",
            "roller",
            "--scale",
            "1e-45",
            "--out",
            "/tmp/zl-never.png",
        ],
        "scale = 1e-45: must be 0.5 to 8 pixels per point",
    ),
    // A map axis's range is checked as the axis takes it, not as a load.
    refused(
        &[
            "map",
            "--preset",
            "beck",
            "--x",
            "load:0:1:2",
            "--y",
            "eta:-1:1:2",
            "--out",
            "/tmp/zl-never.csv",
        ],
        "eta = -1: must be a finite number in [0, 1]",
    ),
    // Masses so unequal that rounding leaves one no digits: said so, not
    // "needs mass beyond the joint".
    refused(
        &["critical", "--preset", "roller", "--set", "m_tip=1e149"],
        "mass matrix = 0: the masses are too unequal",
    ),
    // A long unknown word is repeated clipped, with its length.
    refused(
        &[
            "critical",
            "--preset",
            "roller",
            "--set",
            "kkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkk=1",
        ],
        "unknown key 'kkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkk... (64 characters)' for preset roller",
    ),
    // Only a regular file of at most 1 MiB is read as a lesson: a device
    // never ends, a pipe blocks.
    refused(
        &["lesson", "--check", "/dev/zero"],
        "cannot read /dev/zero: it is a device, a pipe or a socket, not a regular file",
    ),
    refused(
        &["lesson", "--check", "/tmp"],
        "cannot read /tmp: it is a folder, not a regular file",
    ),
    // A layout smaller than the panel can take is refused, not drawn as a
    // clipped fragment or a transparent picture.
    refused(
        &[
            "snapshot",
            "--preset",
            "roller",
            "--size",
            "800x500",
            "--scale",
            "8",
            "--out",
            "/tmp/zl-never.png",
        ],
        "size = 800x500 at scale = 8 lays out 100x62 points; the window (the smallest it opens at) needs at least 1024x700",
    ),
    refused(
        &[
            "record",
            "--preset",
            "roller",
            "--panel",
            "scene",
            "--size",
            "64x64",
            "--out",
            "/tmp/zl-never.gif",
        ],
        "size = 64x64 at scale = 1 lays out 64x64 points; one panel needs at least 480x300",
    ),
    refused(
        &[
            "snapshot",
            "--preset",
            "roller",
            "--scale",
            "-1",
            "--out",
            "/tmp/x.png",
        ],
        "scale = -1: must be 0.5 to 8 pixels per point",
    ),
    refused(
        &["bench", "--frames", "-1"],
        "invalid value '-1' for '--frames <FRAMES>'",
    ),
    // A ramp sets the load: a --set of it in any of its names is refused
    // (it was silently overridden), and so is a ramp to a load the model
    // cannot take, before the run, in every command that ramps.
    refused(
        &[
            "simulate",
            "--preset",
            "roller",
            "--duration",
            "1",
            "--ramp",
            "0:2:0.1",
            "--set",
            "R=50",
        ],
        "--ramp sets the load (from its FROM on): leave out --set R",
    ),
    refused(
        &[
            "simulate",
            "--preset",
            "ziegler-1952",
            "--duration",
            "1",
            "--ramp",
            "0:2:0.1",
            "--set",
            "P=5",
        ],
        "leave out --set P",
    ),
    refused(
        &[
            "simulate",
            "--preset",
            "roller",
            "--duration",
            "1",
            "--ramp",
            "0:1e300:1e300",
        ],
        "--ramp: ramp to = 1e300: the load P = 1e299: beyond",
    ),
    refused(
        &[
            "record",
            "--preset",
            "roller",
            "--duration",
            "1",
            "--ramp",
            "0:1e300:1e300",
            "--out",
            "/tmp/zieglerlab-ramp-refused.gif",
        ],
        "ramp to = 1e300",
    ),
    refused(
        &[
            "map",
            "--preset",
            "roller",
            "--x",
            "load:0:8:256",
            "--y",
            "nu:0.005:1:256",
            "--out",
            "/proc/m.csv",
        ],
        "out = /proc/m.csv: the folder /proc takes no new file",
    ),
    refused(
        &["snapshot", "--preset", "roller", "--out", "/proc/x.png"],
        "out = /proc/x.png: the folder /proc takes no new file",
    ),
    refused(
        &["bench", "--frames", "0"],
        "frames = 0: must be 1 to 10000",
    ),
    refused(&["bench", "--frames", "many"], "invalid value"),
    // Figures: the format from the name, the page, options the kind does not use.
    refused(
        &[
            "figure",
            "--preset",
            "roller",
            "--kind",
            "locus",
            "--out",
            "/tmp/zl-never.pdf",
        ],
        "figures are written as SVG or PNG; name the file *.svg or *.png",
    ),
    refused(
        &[
            "figure",
            "--preset",
            "roller",
            "--kind",
            "locus",
            "--width-mm",
            "10",
            "--out",
            "/tmp/zl-never.svg",
        ],
        "width-mm = 10: must be 30 to 500",
    ),
    refused(
        &[
            "figure",
            "--preset",
            "roller",
            "--kind",
            "re-im",
            "--width-mm",
            "500",
            "--height-mm",
            "400",
            "--dpi",
            "1200",
            "--out",
            "/tmp/zl-never.png",
        ],
        "has 446 million pixels, more than the 64 million a figure may have: use --dpi 454 or less, or an SVG",
    ),
    refused(
        &[
            "figure",
            "--preset",
            "roller",
            "--kind",
            "map",
            "--overlay",
            "ziegler-1952",
            "--out",
            "/tmp/zl-never.svg",
        ],
        "--kind map: does not use --overlay (locus and re-im only)",
    ),
    refused(
        &[
            "figure",
            "--preset",
            "roller",
            "--kind",
            "paradox",
            "--damping",
            "external",
            "--out",
            "/tmp/zl-never.svg",
        ],
        "the roller's curves sweep its mass ratio nu",
    ),
    refused(
        &[
            "figure",
            "--preset",
            "ziegler-1952",
            "--kind",
            "locus",
            "--load-min",
            "3",
            "--load-max",
            "1",
            "--out",
            "/tmp/zl-never.svg",
        ],
        "load-max = 1: must be finite and >= load-min",
    ),
    refused(
        &[
            "figure",
            "--preset",
            "ziegler-1952",
            "--kind",
            "paradox",
            "--set",
            "eta=0",
            "--out",
            "/tmp/zl-never.svg",
        ],
        "nothing to draw: A dead load (eta = 0) is conservative",
    ),
    // Limit cycles: the axis, the range, the sweep's times.
    refused(
        &["bifurcation", "--preset", "roller", "--x", "nu:0:1:3"],
        "the diagram's axis is the load",
    ),
    refused(
        &["bifurcation", "--preset", "roller", "--x", "load:-1:1:3"],
        "loads must be >= 0",
    ),
    refused(
        &["bifurcation", "--preset", "roller", "--x", "load:0:1:1"],
        "a diagram needs a range of loads",
    ),
    refused(
        &[
            "bifurcation",
            "--preset",
            "roller",
            "--x",
            "load:0:0.05:3",
            "--sweep",
            "--settle-periods",
            "-1",
        ],
        "--settle-periods -1: must be a number of periods in (0, 10000]",
    ),
    refused(
        &[
            "bifurcation",
            "--preset",
            "roller",
            "--x",
            "load:0:0.05:3",
            "--format",
            "png",
        ],
        "--format png: give the picture's file with --out FILE.png",
    ),
];
