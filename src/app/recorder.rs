//! The record button's work: screenshots of the window at a steady rate
//! for the chosen seconds of wall time, then a GIF made off the UI thread
//! and written whole into the chosen folder, with progress on the way and a
//! notice saying where the file went.

use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, mpsc};

use eframe::egui::{self, ColorImage};

use crate::recording::GifRecording;

/// Frames per second of a recording of the window.
pub const RECORD_FPS: u16 = 10;

/// Where a recording is.
#[derive(Default)]
pub enum Recorder {
    #[default]
    Idle,
    /// Taking a screenshot every 1/fps s until `until_secs` (the context's
    /// clock).
    Capturing {
        folder: PathBuf,
        next_secs: f64,
        until_secs: f64,
        frames: Arc<Mutex<Vec<Arc<ColorImage>>>>,
    },
    /// Making the GIF: frames done of all, and the file (or why not).
    Encoding {
        done: Arc<AtomicUsize>,
        total: usize,
        result: mpsc::Receiver<Result<PathBuf, String>>,
    },
}

/// The seconds that are due a frame from `next_secs` to `now_secs`, at
/// `fps`: how many screenshots to ask for now and the next due time (a
/// late frame is taken once, not made up for).
#[must_use]
pub fn due(next_secs: f64, now_secs: f64, fps: u16) -> (bool, f64) {
    if now_secs < next_secs {
        return (false, next_secs);
    }
    let period = 1.0 / f64::from(fps.max(1));
    let mut next = next_secs + period;
    if next <= now_secs {
        next = now_secs + period;
    }
    (true, next)
}

impl Recorder {
    /// Starts recording the next `secs` seconds into `folder`.
    pub fn start(&mut self, folder: PathBuf, secs: f64, now_secs: f64) {
        *self = Self::Capturing {
            folder,
            next_secs: now_secs,
            until_secs: now_secs + secs,
            frames: Arc::default(),
        };
    }

    /// One frame of the window: a screenshot when one is due; at the end,
    /// the GIF made on a thread. Returns a finished file's path, or why the
    /// recording failed.
    pub fn frame(&mut self, ctx: &egui::Context) -> Option<Result<PathBuf, String>> {
        let now_secs = ctx.input(|i| i.time);
        match self {
            Self::Idle => None,
            Self::Capturing {
                folder,
                next_secs,
                until_secs,
                frames,
            } => {
                if now_secs >= *until_secs {
                    let taken = frames.lock().map(|f| f.clone()).unwrap_or_default();
                    *self = Self::encode(folder.clone(), taken);
                    return None;
                }
                let (take, next) = due(*next_secs, now_secs, RECORD_FPS);
                *next_secs = next;
                if take {
                    let frames = Arc::clone(frames);
                    ctx.request_screenshot(move |image| {
                        if let Ok(mut frames) = frames.lock() {
                            frames.push(image);
                        }
                    });
                }
                ctx.request_repaint();
                None
            }
            Self::Encoding { result, .. } => match result.try_recv() {
                Ok(done) => {
                    *self = Self::Idle;
                    Some(done)
                }
                Err(mpsc::TryRecvError::Empty) => {
                    ctx.request_repaint();
                    None
                }
                Err(mpsc::TryRecvError::Disconnected) => {
                    *self = Self::Idle;
                    Some(Err("the recording stopped unexpectedly".to_owned()))
                }
            },
        }
    }

    /// The GIF of `frames` made on a thread and written into `folder`.
    fn encode(folder: PathBuf, frames: Vec<Arc<ColorImage>>) -> Self {
        let (sender, result) = mpsc::channel();
        let failed = sender.clone();
        let done = Arc::new(AtomicUsize::new(0));
        let total = frames.len();
        let counter = Arc::clone(&done);
        let spawned = std::thread::Builder::new()
            .name("recording".to_owned())
            .spawn(move || {
                drop(sender.send(write_gif(&folder, &frames, &counter)));
            });
        if let Err(error) = spawned {
            drop(failed.send(Err(format!("no thread for the recording: {error}"))));
        }
        Self::Encoding {
            done,
            total,
            result,
        }
    }

    /// A line saying how far the recording is, if it is under way.
    #[must_use]
    pub fn progress_text(&self, now_secs: f64) -> Option<String> {
        match self {
            Self::Idle => None,
            Self::Capturing {
                until_secs, frames, ..
            } => Some(format!(
                "recording: {:.0} s to go, {} frames",
                (until_secs - now_secs).max(0.0).ceil(),
                frames.lock().map_or(0, |f| f.len())
            )),
            Self::Encoding { done, total, .. } => Some(format!(
                "making the GIF: frame {} of {total}",
                done.load(Ordering::Relaxed)
            )),
        }
    }
}

/// The GIF of `frames` (those of the first frame's size: a window resized
/// mid-way leaves the others out) written into `folder`, named by the time.
fn write_gif(
    folder: &std::path::Path,
    frames: &[Arc<ColorImage>],
    done: &AtomicUsize,
) -> Result<PathBuf, String> {
    let first = frames.first().ok_or("no frame was captured")?;
    let [width, height] = first.size;
    let side = |n: usize| u16::try_from(n).map_err(|_| format!("a frame {n} pixels wide"));
    let (w, h) = (side(width)?, side(height)?);
    let mut gif = GifRecording::new(w, h, RECORD_FPS).map_err(|e| e.to_string())?;
    for frame in frames.iter().filter(|f| f.size == first.size) {
        let mut rgba: Vec<u8> = frame
            .pixels
            .iter()
            .flat_map(egui::Color32::to_array)
            .collect();
        gif.push(&mut rgba).map_err(|e| e.to_string())?;
        done.fetch_add(1, Ordering::Relaxed);
    }
    let bytes = gif.finish().map_err(|e| e.to_string())?;
    let stamp = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    let path = folder.join(format!("zieglerlab-{stamp}.gif"));
    crate::files::write_atomically(&path, |w| std::io::Write::write_all(w, &bytes))
        .map_err(|e| e.to_string())?;
    Ok(path)
}

/// What the next recording will be: its length and its folder.
pub struct RecordChoice {
    pub secs: f64,
    pub folder: String,
}

impl Default for RecordChoice {
    fn default() -> Self {
        Self {
            secs: 10.0,
            folder: ".".to_owned(),
        }
    }
}

/// The record controls: seconds, folder, the button, and the progress.
pub fn record_ui(ui: &mut egui::Ui, choice: &mut RecordChoice, recorder: &mut Recorder) {
    egui::CollapsingHeader::new("record a GIF").show(ui, |ui| {
        ui.horizontal(|ui| {
            ui.label("the next");
            ui.add(
                egui::DragValue::new(&mut choice.secs)
                    .range(1.0..=60.0)
                    .speed(0.5),
            )
            .accessible_name("record seconds")
            .on_hover_text("seconds of the window to record (1 to 60)");
            ui.label("s into");
        });
        ui.add(egui::TextEdit::singleline(&mut choice.folder).desired_width(220.0))
            .accessible_name("record folder")
            .on_hover_text("the folder the GIF goes in");
        let now_secs = ui.input(|i| i.time);
        if let Some(progress) = recorder.progress_text(now_secs) {
            ui.label(progress);
            return;
        }
        let folder = PathBuf::from(choice.folder.trim());
        let ready = folder.is_dir();
        if ui
            .add_enabled(ready, egui::Button::new("record"))
            .on_hover_text("record what the window shows, 10 frames a second, to a GIF")
            .on_disabled_hover_text("the folder does not exist")
            .clicked()
        {
            recorder.start(folder, choice.secs, now_secs);
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;
    use eframe::egui::Color32;

    #[test]
    fn a_frame_is_due_every_tenth_of_a_second_and_late_ones_are_not_made_up() {
        assert_eq!(due(1.0, 0.95, 10), (false, 1.0));
        let (take, next) = due(1.0, 1.01, 10);
        assert!(take && (next - 1.1).abs() < 1e-12);
        let (take, next) = due(1.0, 1.55, 10);
        assert!(
            take && (next - 1.65).abs() < 1e-12,
            "a stall: one frame, then on"
        );
    }

    #[test]
    fn the_frames_become_a_gif_in_the_folder() {
        let folder = tempfile::tempdir().unwrap();
        let frames: Vec<Arc<ColorImage>> = [Color32::RED, Color32::BLUE]
            .into_iter()
            .map(|c| Arc::new(ColorImage::filled([8, 6], c)))
            .collect();
        let done = AtomicUsize::new(0);
        let path = write_gif(folder.path(), &frames, &done).unwrap();
        assert_eq!(done.load(Ordering::Relaxed), 2);
        let bytes = std::fs::read(&path).unwrap();
        assert!(bytes.starts_with(b"GIF89a"));
        assert_eq!(u16::from_le_bytes([bytes[6], bytes[7]]), 8, "width");
        assert!(write_gif(folder.path(), &[], &done).is_err());
    }
}
