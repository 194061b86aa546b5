//! [`Interrupt`]: SIGINT and SIGTERM, handled alike.

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicI32, Ordering};

use signal_hook::consts::{SIGINT, SIGTERM};

use crate::HarnessError;

/// The process's reaction to SIGINT (Ctrl-C) and SIGTERM (what Slurm sends at a job's time
/// limit): the first one raises a flag that stops scheduling new runs and stops the planners in
/// flight (their runs are discarded; finished runs are already on disk), after which the command
/// writes its summaries and the process exits with `128 + signal` (130 or 143). A second signal
/// leaves at once (exit code `128 +` that signal); the raw files are complete up to the last
/// finished run then.
///
/// ```no_run
/// use std::sync::atomic::Ordering;
/// let interrupt = mit_star_benches::Interrupt::install()?;
/// let flag = interrupt.flag(); // hand to `bench`/`plan`; planners poll it
/// // … the command stops early when `flag` is raised, writes what it has, and then:
/// if interrupt.raised() {
///     std::process::exit(i32::from(interrupt.exit_code())); // 130 (SIGINT) or 143 (SIGTERM)
/// }
/// # Ok::<(), mit_star_benches::HarnessError>(())
/// ```
#[derive(Debug, Clone)]
pub struct Interrupt {
    flag: Arc<AtomicBool>,
    signal: Arc<AtomicI32>,
}

impl Interrupt {
    /// Installs the handler (a thread waiting for SIGINT and SIGTERM).
    ///
    /// # Errors
    /// [`HarnessError::Usage`] if the operating system refuses the handler.
    pub fn install() -> Result<Self, HarnessError> {
        let interrupt = Self::detached();
        let mut signals = signal_hook::iterator::Signals::new([SIGINT, SIGTERM])
            .map_err(|e| HarnessError::Usage(format!("cannot handle SIGINT/SIGTERM: {e}")))?;
        let handler = interrupt.clone();
        std::thread::Builder::new()
            .name("mit-star-signals".into())
            .spawn(move || {
                for received in signals.forever() {
                    let name = if received == SIGTERM { "SIGTERM" } else { "SIGINT" };
                    if handler.receive(received) {
                        eprintln!(
                            "\n{name}: finishing, then writing every finished run (send it again to leave at once)"
                        );
                    } else {
                        eprintln!("\n{name} again: leaving at once");
                        std::process::exit(128 + received);
                    }
                }
            })
            .map_err(|e| HarnessError::Usage(format!("cannot start the signal thread: {e}")))?;
        Ok(interrupt)
    }

    /// Records the arrival of `signal`: raises the flag and, for the first signal, remembers
    /// it (its exit code is the command's). Returns `false` if the flag was already raised —
    /// the handler then leaves at once.
    fn receive(&self, signal: i32) -> bool {
        let first = !self.flag.swap(true, Ordering::SeqCst);
        if first {
            self.signal.store(signal, Ordering::SeqCst);
        }
        first
    }

    /// A flag nobody raises but the caller (for tests and library use).
    pub fn detached() -> Self {
        Self {
            flag: Arc::new(AtomicBool::new(false)),
            signal: Arc::new(AtomicI32::new(0)),
        }
    }

    /// The flag commands poll.
    pub fn flag(&self) -> Arc<AtomicBool> {
        Arc::clone(&self.flag)
    }

    /// `true` once a signal arrived (or the flag was raised).
    pub fn raised(&self) -> bool {
        self.flag.load(Ordering::SeqCst)
    }

    /// The signal that raised the flag (`SIGINT` = 2, `SIGTERM` = 15), if one did.
    pub fn signal(&self) -> Option<i32> {
        match self.signal.load(Ordering::SeqCst) {
            0 => None,
            s => Some(s),
        }
    }

    /// The exit code of an interrupted command: `128 + signal` (130 for SIGINT, 143 for
    /// SIGTERM); 130 if the flag was raised without a signal.
    pub fn exit_code(&self) -> u8 {
        match self.signal.load(Ordering::SeqCst) {
            0 => 130,
            s => u8::try_from(128 + s).unwrap_or(130),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_first_signal_raises_the_flag_and_sets_the_exit_code() {
        let interrupt = Interrupt::detached();
        assert!(!interrupt.raised());
        assert_eq!(interrupt.signal(), None);
        assert!(interrupt.receive(SIGTERM));
        assert!(interrupt.raised() && interrupt.flag().load(Ordering::SeqCst));
        assert_eq!((interrupt.signal(), interrupt.exit_code()), (Some(15), 143));
        // A second signal (of either kind) is not the first; the first one's code stays.
        assert!(!interrupt.receive(SIGINT));
        assert_eq!(interrupt.exit_code(), 143);

        let interrupt = Interrupt::detached();
        assert!(interrupt.receive(SIGINT));
        assert_eq!((interrupt.signal(), interrupt.exit_code()), (Some(2), 130));
    }

    #[test]
    fn a_flag_raised_by_the_caller_exits_like_sigint() {
        let interrupt = Interrupt::detached();
        interrupt.flag().store(true, Ordering::SeqCst);
        assert!(interrupt.raised());
        assert_eq!((interrupt.signal(), interrupt.exit_code()), (None, 130));
        // A signal after the caller raised the flag leaves at once.
        assert!(!interrupt.receive(SIGTERM));
    }
}
