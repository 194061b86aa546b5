//! Stop conditions: the question every loop in the framework asks before doing more work.
//!
//! This is OMPL's `PlannerTerminationCondition` reduced to its core: a cheap, side-effect-free
//! `should_stop()`. Samplers, edge checkers and planners poll it in every loop that could run long.
//! The planner's richer termination conditions (iterations, cost thresholds, combinations) are
//! built on top and handed down to the building blocks through this trait.

use std::time::{Duration, Instant};

/// Something that can tell a loop to give up.
///
/// Implementations must be cheap: they are polled in inner loops. The trait is object safe, so
/// building blocks take `&dyn Stop`.
pub trait Stop {
    /// `true` once the work should stop.
    fn should_stop(&self) -> bool;
}

/// Never stops. Use in tests and where a loop is already bounded.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Never;

impl Stop for Never {
    #[inline]
    fn should_stop(&self) -> bool {
        false
    }
}

/// Stops at a wall-clock instant.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Deadline {
    at: Instant,
}

impl Deadline {
    /// A deadline at the given instant.
    pub fn at(at: Instant) -> Self {
        Self { at }
    }

    /// A deadline `budget` from now.
    pub fn after(budget: Duration) -> Self {
        Self {
            at: Instant::now() + budget,
        }
    }

    /// The instant at which this deadline fires.
    pub fn instant(&self) -> Instant {
        self.at
    }
}

impl Stop for Deadline {
    #[inline]
    fn should_stop(&self) -> bool {
        Instant::now() >= self.at
    }
}

impl<F: Fn() -> bool> Stop for F {
    #[inline]
    fn should_stop(&self) -> bool {
        self()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn never_does_not_stop_and_past_deadline_does() {
        assert!(!Never.should_stop());
        assert!(Deadline::at(Instant::now()).should_stop());
        assert!(!Deadline::after(Duration::from_secs(3600)).should_stop());
    }

    #[test]
    fn closures_are_stop_conditions() {
        let flag = std::cell::Cell::new(false);
        let stop = || flag.get();
        assert!(!stop.should_stop());
        flag.set(true);
        let dynamic: &dyn Stop = &stop;
        assert!(dynamic.should_stop());
    }
}
