//! Files written whole or not at all: a temporary file in the same folder,
//! synced and renamed over the target, with the permissions a new file (or
//! the one it replaces) would have; devices and pipes are written directly.

use std::io::Write as _;
use std::path::Path;

/// A file that could not be written, and why.
#[derive(Debug, thiserror::Error)]
#[error("cannot write {path}: {why}")]
pub struct WriteError {
    pub path: String,
    pub why: String,
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
    write: impl FnOnce(&mut std::io::BufWriter<&mut std::fs::File>) -> std::io::Result<()>,
) -> Result<(), WriteError> {
    let error = |e: &dyn std::fmt::Display| WriteError {
        path: out.display().to_string(),
        why: e.to_string(),
    };
    if std::fs::metadata(out).is_ok_and(|m| !m.is_file()) {
        // A device or a pipe (/dev/stdout, /dev/null): nothing to replace.
        let mut file = std::fs::File::options()
            .write(true)
            .open(out)
            .map_err(|e| error(&e))?;
        let mut buffered = std::io::BufWriter::new(&mut file);
        return write(&mut buffered)
            .and_then(|()| buffered.flush())
            .map_err(|e| error(&e));
    }
    let folder = folder_of(out);
    let mut file = tempfile::NamedTempFile::new_in(folder).map_err(|e| error(&e))?;
    {
        let mut buffered = std::io::BufWriter::new(file.as_file_mut());
        write(&mut buffered)
            .and_then(|()| buffered.flush())
            .map_err(|e| error(&e))?;
    }
    // A temporary file is private (0600); the result gets the permissions
    // of the file it replaces, or those of a new file (0644 on Unix).
    let permissions = std::fs::metadata(out)
        .map(|m| m.permissions())
        .ok()
        .or_else(new_file_permissions);
    if let Some(permissions) = permissions {
        file.as_file()
            .set_permissions(permissions)
            .map_err(|e| error(&e))?;
    }
    file.as_file().sync_all().map_err(|e| error(&e))?;
    file.persist(out).map_err(|e| error(&e.error))?;
    Ok(())
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
