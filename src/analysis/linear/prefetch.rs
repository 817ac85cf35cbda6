//! A long chain's spectra at the locus's evenly spaced loads, computed a
//! block at a time on the threads its pencil allows, ahead of the tracking.

use std::sync::atomic::{AtomicUsize, Ordering};

use crate::analysis::pencil::AffinePencil;
use crate::analysis::{AnalysisError, C64};

/// Evenly spaced loads whose spectra are computed together, on the pencil's threads,
/// ahead of the tracking (per thread): a long chain's eigenvalues come from
/// the QR iteration, about 50 µs each at 32 rods, and long blocks keep the
/// threads' start and the wait for the slower one small beside them.
const PREFETCH_PER_THREAD: usize = 128;

/// The spectra of the evenly spaced loads of a locus whose eigenvalues all
/// come from the Schur path (more than [`MAX_DEGREE`](crate::analysis::roots::MAX_DEGREE) of them: no
/// characteristic polynomial), computed a block at a time on the pencil's threads.
/// The tracking assigns them exactly as [`eigenvalues_near`](super::matching::eigenvalues_near) would, so the
/// locus is the same to the last bit; an error is returned only when its
/// load is reached.
pub(in crate::analysis) struct Prefetched {
    threads: usize,
    /// The grid index of `spectra[0]`.
    from: usize,
    spectra: Vec<Result<Vec<C64>, AnalysisError>>,
}

impl Prefetched {
    /// Spectra computed on `threads` threads.
    pub(in crate::analysis) fn new(threads: usize) -> Self {
        Self {
            threads,
            from: 0,
            spectra: Vec::new(),
        }
    }

    /// The moving eigenvalues at `grid[index]`, computing the block that
    /// starts there when it is not held.
    pub(in crate::analysis) fn at(
        &mut self,
        pencil: &AffinePencil,
        grid: &[f64],
        index: usize,
    ) -> Result<&[C64], AnalysisError> {
        if !(self.from..self.from + self.spectra.len()).contains(&index) {
            let end = (index + PREFETCH_PER_THREAD * self.threads).min(grid.len());
            let loads = &grid[index..end];
            self.spectra = spectra_on_threads(pencil, loads, self.threads);
            self.from = index;
        }
        match &self.spectra[index - self.from] {
            Ok(eigenvalues) => Ok(eigenvalues),
            Err(error) => Err(error.clone()),
        }
    }
}

/// The moving eigenvalues of `pencil` at each of `loads`, in order, on
/// `threads` threads (the calling one among them), each taking the next
/// load not yet taken: loads whose QR iterations take longer do not keep
/// the others waiting.
fn spectra_on_threads(
    pencil: &AffinePencil,
    loads: &[f64],
    threads: usize,
) -> Vec<Result<Vec<C64>, AnalysisError>> {
    let spectrum = |p: f64| pencil.spectrum(p).map(|s| s.eigenvalues);
    if threads < 2 || loads.len() < 2 {
        return loads.iter().map(|&p| spectrum(p)).collect();
    }
    let next = AtomicUsize::new(0);
    let work = || {
        let mut done = Vec::new();
        loop {
            let i = next.fetch_add(1, Ordering::Relaxed);
            let Some(&p) = loads.get(i) else {
                return done;
            };
            done.push((i, spectrum(p)));
        }
    };
    let mut spectra: Vec<Result<Vec<C64>, AnalysisError>> = loads
        .iter()
        .map(|&load| Err(AnalysisError::NotConverged { load }))
        .collect();
    std::thread::scope(|scope| {
        let helpers: Vec<_> = (1..threads.min(loads.len()))
            .map(|_| scope.spawn(work))
            .collect();
        let own = work();
        // A helper that failed leaves its loads unanswered (the error above).
        let helped = helpers.into_iter().filter_map(|helper| helper.join().ok());
        for (i, result) in helped.flatten().chain(own) {
            spectra[i] = result;
        }
    });
    spectra
}
