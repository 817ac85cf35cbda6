//! The analysis of the current parameters computed off the UI thread: one
//! thread that always works on the newest parameters asked for, so dragging
//! a slider never waits for a locus.

use std::sync::mpsc::{self, Receiver, Sender};

use crate::analysis::AnalysisError;
use crate::model::Model;

use super::analysis_cache::Analysis;

/// An analysis and the parameters (at p = 0) it is for.
pub type Finished = (Model, Result<Analysis, AnalysisError>);

/// A thread that analyses the parameters it is sent, skipping any that were
/// overtaken by newer ones before it got to them. It ends when dropped.
pub struct AnalysisWorker {
    requests: Sender<Model>,
    results: Receiver<Finished>,
}

impl AnalysisWorker {
    /// Starts the thread.
    ///
    /// # Errors
    /// When the system gives no thread (the caller analyses inline instead).
    pub fn start() -> std::io::Result<Self> {
        let (requests, incoming) = mpsc::channel::<Model>();
        let (finished, results) = mpsc::channel();
        std::thread::Builder::new()
            .name("analysis".into())
            .spawn(move || {
                while let Ok(mut key) = incoming.recv() {
                    // Parameters dragged past while the last one was computed
                    // are for no one: only the newest is analysed.
                    while let Ok(newer) = incoming.try_recv() {
                        key = newer;
                    }
                    let analysis = Analysis::new(&key);
                    if finished.send((key, analysis)).is_err() {
                        return;
                    }
                }
            })?;
        Ok(Self { requests, results })
    }

    /// Asks for the analysis of `key`. False when the thread is gone.
    pub fn request(&self, key: Model) -> bool {
        self.requests.send(key).is_ok()
    }

    /// Every analysis finished since the last call, oldest first.
    pub fn finished(&self) -> Vec<Finished> {
        self.results.try_iter().collect()
    }

    /// Waits for the next finished analysis; `None` when the thread is gone.
    pub fn wait(&self) -> Option<Finished> {
        self.results.recv().ok()
    }
}
