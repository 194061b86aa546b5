//! [`MemoryBudget`]: how much memory a request may claim, so that sizes that cannot fit are
//! refused with a typed error before anything is allocated (instead of an abort).

/// The memory a single request (a problem, a batch of samples, an experiment's schedule) may
/// claim: what the operating system reports as available, or 8 GiB where it reports nothing.
///
/// Checks are estimates made before allocating, deliberately generous to the request: they
/// exist to turn "abort on allocation" into a clear error, not to police every byte.
///
/// ```
/// use mit_star_spaces::MemoryBudget;
/// let budget = MemoryBudget::of_machine();
/// assert!(budget.bytes() > 0);
/// assert!(budget.fits(1 << 20));
/// assert!(!budget.fits(u64::MAX));
/// assert_eq!(MemoryBudget::bytes_for(&[1_000_000, 32, 8]), Some(256_000_000));
/// assert_eq!(MemoryBudget::bytes_for(&[u64::MAX, 2]), None);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct MemoryBudget(u64);

impl MemoryBudget {
    /// Assumed when the operating system does not say (non-Linux, no `/proc`).
    pub const FALLBACK: u64 = 8 << 30;

    /// The memory available on this machine now (`MemAvailable` of `/proc/meminfo` on Linux).
    pub fn of_machine() -> Self {
        Self(available_bytes().unwrap_or(Self::FALLBACK))
    }

    /// Checks `bytes` (a size from [`bytes_for`](Self::bytes_for); `None` when it overflowed)
    /// against this machine's available memory: `Ok` if it fits, else the budget it exceeds.
    /// Sizes up to [`SURELY_FITS`](Self::SURELY_FITS) are accepted without asking the
    /// operating system, so that a check made at every planner's or problem's construction
    /// costs nothing (reading `/proc/meminfo` took three quarters of MIT*'s construction on the
    /// Panda). The planner builder's batch check, the problem catalogue and the experiment
    /// definitions all check their sizes through it.
    ///
    /// ```
    /// use mit_star_spaces::MemoryBudget;
    /// assert!(MemoryBudget::check_on_machine(Some(4096)).is_ok());
    /// assert!(MemoryBudget::check_on_machine(None).is_err());
    /// assert!(MemoryBudget::check_on_machine(Some(u64::MAX)).is_err());
    /// ```
    pub fn check_on_machine(bytes: Option<u64>) -> Result<(), Self> {
        match bytes {
            Some(b) if b <= Self::SURELY_FITS => Ok(()),
            _ => {
                let budget = Self::of_machine();
                if bytes.is_some_and(|b| budget.fits(b)) {
                    Ok(())
                } else {
                    Err(budget)
                }
            }
        }
    }

    /// Sizes that fit on any machine a planner runs on (64 MiB):
    /// [`check_on_machine`](Self::check_on_machine) accepts them without reading the machine's
    /// memory.
    pub const SURELY_FITS: u64 = 64 << 20;

    /// A fixed budget (for tests and embedded use).
    pub fn new(bytes: u64) -> Self {
        Self(bytes)
    }

    /// The budget in bytes.
    pub fn bytes(self) -> u64 {
        self.0
    }

    /// `true` if `bytes` fit.
    pub fn fits(self, bytes: u64) -> bool {
        bytes <= self.0
    }

    /// The product of `factors` (counts and sizes), `None` if it overflows `u64` — which never
    /// fits.
    pub fn bytes_for(factors: &[u64]) -> Option<u64> {
        factors
            .iter()
            .try_fold(1_u64, |product, &factor| product.checked_mul(factor))
    }

    /// A size for messages: `1.5 GiB`, `300 MiB`, `12 KiB`.
    pub fn describe(bytes: u64) -> String {
        const UNITS: [&str; 6] = ["B", "KiB", "MiB", "GiB", "TiB", "PiB"];
        let mut value = bytes as f64;
        let mut unit = 0;
        while value >= 1024.0 && unit + 1 < UNITS.len() {
            value /= 1024.0;
            unit += 1;
        }
        if unit == 0 {
            format!("{bytes} B")
        } else if value >= 10_000.0 {
            format!("{value:.2e} {}", UNITS[unit])
        } else {
            format!("{value:.1} {}", UNITS[unit])
        }
    }
}

/// `MemAvailable` from `/proc/meminfo`, in bytes.
fn available_bytes() -> Option<u64> {
    let text = std::fs::read_to_string("/proc/meminfo").ok()?;
    let line = text.lines().find(|l| l.starts_with("MemAvailable:"))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    kib.checked_mul(1024)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_read_like_sizes() {
        assert_eq!(MemoryBudget::describe(512), "512 B");
        assert_eq!(MemoryBudget::describe(3 << 29), "1.5 GiB");
        assert_eq!(MemoryBudget::describe(u64::MAX), "1.64e4 PiB");
    }

    #[test]
    fn this_machine_reports_something_sensible() {
        let budget = MemoryBudget::of_machine();
        assert!(budget.bytes() >= 1 << 20, "{budget:?}");
    }
}
