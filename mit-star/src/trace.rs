//! [`Trace`]: the anytime record of solution improvements.

use serde::{Deserialize, Serialize};

/// One improvement of the best solution.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct TracePoint {
    /// Planning time in seconds when the solution was found (summed over `solve` calls).
    pub time: f64,
    /// Its cost.
    pub cost: f64,
}

/// Every `(time, cost)` at which a planner's best solution improved, oldest first. Costs
/// strictly decrease along the trace.
///
/// ```
/// use mit_star::Trace;
/// let trace = Trace::default();
/// assert!(trace.initial().is_none() && trace.is_empty());
/// ```
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Trace {
    points: Vec<TracePoint>,
}

impl Trace {
    /// Records an improvement.
    pub(crate) fn push(&mut self, time: f64, cost: f64) {
        self.points.push(TracePoint { time, cost });
    }

    /// Forgets every point.
    pub(crate) fn clear(&mut self) {
        self.points.clear();
    }

    /// The points, oldest first.
    pub fn points(&self) -> &[TracePoint] {
        &self.points
    }

    /// The first solution (time to it and its cost).
    pub fn initial(&self) -> Option<TracePoint> {
        self.points.first().copied()
    }

    /// The latest (best) solution.
    pub fn last(&self) -> Option<TracePoint> {
        self.points.last().copied()
    }

    /// Number of improvements.
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// `true` if no solution was found.
    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// The best cost known at `time` seconds (∞ before the first solution): the piecewise
    /// constant interpolation benchmark plots use.
    pub fn cost_at(&self, time: f64) -> f64 {
        self.points
            .iter()
            .take_while(|p| p.time <= time)
            .last()
            .map_or(f64::INFINITY, |p| p.cost)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cost_at_is_piecewise_constant() {
        let mut t = Trace::default();
        t.push(0.1, 3.0);
        t.push(0.5, 2.0);
        assert_eq!(t.cost_at(0.05), f64::INFINITY);
        assert_eq!(t.cost_at(0.1), 3.0);
        assert_eq!(t.cost_at(0.7), 2.0);
        assert_eq!(t.initial().map(|p| p.cost), Some(3.0));
        assert_eq!(t.last().map(|p| p.time), Some(0.5));
        assert_eq!(t.len(), 2);
        t.clear();
        assert!(t.is_empty());
    }
}
