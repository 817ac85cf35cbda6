//! The streams of this process named by a path (`/dev/stdout`,
//! `/dev/fd/N`, `/proc/self/fd/N`): which descriptor a path names, whether
//! it may be written (open, and opened for writing), and the descriptor
//! opened for writing where the shell left it.

use std::path::Path;

use super::folder_of;

/// Most links followed from a path to the stream it names.
const MOST_LINKS: usize = 40;

/// The descriptor of this process that `path` names, if it names one:
/// `/dev/stdout`, `/dev/stderr`, `/dev/fd/N`, `/proc/self/fd/N` or
/// `/proc/<this process>/fd/N`, as typed or through symbolic links to them.
/// Such a path is a stream the shell opened, not a file to replace.
#[must_use]
pub fn named_descriptor(path: &Path) -> Option<u32> {
    let own = format!("/proc/{}/fd/", std::process::id());
    let in_name = |path: &Path| -> Option<u32> {
        let text = path.to_str()?;
        match text {
            "/dev/stdin" => Some(0),
            "/dev/stdout" => Some(1),
            "/dev/stderr" => Some(2),
            _ => ["/dev/fd/", "/proc/self/fd/", own.as_str()]
                .iter()
                .find_map(|prefix| text.strip_prefix(prefix)?.parse().ok()),
        }
    };
    let mut current = path.to_owned();
    for _ in 0..MOST_LINKS {
        if let Some(descriptor) = in_name(&current) {
            return Some(descriptor);
        }
        // Only this hop's own link: the links of the folders above it
        // (`/dev/fd` itself) would take the path past its name.
        let next = std::fs::read_link(&current).ok()?;
        current = if next.is_absolute() {
            next
        } else {
            folder_of(&current).join(next)
        };
    }
    None
}

/// Descriptor `descriptor` of this process opened for writing where it
/// stands: standard output and error shared (their offset and append mode
/// are the shell's); another one reopened through `/proc/self/fd` with its
/// append mode, or at its offset, as `/proc/self/fdinfo` gives them.
pub(super) fn open_descriptor(descriptor: u32) -> std::io::Result<std::fs::File> {
    use std::io::Seek as _;
    use std::os::fd::AsFd as _;
    let info = descriptor_info(descriptor)?;
    if let Err(why) = writable_info(&info) {
        return Err(std::io::Error::new(
            std::io::ErrorKind::PermissionDenied,
            why,
        ));
    }
    match descriptor {
        1 => return Ok(std::io::stdout().as_fd().try_clone_to_owned()?.into()),
        2 => return Ok(std::io::stderr().as_fd().try_clone_to_owned()?.into()),
        _ => {}
    }
    let field = |name: &str| info_field(&info, name);
    let append = info_flags(&info).is_some_and(|flags| flags & APPEND_FLAG != 0);
    let path = format!("/proc/self/fd/{descriptor}");
    let mut file = std::fs::File::options()
        .write(true)
        .append(append)
        .open(&path)?;
    if !append
        && file.metadata()?.is_file()
        && let Some(offset) = field("pos:").and_then(|pos| pos.parse::<u64>().ok())
    {
        file.seek(std::io::SeekFrom::Start(offset))?;
    }
    Ok(file)
}

/// `O_APPEND` in the octal flags of `/proc/self/fdinfo`.
const APPEND_FLAG: u32 = 0o2000;
/// The access mode's bits of those flags: `O_RDONLY` 0, `O_WRONLY` 1,
/// `O_RDWR` 2.
const ACCESS_MODE: u32 = 0o3;

/// `/proc/self/fdinfo/N` of descriptor `descriptor`: what the kernel says
/// of how it was opened.
fn descriptor_info(descriptor: u32) -> std::io::Result<String> {
    std::fs::read_to_string(format!("/proc/self/fdinfo/{descriptor}"))
}

/// The value of the field `name` (with its colon) in a descriptor's info.
fn info_field<'a>(info: &'a str, name: &str) -> Option<&'a str> {
    info.lines()
        .find_map(|line| line.strip_prefix(name))
        .map(str::trim)
}

/// The open flags in a descriptor's info.
fn info_flags(info: &str) -> Option<u32> {
    info_field(info, "flags:").and_then(|flags| u32::from_str_radix(flags, 8).ok())
}

/// Whether a descriptor with this info may be written: it was opened for
/// writing (`>`, `>>`, `<>`), not only for reading (`<`).
fn writable_info(info: &str) -> Result<(), &'static str> {
    match info_flags(info) {
        Some(flags) if flags & ACCESS_MODE == 0 => {
            Err("the shell opened it for reading only (`<`): it is input, and is not written over")
        }
        _ => Ok(()),
    }
}

/// Why descriptor `descriptor` of this process cannot take an output, if it
/// cannot: it is not open, or it was opened for reading only (`--out
/// /dev/stdin < data` would write over the data).
#[must_use]
pub fn descriptor_refusal(descriptor: u32) -> Option<String> {
    let what = match descriptor {
        0 => "standard input".to_owned(),
        1 => "standard output".to_owned(),
        2 => "standard error".to_owned(),
        n => format!("descriptor {n}"),
    };
    let closed = || format!("{what} is not open (the shell closed it or never opened it)");
    match descriptor_info(descriptor) {
        Err(_) => Some(closed()),
        Ok(_) if descriptor <= 2 && stands_in_for_closed(descriptor) => Some(closed()),
        Ok(info) => writable_info(&info)
            .err()
            .map(|why| format!("{what}: {why}")),
    }
}

/// Whether standard stream `descriptor` is the `/dev/null` that Rust's
/// runtime opens (for reading and writing) where the process started with
/// it closed (`>&-`); the shell's `> /dev/null` opens it for writing only.
fn stands_in_for_closed(descriptor: u32) -> bool {
    let null = std::fs::read_link(format!("/proc/self/fd/{descriptor}"))
        .is_ok_and(|target| target == Path::new("/dev/null"));
    let read_write = descriptor_info(descriptor)
        .ok()
        .and_then(|info| info_flags(&info))
        .is_some_and(|flags| flags & ACCESS_MODE == 2);
    null && read_write
}
