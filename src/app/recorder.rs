//! The record button's work: screenshots of the window at a steady rate
//! for the chosen seconds of wall time, then a GIF made off the UI thread
//! and written whole into the chosen folder, with progress on the way and a
//! notice saying where the file went.

use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, mpsc};

use eframe::egui::{self, ColorImage};

use crate::recording::GifRecording;

/// The window's title, also after a recording has shown its progress there.
pub const WINDOW_TITLE: &str = "zieglerlab";

/// Frames per second of a recording of the window (at most: a busy machine
/// draws fewer, and each frame then lasts until the next).
pub const RECORD_FPS: u16 = 10;

/// How long after its end a recording waits for screenshots asked for and
/// not yet delivered (they come a frame or two later).
const LATE_SCREENSHOT_SECS: f64 = 2.0;

/// Shortest delay written to the GIF, in hundredths of a second: browsers
/// show a frame of 0 or 1 for a tenth of a second instead.
const MIN_DELAY_CS: u16 = 2;

/// A screenshot and the time (the context's clock) of the frame it shows.
type TimedFrame = (f64, Arc<ColorImage>);

/// Where a recording is.
#[derive(Default)]
pub enum Recorder {
    #[default]
    Idle,
    /// Taking a screenshot every 1/fps s until `until_secs` (the context's
    /// clock), each kept with the time of the frame it shows; then waiting
    /// (at most [`LATE_SCREENSHOT_SECS`]) for those asked for and not yet
    /// delivered.
    Capturing {
        folder: PathBuf,
        next_secs: f64,
        until_secs: f64,
        requested: usize,
        frames: Arc<Mutex<Vec<TimedFrame>>>,
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
            requested: 0,
            frames: Arc::default(),
        };
    }

    /// Whether screenshots are being taken (the window then draws no hints,
    /// and the progress goes to the window's title, out of the pictures).
    #[must_use]
    pub fn is_capturing(&self) -> bool {
        matches!(self, Self::Capturing { .. })
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
                requested,
                frames,
            } => {
                if now_secs >= *until_secs {
                    let taken = frames.lock().map(|f| f.clone()).unwrap_or_default();
                    let waiting =
                        taken.len() < *requested && now_secs < *until_secs + LATE_SCREENSHOT_SECS;
                    if !waiting {
                        *self = Self::encode(folder.clone(), taken, *until_secs);
                        ctx.send_viewport_cmd(egui::ViewportCommand::Title(
                            WINDOW_TITLE.to_owned(),
                        ));
                    }
                    ctx.request_repaint();
                    return None;
                }
                let (take, next) = due(*next_secs, now_secs, RECORD_FPS);
                *next_secs = next;
                if take {
                    ctx.send_viewport_cmd(egui::ViewportCommand::Title(format!(
                        "{WINDOW_TITLE}: recording, {:.0} s to go",
                        (*until_secs - now_secs).max(0.0).ceil()
                    )));
                }
                if take {
                    *requested += 1;
                    let frames = Arc::clone(frames);
                    ctx.request_screenshot(move |image| {
                        if let Ok(mut frames) = frames.lock() {
                            frames.push((now_secs, image));
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

    /// The GIF of `frames` (the last lasting until `end_secs`) made on a
    /// thread and written into `folder`.
    fn encode(folder: PathBuf, frames: Vec<TimedFrame>, end_secs: f64) -> Self {
        let (sender, result) = mpsc::channel();
        let failed = sender.clone();
        let done = Arc::new(AtomicUsize::new(0));
        let total = frames.len();
        let counter = Arc::clone(&done);
        let spawned = std::thread::Builder::new()
            .name("recording".to_owned())
            .spawn(move || {
                drop(sender.send(write_gif(&folder, &frames, end_secs, &counter)));
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

    /// A line saying how far the making of the GIF is, if it is under way
    /// (the capture's own progress is in the window's title).
    #[must_use]
    pub fn progress_text(&self) -> Option<String> {
        match self {
            Self::Encoding { done, total, .. } => Some(format!(
                "making the GIF: frame {} of {total}",
                done.load(Ordering::Relaxed)
            )),
            Self::Idle | Self::Capturing { .. } => None,
        }
    }
}

/// How long each frame taken at `times_secs` (increasing) is shown, in
/// hundredths of a second, the last until `end_secs`: each frame lasts
/// until the next was taken, so the GIF plays in the time it recorded
/// however unevenly the frames came. Rounding is carried from frame to
/// frame (the total is the recorded time to the hundredth) and no delay is
/// below [`MIN_DELAY_CS`].
#[must_use]
pub fn delays_cs(times_secs: &[f64], end_secs: f64) -> Vec<u16> {
    let Some(&start) = times_secs.first() else {
        return Vec::new();
    };
    let ends = times_secs.iter().skip(1).chain([&end_secs]);
    let mut shown_cs: i64 = 0;
    ends.map(|&end| {
        #[expect(
            clippy::cast_possible_truncation,
            reason = "a recording lasts at most a minute: 6000 hundredths"
        )]
        let due_cs = ((end - start) * 100.0).round() as i64;
        let delay = (due_cs - shown_cs).clamp(i64::from(MIN_DELAY_CS), i64::from(u16::MAX));
        shown_cs += delay;
        u16::try_from(delay).unwrap_or(u16::MAX)
    })
    .collect()
}

/// The GIF of `frames` (those of the first frame's size: a window resized
/// mid-way leaves the others out), the last shown until `end_secs`, written
/// into `folder`, named by the time.
fn write_gif(
    folder: &std::path::Path,
    frames: &[TimedFrame],
    end_secs: f64,
    done: &AtomicUsize,
) -> Result<PathBuf, String> {
    let (_, first) = frames.first().ok_or("no frame was captured")?;
    let [width, height] = first.size;
    let side = |n: usize| u16::try_from(n).map_err(|_| format!("a frame {n} pixels wide"));
    let (w, h) = (side(width)?, side(height)?);
    let mut gif = GifRecording::new(w, h, RECORD_FPS).map_err(|e| e.to_string())?;
    let mut kept: Vec<&TimedFrame> = frames
        .iter()
        .filter(|(_, f)| f.size == first.size)
        .collect();
    kept.sort_by(|a, b| a.0.total_cmp(&b.0));
    let times: Vec<f64> = kept.iter().map(|(t, _)| *t).collect();
    for ((_, frame), delay) in kept.iter().zip(delays_cs(&times, end_secs)) {
        let mut rgba: Vec<u8> = frame
            .pixels
            .iter()
            .flat_map(egui::Color32::to_array)
            .collect();
        gif.push_lasting(&mut rgba, delay)
            .map_err(|e| e.to_string())?;
        done.fetch_add(1, Ordering::Relaxed);
    }
    let bytes = gif.finish().map_err(|e| e.to_string())?;
    let stamp = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    // A free name: two windows finishing in the same second keep both files.
    crate::files::write_new(folder, &format!("zieglerlab-{stamp}"), "gif", |w| {
        std::io::Write::write_all(w, &bytes)
    })
    .map_err(|e| e.to_string())
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
        if recorder.is_capturing() {
            // Nothing here that the pictures would show: the window's
            // title counts down.
            return;
        }
        if let Some(progress) = recorder.progress_text() {
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

    /// Frames that came unevenly (3 to 5 a second, as on a busy machine)
    /// each last until the next, and the whole plays in the time recorded.
    #[test]
    fn each_frame_lasts_until_the_next_and_the_whole_takes_the_time_recorded() {
        assert_eq!(delays_cs(&[0.0, 0.1, 0.2], 0.3), [10, 10, 10]);
        let times = [5.0, 5.31, 5.52, 5.9, 6.13, 6.4];
        let delays = delays_cs(&times, 7.0);
        assert_eq!(delays, [31, 21, 38, 23, 27, 60]);
        let total: u32 = delays.iter().map(|&d| u32::from(d)).sum();
        assert_eq!(total, 200, "two seconds recorded, two seconds played");
        // Rounding is carried: thirds of a tenth never drift.
        let thirds: Vec<f64> = (0..30).map(|i| f64::from(i) / 30.0).collect();
        let total: u32 = delays_cs(&thirds, 1.0).iter().map(|&d| u32::from(d)).sum();
        assert_eq!(total, 100);
        // Never a delay a browser would show for a tenth of a second.
        assert!(
            delays_cs(&[0.0, 0.001, 0.002], 0.003)
                .iter()
                .all(|&d| d >= MIN_DELAY_CS)
        );
        assert!(delays_cs(&[], 1.0).is_empty());
    }

    #[test]
    fn the_frames_become_a_gif_in_the_folder() {
        let folder = tempfile::tempdir().unwrap();
        let frames: Vec<TimedFrame> = [(0.0, Color32::RED), (0.4, Color32::BLUE)]
            .into_iter()
            .map(|(t, c)| (t, Arc::new(ColorImage::filled([8, 6], c))))
            .collect();
        let done = AtomicUsize::new(0);
        let path = write_gif(folder.path(), &frames, 1.0, &done).unwrap();
        assert_eq!(done.load(Ordering::Relaxed), 2);
        let bytes = std::fs::read(&path).unwrap();
        assert!(bytes.starts_with(b"GIF89a"));
        assert_eq!(u16::from_le_bytes([bytes[6], bytes[7]]), 8, "width");
        // The frames' delays as read back: 0.4 s and 0.6 s.
        let mut decoder = gif::DecodeOptions::new()
            .read_info(std::io::Cursor::new(&bytes))
            .unwrap();
        let mut delays = Vec::new();
        while let Some(frame) = decoder.read_next_frame().unwrap() {
            delays.push(frame.delay);
        }
        assert_eq!(delays, [40, 60]);
        assert!(write_gif(folder.path(), &[], 1.0, &done).is_err());
        // Recordings finished in the same second keep their own files.
        let again = write_gif(folder.path(), &frames, 1.0, &done).unwrap();
        let third = write_gif(folder.path(), &frames, 1.0, &done).unwrap();
        assert!(again != path && third != path && third != again);
        assert_eq!(std::fs::read_dir(folder.path()).unwrap().count(), 3);
    }
}
