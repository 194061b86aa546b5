//! [`Interrupt`]: SIGINT and SIGTERM, handled alike.

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicI32, Ordering};

use signal_hook::consts::{SIGINT, SIGTERM};

use crate::HarnessError;

/// The process's reaction to SIGINT (Ctrl-C) and SIGTERM (what Slurm sends at a job's time
/// limit): the first one raises a flag that stops scheduling new runs and stops the planners in
/// flight (their runs are discarded; finished runs are already on disk), after which the command
/// writes its summaries and the process exits with `128 + signal` (130 or 143). A second signal
/// leaves at once with the same code.
///
/// ```no_run
/// let interrupt = mit_star_benches::Interrupt::install()?;
/// let flag = interrupt.flag(); // hand to `bench`/`plan`
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
        let (flag, signal) = (Arc::clone(&interrupt.flag), Arc::clone(&interrupt.signal));
        std::thread::Builder::new()
            .name("mit-star-signals".into())
            .spawn(move || {
                for received in signals.forever() {
                    if flag.swap(true, Ordering::SeqCst) {
                        eprintln!("\nsignal {received} again: leaving at once");
                        std::process::exit(128 + received);
                    }
                    signal.store(received, Ordering::SeqCst);
                    let name = if received == SIGTERM { "SIGTERM" } else { "SIGINT" };
                    eprintln!(
                        "\n{name}: finishing, then writing every finished run (send it again to leave at once)"
                    );
                }
            })
            .map_err(|e| HarnessError::Usage(format!("cannot start the signal thread: {e}")))?;
        Ok(interrupt)
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

    /// The exit code of an interrupted command: `128 + signal` (130 for SIGINT, 143 for
    /// SIGTERM); 130 if the flag was raised without a signal.
    pub fn exit_code(&self) -> u8 {
        match self.signal.load(Ordering::SeqCst) {
            0 => 130,
            s => u8::try_from(128 + s).unwrap_or(130),
        }
    }
}
