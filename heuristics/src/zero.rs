//! [`Zero`]: the trivially admissible heuristic.

use mit_star_spaces::StateSpace;

use crate::Heuristic;

/// Estimates every cost and every effort as zero: trivially admissible, and turns a heuristic
/// search into Dijkstra's algorithm. The baseline for measuring what a heuristic buys.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Zero;

impl<S: StateSpace + ?Sized> Heuristic<S> for Zero {
    #[inline]
    fn edge_cost(&self, _space: &S, _a: &[f64], _b: &[f64]) -> f64 {
        0.0
    }
    #[inline]
    fn cost_to_go(&self, _space: &S, _x: &[f64], goals: &[Vec<f64>]) -> f64 {
        if goals.is_empty() { f64::INFINITY } else { 0.0 }
    }
    #[inline]
    fn effort(&self, _space: &S, _a: &[f64], _b: &[f64], _step: f64) -> u64 {
        0
    }
}
