//! Files the command line writes: the path checked before any work, then
//! written whole or not at all.

use std::io::Write as _;
use std::path::Path;

use anyhow::Result;

/// Refuses an output path before any work is done: its folder must exist,
/// and a picture must be named `*.png` (the only format written).
pub fn check_output(out: &Path, png: bool) -> Result<()> {
    let shown = out.display();
    if png
        && !out
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("png"))
    {
        anyhow::bail!("out = {shown}: pictures are written as PNG; name the file *.png");
    }
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
    Ok(())
}

/// The folder `out` is written in (`.` for a bare file name).
fn folder_of(out: &Path) -> &Path {
    match out.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    }
}

/// Writes `out` whole or not at all: into a temporary file in the same
/// folder, flushed and synced, then renamed over `out`. A failure (a full
/// disk, a killed process) leaves any existing `out` as it was.
pub fn write_atomically(
    out: &Path,
    write: impl FnOnce(&mut std::io::BufWriter<&mut std::fs::File>) -> std::io::Result<()>,
) -> Result<()> {
    let error = |e: &dyn std::fmt::Display| anyhow::anyhow!("cannot write {}: {e}", out.display());
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

/// `image` as a PNG file at `out`, atomically.
pub fn write_png(out: &Path, image: &image::RgbaImage) -> Result<()> {
    write_atomically(out, |w| {
        let mut encoded = Vec::new();
        image
            .write_to(
                &mut std::io::Cursor::new(&mut encoded),
                image::ImageFormat::Png,
            )
            .map_err(std::io::Error::other)?;
        w.write_all(&encoded)
    })
}
