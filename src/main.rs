//! The `zieglerlab` command line: headless access to the library.

// App code answers bad input with an error, never a panic (tests may unwrap).
#![deny(clippy::unwrap_used, clippy::expect_used)]

mod cli;

fn main() -> std::process::ExitCode {
    cli::run()
}
