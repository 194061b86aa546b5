//! [`AnytimeSeries`]: median cost and success rate over time, from anytime traces.

use mit_star::TracePoint;
use serde::Serialize;

use crate::statistics::{ClopperPearson, MedianEstimate};

/// `points` times spread evenly on a logarithmic scale over `[first, last]` (both included).
/// `first` is raised to a positive value if needed; one point gives `[last]`.
///
/// ```
/// let t = mit_star_benches::statistics::log_time_grid(0.001, 1.0, 4);
/// assert_eq!(t.len(), 4);
/// assert!((t[1] - 0.01).abs() < 1e-12 && (t[3] - 1.0).abs() < 1e-12);
/// ```
pub fn log_time_grid(first: f64, last: f64, points: usize) -> Vec<f64> {
    if points == 0 {
        return Vec::new();
    }
    if points == 1 {
        return vec![last];
    }
    let first = if first > 0.0 { first } else { last * 1e-3 }.min(last);
    let (a, b) = (first.ln(), last.ln());
    (0..points)
        .map(|i| {
            if i + 1 == points {
                last
            } else {
                (a + (b - a) * i as f64 / (points - 1) as f64).exp()
            }
        })
        .collect()
}

/// The best cost known at `time` along a trace (time ascending, cost decreasing): the cost of
/// the last improvement at or before `time`, `+∞` before the first solution. This is the
/// piecewise-constant interpolation PDT uses for cost-over-time plots.
///
/// ```
/// use mit_star::TracePoint;
/// use mit_star_benches::statistics::cost_at;
/// let trace = [TracePoint { time: 0.1, cost: 2.0 }, TracePoint { time: 0.3, cost: 1.5 }];
/// assert_eq!(cost_at(&trace, 0.05), f64::INFINITY);
/// assert_eq!(cost_at(&trace, 0.1), 2.0);
/// assert_eq!(cost_at(&trace, 0.29), 2.0);
/// assert_eq!(cost_at(&trace, 9.0), 1.5);
/// ```
pub fn cost_at(trace: &[TracePoint], time: f64) -> f64 {
    let known = trace.partition_point(|p| p.time <= time);
    if known == 0 {
        f64::INFINITY
    } else {
        trace[known - 1].cost
    }
}

/// Statistics of one planner's runs at fixed times: the median best cost with its
/// nonparametric confidence interval, and the success rate (fraction of runs with a solution)
/// with its Clopper–Pearson interval.
///
/// Each run contributes its trace; a failed run (no solution, or a solution that failed
/// validation) contributes an empty trace, i.e. `+∞` at every time.
///
/// ```
/// use mit_star::TracePoint;
/// use mit_star_benches::statistics::AnytimeSeries;
/// let a = [TracePoint { time: 0.1, cost: 2.0 }];
/// let b = [TracePoint { time: 0.2, cost: 1.0 }];
/// let series = AnytimeSeries::new(&[&a, &b, &[]], &[0.15, 0.3], 0.99);
/// assert_eq!(series.median_cost[0].median, f64::INFINITY); // sorted 2, ∞, ∞
/// assert_eq!(series.median_cost[1].median, 2.0);           // sorted 1, 2, ∞
/// assert!((series.success[1].rate - 2.0 / 3.0).abs() < 1e-12);
/// ```
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AnytimeSeries {
    /// The times, in seconds since the start of each run.
    pub times: Vec<f64>,
    /// Median best cost and its confidence interval at each time.
    pub median_cost: Vec<MedianEstimate>,
    /// Success rate and its Clopper–Pearson interval at each time.
    pub success: Vec<ClopperPearson>,
}

impl AnytimeSeries {
    /// The series of `traces` (one per run) at `times`, with intervals at `confidence`.
    /// With no runs the series is empty.
    pub fn new(traces: &[&[TracePoint]], times: &[f64], confidence: f64) -> Self {
        let mut median_cost = Vec::with_capacity(times.len());
        let mut success = Vec::with_capacity(times.len());
        let mut costs = Vec::with_capacity(traces.len());
        for &t in times {
            costs.clear();
            costs.extend(traces.iter().map(|trace| cost_at(trace, t)));
            costs.sort_by(f64::total_cmp);
            let Some(estimate) = MedianEstimate::of_sorted(&costs, confidence) else {
                return Self {
                    times: Vec::new(),
                    median_cost: Vec::new(),
                    success: Vec::new(),
                };
            };
            median_cost.push(estimate);
            let solved = costs.iter().filter(|c| c.is_finite()).count();
            success.push(ClopperPearson::new(solved, costs.len(), confidence));
        }
        Self {
            times: times.to_vec(),
            median_cost,
            success,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn trace(points: &[(f64, f64)]) -> Vec<TracePoint> {
        points
            .iter()
            .map(|&(time, cost)| TracePoint { time, cost })
            .collect()
    }

    #[test]
    fn interpolation_is_piecewise_constant_and_right_continuous() {
        let t = trace(&[(0.1, 3.0), (0.2, 2.0), (0.4, 1.0)]);
        assert_eq!(cost_at(&t, 0.0), f64::INFINITY);
        assert_eq!(cost_at(&t, 0.099_999), f64::INFINITY);
        assert_eq!(cost_at(&t, 0.2), 2.0);
        assert_eq!(cost_at(&t, 0.399), 2.0);
        assert_eq!(cost_at(&t, 0.4), 1.0);
        assert_eq!(cost_at(&[], 1.0), f64::INFINITY);
    }

    #[test]
    fn medians_and_success_follow_the_runs() {
        let runs: Vec<Vec<TracePoint>> = (1..=9)
            .map(|i| trace(&[(0.1 * f64::from(i), 10.0 - f64::from(i))]))
            .collect();
        let refs: Vec<&[TracePoint]> = runs.iter().map(Vec::as_slice).collect();
        let times = [0.05, 0.45, 0.5, 1.0];
        let s = AnytimeSeries::new(&refs, &times, 0.95);
        // At 0.05 nobody solved; at 0.45 four of nine (median ∞); at 0.5 five, costs 9..5
        // (median index 4 of [5, 6, 7, 8, 9, ∞, …] = 9); at 1.0 all nine (median 5).
        assert_eq!(s.success[0].rate, 0.0);
        assert_eq!(s.median_cost[1].median, f64::INFINITY);
        assert_eq!(s.median_cost[2].median, 9.0);
        assert_eq!(s.median_cost[3].median, 5.0);
        assert_eq!(s.success[3].rate, 1.0);
        // Success never decreases and the median never increases over time.
        for w in s.success.windows(2) {
            assert!(w[1].rate >= w[0].rate);
        }
        for w in s.median_cost.windows(2) {
            assert!(w[1].median <= w[0].median);
        }
    }

    #[test]
    fn grids() {
        assert!(log_time_grid(0.1, 1.0, 0).is_empty());
        assert_eq!(log_time_grid(0.1, 1.0, 1), vec![1.0]);
        let g = log_time_grid(0.0, 2.0, 3);
        assert!((g[0] - 0.002).abs() < 1e-15 && g[2] == 2.0);
        assert!(g.windows(2).all(|w| w[1] > w[0]));
        let empty = AnytimeSeries::new(&[], &g, 0.99);
        assert!(empty.times.is_empty() && empty.success.is_empty());
    }
}
