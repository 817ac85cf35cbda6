//! Output to a stream (standard output, a pipe, the shell's `>>`) passed on
//! whole lines at a time and counted, so that a command stopped part way
//! leaves its stream ending on a whole line and can say what reached it.

use std::io::Write;
use std::sync::{Mutex, MutexGuard, TryLockError};
use std::time::{Duration, Instant};

/// What has reached the streams so far: the last one's name, the lines and
/// the bytes. A write holds this lock from its first byte to its last, so
/// whoever holds it knows no write is half done.
static REACHED: Mutex<Reached> = Mutex::new(Reached {
    name: String::new(),
    lines: 0,
    bytes: 0,
});

/// How much output reached the streams.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Reached {
    /// The stream written last, as the user named it (`standard output`,
    /// `/dev/fd/3`); empty if none has been written.
    pub name: String,
    /// Whole lines passed on.
    pub lines: u64,
    /// Bytes passed on.
    pub bytes: u64,
}

/// The pending output above which whole lines are passed on when the
/// stream is not a terminal (a terminal gets each line as it comes).
const BATCH_BYTES: usize = 8192;

/// A writer that passes on to `inner` only whole lines (the rest of the
/// output at [`Write::flush`]), each pass counted in [`REACHED`].
pub struct WholeLines<W: Write> {
    inner: W,
    name: String,
    pending: Vec<u8>,
    batch_bytes: usize,
}

impl<W: Write> WholeLines<W> {
    /// Passes whole lines to `inner`, named `name` in what is said of it;
    /// `at_once` passes each line as it comes (for a terminal), else in
    /// batches of about [`BATCH_BYTES`].
    pub fn new(inner: W, name: &str, at_once: bool) -> Self {
        Self {
            inner,
            name: name.to_owned(),
            pending: Vec::new(),
            batch_bytes: if at_once { 0 } else { BATCH_BYTES },
        }
    }

    /// Passes the first `upto` pending bytes on, flushed, and counts them.
    fn pass(&mut self, upto: usize) -> std::io::Result<()> {
        let mut reached = REACHED
            .lock()
            .map_err(|_| std::io::Error::other("a stream's count was lost to a panic"))?;
        let bytes = &self.pending[..upto];
        self.inner.write_all(bytes)?;
        self.inner.flush()?;
        if reached.name != self.name {
            reached.name.clone_from(&self.name);
        }
        #[expect(
            clippy::naive_bytecount,
            reason = "a count beside a write to the system costs nothing"
        )]
        let lines = bytes.iter().filter(|&&b| b == b'\n').count();
        reached.lines += u64::try_from(lines).unwrap_or(u64::MAX);
        reached.bytes += u64::try_from(upto).unwrap_or(u64::MAX);
        drop(reached);
        self.pending.drain(..upto);
        Ok(())
    }
}

impl<W: Write> Write for WholeLines<W> {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.pending.extend_from_slice(buf);
        if self.pending.len() > self.batch_bytes
            && let Some(last) = self.pending.iter().rposition(|&b| b == b'\n')
        {
            self.pass(last + 1)?;
        }
        Ok(buf.len())
    }

    /// Passes everything pending on, the end of the output included.
    fn flush(&mut self) -> std::io::Result<()> {
        if self.pending.is_empty() {
            return self.inner.flush();
        }
        self.pass(self.pending.len())
    }
}

impl<W: Write> Drop for WholeLines<W> {
    /// A writer dropped unflushed (its command failed part way) passes on
    /// the whole lines it holds, never a part of one.
    fn drop(&mut self) {
        if let Some(last) = self.pending.iter().rposition(|&b| b == b'\n') {
            // Nothing to tell of a failure here: the command's own error
            // is what the user hears.
            let _ = self.pass(last + 1);
        }
    }
}

/// Stops every stream for good (the process is about to end): waits at
/// most `wait` for a write in progress to finish, then keeps the lock so
/// no other starts. What reached the streams comes back, or `None` if a
/// write was still blocked after `wait` (a reader that reads nothing).
pub fn stop_streams(wait: Duration) -> Option<Reached> {
    let start = Instant::now();
    loop {
        match REACHED.try_lock() {
            Ok(guard) => return Some(held_for_good(guard)),
            Err(TryLockError::Poisoned(poisoned)) => {
                return Some(held_for_good(poisoned.into_inner()));
            }
            Err(TryLockError::WouldBlock) if start.elapsed() < wait => {
                std::thread::sleep(Duration::from_millis(10));
            }
            Err(TryLockError::WouldBlock) => return None,
        }
    }
}

/// What `guard` holds, the lock never released.
fn held_for_good(guard: MutexGuard<'static, Reached>) -> Reached {
    let reached = guard.clone();
    std::mem::forget(guard);
    reached
}

/// What a stopped command says of its streams, after its reason: nothing
/// if none was written, else how much reached which, and that the rest is
/// missing.
#[must_use]
pub fn stopped_words(reached: Option<&Reached>) -> String {
    match reached {
        None => "; a write to a stream was still blocked, so it may end part way through a line"
            .to_owned(),
        Some(reached) if reached.bytes == 0 => String::new(),
        Some(reached) => format!(
            "; {} had got {} {} ({} bytes) before the stop, ending on a whole line: the rest is missing",
            reached.name,
            reached.lines,
            if reached.lines == 1 { "line" } else { "lines" },
            reached.bytes
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Whole lines pass on as they are finished (at once) or in batches;
    /// a part of a line waits for its end or the flush; what passed is
    /// counted and said.
    #[test]
    fn only_whole_lines_pass_until_the_flush() {
        let mut out = Vec::new();
        let before = REACHED.lock().unwrap().clone();
        {
            let mut lines = WholeLines::new(&mut out, "the test's stream", true);
            write!(lines, "load,state\n0.5,sta").unwrap();
            assert_eq!(lines.inner.as_slice(), b"load,state\n");
            write!(lines, "ble\n1.5,flutter").unwrap();
            assert_eq!(lines.inner.as_slice(), b"load,state\n0.5,stable\n");
            lines.flush().unwrap();
        }
        assert_eq!(out, b"load,state\n0.5,stable\n1.5,flutter");
        let after = REACHED.lock().unwrap().clone();
        // Other tests may write streams too: at least these counts.
        assert!(after.lines >= before.lines + 2 && after.bytes >= before.bytes + 33);
        let mut batched = Vec::new();
        {
            let mut lines = WholeLines::new(&mut batched, "a file", false);
            writeln!(lines, "short").unwrap();
            assert!(lines.inner.is_empty(), "a batch waits for 8 kB");
            lines.write_all(&[b'x'; BATCH_BYTES]).unwrap();
            assert_eq!(lines.inner.as_slice(), b"short\n");
        }
        let said = stopped_words(Some(&Reached {
            name: "standard output".to_owned(),
            lines: 1,
            bytes: 6,
        }));
        assert!(
            said.contains("standard output had got 1 line (6 bytes)"),
            "{said}"
        );
        assert_eq!(stopped_words(Some(&Reached::default())), "");
    }
}
