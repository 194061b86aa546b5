//! Time budgets: seconds as given by a user, checked into a [`Duration`] every clock can hold.

use std::time::{Duration, Instant};

/// The largest budget accepted, in seconds (10⁷ s, about 116 days): far beyond any planning
/// experiment, and far below what `Instant` arithmetic can overflow on any platform.
pub const MAX_BUDGET_SECONDS: f64 = 1e7;

/// A budget in seconds that is not a usable time limit.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[error(
    "{} is not a usable time budget: give a positive number of seconds, at most {MAX_BUDGET_SECONDS:e} (about 116 days)",
    short_number(*.0)
)]
pub struct BudgetError(pub f64);

/// Converts a budget in seconds into a [`Duration`], refusing zero, negative, non-finite,
/// subnormal-small (below one nanosecond) and absurdly large values.
///
/// ```
/// use mit_star_benches::budget_duration;
/// assert_eq!(budget_duration(0.25)?, std::time::Duration::from_millis(250));
/// assert!(budget_duration(1e308).is_err());
/// assert!(budget_duration(f64::NAN).is_err());
/// assert!(budget_duration(-1.0).is_err());
/// # Ok::<(), mit_star_benches::BudgetError>(())
/// ```
///
/// # Errors
/// [`BudgetError`] naming the value.
pub fn budget_duration(seconds: f64) -> Result<Duration, BudgetError> {
    if !(seconds.is_finite() && seconds > 0.0 && seconds <= MAX_BUDGET_SECONDS) {
        return Err(BudgetError(seconds));
    }
    let duration = Duration::try_from_secs_f64(seconds).map_err(|_| BudgetError(seconds))?;
    if duration.is_zero() {
        return Err(BudgetError(seconds));
    }
    Ok(duration)
}

/// The deadline `budget` after `start`, or an error if the clock cannot represent it.
///
/// # Errors
/// [`BudgetError`] naming the budget.
pub fn deadline_after(start: Instant, seconds: f64) -> Result<Instant, BudgetError> {
    let budget = budget_duration(seconds)?;
    start.checked_add(budget).ok_or(BudgetError(seconds))
}

pub use mit_star_spaces::short_number;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn extreme_budgets_are_refused_with_a_short_message() {
        for bad in [
            0.0,
            -0.0,
            -1.0,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            1e308,
            1e19,
            f64::MIN_POSITIVE,
            5e-324,
            1e-12,
        ] {
            let e = budget_duration(bad).unwrap_err();
            let text = e.to_string();
            assert!(text.len() < 160, "{text}");
            assert!(text.contains("not a usable time budget"), "{text}");
        }
        assert!(deadline_after(Instant::now(), 1e19).is_err());
    }

    #[test]
    fn everyday_budgets_convert_exactly() {
        assert_eq!(budget_duration(1.5).unwrap(), Duration::from_millis(1500));
        assert_eq!(budget_duration(1e-3).unwrap(), Duration::from_millis(1));
        assert!(deadline_after(Instant::now(), MAX_BUDGET_SECONDS).is_ok());
    }
}
