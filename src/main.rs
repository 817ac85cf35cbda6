//! The `zieglerlab` command line: headless access to the library.

mod cli;

fn main() -> std::process::ExitCode {
    cli::run()
}
