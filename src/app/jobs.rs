//! Work done off the UI thread, one mechanism for every thread the window
//! starts (the analysis of new parameters, an overlay, the stability map,
//! the paradox curves, the limit cycles, a recording's encoding, a table's
//! writing, a lesson file's reading, the desktop's file dialog): each
//! request is for a key; the newest request wins (the one before is
//! cancelled, and the new one starts when its thread has ended, so a drag's
//! restarts queue instead of running side by side); what a job finds comes
//! back tagged with its key, as it goes; dropping the jobs cancels them; and
//! `wait` blocks for pictures and tests.

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, Receiver, Sender};
use std::thread::JoinHandle;

/// Tells a job to stop early: it checks between units of its work.
#[derive(Clone, Debug, Default)]
pub struct Cancel(Arc<AtomicBool>);

impl Cancel {
    #[must_use]
    pub fn requested(&self) -> bool {
        self.0.load(Ordering::Relaxed)
    }

    /// The flag itself, for work that takes one.
    #[must_use]
    pub fn flag(&self) -> &AtomicBool {
        &self.0
    }

    fn request(&self) {
        self.0.store(true, Ordering::Relaxed);
    }
}

/// What a job that sends one message has come to ([`Jobs::reply`]).
pub enum Reply<M> {
    /// At work, nothing sent yet.
    Pending,
    Sent(M),
    /// Ended without a message (it panicked).
    Ended,
}

/// The job under way (or done) for the newest key.
struct Running<K> {
    key: K,
    cancel: Cancel,
    thread: Option<JoinHandle<()>>,
}

/// A line of jobs of one kind, and what they sent back (`M`, tagged with
/// the key it is for).
pub struct Jobs<K, M> {
    name: &'static str,
    sender: Sender<(K, M)>,
    receiver: Receiver<(K, M)>,
    current: Option<Running<K>>,
}

impl<K, M> Jobs<K, M>
where
    K: Clone + PartialEq + Send + Sync + 'static,
    M: Send + 'static,
{
    /// No job yet; threads will be named `name`.
    #[must_use]
    pub fn new(name: &'static str) -> Self {
        let (sender, receiver) = mpsc::channel();
        Self {
            name,
            sender,
            receiver,
            current: None,
        }
    }

    /// The key of the newest job asked for.
    #[must_use]
    pub fn key(&self) -> Option<&K> {
        self.current.as_ref().map(|running| &running.key)
    }

    /// Starts `work` for `key`, the newest wins: the job before is
    /// cancelled, and this one starts once its thread has ended (a job
    /// cancelled before it started never starts). `work` sends what it
    /// finds through the function it is given.
    ///
    /// # Errors
    /// The system gives no thread.
    pub fn request(
        &mut self,
        key: K,
        work: impl FnOnce(&K, &Cancel, &(dyn Fn(M) + Sync)) + Send + 'static,
    ) -> std::io::Result<()> {
        let previous = self.current.take().and_then(|mut running| {
            running.cancel.request();
            running.thread.take()
        });
        let cancel = Cancel::default();
        let (sender, job_key, job_cancel) = (self.sender.clone(), key.clone(), cancel.clone());
        let spawned = std::thread::Builder::new()
            .name(self.name.to_owned())
            .spawn(move || {
                if let Some(previous) = previous {
                    // A panic there was that job's; this one goes on.
                    drop(previous.join());
                }
                if job_cancel.requested() {
                    return;
                }
                // A closed channel: the jobs were dropped, nobody to tell.
                let send = |message| drop(sender.send((job_key.clone(), message)));
                work(&job_key, &job_cancel, &send);
            });
        let thread = match spawned {
            Ok(handle) => Some(handle),
            Err(error) => {
                self.current = None;
                return Err(error);
            }
        };
        self.current = Some(Running {
            key,
            cancel,
            thread,
        });
        Ok(())
    }

    /// Everything sent since the last call, oldest first.
    pub fn drain(&self) -> impl Iterator<Item = (K, M)> + '_ {
        self.receiver.try_iter()
    }

    /// What a job that sends one message (a dialog, a file read) has come
    /// to. Whether it was at work is asked before looking: a job that had
    /// ended had sent what it would.
    pub fn reply(&self) -> Reply<M> {
        let busy = self.busy();
        match self.drain().next() {
            Some((_, message)) => Reply::Sent(message),
            None if busy => Reply::Pending,
            None => Reply::Ended,
        }
    }

    /// Whether the newest job's thread is still at work.
    #[must_use]
    pub fn busy(&self) -> bool {
        self.current
            .as_ref()
            .and_then(|running| running.thread.as_ref())
            .is_some_and(|thread| !thread.is_finished())
    }

    /// Blocks until the newest job has ended (for pictures and tests; the
    /// window never waits). What it sent is then in [`Self::drain`].
    pub fn wait(&mut self) {
        if let Some(thread) = self.current.as_mut().and_then(|r| r.thread.take()) {
            drop(thread.join());
        }
    }
}

impl<K, M> Drop for Jobs<K, M> {
    fn drop(&mut self) {
        if let Some(running) = &self.current {
            running.cancel.request();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Requests in quick succession: the newest runs to its end and its
    /// result comes back tagged; one cancelled before it started never runs;
    /// a job checks its flag and stops early when overtaken.
    #[test]
    fn the_newest_request_wins_and_the_ones_it_overtook_stop() {
        let mut jobs: Jobs<u32, u64> = Jobs::new("test");
        let (release, gate) = mpsc::channel::<()>();
        let (started, has_started) = mpsc::channel::<()>();
        let gate = std::sync::Mutex::new(gate);
        // Job 1 says it started, holds until released, then counts while
        // not cancelled, for ten seconds at most: were cancelling broken,
        // the test would fail on its count, not hang.
        let limit = std::time::Duration::from_secs(10);
        jobs.request(1, move |_, cancel, send| {
            started.send(()).unwrap();
            gate.lock().unwrap().recv_timeout(limit).unwrap();
            let since = std::time::Instant::now();
            let mut n = 0;
            while !cancel.requested() && since.elapsed() < limit {
                n += 1;
            }
            send(n);
        })
        .unwrap();
        has_started.recv_timeout(limit).expect("job 1 started");
        // Job 2 is overtaken before job 1 ends: it never starts.
        jobs.request(2, |_, _, send| send(2)).unwrap();
        jobs.request(3, |key, _, send| send(u64::from(*key) * 10))
            .unwrap();
        release.send(()).unwrap();
        jobs.wait();
        let sent: Vec<(u32, u64)> = jobs.drain().collect();
        assert_eq!(sent.len(), 2, "{sent:?}");
        assert_eq!(sent[0], (1, 0), "job 1 stopped at once when cancelled");
        assert_eq!(sent[1], (3, 30));
        assert_eq!(jobs.key(), Some(&3));
        assert!(!jobs.busy());
    }
}
