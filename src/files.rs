//! Files written whole or not at all (a temporary file in the same folder,
//! synced and renamed over the target or to a free name, with the
//! permissions a new file or the one it replaces would have; devices and
//! pipes are written directly, and a stream of the process named by a path,
//! `/dev/stdout` or `/dev/fd/N`, where the shell opened it; a temporary
//! file left by a stopping signal is removed), and text files read with a
//! bound on size.

use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

mod descriptor;
mod stream;

use descriptor::open_descriptor;
pub use descriptor::{descriptor_refusal, named_descriptor};
pub use stream::{Reached, WholeLines, stop_streams, stopped_words};

/// The temporary files being written now, for [`remove_unfinished`].
static UNFINISHED: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// A temporary file listed in [`UNFINISHED`] while it lives.
struct Unfinished(PathBuf);

impl Unfinished {
    fn new(path: &Path) -> Self {
        if let Ok(mut paths) = UNFINISHED.lock() {
            paths.push(path.to_owned());
        }
        Self(path.to_owned())
    }
}

impl Drop for Unfinished {
    fn drop(&mut self) {
        if let Ok(mut paths) = UNFINISHED.lock() {
            paths.retain(|p| p != &self.0);
        }
    }
}

/// Removes the temporary files being written: for a handler of Ctrl-C or
/// SIGTERM, so that a stopped write leaves nothing beside its output (a
/// file renamed into place meanwhile is not touched: its temporary name is
/// gone).
pub fn remove_unfinished() {
    remove_unfinished_where(|_| true);
}

/// Removes the listed temporary files (and folders) whose path `chosen`
/// picks.
fn remove_unfinished_where(chosen: impl Fn(&Path) -> bool) {
    if let Ok(paths) = UNFINISHED.lock() {
        for path in paths.iter().filter(|p| chosen(p)) {
            // Already renamed or removed: nothing left to do.
            if std::fs::symlink_metadata(path).is_ok_and(|m| m.is_dir()) {
                let _ = std::fs::remove_dir_all(path);
            } else {
                let _ = std::fs::remove_file(path);
            }
        }
    }
}

/// A temporary folder made in `folder` (named `.{prefix}XXXXXX`), removed
/// when the value is dropped and by [`remove_unfinished`] when a signal or
/// the time limit stops the process first.
pub struct StagingFolder {
    folder: tempfile::TempDir,
    _listed: Unfinished,
}

impl StagingFolder {
    /// A new staging folder in `folder`.
    ///
    /// # Errors
    /// The folder takes no new folder.
    pub fn new_in(folder: &Path, prefix: &str) -> std::io::Result<Self> {
        let made = tempfile::Builder::new().prefix(prefix).tempdir_in(folder)?;
        let listed = Unfinished::new(made.path());
        Ok(Self {
            folder: made,
            _listed: listed,
        })
    }

    /// Where it is.
    #[must_use]
    pub fn path(&self) -> &Path {
        self.folder.path()
    }
}

/// A file that could not be written, and why.
#[derive(Debug, thiserror::Error)]
#[error("cannot write {path}: {why}")]
pub struct WriteError {
    pub path: String,
    pub why: String,
}

/// A text file that could not be read, and why.
#[derive(Debug, thiserror::Error)]
#[error("cannot read {path}: {why}")]
pub struct ReadError {
    pub path: String,
    pub why: String,
}

/// Reads the text file at `path`, of at most `most_bytes` bytes, without a
/// UTF-8 byte-order mark. Only a regular file is read: a folder, a device
/// (`/dev/zero` never ends) or a pipe (which blocks until someone writes)
/// is refused before it is opened, and a file that grows past the bound
/// while it is read is refused too.
///
/// # Errors
/// Not a regular file, larger than `most_bytes`, unreadable, or not UTF-8.
pub fn read_text(path: &Path, most_bytes: u64) -> Result<String, ReadError> {
    use std::io::Read as _;
    let error = |why: String| ReadError {
        path: path.display().to_string(),
        why,
    };
    let metadata = std::fs::metadata(path).map_err(|e| error(e.to_string()))?;
    if !metadata.is_file() {
        let kind = if metadata.is_dir() {
            "a folder"
        } else {
            "a device, a pipe or a socket"
        };
        return Err(error(format!("it is {kind}, not a regular file")));
    }
    let too_large = |bytes: u64| {
        error(format!(
            "it holds {bytes} bytes; at most {most_bytes} are read"
        ))
    };
    if metadata.len() > most_bytes {
        return Err(too_large(metadata.len()));
    }
    let file = std::fs::File::open(path).map_err(|e| error(e.to_string()))?;
    let mut bytes = Vec::new();
    file.take(most_bytes.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(|e| error(e.to_string()))?;
    if bytes.len() as u64 > most_bytes {
        return Err(too_large(bytes.len() as u64));
    }
    let text = String::from_utf8(bytes).map_err(|e| {
        error(format!(
            "it is not UTF-8 text (byte {} is not)",
            e.utf8_error().valid_up_to() + 1
        ))
    })?;
    Ok(match text.strip_prefix('\u{feff}') {
        Some(rest) => rest.to_owned(),
        None => text,
    })
}

/// The folder `out` is written in (`.` for a bare file name).
#[must_use]
pub fn folder_of(out: &Path) -> &Path {
    match out.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    }
}

/// Writes `out` whole or not at all: into a temporary file in the same
/// folder, flushed and synced, then renamed over `out`. A failure (a full
/// disk, a killed process) leaves any existing `out` as it was.
///
/// # Errors
/// The folder, the temporary file, `write` or the rename failing.
pub fn write_atomically(
    out: &Path,
    write: impl FnOnce(&mut dyn std::io::Write) -> std::io::Result<()>,
) -> Result<(), WriteError> {
    let error = |e: &dyn std::fmt::Display| WriteError {
        path: out.display().to_string(),
        why: e.to_string(),
    };
    // A stream of this process named by a path (`--out /dev/stdout` with
    // the shell's `>> results.csv`): written where the shell opened it,
    // appended where it opened it for appending; renaming over the file
    // behind it would destroy what it held.
    if let Some(descriptor) = named_descriptor(out) {
        let file = open_descriptor(descriptor).map_err(|e| error(&e))?;
        return write_stream(file, &out.display().to_string(), write).map_err(|e| error(&e));
    }
    // A symbolic link is written through: the file it names is replaced,
    // the link stays (renaming over the link would replace the link).
    let target = link_target(out).map_err(|e| error(&e))?;
    let out = target.as_deref().unwrap_or(out);
    if std::fs::metadata(out).is_ok_and(|m| !m.is_file()) {
        // A device or a pipe (/dev/stdout, /dev/null): nothing to replace.
        let file = std::fs::File::options()
            .write(true)
            .open(out)
            .map_err(|e| error(&e))?;
        return write_stream(file, &out.display().to_string(), write).map_err(|e| error(&e));
    }
    // A file the user may not write is not replaced (the shell's `>`
    // refuses it too), though its folder would take the rename.
    if let Some(why) = protected(out) {
        return Err(error(&why));
    }
    // A temporary file is private (0600); the result gets the permissions
    // of the file it replaces, or those of a new file (0644 on Unix).
    let permissions = std::fs::metadata(out)
        .map(|m| m.permissions())
        .ok()
        .or_else(new_file_permissions);
    match tempfile::NamedTempFile::new_in(folder_of(out)) {
        Ok(file) => {
            let (file, _listed) =
                written_temporary(file, permissions, write).map_err(|e| error(&e))?;
            file.persist(out).map_err(|e| error(&e.error))?;
        }
        // A folder that takes no new file, around a file that may be
        // written: written in place, as the shell's `>` would.
        Err(_) if std::fs::metadata(out).is_ok_and(|m| m.is_file()) => {
            write_in_place(out, write).map_err(|e| error(&e))?;
        }
        Err(e) => return Err(error(&e)),
    }
    Ok(())
}

/// Why the existing file `out` may not be written, if it may not: opened
/// for writing (neither truncated nor changed) as the shell's `>` would
/// open it, refused by its mode or owner.
#[must_use]
pub fn protected(out: &Path) -> Option<String> {
    protected_by(out)
        .map(|e| format!("the file exists and may not be written ({e}); it is left as it was"))
}

/// [`protected`]'s refusal as the system gave it, for a caller to word.
#[must_use]
pub fn protected_by(out: &Path) -> Option<std::io::Error> {
    if !std::fs::metadata(out).is_ok_and(|m| m.is_file()) {
        return None;
    }
    match std::fs::File::options().write(true).open(out) {
        Err(e) if e.kind() == std::io::ErrorKind::PermissionDenied => Some(e),
        _ => None,
    }
}

/// `write` into the existing file `out` where it stands (its folder takes
/// no temporary file), never half-written by a failed write: the whole
/// output is made in memory first, the room for it is reserved on the disk
/// (a full disk refuses here, the file untouched), then it is written over
/// the old bytes and the file cut to its length. Only a kill within that
/// last write can cut it short.
fn write_in_place(
    out: &Path,
    write: impl FnOnce(&mut dyn std::io::Write) -> std::io::Result<()>,
) -> std::io::Result<()> {
    use std::io::Read as _;
    let mut memory = tempfile::tempfile()?;
    {
        let mut buffered = std::io::BufWriter::new(&mut memory);
        write(&mut buffered)?;
        buffered.flush()?;
    }
    let mut bytes = Vec::new();
    std::io::Seek::rewind(&mut memory)?;
    memory.read_to_end(&mut bytes)?;
    let mut file = std::fs::File::options().write(true).open(out)?;
    let length = u64::try_from(bytes.len()).unwrap_or(u64::MAX);
    if length > 0 {
        rustix::fs::fallocate(&file, rustix::fs::FallocateFlags::KEEP_SIZE, 0, length).or_else(
            |e| {
                // A file system without fallocate: nothing reserved.
                if e == rustix::io::Errno::OPNOTSUPP {
                    Ok(())
                } else {
                    Err(std::io::Error::from(e))
                }
            },
        )?;
    }
    file.write_all(&bytes)?;
    file.set_len(length)?;
    file.sync_all()
}

/// `write` straight into `file` (a device, a pipe or the shell's stream:
/// nothing to write beside and rename), named `name`: whole lines at a
/// time ([`WholeLines`]), the rest at the end.
fn write_stream(
    file: std::fs::File,
    name: &str,
    write: impl FnOnce(&mut dyn std::io::Write) -> std::io::Result<()>,
) -> std::io::Result<()> {
    let at_once = std::io::IsTerminal::is_terminal(&file);
    let mut lines = WholeLines::new(file, name, at_once);
    write(&mut lines)?;
    lines.flush()
}

/// Standard output, passed on whole lines at a time ([`WholeLines`]):
/// each line as it comes on a terminal, in batches elsewhere.
#[must_use]
pub fn standard_output() -> WholeLines<std::io::StdoutLock<'static>> {
    let stdout = std::io::stdout();
    let at_once = std::io::IsTerminal::is_terminal(&stdout);
    WholeLines::new(stdout.lock(), "standard output", at_once)
}

/// `image` as a PNG file at `out`, written as [`write_atomically`] does.
///
/// # Errors
/// The encoding or the writing failing.
pub fn write_png(out: &Path, image: &image::RgbaImage) -> Result<(), WriteError> {
    write_atomically(out, |w| {
        let mut encoded = Vec::new();
        image
            .write_to(
                &mut std::io::Cursor::new(&mut encoded),
                image::ImageFormat::Png,
            )
            .map_err(std::io::Error::other)?;
        std::io::Write::write_all(w, &encoded)
    })
}

/// The file a symbolic link at `path` names, in the end (through links to
/// links), or `None` when `path` is no link. A link to nothing names the
/// file it would create.
///
/// # Errors
/// The link cannot be read.
pub fn link_target(path: &Path) -> std::io::Result<Option<std::path::PathBuf>> {
    if !std::fs::symlink_metadata(path).is_ok_and(|m| m.file_type().is_symlink()) {
        return Ok(None);
    }
    if let Ok(resolved) = std::fs::canonicalize(path) {
        return Ok(Some(resolved));
    }
    let named = std::fs::read_link(path)?;
    Ok(Some(folder_of(path).join(named)))
}

/// A temporary file in `folder` holding what `write` wrote, flushed, given
/// `permissions` and synced: ready to be renamed into place.
fn written_temporary(
    mut file: tempfile::NamedTempFile,
    permissions: Option<std::fs::Permissions>,
    write: impl FnOnce(&mut dyn std::io::Write) -> std::io::Result<()>,
) -> std::io::Result<(tempfile::NamedTempFile, Unfinished)> {
    let listed = Unfinished::new(file.path());
    {
        let mut buffered = std::io::BufWriter::new(file.as_file_mut());
        write(&mut buffered)?;
        buffered.flush()?;
    }
    if let Some(permissions) = permissions {
        file.as_file().set_permissions(permissions)?;
    }
    file.as_file().sync_all()?;
    Ok((file, listed))
}

/// Most names [`write_new`] tries before giving up.
const MAX_NAME_TRIES: u32 = 1000;

/// Writes a new file in `folder`, whole or not at all, named
/// `stem.extension` or, where that is taken, `stem-2.extension`,
/// `stem-3.extension`, ...: never over an existing file, also when two
/// processes write into the folder at the same moment (each name is taken
/// by an atomic rename that refuses to replace). Returns the path written.
///
/// # Errors
/// The folder, the temporary file, `write`, or no free name.
pub fn write_new(
    folder: &Path,
    stem: &str,
    extension: &str,
    write: impl FnOnce(&mut dyn std::io::Write) -> std::io::Result<()>,
) -> Result<std::path::PathBuf, WriteError> {
    let name = |k: u32| {
        let suffix = if k == 1 {
            String::new()
        } else {
            format!("-{k}")
        };
        folder.join(format!("{stem}{suffix}.{extension}"))
    };
    let error = |e: &dyn std::fmt::Display| WriteError {
        path: name(1).display().to_string(),
        why: e.to_string(),
    };
    let (mut file, _listed) = tempfile::NamedTempFile::new_in(folder)
        .and_then(|file| written_temporary(file, new_file_permissions(), write))
        .map_err(|e| error(&e))?;
    for k in 1..=MAX_NAME_TRIES {
        let path = name(k);
        match file.persist_noclobber(&path) {
            Ok(_) => return Ok(path),
            Err(refused) if refused.error.kind() == std::io::ErrorKind::AlreadyExists => {
                file = refused.file;
            }
            Err(refused) => return Err(error(&refused.error)),
        }
    }
    Err(error(&format!(
        "{MAX_NAME_TRIES} names from {stem}.{extension} on are taken"
    )))
}

/// The permissions of a newly made file: readable by all, writable by the
/// owner.
#[cfg(unix)]
#[expect(clippy::unnecessary_wraps, reason = "None on other systems")]
fn new_file_permissions() -> Option<std::fs::Permissions> {
    use std::os::unix::fs::PermissionsExt as _;
    Some(std::fs::Permissions::from_mode(0o644))
}

/// Elsewhere the temporary file's own permissions stay.
#[cfg(not(unix))]
fn new_file_permissions() -> Option<std::fs::Permissions> {
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A stopping signal's handler removes the temporary file of a write
    /// under way: nothing is left beside the output, and the write fails.
    #[test]
    fn a_stopped_write_leaves_no_temporary() {
        let folder = tempfile::tempdir().unwrap();
        let out = folder.path().join("map.csv");
        // This folder's only: other tests write files meanwhile.
        let ours = |p: &Path| p.starts_with(folder.path());
        let written = write_atomically(&out, |w| {
            remove_unfinished_where(ours);
            w.write_all(b"half")
        });
        assert!(written.is_err());
        assert_eq!(std::fs::read_dir(folder.path()).unwrap().count(), 0);
        let listed = UNFINISHED.lock().unwrap().iter().any(|p| ours(p));
        assert!(!listed, "no longer listed");
    }

    /// A link is written through: the file it names gets the text, the
    /// link stays a link.
    #[cfg(unix)]
    /// A staging folder and what it holds are gone after a stop (as the
    /// signal handlers and the time limit call it) and after a drop.
    #[test]
    fn a_stopped_staging_folder_is_removed() {
        let dir = tempfile::tempdir().unwrap();
        let staging = StagingFolder::new_in(dir.path(), ".test-staging").unwrap();
        std::fs::write(staging.path().join("page.1"), "made").unwrap();
        let path = staging.path().to_owned();
        remove_unfinished_where(|p| p == path);
        assert!(!path.exists());
        let again = StagingFolder::new_in(dir.path(), ".test-staging").unwrap();
        let path = again.path().to_owned();
        drop(again);
        assert!(!path.exists());
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
    }

    #[test]
    fn a_link_is_written_through() {
        let folder = tempfile::tempdir().unwrap();
        let target = folder.path().join("target.csv");
        let link = folder.path().join("link.csv");
        std::fs::write(&target, "old").unwrap();
        std::os::unix::fs::symlink(&target, &link).unwrap();
        write_atomically(&link, |w| w.write_all(b"new")).unwrap();
        assert!(
            std::fs::symlink_metadata(&link)
                .unwrap()
                .file_type()
                .is_symlink()
        );
        assert_eq!(std::fs::read_to_string(&target).unwrap(), "new");
        // A link to a file not made yet makes it.
        let dangling = folder.path().join("dangling.csv");
        std::os::unix::fs::symlink("made.csv", &dangling).unwrap();
        write_atomically(&dangling, |w| w.write_all(b"made")).unwrap();
        assert_eq!(
            std::fs::read_to_string(folder.path().join("made.csv")).unwrap(),
            "made"
        );
    }

    /// Only regular files of at most the bound are read; a byte-order mark
    /// is dropped; a device, a folder and a pipe are refused unopened.
    #[test]
    fn text_is_read_from_regular_files_within_the_bound() {
        let folder = tempfile::tempdir().unwrap();
        let path = folder.path().join("lesson.ron");
        std::fs::write(&path, "\u{feff}(title: \"t\")").unwrap();
        assert_eq!(read_text(&path, 100).unwrap(), "(title: \"t\")");
        let why = |p: &Path, most| read_text(p, most).unwrap_err().why;
        assert_eq!(why(&path, 10), "it holds 15 bytes; at most 10 are read");
        assert_eq!(
            why(folder.path(), 100),
            "it is a folder, not a regular file"
        );
        assert_eq!(
            why(Path::new("/dev/zero"), 100),
            "it is a device, a pipe or a socket, not a regular file"
        );
        std::fs::write(&path, [b'a', 0xff]).unwrap();
        assert_eq!(why(&path, 100), "it is not UTF-8 text (byte 2 is not)");
    }

    /// A taken name is never replaced: the next free one is used, and a
    /// file named like a later one is stepped over too.
    #[test]
    fn a_new_file_takes_the_next_free_name() {
        let folder = tempfile::tempdir().unwrap();
        let put = |text: &'static str| {
            write_new(folder.path(), "clip", "gif", |w| {
                w.write_all(text.as_bytes())
            })
            .unwrap()
        };
        let first = put("one");
        std::fs::write(folder.path().join("clip-2.gif"), "someone else's").unwrap();
        let second = put("two");
        let third = put("three");
        let name = |p: &std::path::Path| p.file_name().unwrap().to_string_lossy().into_owned();
        assert_eq!(name(&first), "clip.gif");
        assert_eq!(name(&second), "clip-3.gif");
        assert_eq!(name(&third), "clip-4.gif");
        let read = |n: &str| std::fs::read_to_string(folder.path().join(n)).unwrap();
        assert_eq!(read("clip.gif"), "one");
        assert_eq!(read("clip-2.gif"), "someone else's");
        assert_eq!(read("clip-3.gif"), "two");
        assert_eq!(
            std::fs::read_dir(folder.path()).unwrap().count(),
            4,
            "no temporary left"
        );
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt as _;
            let mode = std::fs::metadata(&first).unwrap().permissions().mode();
            assert_eq!(mode & 0o777, 0o644);
        }
    }
}
