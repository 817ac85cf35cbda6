//! The pictures and files the command line writes: PNG snapshots and maps
//! of the asked size, GIF recordings with one frame per 1/fps s of
//! simulated time, and files readable by all.

use crate::cli::{run, stdout};

/// Width and height from a PNG's IHDR chunk.
fn png_size(path: &std::path::Path) -> (u32, u32) {
    let bytes = std::fs::read(path).expect("png written");
    assert_eq!(&bytes[1..4], b"PNG");
    let word =
        |at: usize| u32::from_be_bytes([bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]]);
    (word(16), word(20))
}

#[test]
fn snapshot_writes_a_png_of_the_asked_size() {
    let dir = std::env::temp_dir().join(format!("zieglerlab-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let window = dir.join("window.png");
    let out = window.to_str().expect("utf-8 path");
    stdout(&[
        "snapshot", "--preset", "roller", "--time", "1", "--size", "1024x700", "--out", out,
    ]);
    assert_eq!(png_size(&window), (1024, 700));
    let panel = dir.join("locus.png");
    let out = panel.to_str().expect("utf-8 path");
    stdout(&[
        "snapshot",
        "--preset",
        "midpoint-masses",
        "--panel",
        "locus",
        "--size",
        "480x300",
        "--out",
        out,
    ]);
    assert_eq!(png_size(&panel), (480, 300));
    std::fs::remove_dir_all(&dir).expect("cleanup");
}

#[test]
fn map_png_is_written() {
    let path = std::env::temp_dir().join(format!("zl-map-{}.png", std::process::id()));
    let out = run(&[
        "map",
        "--preset",
        "ziegler-1952",
        "--x",
        "load:0:8:64",
        "--y",
        "damping:0:0.3:32",
        "--format",
        "png",
        "--out",
        path.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // The map figure (as `figure --kind map`) on its default page: 85 x 68
    // mm at 300 dpi.
    assert_eq!(png_size(&path), (1004, 803));
    std::fs::remove_file(&path).unwrap();
}

/// The frames of a GIF, each as RGBA pixels, and its size.
fn gif_frames(path: &std::path::Path) -> ((u16, u16), Vec<Vec<u8>>) {
    let mut options = gif::DecodeOptions::new();
    options.set_color_output(gif::ColorOutput::RGBA);
    let mut decoder = options
        .read_info(std::fs::File::open(path).expect("the GIF opens"))
        .expect("a GIF");
    let size = (decoder.width(), decoder.height());
    let mut frames = Vec::new();
    while let Some(frame) = decoder.read_next_frame().expect("a frame") {
        frames.push(frame.buffer.to_vec());
    }
    (size, frames)
}

/// `record`: one frame per 1/fps s of simulated time at the given size,
/// the same bytes for the same arguments, frames that change while the
/// column moves (the tabletop column fluttering at p = 3), and bad
/// arguments refused before anything is drawn or written.
#[test]
fn record_writes_a_deterministic_gif_of_the_run() {
    let folder = tempfile::tempdir().expect("a temporary folder");
    let out = |name: &str| folder.path().join(name);
    let record = |path: &std::path::Path| {
        stdout(&[
            "record",
            "--preset",
            "tabletop",
            "--set",
            "load=3",
            "--panel",
            "scene",
            "--duration",
            "3",
            "--fps",
            "4",
            "--size",
            "480x300",
            "--out",
            path.to_str().expect("a path"),
        ])
    };
    record(&out("a.gif"));
    record(&out("b.gif"));
    let (a, b) = (
        std::fs::read(out("a.gif")).expect("written"),
        std::fs::read(out("b.gif")).expect("written"),
    );
    assert_eq!(a, b, "the same arguments give the same bytes");
    let (size, frames) = gif_frames(&out("a.gif"));
    assert_eq!(size, (480, 300));
    assert_eq!(frames.len(), 12, "3 s at 4 frames per second");
    assert_ne!(frames[0], frames[11], "the column moved");
    for (args, says) in [
        (vec!["--out", "x.png"], "name the file *.gif"),
        (vec!["--fps", "0", "--out", "x.gif"], "fps = 0"),
        (
            vec!["--duration", "1000", "--out", "x.gif"],
            "at most 3000 frames",
        ),
        (vec!["--scale", "9", "--out", "x.gif"], "scale = 9"),
    ] {
        let mut all = vec!["record", "--preset", "tabletop"];
        all.extend(args);
        let refused = run(&all);
        assert_eq!(refused.status.code(), Some(2), "{all:?}");
        assert!(
            String::from_utf8_lossy(&refused.stderr).contains(says),
            "{all:?}"
        );
    }
    assert!(!std::path::Path::new("x.gif").exists(), "nothing written");
}

/// A file the CLI writes gets the usual permissions (readable by all), not
/// those of the private temporary file it is written through.
#[cfg(unix)]
#[test]
fn written_files_are_readable_by_all() {
    use std::os::unix::fs::PermissionsExt as _;
    let folder = tempfile::tempdir().expect("a temporary folder");
    let out = folder.path().join("map.csv");
    stdout(&[
        "map",
        "--preset",
        "ziegler-1952",
        "--x",
        "load:0:4:3",
        "--y",
        "damping:0:0.5:2",
        "--out",
        out.to_str().expect("a path"),
    ]);
    let mode = std::fs::metadata(&out)
        .expect("written")
        .permissions()
        .mode();
    assert_eq!(mode & 0o777, 0o644);
}

/// `snapshot --lesson NAME --step N`: a built-in lesson at a step, drawn as
/// the window shows it there (a handout); a step the lesson does not have,
/// a lesson that does not exist and `--step` without a lesson are refused
/// before anything is drawn.
#[test]
fn snapshot_draws_a_lesson_at_a_step() {
    let folder = tempfile::tempdir().expect("a temporary folder");
    let out = folder.path().join("step2.png");
    let out_text = out.to_str().unwrap();
    stdout(&[
        "snapshot",
        "--preset",
        "roller",
        "--lesson",
        "where-flutter-starts",
        "--step",
        "2",
        "--size",
        "1024x768",
        "--projector",
        "--out",
        out_text,
    ]);
    assert_eq!(png_size(&out), (1024, 768));
    for (args, says) in [
        (
            &["--lesson", "where-flutter-starts", "--step", "99"][..],
            "step = 99: the lesson has steps 1 to ",
        ),
        (
            &["--lesson", "where-flutter-starts", "--step", "0"][..],
            "step = 0: the lesson has steps 1 to ",
        ),
        (&["--lesson", "no-such-lesson"][..], "no-such-lesson"),
        (&["--step", "2"][..], "--lesson"),
    ] {
        let refused = folder.path().join("refused.png");
        let mut line = vec!["snapshot", "--preset", "roller", "--out"];
        line.push(refused.to_str().unwrap());
        line.extend_from_slice(args);
        let result = run(&line);
        let stderr = String::from_utf8_lossy(&result.stderr);
        assert_eq!(result.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.contains(says), "{args:?}: {stderr}");
        assert!(!refused.exists(), "{args:?}");
    }
}
