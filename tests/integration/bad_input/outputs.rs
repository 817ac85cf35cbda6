//! Outputs that must not be written, and runs that must survive: a stream
//! the shell opened for reading, a file the user may not write, a path
//! that names a folder or a closed descriptor, and a long run started
//! under `nohup` or as a background job. Each is checked before the work,
//! by the one check every command's `--out` goes through.

use std::process::{Command, Stdio};
use std::time::Duration;

use super::wait_within;

const BIN: &str = env!("CARGO_BIN_EXE_zieglerlab");

/// A quick command with `--out` (a 3 by 2 map as CSV).
fn map_into(out: &str) -> String {
    format!("{BIN} map --preset ziegler-1952 --x load:0:4:3 --y damping:0:0.5:2 --out {out}")
}

/// `script` run by `sh`, within a minute; its status and stderr.
fn shell(script: &str) -> (Option<i32>, String) {
    let mut child = Command::new("sh")
        .args(["-c", script])
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("sh runs");
    let mut stderr = child.stderr.take().expect("piped");
    let reader = std::thread::spawn(move || {
        let mut text = String::new();
        std::io::Read::read_to_string(&mut stderr, &mut text).map(|_| text)
    });
    let status = wait_within(&mut child, Duration::from_mins(1), script);
    (status.code(), reader.join().expect("read").expect("text"))
}

/// `--out /dev/stdin < data`, `/dev/fd/3 3< data`, `/proc/self/fd/3` and a
/// link to `/dev/stdin`: each names a stream opened for reading; the data
/// stays as it was and the command says why before any work.
#[test]
fn a_stream_opened_for_reading_is_never_written() {
    let folder = tempfile::tempdir().expect("a folder");
    let data = folder.path().join("data.csv");
    let held = "the user's data, not to be written over\n";
    let link = folder.path().join("input");
    std::os::unix::fs::symlink("/dev/stdin", &link).expect("a link");
    let data_path = data.display();
    let cases = [
        format!("{} < {data_path}", map_into("/dev/stdin")),
        format!("{} 3< {data_path}", map_into("/dev/fd/3")),
        format!("{} 3< {data_path}", map_into("/proc/self/fd/3")),
        format!("{} < {data_path}", map_into(&link.display().to_string())),
    ];
    for script in cases {
        std::fs::write(&data, held).expect("written");
        let (status, stderr) = shell(&script);
        assert_eq!(status, Some(2), "{script}: {stderr}");
        assert!(stderr.contains("for reading only"), "{script}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{script}: {stderr}");
        assert_eq!(
            std::fs::read_to_string(&data).expect("read"),
            held,
            "{script}"
        );
    }
    // Opened for reading and writing (`<>`), the stream is the user's to
    // write: the map goes where the shell opened it.
    std::fs::write(&data, "").expect("emptied");
    let (status, stderr) = shell(&format!("{} 3<> {data_path}", map_into("/dev/fd/3")));
    assert_eq!(status, Some(0), "{stderr}");
    assert!(
        std::fs::read_to_string(&data)
            .expect("read")
            .starts_with("load,")
    );
}

/// A path ending in `/`, a link to a closed descriptor and `/dev/stdout`
/// with standard output closed are refused before the work, naming why
/// (a GIF's `clip.gif/` was refused after 31 s of recording; the closed
/// standard output ended with status 0 and nothing written).
#[test]
fn an_output_that_cannot_be_written_is_refused_before_the_work() {
    let folder = tempfile::tempdir().expect("a folder");
    let closed = folder.path().join("closed");
    std::os::unix::fs::symlink("/dev/fd/7", &closed).expect("a link");
    let gif = folder.path().join("clip.gif/");
    let record = format!(
        "{BIN} record --preset roller --duration 30 --out {}",
        gif.display()
    );
    let cases = [
        (record, "ends in `/`"),
        (
            map_into(&closed.display().to_string()),
            "descriptor 7 is not open",
        ),
        (
            format!("{} >&-", map_into("/dev/stdout")),
            "standard output is not open",
        ),
    ];
    for (script, why) in cases {
        let started = std::time::Instant::now();
        let (status, stderr) = shell(&script);
        assert_eq!(status, Some(2), "{script}: {stderr}");
        assert!(stderr.contains(why), "{script}: {stderr}");
        // Refused at once, not after the recording.
        assert!(started.elapsed() < Duration::from_secs(10), "{script}");
    }
    assert_eq!(std::fs::read_dir(folder.path()).expect("listed").count(), 1);
}

/// Whether this process runs as root (who may write any file).
fn root() -> bool {
    std::fs::read_to_string("/proc/self/status")
        .expect("status")
        .lines()
        .find_map(|line| line.strip_prefix("Uid:"))
        .and_then(|ids| ids.split_whitespace().nth(1).map(|id| id == "0"))
        .expect("an effective user")
}

/// `script` as a user who is not root (nobody, through util-linux's
/// `setpriv`, where the tests run as root).
fn as_a_user(script: &str) -> (Option<i32>, String) {
    if root() {
        shell(&format!(
            "setpriv --reuid=65534 --regid=65534 --clear-groups sh -c '{script}'"
        ))
    } else {
        shell(script)
    }
}

/// A file the user may not write (mode 0444) stays as it was, refused as
/// the shell's `>` refuses it; a writable file in a folder that takes no
/// new file is written where it stands.
#[cfg(unix)]
#[test]
fn a_protected_file_stays_protected() {
    use std::os::unix::fs::PermissionsExt as _;
    let folder = tempfile::tempdir().expect("a folder");
    let mode = |path: &std::path::Path, mode: u32| {
        std::fs::set_permissions(path, std::fs::Permissions::from_mode(mode)).expect("chmod");
    };
    // Nobody may reach the folder (a temporary folder is 0700).
    mode(folder.path(), 0o777);
    let kept = folder.path().join("kept.csv");
    std::fs::write(&kept, "the user's results\n").expect("written");
    mode(&kept, 0o444);
    let (status, stderr) = as_a_user(&map_into(&kept.display().to_string()));
    assert_eq!(status, Some(2), "{stderr}");
    assert!(stderr.contains("may not be written"), "{stderr}");
    assert_eq!(
        std::fs::read_to_string(&kept).expect("read"),
        "the user's results\n"
    );
    // The shell refuses the same file.
    let (shell_status, _) = as_a_user(&format!("echo x > {}", kept.display()));
    assert_ne!(shell_status, Some(0));
    // A folder that takes no new file, a file in it that may be written.
    let sealed = folder.path().join("sealed");
    std::fs::create_dir(&sealed).expect("a folder");
    let open = sealed.join("open.csv");
    std::fs::write(&open, "old and longer than nothing\n".repeat(200)).expect("written");
    mode(&open, 0o666);
    mode(&sealed, 0o555);
    let (status, stderr) = as_a_user(&map_into(&open.display().to_string()));
    assert_eq!(status, Some(0), "{stderr}");
    let written = std::fs::read_to_string(&open).expect("read");
    assert!(written.starts_with("load,"), "{written}");
    assert!(!written.contains("old and longer"), "cut to its length");
    assert_eq!(std::fs::read_dir(&sealed).expect("listed").count(), 1);
}

/// A long run started with SIGHUP ignored (`nohup`) or SIGINT ignored (a
/// script's background job) keeps that disposition: the signal does not
/// stop it; SIGTERM still does, with no file left behind.
#[test]
fn nohup_and_a_background_job_keep_running() {
    for (ignored, signal) in [("HUP", "-HUP"), ("INT", "-INT")] {
        let folder = tempfile::tempdir().expect("a folder");
        let out = folder.path().join("never.png");
        let mut child = Command::new("sh")
            .args([
                "-c",
                &format!(
                    "trap '' {ignored}; exec {BIN} snapshot --preset roller --time 100000 --out {}",
                    out.display()
                ),
            ])
            .spawn()
            .expect("sh runs");
        std::thread::sleep(Duration::from_millis(700));
        let pid = child.id().to_string();
        let sent = Command::new("kill").args([signal, &pid]).status();
        assert!(sent.expect("kill runs").success());
        std::thread::sleep(Duration::from_millis(700));
        assert!(
            child.try_wait().expect("waited").is_none(),
            "SIG{ignored}, ignored at start, stopped the run"
        );
        let sent = Command::new("kill").args(["-TERM", &pid]).status();
        assert!(sent.expect("kill runs").success());
        let status = wait_within(&mut child, Duration::from_secs(20), "SIGTERM");
        assert_eq!(status.code(), Some(130));
        assert_eq!(std::fs::read_dir(folder.path()).expect("listed").count(), 0);
    }
}

/// A run streaming rows into a redirected standard output, stopped by its
/// time limit: the rows written so far stay, end on a whole line, and the
/// status line counts exactly the lines and bytes the file holds.
#[test]
fn a_stopped_stream_ends_on_a_whole_line_and_says_how_much() {
    let folder = tempfile::tempdir().expect("a folder");
    let rows = folder.path().join("rows.csv");
    let (status, said) = shell(&format!(
        "{BIN} simulate --preset beck --duration 1000000 --dt 0.1 --time-limit 1 > {}",
        rows.display()
    ));
    assert_eq!(status, Some(124), "{said}");
    let text = std::fs::read_to_string(&rows).expect("the rows");
    assert!(text.starts_with("t,") && text.ends_with('\n'), "{said}");
    let lines = text.lines().count();
    assert!(lines > 1, "{said}");
    let counted = format!(
        "standard output had got {lines} lines ({} bytes) before the stop, ending on a whole line",
        text.len()
    );
    assert!(said.contains(&counted), "{said} (the file: {counted})");
    // Nothing reached a stream: the line says only that no file was left.
    let folder = tempfile::tempdir().expect("a folder");
    let (status, said) = shell(&format!(
        "{BIN} critical --preset beck --set rods=32 --load-max 1e150 --time-limit 1 > {}",
        folder.path().join("none.csv").display()
    ));
    assert_eq!(status, Some(124), "{said}");
    assert!(said.ends_with("no file was left half-written\n"), "{said}");
}
