//! A long chain's spectra at the locus's evenly spaced loads, computed
//! ahead of the tracking on the threads its pencil allows, while the
//! tracking goes on.

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Mutex, PoisonError};
use std::time::Duration;

use crate::analysis::pencil::AffinePencil;
use crate::analysis::{AnalysisError, C64};

/// Evenly spaced loads a helper may compute ahead of the tracking (per
/// thread): a long chain's eigenvalues come from the QR iteration, about
/// 50 µs each at 32 rods, and the tracking of a load takes a few µs, so
/// this keeps the helpers busy and bounds the spectra held.
const PREFETCH_PER_THREAD: usize = 128;

/// How long a helper that is that far ahead waits before looking again.
const AHEAD_PAUSE: Duration = Duration::from_micros(100);

type Eigenvalues = Result<Vec<C64>, AnalysisError>;

/// What the tracking and its helpers share: the loads, which of them are
/// taken, and the spectra computed and not yet read.
struct Shared<'a> {
    pencil: &'a AffinePencil,
    grid: &'a [f64],
    /// The first grid index no thread has taken.
    next: AtomicUsize,
    /// The grid index the tracking asked for last.
    reached: AtomicUsize,
    /// Helpers still running (one that panicked is not).
    helpers: AtomicUsize,
    /// The tracking has ended.
    stop: AtomicBool,
    spectra: Vec<Mutex<Option<Eigenvalues>>>,
}

impl Shared<'_> {
    /// How far past the tracking's load the loads may be taken.
    fn ahead(&self) -> usize {
        PREFETCH_PER_THREAD * self.pencil.threads()
    }

    /// Takes the next load not yet taken (none beyond `limit`), or `None`.
    fn take(&self, limit: usize) -> Option<usize> {
        let mut index = self.next.load(Ordering::Acquire);
        while index < self.grid.len().min(limit + 1) {
            match self.next.compare_exchange_weak(
                index,
                index + 1,
                Ordering::AcqRel,
                Ordering::Acquire,
            ) {
                Ok(_) => return Some(index),
                Err(now) => index = now,
            }
        }
        None
    }

    fn compute(&self, index: usize) -> Eigenvalues {
        self.pencil
            .spectrum(self.grid[index])
            .map(|spectrum| spectrum.eigenvalues)
    }

    /// Computes the load `index` into its slot for the tracking to read.
    fn fill(&self, index: usize) {
        let eigenvalues = self.compute(index);
        *self.slot(index) = Some(eigenvalues);
    }

    fn slot(&self, index: usize) -> std::sync::MutexGuard<'_, Option<Eigenvalues>> {
        self.spectra[index]
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
    }

    /// A helper's work: the next load, while the tracking goes on.
    fn help(&self) {
        while !self.stop.load(Ordering::Acquire)
            && self.next.load(Ordering::Acquire) < self.grid.len()
        {
            let limit = self.reached.load(Ordering::Acquire) + self.ahead();
            match self.take(limit) {
                Some(index) => self.fill(index),
                None => std::thread::sleep(AHEAD_PAUSE),
            }
        }
    }
}

/// Runs its closure when dropped: on return and on a panic's unwinding.
struct OnDrop<F: FnMut()>(F);

impl<F: FnMut()> Drop for OnDrop<F> {
    fn drop(&mut self) {
        (self.0)();
    }
}

/// The spectra of the evenly spaced loads of a locus whose eigenvalues all
/// come from the Schur path (more than [`MAX_DEGREE`](crate::analysis::roots::MAX_DEGREE) of them: no
/// characteristic polynomial), computed ahead by helper threads (the
/// pencil's threads less one) while the tracking asks for them in order;
/// the tracking computes loads too while it waits. Each load's spectrum is
/// the same whichever thread computes it, and the tracking assigns them
/// exactly as [`eigenvalues_near`](super::matching::eigenvalues_near)
/// would, so the locus is the same to the last bit; an error is returned
/// only when its load is reached.
pub(in crate::analysis) struct Prefetched<'a> {
    shared: &'a Shared<'a>,
    /// The last load asked for and its spectrum (a step may reach a load
    /// again after halving).
    held: Option<(usize, Eigenvalues)>,
}

impl Prefetched<'_> {
    /// The moving eigenvalues at `grid[index]` (asked for in increasing
    /// order).
    pub(in crate::analysis) fn at(&mut self, index: usize) -> Result<&[C64], AnalysisError> {
        let held = match self.held.take() {
            Some((i, eigenvalues)) if i == index => (i, eigenvalues),
            _ => (index, self.wait_for(index)),
        };
        let (_, eigenvalues) = self.held.insert(held);
        eigenvalues.as_deref().map_err(Clone::clone)
    }

    /// The spectrum at `grid[index]`: computed by a helper, or here (that
    /// load, or loads ahead while a helper finishes it).
    fn wait_for(&self, index: usize) -> Eigenvalues {
        let shared = self.shared;
        shared.reached.store(index, Ordering::Release);
        loop {
            if let Some(eigenvalues) = shared.slot(index).take() {
                return eigenvalues;
            }
            match shared.take(index + shared.ahead()) {
                Some(taken) if taken == index => return shared.compute(index),
                Some(taken) => shared.fill(taken),
                // Taken by a helper that has gone (a panic): computed here.
                None if shared.helpers.load(Ordering::Acquire) == 0 => {
                    if let Some(eigenvalues) = shared.slot(index).take() {
                        return eigenvalues;
                    }
                    return shared.compute(index);
                }
                None => std::thread::yield_now(),
            }
        }
    }
}

/// Runs `track` with the spectra of `grid` (from index 1 on) prefetched on
/// the pencil's threads, the helpers stopped when it returns.
pub(in crate::analysis) fn with_prefetched<R>(
    pencil: &AffinePencil,
    grid: &[f64],
    track: impl FnOnce(&mut Prefetched<'_>) -> R,
) -> R {
    let helpers = pencil.threads().saturating_sub(1).min(grid.len());
    let shared = Shared {
        pencil,
        grid,
        next: AtomicUsize::new(1),
        reached: AtomicUsize::new(1),
        helpers: AtomicUsize::new(helpers),
        stop: AtomicBool::new(false),
        spectra: grid.iter().map(|_| Mutex::new(None)).collect(),
    };
    std::thread::scope(|scope| {
        for _ in 0..helpers {
            scope.spawn(|| {
                // Counted out however it ends.
                let _leaving = OnDrop(|| {
                    shared.helpers.fetch_sub(1, Ordering::AcqRel);
                });
                shared.help();
            });
        }
        // The helpers stop however the tracking ends (a panic too: else
        // they would wait for it forever and the scope would never close).
        let _stopping = OnDrop(|| shared.stop.store(true, Ordering::Release));
        track(&mut Prefetched {
            shared: &shared,
            held: None,
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::load_grid;
    use crate::model::PresetId;

    /// However the tracking ends, the helpers stop and the scope closes:
    /// a tracking that reads one load of 2000 and returns, and one that
    /// panics after it (its helpers would otherwise wait for it forever).
    /// The load read is the spectrum computed on its own.
    #[test]
    fn the_helpers_stop_however_the_tracking_ends() {
        let mut model = PresetId::UniformRods.model();
        model.column.rods = 8;
        let pencil = AffinePencil::new(&model).unwrap().with_threads(3);
        let grid = load_grid(0.0, model.analysis_max_p(), 2000).unwrap();
        let read = with_prefetched(&pencil, &grid, |prefetched| {
            prefetched.at(5).map(<[C64]>::to_vec)
        });
        assert_eq!(read.unwrap(), pencil.spectrum(grid[5]).unwrap().eigenvalues);
        let panicked = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            with_prefetched(&pencil, &grid, |prefetched| {
                prefetched.at(1).unwrap();
                panic!("the tracking fails");
            })
        }));
        assert!(panicked.is_err());
    }
}
