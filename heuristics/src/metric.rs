//! [`Euclidean`] and [`SpaceMetric`]: the exact straight-line lower bounds of path length.

use mit_star_spaces::{StateSpace, euclidean_distance};

use crate::Heuristic;

/// The Euclidean norm of the coordinate difference: the path-length lower bound in `R^n` (and
/// in joint spaces whose metric is the unweighted Euclidean one).
///
/// Admissible for any space whose metric is at least the coordinate Euclidean norm; for a
/// weighted or wrapping metric use [`SpaceMetric`].
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Euclidean;

impl<S: StateSpace + ?Sized> Heuristic<S> for Euclidean {
    #[inline]
    fn edge_cost(&self, _space: &S, a: &[f64], b: &[f64]) -> f64 {
        euclidean_distance(a, b)
    }

    /// The known distance itself where the space's metric is the Euclidean norm.
    #[inline]
    fn edge_cost_given_distance(&self, space: &S, a: &[f64], b: &[f64], distance: f64) -> f64 {
        if space.is_euclidean() {
            distance
        } else {
            euclidean_distance(a, b)
        }
    }
}

/// The space's own metric ([`StateSpace::distance`]): for path length, the cost of the straight
/// edge, hence the tightest admissible bound. In a [`JointSpace`](mit_star_spaces::JointSpace) this is the
/// joint-space metric — weighted, with continuous joints taking the short way round.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct SpaceMetric;

impl<S: StateSpace + ?Sized> Heuristic<S> for SpaceMetric {
    #[inline]
    fn edge_cost(&self, space: &S, a: &[f64], b: &[f64]) -> f64 {
        space.distance(a, b)
    }

    #[inline]
    fn edge_cost_given_distance(&self, _space: &S, _a: &[f64], _b: &[f64], distance: f64) -> f64 {
        distance
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use mit_star_spaces::{Joint, JointSpace, RealVectorSpace};

    #[test]
    fn euclidean_and_metric_agree_in_rn() {
        let space = RealVectorSpace::cube(3, -1.0, 1.0).unwrap();
        let (a, b) = ([0.0, 0.5, -0.5], [0.3, -0.1, 0.2]);
        let e = Euclidean.edge_cost(&space, &a, &b);
        assert!((e - SpaceMetric.edge_cost(&space, &a, &b)).abs() < 1e-15);
        let goals = vec![vec![1.0, 1.0, 1.0], b.to_vec()];
        assert!((Euclidean.cost_to_go(&space, &a, &goals) - e).abs() < 1e-15);
    }

    #[test]
    fn a_known_distance_is_reused_only_where_it_is_the_bound() {
        let plain = JointSpace::new(vec![
            Joint::revolute("a", -2.0, 2.0),
            Joint::prismatic("b", 0.0, 1.0),
        ])
        .unwrap();
        let weighted = JointSpace::new(vec![
            Joint::revolute("a", -2.0, 2.0).weight(3.0),
            Joint::prismatic("b", 0.0, 1.0),
        ])
        .unwrap();
        let (a, b) = ([-1.3, 0.1], [0.7, 0.9]);
        // Unit weights: the space's distance is the Euclidean bound, to the last bit.
        let d = plain.distance(&a, &b);
        assert_eq!(Euclidean.edge_cost_given_distance(&plain, &a, &b, d), d);
        assert_eq!(Euclidean.edge_cost(&plain, &a, &b).to_bits(), d.to_bits());
        // A weighted metric is longer than the Euclidean bound, which is measured instead.
        let d = weighted.distance(&a, &b);
        let bound = Euclidean.edge_cost_given_distance(&weighted, &a, &b, d);
        assert_eq!(bound, Euclidean.edge_cost(&weighted, &a, &b));
        assert!(bound < d);
        assert_eq!(
            SpaceMetric.edge_cost_given_distance(&weighted, &a, &b, d),
            d
        );
    }

    #[test]
    fn joint_metric_wraps_continuous_joints() {
        let space = JointSpace::new(vec![Joint::continuous("c")]).unwrap();
        let (a, b) = ([3.0], [-3.0]);
        let wrapped = SpaceMetric.edge_cost(&space, &a, &b);
        assert!(wrapped < Euclidean.edge_cost(&space, &a, &b));
        assert!((wrapped - (std::f64::consts::TAU - 6.0)).abs() < 1e-12);
    }

    #[test]
    fn effort_counts_interior_grid_points() {
        let space = RealVectorSpace::cube(1, 0.0, 1.0).unwrap();
        assert_eq!(SpaceMetric.effort(&space, &[0.0], &[1.0], 0.1), 9);
        assert_eq!(SpaceMetric.effort(&space, &[0.0], &[0.05], 0.1), 0);
    }
}
