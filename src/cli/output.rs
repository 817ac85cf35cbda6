//! Files the command line writes: the path checked before any work, then
//! written whole or not at all.

use std::path::Path;

use anyhow::Result;

/// Refuses an output path before any work is done, for every command: its
/// folder must exist and take a new file (the output is written there
/// first and renamed into place) unless the file exists and may be written
/// in place; an existing file must be writable (as the shell's `>` asks);
/// a stream of this process must be open for writing; a path ending in
/// `/` names a folder; a picture must be named `*.png`.
pub fn check_output(out: &Path, png: bool) -> Result<()> {
    let shown = out.display();
    if png
        && !out
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("png"))
    {
        anyhow::bail!("out = {shown}: pictures are written as PNG; name the file *.png");
    }
    // A stream the shell opened (/dev/stdout, /dev/fd/3) is written where
    // it stands: there is no folder to check.
    if let Some(descriptor) = zieglerlab::files::named_descriptor(out) {
        if let Some(why) = zieglerlab::files::descriptor_refusal(descriptor) {
            anyhow::bail!("out = {shown}: {why}");
        }
        return Ok(());
    }
    // `clip.gif/` names a folder: refused now, not after the work.
    if out.as_os_str().to_string_lossy().ends_with('/') && !out.is_dir() {
        anyhow::bail!("out = {shown}: ends in `/`, so it names a folder; name a file");
    }
    // A link is written through: the file it names is what is checked.
    let target = zieglerlab::files::link_target(out)
        .map_err(|e| anyhow::anyhow!("out = {shown}: the link cannot be read ({e})"))?;
    let out = target.as_deref().unwrap_or(out);
    let folder = folder_of(out);
    if !folder.is_dir() {
        anyhow::bail!(
            "out = {shown}: the folder {} does not exist",
            folder.display()
        );
    }
    if out.is_dir() {
        anyhow::bail!("out = {shown}: is a folder, not a file");
    }
    if let Some(why) = zieglerlab::files::protected(out) {
        anyhow::bail!("out = {shown}: {why}");
    }
    // A device or a pipe (/dev/stdout) is written directly, and an existing
    // file where it stands if its folder takes no new one; anything else
    // goes through a temporary file in the folder: try one now, so that a
    // folder that takes no files (read-only, /proc) is found before the work.
    let direct = std::fs::metadata(out).is_ok();
    if !direct && let Err(why) = tempfile::NamedTempFile::new_in(folder) {
        // The kind alone: the temporary file's own name means nothing here.
        anyhow::bail!(
            "out = {shown}: the folder {} takes no new file ({})",
            folder.display(),
            std::io::Error::from(why.kind())
        );
    }
    Ok(())
}

use zieglerlab::files::folder_of;

/// `write` to `out`, whole or not at all (see [`zieglerlab::files`]).
///
/// # Errors
/// The file cannot be written.
pub fn write_atomically(
    out: &Path,
    write: impl FnOnce(&mut dyn std::io::Write) -> std::io::Result<()>,
) -> Result<()> {
    Ok(zieglerlab::files::write_atomically(out, write)?)
}

/// `image` as a PNG file at `out`, atomically.
pub fn write_png(out: &Path, image: &image::RgbaImage) -> Result<()> {
    Ok(zieglerlab::files::write_png(out, image)?)
}

/// Ends the process quietly (status 0, as a Unix tool ends when its reader
/// has gone) as soon as the reader of standard output goes away, watched on
/// a thread of its own: a long computation whose output nobody reads stops
/// at once instead of at its first write. Standard output that is a file or
/// a terminal is never closed under the process, so this then does nothing.
pub fn stop_when_the_reader_goes() {
    use rustix::event::{PollFd, PollFlags, Timespec, poll};
    use std::os::fd::AsFd as _;
    let watch = || {
        let stdout = std::io::stdout();
        let fd = stdout.as_fd();
        let every = Timespec {
            tv_sec: 0,
            tv_nsec: 100_000_000,
        };
        loop {
            // No event asked for: poll reports only an error or a hang-up,
            // which is what the write end of a pipe gets when its reader
            // closes it.
            let mut fds = [PollFd::new(&fd, PollFlags::empty())];
            let gone = poll(&mut fds, Some(&every))
                .is_ok_and(|_| fds[0].revents().intersects(PollFlags::ERR | PollFlags::HUP));
            if gone {
                zieglerlab::files::remove_unfinished();
                std::process::exit(0);
            }
        }
    };
    // Without a thread the closed pipe is still noticed at the first write.
    drop(
        std::thread::Builder::new()
            .name("reader".to_owned())
            .spawn(watch),
    );
}

/// Whether an answer written to `out` goes to a stream (standard output
/// when there is no `out`, a pipe or a device such as `/dev/stdout`)
/// rather than a file: the command then stops when nobody reads it.
pub fn streams(out: Option<&Path>) -> bool {
    out.is_none_or(|out| std::fs::metadata(out).is_ok_and(|m| !m.is_file() && !m.is_dir()))
}
