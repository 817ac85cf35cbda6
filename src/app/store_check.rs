//! Checks eframe's stored file before the window opens: entries that would
//! crash or cripple the start (a NaN or absurd zoom factor, a window of no
//! size) are dropped, and a file that cannot be read is copied aside before
//! eframe's autosave can overwrite it. Says what it did, in words.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use super::SETTINGS_KEY;
use crate::format::Shown;
use crate::i18n::Words;
use crate::tr;

/// The zoom factors egui's own settings offer.
const ZOOM_RANGE: std::ops::RangeInclusive<f64> = 0.2..=5.0;
/// Window sizes a stored geometry may ask for, in points.
const WINDOW_POINTS: std::ops::RangeInclusive<f64> = 64.0..=65_536.0;

/// The number written after `key` in a stored entry (`zoom_factor:1.0`),
/// as Rust reads it (`NaN` and `inf` included); `None` without the key.
fn number_after(text: &str, key: &str) -> Option<f64> {
    let start = text.find(key)? + key.len();
    let rest = &text[start..];
    let end = rest.find([',', ')']).unwrap_or(rest.len());
    let number = rest[..end].trim();
    Some(number.parse::<f64>().unwrap_or(f64::NAN))
}

/// Why an entry of eframe's store must not reach the window, if it must not.
fn harmful(key: &str, value: &str, words: &'static Words) -> Option<String> {
    match key {
        "egui" => number_after(value, "zoom_factor:")
            .filter(|zoom| !ZOOM_RANGE.contains(zoom))
            .map(|zoom| tr!(words, "store-zoom", zoom = Shown(zoom).to_string())),
        "window" => {
            let size = value
                .find("inner_size_points:")
                .map_or("", |start| &value[start..]);
            let sizes = [
                number_after(size, "(x:"),
                number_after(size, ",y:"),
                number_after(value, "scale_factor:"),
            ];
            let [width, height, scale] = sizes.map(|n| n.unwrap_or(1.0));
            let sound = WINDOW_POINTS.contains(&width)
                && WINDOW_POINTS.contains(&height)
                && scale.is_finite()
                && scale > 0.0;
            (!sound).then(|| {
                tr!(
                    words,
                    "store-geometry",
                    width = Shown(width).to_string(),
                    height = Shown(height).to_string(),
                    scale = Shown(scale).to_string()
                )
            })
        }
        _ => None,
    }
}

/// The local date and time in a name (`2026-12-03T11-40-32`), so copies
/// made on different days sort and read as dates.
fn stamp() -> String {
    jiff::Zoned::now().strftime("%Y-%m-%dT%H-%M-%S").to_string()
}

/// `path` with `.what-<date>` after its name (`app.ron.unreadable-<date>`),
/// at a name no file holds yet.
fn beside(path: &Path, what: &str) -> PathBuf {
    let name = path
        .file_name()
        .map_or_else(|| "app.ron".into(), |n| n.to_string_lossy().into_owned());
    let stem = format!("{name}.{what}-{}", stamp());
    let mut candidate = path.with_file_name(&stem);
    let mut k = 2;
    while std::fs::symlink_metadata(&candidate).is_ok() {
        candidate = path.with_file_name(format!("{stem}-{k}"));
        k += 1;
    }
    candidate
}

/// A copy of `path` beside it, named with the date, that no autosave
/// touches.
fn keep_copy(path: &Path) -> std::io::Result<PathBuf> {
    let copy = beside(path, "unreadable");
    std::fs::copy(path, &copy)?;
    Ok(copy)
}

/// What to say of a store that could not be read (`why`): a copy of it is
/// kept beside, or, where none can be made, the store is moved aside so
/// the autosave cannot overwrite what nobody has a copy of.
fn unreadable(path: &Path, why: &str, words: &'static Words) -> String {
    match keep_copy(path) {
        Ok(copy) => tr!(
            words,
            "store-unreadable",
            why = why,
            copy = copy.display().to_string()
        ),
        Err(copy_error) => move_aside(
            path,
            &tr!(
                words,
                "store-unreadable-uncopied",
                why = why,
                error = copy_error.to_string()
            ),
            words,
        ),
    }
}

/// The largest store read, in bytes: a few kB are written; anything near
/// this is not the app's.
const MOST_STORE_BYTES: u64 = 16 << 20;

/// Moves `path` aside (a folder, a pipe, a device, or a file too large to
/// be the app's store), so that eframe neither blocks on reading it nor
/// fails to write the settings. Says what was done.
fn move_aside(path: &Path, why: &str, words: &'static Words) -> String {
    let aside = beside(path, "unusable");
    match std::fs::rename(path, &aside) {
        Ok(()) => tr!(
            words,
            "store-moved",
            path = path.display().to_string(),
            why = why,
            aside = aside.display().to_string()
        ),
        Err(error) => tr!(
            words,
            "store-not-moved",
            path = path.display().to_string(),
            why = why,
            error = error.to_string()
        ),
    }
}

/// Whether the settings can be saved at `path`: the folder takes a new
/// file and an existing store is writable. Says why not, if not.
fn unwritable(path: &Path, words: &'static Words) -> Option<String> {
    let folder = path.parent().unwrap_or_else(|| Path::new("."));
    // On a first launch the folder is not there yet: eframe makes it.
    if let Err(error) = std::fs::create_dir_all(folder) {
        return Some(tr!(
            words,
            "store-folder-not-made",
            folder = folder.display().to_string(),
            error = error.to_string()
        ));
    }
    if let Err(error) = tempfile::NamedTempFile::new_in(folder) {
        return Some(tr!(
            words,
            "store-folder-full",
            folder = folder.display().to_string(),
            error = std::io::Error::from(error.kind()).to_string()
        ));
    }
    if let Err(error) = std::fs::OpenOptions::new().append(true).open(path)
        && error.kind() != std::io::ErrorKind::NotFound
    {
        return Some(tr!(
            words,
            "store-not-writable",
            path = path.display().to_string(),
            error = error.to_string()
        ));
    }
    None
}

/// Checks and repairs eframe's store at `path` (`app.ron`) before eframe
/// reads it: what it holds, and that it can be written. Returns what the
/// user should be told, if anything, in `words`' language.
#[must_use]
pub fn check_stored_file(path: &Path, words: &'static Words) -> Option<String> {
    let read = check_stored_entries(path, words);
    let write = unwritable(path, words);
    match (read, write) {
        (Some(read), Some(write)) => Some(format!("{read}; {write}")),
        (read, write) => read.or(write),
    }
}

/// Checks and repairs the entries of eframe's store at `path`.
fn check_stored_entries(path: &Path, words: &'static Words) -> Option<String> {
    let metadata = std::fs::metadata(path).ok()?;
    if !metadata.is_file() {
        let kind = if metadata.is_dir() {
            tr!(words, "store-is-folder")
        } else {
            tr!(words, "store-is-device")
        };
        return Some(move_aside(path, &kind, words));
    }
    if metadata.len() > MOST_STORE_BYTES {
        let why = tr!(
            words,
            "store-too-large",
            bytes = metadata.len().to_string(),
            most = MOST_STORE_BYTES.to_string()
        );
        return Some(move_aside(path, &why, words));
    }
    // Bytes that are not UTF-8 (a Latin-1 edit, binary junk) make eframe
    // start from nothing and autosave over the file: kept first.
    let text = match crate::files::read_text(path, MOST_STORE_BYTES) {
        Ok(text) => text,
        Err(error) => return Some(unreadable(path, &error.why, words)),
    };
    let mut entries: BTreeMap<String, String> = match ron::from_str(&text) {
        Ok(entries) => entries,
        Err(error) => return Some(unreadable(path, &error.to_string(), words)),
    };
    let harmful_entries: Vec<(String, String)> = entries
        .iter()
        .filter_map(|(key, value)| harmful(key, value, words).map(|why| (key.clone(), why)))
        .collect();
    let dropped: Vec<String> = harmful_entries
        .iter()
        .map(|(key, why)| tr!(words, "store-entry", why = why.as_str(), key = key.as_str()))
        .collect();
    let settings_unreadable = entries
        .get(SETTINGS_KEY)
        .is_some_and(|settings| super::settings_text::read(settings).is_err());
    if dropped.is_empty() && !settings_unreadable {
        return None;
    }
    let copy = keep_copy(path);
    for (key, _) in &harmful_entries {
        entries.remove(key);
    }
    let mut note = Vec::new();
    if !dropped.is_empty() {
        let written = ron::ser::to_string_pretty(&entries, ron::ser::PrettyConfig::default())
            .map_err(|e| e.to_string())
            .and_then(|repaired| {
                crate::files::write_atomically(path, |w| {
                    std::io::Write::write_all(w, repaired.as_bytes())
                })
                .map_err(|e| e.why)
            });
        note.push(match written {
            Ok(()) => tr!(words, "store-ignored", what = dropped.join(", ")),
            Err(error) => tr!(
                words,
                "store-ignored-not-rewritten",
                what = dropped.join(", "),
                error = error
            ),
        });
    }
    if settings_unreadable {
        note.push(tr!(words, "store-settings-unreadable"));
    }
    match copy {
        Ok(copy) => note.push(tr!(
            words,
            "store-original-kept",
            copy = copy.display().to_string()
        )),
        Err(error) => note.push(tr!(words, "store-original-lost", error = error.to_string())),
    }
    Some(note.join("; "))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn english() -> &'static Words {
        crate::i18n::words(crate::i18n::Language::English)
    }

    fn store(dir: &Path, text: &str) -> PathBuf {
        std::fs::create_dir_all(dir).unwrap();
        let path = dir.join("app.ron");
        std::fs::write(&path, text).unwrap();
        path
    }

    fn dir(name: &str) -> PathBuf {
        std::env::temp_dir().join(format!("zl-store-{name}-{}", std::process::id()))
    }

    const WINDOW: &str = "(normal_geometry:(outer_position_pixels:Some((x:0.0,y:0.0)),scale_factor:1.0,inner_size_points:(x:1280.0,y:800.0)),fullscreen:false,maximized:false)";

    fn file(zoom: &str, window: &str) -> String {
        let entries = BTreeMap::from([
            (
                "egui".to_owned(),
                format!(
                    "(options:(theme_preference:System,zoom_factor:{zoom},tessellation_options:(feathering:true)))"
                ),
            ),
            ("window".to_owned(), window.to_owned()),
        ]);
        ron::to_string(&entries).unwrap()
    }

    #[test]
    fn a_sound_file_is_left_alone() {
        let dir = dir("sound");
        let path = store(&dir, &file("1.0", WINDOW));
        assert_eq!(check_stored_file(&path, english()), None);
        assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_bad_zoom_or_window_is_dropped_and_the_original_kept() {
        for (zoom, window) in [
            ("NaN", WINDOW),
            ("0.0", WINDOW),
            ("1e9", WINDOW),
            ("1.0", &WINDOW.replace("x:1280.0", "x:NaN")),
            ("1.0", &WINDOW.replace("y:800.0", "y:-5.0")),
        ] {
            let dir = dir("bad");
            let original = file(zoom, window);
            let path = store(&dir, &original);
            let note = check_stored_file(&path, english()).unwrap();
            assert!(note.starts_with("stored state: ignored"), "{note}");
            let repaired: BTreeMap<String, String> =
                ron::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
            assert_eq!(repaired.len(), 1, "{zoom} {window}: {repaired:?}");
            let copies: Vec<_> = std::fs::read_dir(&dir).unwrap().collect();
            assert_eq!(copies.len(), 2);
            let copy = copies
                .into_iter()
                .map(|e| e.unwrap().path())
                .find(|p| p != &path)
                .unwrap();
            assert_eq!(std::fs::read_to_string(copy).unwrap(), original);
            std::fs::remove_dir_all(&dir).unwrap();
        }
    }

    #[test]
    fn an_unreadable_file_is_copied_aside_and_said_so() {
        let dir = dir("garbage");
        let path = store(&dir, "{\"zieglerlab-settings\": \"(preset:");
        let note = check_stored_file(&path, english()).unwrap();
        assert!(
            note.contains("could not be read") && note.contains("a copy is kept at"),
            "{note}"
        );
        assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 2);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    /// A store that is not UTF-8 (a Latin-1 byte, binary junk) is said to
    /// be unreadable and kept byte for byte beside, named with the date,
    /// before eframe's autosave can overwrite it.
    #[test]
    fn a_store_that_is_not_utf8_is_kept_and_said_so() {
        // "café" with é as the one Latin-1 byte 0xe9.
        let latin1 = [
            &br#"{"zieglerlab-settings":"preset = roller\n# caf"#[..],
            &[0xe9],
            br#""}"#,
        ]
        .concat();
        for (name, bytes) in [
            ("latin1", latin1),
            ("binary", vec![0u8, 0xff, 0xfe, 7, 0x80]),
        ] {
            let dir = dir(name);
            std::fs::create_dir_all(&dir).unwrap();
            let path = dir.join("app.ron");
            std::fs::write(&path, &bytes).unwrap();
            let note = check_stored_file(&path, english()).unwrap();
            assert!(
                note.contains("could not be read (it is not UTF-8")
                    && note.contains("a copy is kept at"),
                "{name}: {note}"
            );
            let copies: Vec<PathBuf> = std::fs::read_dir(&dir)
                .unwrap()
                .map(|e| e.unwrap().path())
                .filter(|p| p != &path)
                .collect();
            assert_eq!(copies.len(), 1, "{name}");
            let copy_name = copies[0]
                .file_name()
                .unwrap()
                .to_string_lossy()
                .into_owned();
            assert!(
                copy_name.starts_with("app.ron.unreadable-20"),
                "{copy_name}"
            );
            assert_eq!(
                std::fs::read(&copies[0]).unwrap(),
                bytes,
                "{name}: byte for byte"
            );
            std::fs::remove_dir_all(&dir).unwrap();
        }
    }

    /// A folder or a pipe where the store should be is moved aside before
    /// eframe blocks on it (a pipe) or cannot save (a folder), and said so.
    #[test]
    fn a_folder_or_a_pipe_in_place_of_the_store_is_moved_aside() {
        for kind in ["folder", "pipe"] {
            let dir = dir(kind);
            std::fs::create_dir_all(&dir).unwrap();
            let path = dir.join("app.ron");
            if kind == "folder" {
                std::fs::create_dir(&path).unwrap();
            } else {
                let made = std::process::Command::new("mkfifo").arg(&path).status();
                assert!(made.unwrap().success());
            }
            let note = check_stored_file(&path, english()).unwrap();
            assert!(note.contains("moved to"), "{note}");
            assert!(!path.exists(), "{kind}: moved away");
            assert_eq!(
                check_stored_file(&path, english()),
                None,
                "{kind}: nothing left to say"
            );
            std::fs::remove_dir_all(&dir).unwrap();
        }
    }

    /// A first launch, with no folder for the store yet, says nothing.
    #[test]
    fn a_first_launch_has_nothing_to_say() {
        let dir = dir("first");
        let path = dir.join("zieglerlab").join("app.ron");
        assert_eq!(check_stored_file(&path, english()), None);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
