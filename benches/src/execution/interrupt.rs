//! [`Interrupt`]: SIGINT and SIGTERM, handled alike.

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicI32, AtomicUsize, Ordering};

use signal_hook::consts::{SIGINT, SIGTERM};

use crate::error::HarnessError;

/// The process's reaction to SIGINT (Ctrl-C) and SIGTERM (what Slurm sends at a job's time
/// limit): the first one raises a flag that stops scheduling new runs and stops the planners in
/// flight (their runs are discarded; finished runs are already on disk), after which the command
/// writes its summaries and the process exits with `128 + signal` (130 or 143). A second signal
/// leaves at once (exit code `128 +` that signal); the raw files are complete up to the last
/// finished run then.
///
/// While a command reads its inputs (`ReadingInputs::begin`), a read may
/// block (a FIFO, a stalled network file system) where no flag is polled: a signal then leaves
/// at once, saying so, with the same exit code; nothing was run yet.
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
                    // The flag first, then the phase: a command that enters the input phase
                    // checks the flag after announcing it (`ReadingInputs::begin`), so one of the two
                    // sees the other.
                    let first = handler.receive(received);
                    if ReadingInputs::active() {
                        eprintln!("\n{name} while reading the inputs: leaving at once (nothing was run)");
                        std::process::exit(128 + received);
                    }
                    if NothingToSave::active() {
                        eprintln!("\n{name}: leaving at once (this command writes nothing to keep)");
                        std::process::exit(128 + received);
                    }
                    if first {
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

/// How many [`ReadingInputs`] guards are alive in the process (signals are the process's).
static READING_INPUTS: AtomicUsize = AtomicUsize::new(0);

/// The input phase of a command: while a guard lives, a SIGINT or SIGTERM makes the process
/// leave at once (128 + signal) instead of raising the flag, since a read blocked on a FIFO or
/// a stalled file system polls no flag. Guards nest; the phase ends when the last is dropped.
#[derive(Debug)]
#[must_use = "the input phase ends when the guard is dropped"]
pub(crate) struct ReadingInputs<'a> {
    flag: &'a AtomicBool,
}

impl<'a> ReadingInputs<'a> {
    /// Begins the input phase of a command polling `flag` (the [`Interrupt`]'s). Check
    /// [`interrupted`](Self::interrupted) at once: a signal may have come just before.
    pub(crate) fn begin(flag: &'a AtomicBool) -> Self {
        READING_INPUTS.fetch_add(1, Ordering::SeqCst);
        Self { flag }
    }

    /// `true` if the flag is raised: a signal arrived before the input phase began (or the
    /// caller raised it), and the command should stop before reading anything.
    pub(crate) fn interrupted(&self) -> bool {
        self.flag.load(Ordering::SeqCst)
    }

    /// `true` while some guard of the process is alive.
    fn active() -> bool {
        READING_INPUTS.load(Ordering::SeqCst) > 0
    }
}

impl Drop for ReadingInputs<'_> {
    fn drop(&mut self) {
        READING_INPUTS.fetch_sub(1, Ordering::SeqCst);
    }
}

/// How many [`NothingToSave`] guards are alive in the process.
static NOTHING_TO_SAVE: AtomicUsize = AtomicUsize::new(0);

/// A command that polls no flag and has nothing to write when stopped (`check-path`,
/// `check-state`, the listings, `compare`, `merge`, `spherise`): while a guard lives, the
/// first SIGINT or SIGTERM makes the process leave at once (128 + signal), as a second one
/// does for every command.
#[derive(Debug)]
#[must_use = "the command's phase ends when the guard is dropped"]
pub(crate) struct NothingToSave(());

impl NothingToSave {
    /// Begins the phase.
    pub(crate) fn begin() -> Self {
        NOTHING_TO_SAVE.fetch_add(1, Ordering::SeqCst);
        Self(())
    }

    /// `true` while some guard of the process is alive.
    fn active() -> bool {
        NOTHING_TO_SAVE.load(Ordering::SeqCst) > 0
    }
}

impl Drop for NothingToSave {
    fn drop(&mut self) {
        NOTHING_TO_SAVE.fetch_sub(1, Ordering::SeqCst);
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

    #[test]
    fn the_input_phase_lasts_while_a_guard_lives_and_sees_an_earlier_signal() {
        let interrupt = Interrupt::detached();
        let flag = interrupt.flag();
        let outer = ReadingInputs::begin(&flag);
        assert!(ReadingInputs::active() && !outer.interrupted());
        {
            let _inner = ReadingInputs::begin(&flag);
            assert!(ReadingInputs::active());
        }
        assert!(ReadingInputs::active(), "guards nest");
        interrupt.receive(SIGTERM);
        assert!(outer.interrupted());
        // (Other tests of this binary may hold guards meanwhile: the count is not checked to
        // fall to zero.)
    }
}
