//! The record button's work: screenshots of the window at a steady rate
//! for the chosen seconds of wall time, each handed as it arrives to a
//! thread that adds it to the GIF (a few raw frames queued at most, so a
//! long or 4K recording never holds its frames in memory), then the file
//! written whole into the chosen folder, with progress on the way and a
//! notice saying where the file went.

use super::speak::Speak as _;
use crate::i18n::Words;
use crate::tr;
use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, OnceLock, mpsc};

use eframe::egui::{self, ColorImage};

use crate::app::jobs::Jobs;
use crate::recording::GifRecording;

/// The window's title, also after a recording has shown its progress there.
pub const WINDOW_TITLE: &str = "zieglerlab";

/// Frames per second of a recording of the window (at most: a busy machine
/// draws fewer, and each frame then lasts until the next).
pub const RECORD_FPS: u16 = 10;

/// How long after its end a recording waits for screenshots asked for and
/// not yet delivered (they come a frame or two later).
const LATE_SCREENSHOT_SECS: f64 = 2.0;

/// How long after its end a recording that has no frame yet waits for its
/// first (a machine busy enough to deliver none in the recording's time).
const FIRST_SCREENSHOT_SECS: f64 = 10.0;

/// Raw frames waiting for the encoder, at most: a frame that finds the
/// queue full is left out (the others then last longer, so the GIF still
/// plays in the time recorded). A 4K frame is 33 MB.
const QUEUED_FRAMES: usize = 4;

/// How often the encoder looks whether the recording has ended.
const ENCODER_POLL: std::time::Duration = std::time::Duration::from_millis(50);

/// Shortest delay written to the GIF, in hundredths of a second: browsers
/// show a frame of 0 or 1 for a tenth of a second instead.
const MIN_DELAY_CS: u16 = 2;

/// A screenshot and the time (the context's clock) of the frame it shows.
type TimedFrame = (f64, Arc<ColorImage>);

/// The thread making the GIF, and what the window knows of it.
pub struct Encoder {
    frames: mpsc::SyncSender<TimedFrame>,
    /// The recording's end (the context's clock), once it has ended.
    end_secs: Arc<OnceLock<f64>>,
    /// Frames added to the GIF.
    done: Arc<AtomicUsize>,
    /// Frames delivered by the window, and those left out of a full queue.
    delivered: Arc<AtomicUsize>,
    left_out: Arc<AtomicUsize>,
    /// The thread, and the file it wrote (or why not).
    job: Jobs<PathBuf, Result<PathBuf, RecordError>>,
    /// Why the thread could not start, if it could not.
    failed: Option<RecordError>,
    /// The seconds recorded.
    secs: f64,
}

/// A recording written: where, and how many frames of how many seconds.
#[derive(Clone, Debug, PartialEq)]
pub struct Recorded {
    pub path: PathBuf,
    pub frames: usize,
    pub secs: f64,
}

impl Recorded {
    /// What the message line says of it: where, the frames caught, and on
    /// a machine too busy for a smooth GIF (fewer than half the frames a
    /// second asked for), what records more.
    #[must_use]
    pub fn text(&self, words: &'static Words) -> String {
        #[expect(clippy::cast_precision_loss, reason = "a count of frames")]
        let per_sec = self.frames as f64 / self.secs.max(1e-9);
        let slow = if per_sec < f64::from(RECORD_FPS) / 2.0 {
            tr!(
                words,
                "recording-jerky",
                caught = crate::format::number_text((per_sec * 10.0).round() / 10.0),
                fps = RECORD_FPS
            )
        } else {
            String::new()
        };
        tr!(
            words,
            "recording-saved",
            path = self.path.display().to_string(),
            frames = self.frames,
            secs = crate::format::number_text(self.secs),
            slow = slow
        )
    }
}

impl Encoder {
    /// Starts the thread that writes the GIF into `folder`, `secs` long.
    fn start(folder: PathBuf, secs: f64) -> Self {
        let (frames, queue) = mpsc::sync_channel(QUEUED_FRAMES);
        let end_secs = Arc::new(OnceLock::new());
        let done = Arc::new(AtomicUsize::new(0));
        let (end, counter) = (Arc::clone(&end_secs), Arc::clone(&done));
        let mut job = Jobs::new("recording");
        let failed = job
            .request(folder, move |folder, _, send| {
                send(encode_stream(folder, &queue, &end, &counter));
            })
            .err()
            .map(RecordError::NoThread);
        Self {
            frames,
            end_secs,
            done,
            delivered: Arc::default(),
            left_out: Arc::default(),
            job,
            failed,
            secs,
        }
    }

    /// A callback that hands a screenshot of the frame at `time_secs` to
    /// the encoder, or leaves it out when the queue is full.
    fn taker(&self, time_secs: f64) -> impl Fn(Arc<ColorImage>) + Send + Sync + 'static {
        let frames = self.frames.clone();
        let (delivered, left_out) = (Arc::clone(&self.delivered), Arc::clone(&self.left_out));
        move |image| {
            delivered.fetch_add(1, Ordering::Relaxed);
            if frames.try_send((time_secs, image)).is_err() {
                left_out.fetch_add(1, Ordering::Relaxed);
            }
        }
    }
}

/// Where a recording is.
#[derive(Default)]
pub enum Recorder {
    #[default]
    Idle,
    /// Taking a screenshot every 1/fps s until `until_secs` (the context's
    /// clock), each handed to the encoder with the time of the frame it
    /// shows; then waiting (at most [`LATE_SCREENSHOT_SECS`]) for those
    /// asked for and not yet delivered.
    Capturing {
        next_secs: f64,
        until_secs: f64,
        requested: usize,
        encoder: Encoder,
    },
    /// The capture is over: the encoder adds what is queued and writes the
    /// file (or says why not).
    Encoding { encoder: Encoder },
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
            next_secs: now_secs,
            until_secs: now_secs + secs,
            requested: 0,
            encoder: Encoder::start(folder, secs),
        };
    }

    /// Whether screenshots are being taken (the window then draws no hints,
    /// and the progress goes to the window's title, out of the pictures).
    #[must_use]
    pub fn is_capturing(&self) -> bool {
        matches!(self, Self::Capturing { .. })
    }

    /// One frame of the window: a screenshot when one is due; at the end,
    /// the encoder told and then waited for. Returns a finished file's
    /// path, or why the recording failed.
    pub fn frame(&mut self, ctx: &egui::Context) -> Option<Result<Recorded, RecordError>> {
        let now_secs = ctx.input(|i| i.time);
        match self {
            Self::Idle => None,
            Self::Capturing {
                next_secs,
                until_secs,
                requested,
                encoder,
            } => {
                if now_secs >= *until_secs {
                    let delivered = encoder.delivered.load(Ordering::Relaxed);
                    let waiting = (delivered < *requested
                        && now_secs < *until_secs + LATE_SCREENSHOT_SECS)
                        || (delivered == 0 && now_secs < *until_secs + FIRST_SCREENSHOT_SECS);
                    if !waiting {
                        // Set once: this state is left at once.
                        let _ = encoder.end_secs.set(*until_secs);
                        let Self::Capturing { encoder, .. } = std::mem::take(self) else {
                            return None;
                        };
                        *self = Self::Encoding { encoder };
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
                    ctx.send_viewport_cmd(egui::ViewportCommand::Title(tr!(
                        ctx.words(),
                        "recording-title",
                        title = WINDOW_TITLE,
                        secs = format!("{:.0}", (*until_secs - now_secs).max(0.0).ceil())
                    )));
                    *requested += 1;
                    ctx.request_screenshot(encoder.taker(now_secs));
                }
                ctx.request_repaint();
                None
            }
            Self::Encoding { encoder } => {
                // Whether it runs is asked first: a result sent meanwhile is
                // then still found below.
                let running = encoder.job.busy();
                let result = encoder
                    .job
                    .drain()
                    .next()
                    .map(|(_, result)| result)
                    .or_else(|| encoder.failed.take().map(Err));
                match result {
                    Some(done) => {
                        let recorded = done.map(|path| Recorded {
                            path,
                            frames: encoder.done.load(Ordering::Relaxed),
                            secs: encoder.secs,
                        });
                        *self = Self::Idle;
                        Some(recorded)
                    }
                    None if running => {
                        ctx.request_repaint_after(ENCODER_POLL);
                        None
                    }
                    None => {
                        *self = Self::Idle;
                        Some(Err(RecordError::Stopped))
                    }
                }
            }
        }
    }

    /// A line saying how far the making of the GIF is, if only that is left
    /// (the capture's own progress is in the window's title).
    #[must_use]
    pub fn progress_text(&self, words: &'static Words) -> Option<String> {
        match self {
            Self::Encoding { encoder } => {
                let kept = encoder.delivered.load(Ordering::Relaxed)
                    - encoder.left_out.load(Ordering::Relaxed);
                Some(tr!(
                    words,
                    "recording-making",
                    done = encoder.done.load(Ordering::Relaxed),
                    kept = kept
                ))
            }
            Self::Idle | Self::Capturing { .. } => None,
        }
    }
}

/// The delays of frames shown one after another from `start_secs`, in
/// hundredths of a second, with the rounding carried from frame to frame.
struct DelayClock {
    start_secs: f64,
    shown_cs: i64,
}

impl DelayClock {
    /// How long the frame shown now lasts if the next comes at `end_secs`:
    /// the total is the time from the start to the hundredth, and no delay
    /// is below [`MIN_DELAY_CS`].
    fn until(&mut self, end_secs: f64) -> u16 {
        #[expect(
            clippy::cast_possible_truncation,
            reason = "a recording lasts at most a minute: 6000 hundredths"
        )]
        let due_cs = ((end_secs - self.start_secs) * 100.0).round() as i64;
        let delay = (due_cs - self.shown_cs).clamp(i64::from(MIN_DELAY_CS), i64::from(u16::MAX));
        self.shown_cs += delay;
        u16::try_from(delay).unwrap_or(u16::MAX)
    }
}

/// The GIF of the frames `queue` brings (in the order taken; those of
/// another size than the first, from a window resized mid-way, and any
/// taken after the end are left out), each shown until the next, the last
/// until `end_secs` once that is set; written into `folder`, named by the
/// time. One frame is held back until the next gives its delay.
fn encode_stream(
    folder: &std::path::Path,
    queue: &mpsc::Receiver<TimedFrame>,
    end_secs: &OnceLock<f64>,
    done: &AtomicUsize,
) -> Result<PathBuf, RecordError> {
    let mut gif: Option<GifRecording> = None;
    let mut clock: Option<DelayClock> = None;
    let mut held: Option<TimedFrame> = None;
    let add = |gif: &mut GifRecording, frame: &ColorImage, delay_cs: u16| {
        let mut rgba: Vec<u8> = frame
            .pixels
            .iter()
            .flat_map(egui::Color32::to_array)
            .collect();
        gif.push_lasting(&mut rgba, delay_cs)?;
        done.fetch_add(1, Ordering::Relaxed);
        Ok::<(), RecordError>(())
    };
    loop {
        let (time_secs, image) = match queue.recv_timeout(ENCODER_POLL) {
            Ok(frame) => frame,
            Err(mpsc::RecvTimeoutError::Timeout) if end_secs.get().is_none() => continue,
            Err(_) => break,
        };
        let after_end = end_secs.get().is_some_and(|&end| time_secs > end);
        let in_order = held
            .as_ref()
            .is_none_or(|(held_secs, _)| time_secs > *held_secs);
        if after_end || !in_order {
            continue;
        }
        if gif.is_none() {
            let [width, height] = image.size;
            let side = |n: usize| u16::try_from(n).map_err(|_| RecordError::FrameTooLarge(n));
            gif = Some(GifRecording::new(side(width)?, side(height)?, RECORD_FPS)?);
            clock = Some(DelayClock {
                start_secs: time_secs,
                shown_cs: 0,
            });
        }
        let (Some(recording), Some(clock)) = (&mut gif, &mut clock) else {
            continue;
        };
        if held
            .as_ref()
            .is_some_and(|(_, first)| first.size != image.size)
        {
            continue;
        }
        if let Some((_, frame)) = held.replace((time_secs, image)) {
            add(recording, &frame, clock.until(time_secs))?;
        }
    }
    let (Some(mut recording), Some((held_secs, frame)), Some(clock)) = (gif, held, &mut clock)
    else {
        return Err(RecordError::NoFrame);
    };
    let end = end_secs.get().copied().unwrap_or(held_secs).max(held_secs);
    add(&mut recording, &frame, clock.until(end))?;
    let bytes = recording.finish()?;
    // A free name: two windows finishing in the same second keep both files.
    crate::files::write_new(folder, &file_stem(&jiff::Zoned::now()), "gif", |w| {
        std::io::Write::write_all(w, &bytes)
    })
    .map_err(RecordError::from)
}

/// A recording's file name without its extension: the local date and time
/// it was written, `zieglerlab-2026-12-02_14-05-09` (no colon, which some
/// file systems refuse).
fn file_stem(at: &jiff::Zoned) -> String {
    format!("zieglerlab-{}", at.strftime("%Y-%m-%d_%H-%M-%S"))
}

/// Why a recording from the window made no GIF.
#[derive(Debug, thiserror::Error)]
pub enum RecordError {
    #[error("no thread for the recording: {0}")]
    NoThread(std::io::Error),
    #[error("the recording stopped unexpectedly")]
    Stopped,
    #[error("no frame was captured")]
    NoFrame,
    #[error("a frame {0} pixels wide or high: more than a GIF holds")]
    FrameTooLarge(usize),
    #[error(transparent)]
    Encode(#[from] crate::recording::RecordingError),
    #[error(transparent)]
    Write(#[from] crate::files::WriteError),
}

#[cfg(test)]
mod tests {
    use super::*;
    use eframe::egui::Color32;

    /// How long each frame taken at `times_secs` (increasing) is shown, in
    /// hundredths of a second, the last until `end_secs`: each frame lasts
    /// until the next was taken, so the GIF plays in the time it recorded
    /// however unevenly the frames came (see [`DelayClock`]).
    fn delays_cs(times_secs: &[f64], end_secs: f64) -> Vec<u16> {
        let Some(&start_secs) = times_secs.first() else {
            return Vec::new();
        };
        let mut clock = DelayClock {
            start_secs,
            shown_cs: 0,
        };
        times_secs
            .iter()
            .skip(1)
            .chain([&end_secs])
            .map(|&end| clock.until(end))
            .collect()
    }

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

    /// Frames sent through the queue one by one.
    fn gif_of(
        folder: &std::path::Path,
        frames: &[TimedFrame],
        end: f64,
    ) -> Result<PathBuf, RecordError> {
        let (send, queue) = mpsc::sync_channel(QUEUED_FRAMES);
        let end_secs = OnceLock::new();
        let done = AtomicUsize::new(0);
        std::thread::scope(|scope| {
            let (end_ref, counter) = (&end_secs, &done);
            let encoding = scope.spawn(move || encode_stream(folder, &queue, end_ref, counter));
            for frame in frames {
                send.send(frame.clone()).unwrap();
            }
            end_secs.set(end).unwrap();
            let made = encoding.join().unwrap();
            if made.is_ok() {
                assert_eq!(done.load(Ordering::Relaxed), frames.len());
            }
            made
        })
    }

    /// The message of a recording counts its frames, and on a machine too
    /// busy for a smooth GIF (19 frames in 10 s of a 1920x1080 window)
    /// says so and what records more; a smooth one says nothing more.
    #[test]
    fn a_jerky_recording_is_said_to_be_one() {
        let recorded = |frames| Recorded {
            path: PathBuf::from("/tmp/clip.gif"),
            frames,
            secs: 10.0,
        };
        let busy = recorded(19).text(crate::i18n::words(crate::i18n::Language::English));
        assert!(
            busy.starts_with("recording saved to /tmp/clip.gif: 19 frames in 10 s; it caught only 1.9 frames a second of the 10 a second the GIF is made of (the capture rate"),
            "{busy}"
        );
        assert!(busy.contains("a smaller window"), "{busy}");
        assert_eq!(
            recorded(98).text(crate::i18n::words(crate::i18n::Language::English)),
            "recording saved to /tmp/clip.gif: 98 frames in 10 s"
        );
    }

    #[test]
    fn the_frames_become_a_gif_in_the_folder() {
        let folder = tempfile::tempdir().unwrap();
        let frame = |t: f64, c: Color32| (t, Arc::new(ColorImage::filled([8, 6], c)));
        let frames = [frame(0.0, Color32::RED), frame(0.4, Color32::BLUE)];
        let path = gif_of(folder.path(), &frames, 1.0).unwrap();
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
        assert!(matches!(
            gif_of(folder.path(), &[], 1.0).unwrap_err(),
            RecordError::NoFrame
        ));
        // Recordings finished in the same second keep their own files.
        let again = gif_of(folder.path(), &frames, 1.0).unwrap();
        let third = gif_of(folder.path(), &frames, 1.0).unwrap();
        assert!(again != path && third != path && third != again);
        assert_eq!(std::fs::read_dir(folder.path()).unwrap().count(), 3);
    }

    /// Many more frames than the queue holds pass through it (the encoder
    /// takes each as it comes), and their delays add up to the time
    /// recorded.
    #[test]
    fn a_long_recording_streams_through_a_short_queue() {
        let folder = tempfile::tempdir().unwrap();
        let frames: Vec<TimedFrame> = (0..60)
            .map(|i| {
                let shade = u8::try_from(i * 4).unwrap();
                let image = ColorImage::filled([16, 8], Color32::from_gray(shade));
                (f64::from(i) * 0.1, Arc::new(image))
            })
            .collect();
        let path = gif_of(folder.path(), &frames, 6.0).unwrap();
        let bytes = std::fs::read(path).unwrap();
        let mut decoder = gif::DecodeOptions::new()
            .read_info(std::io::Cursor::new(&bytes))
            .unwrap();
        let mut total_cs = 0_u32;
        let mut count = 0;
        while let Some(frame) = decoder.read_next_frame().unwrap() {
            total_cs += u32::from(frame.delay);
            count += 1;
        }
        assert_eq!(count, 60);
        assert_eq!(total_cs, 600, "six seconds recorded, six played");
    }

    /// The name carries the local date and time as a person reads a clock,
    /// in the zone it was made in.
    #[test]
    fn a_recording_is_named_by_its_local_date_and_time() {
        let at: jiff::Zoned = "2026-12-02T14:05:09+01:00[+01:00]".parse().unwrap();
        assert_eq!(file_stem(&at), "zieglerlab-2026-12-02_14-05-09");
    }
}
