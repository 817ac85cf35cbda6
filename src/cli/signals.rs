//! The signals that stop a command (Ctrl-C, SIGTERM, a closed terminal's
//! SIGHUP, SIGQUIT): each ends the process at once, removing a file being
//! written, except where the process was started with it ignored (`nohup`
//! ignores SIGHUP, a script's background job SIGINT), which it stays.

use signal_hook::consts::{SIGHUP, SIGINT, SIGQUIT, SIGTERM};

/// The signals that stop a command, as the handler takes them.
const STOPPING: [i32; 4] = [SIGINT, SIGTERM, SIGHUP, SIGQUIT];

/// Whether `signal` is in the `SigIgn` mask of `/proc/self/status` (a hex
/// mask, bit `signal - 1`): the disposition this process inherited.
fn ignored_in(status: &str, signal: i32) -> bool {
    let Some(mask) = status
        .lines()
        .find_map(|line| line.strip_prefix("SigIgn:"))
        .and_then(|hex| u64::from_str_radix(hex.trim(), 16).ok())
    else {
        return false;
    };
    (1..=64).contains(&signal) && mask & (1 << (signal - 1)) != 0
}

/// The stopping signals this process did not inherit as ignored (all of
/// them where `/proc` cannot tell).
fn not_ignored() -> Vec<i32> {
    let status = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
    STOPPING
        .into_iter()
        .filter(|&signal| !ignored_in(&status, signal))
        .collect()
}

/// From now on each stopping signal not ignored at start ends the process
/// with `status`, a file being written removed first. Where no handler can
/// be set the system's default still stops the process (and may leave a
/// temporary file beside the output: the README says so).
pub fn stop_on_signals(status: i32) {
    let Ok(mut signals) = signal_hook::iterator::Signals::new(not_ignored()) else {
        return;
    };
    let spawned = std::thread::Builder::new()
        .name("signals".to_owned())
        .spawn(move || {
            if signals.forever().next().is_some() {
                zieglerlab::files::remove_unfinished();
                // A stream ends on a whole line (a blocked write is not
                // waited for long: the user asked to stop).
                let _ = zieglerlab::files::stop_streams(std::time::Duration::from_millis(500));
                std::process::exit(status);
            }
        });
    drop(spawned);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A status line as `nohup` leaves it (SIGHUP, 1, ignored) and as a
    /// background job of a script (SIGINT and SIGQUIT, 2 and 3).
    #[test]
    fn the_ignored_mask_is_read_bit_by_bit() {
        let nohup = "Name:\tzieglerlab\nSigBlk:\t0000000000000000\nSigIgn:\t0000000000000001\n";
        assert!(ignored_in(nohup, SIGHUP));
        assert!(!ignored_in(nohup, SIGINT) && !ignored_in(nohup, SIGTERM));
        let background = "SigIgn:\t0000000000000006\n";
        assert!(ignored_in(background, SIGINT) && ignored_in(background, SIGQUIT));
        assert!(!ignored_in(background, SIGHUP));
        assert!(!ignored_in("no such line", SIGINT));
        assert!(!ignored_in(nohup, 0) && !ignored_in(nohup, 65));
    }
}
