//! The `zieglerlab` command line: headless access to the library.

// App code answers bad input with an error, never a panic (tests may unwrap).
#![deny(clippy::unwrap_used, clippy::expect_used)]

mod cli;

/// mimalloc for every allocation: the cycles' solvers allocate and free
/// matrices of tens of kilobytes at every step, and glibc's allocator gave
/// the memory back to the system and faulted it in again each time
/// (445 000 page faults in a 16-rod bifurcation run, a tenth of its time).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() -> std::process::ExitCode {
    cli::run()
}
