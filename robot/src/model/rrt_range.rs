//! The RRT extension range a robot's problems default to: measured for the shipped robots
//! ([`ShippedRobot::range`](crate::ShippedRobot::range)), a rule on the joints' spans for any
//! other ([`RobotModel::range_rule`]).

use mit_star_spaces::{JointKind, JointSpace, StateSpace};

use crate::RobotModel;

impl RobotModel {
    /// The extension range RRT-Connect, AORRTC and Informed RRT* step by on this robot's
    /// problems unless `range` is set: the value set by
    /// [`with_rrt_range`](Self::with_rrt_range) (a shipped robot's, measured), else
    /// [`range_rule`](Self::range_rule) on its joint space.
    pub fn rrt_range(&self) -> f64 {
        self.rrt_range
            .unwrap_or_else(|| Self::range_rule(self.joint_space()))
    }

    /// The same model stepping by `range` ([`rrt_range`](Self::rrt_range)); a value that is
    /// not finite and positive leaves the rule in place.
    #[must_use]
    pub fn with_rrt_range(mut self, range: f64) -> Self {
        self.rrt_range = (range.is_finite() && range > 0.0).then_some(range);
        self
    }

    /// The range of a robot nobody measured: a sixth of the median span of its turning
    /// joints, each span at most one turn (`2π`; a continuous joint's is `2π`), prismatic
    /// joints left out; 0.2 of the joint space's diagonal (OMPL's rule) for a robot of
    /// prismatic joints only. It gives 0.99 rad for the Panda, 1.05 for the UR5, 0.75 for the
    /// Fetch and 0.61 for the Baxter, within a factor of two of the ranges measured for them
    /// (1.0, 1.0, 1.25 and 0.5), where OMPL's rule takes 2.6 rad and more (6.2 rad for a
    /// 6-joint arm of `±2π` joints, for which the rule gives 1.05; `docs/guide/src/your-own-robot.md`,
    /// "RRT's range").
    pub fn range_rule(space: &JointSpace) -> f64 {
        let turn = std::f64::consts::TAU;
        let mut spans: Vec<f64> = space
            .joints()
            .iter()
            .filter_map(|j| match j.kind {
                JointKind::Revolute { lower, upper } => Some((upper - lower).min(turn)),
                JointKind::Continuous => Some(turn),
                JointKind::Prismatic { .. } => None,
            })
            .collect();
        if spans.is_empty() {
            return 0.2 * space.maximum_extent();
        }
        spans.sort_by(f64::total_cmp);
        let n = spans.len();
        let median = if n % 2 == 1 {
            spans[n / 2]
        } else {
            0.5 * (spans[n / 2 - 1] + spans[n / 2])
        };
        median / 6.0
    }
}

#[cfg(test)]
mod tests {
    use mit_star_spaces::Joint;

    use super::*;

    #[test]
    fn the_rule_takes_a_sixth_of_the_median_turning_span_capped_at_a_turn() {
        let arm = |lower: f64, upper: f64| {
            JointSpace::new(
                (0..6)
                    .map(|i| Joint::revolute(format!("j{i}"), lower, upper))
                    .collect(),
            )
            .unwrap()
        };
        let pi = std::f64::consts::PI;
        assert!((RobotModel::range_rule(&arm(-pi, pi)) - pi / 3.0).abs() < 1e-12);
        // ±2π joints: one turn counts, not two (OMPL's rule gives 6.2 rad here).
        let wide = arm(-2.0 * pi, 2.0 * pi);
        assert!((RobotModel::range_rule(&wide) - pi / 3.0).abs() < 1e-12);
        assert!(0.2 * wide.maximum_extent() > 6.0);
        let slides = JointSpace::new(vec![Joint::prismatic("x", 0.0, 1.0)]).unwrap();
        assert!((RobotModel::range_rule(&slides) - 0.2).abs() < 1e-12);
        let mixed = JointSpace::new(vec![
            Joint::prismatic("torso", 0.0, 0.4),
            Joint::revolute("a", -1.0, 1.0),
            Joint::continuous("b"),
        ])
        .unwrap();
        let expected = 0.5 * (2.0 + std::f64::consts::TAU) / 6.0;
        assert!((RobotModel::range_rule(&mixed) - expected).abs() < 1e-12);
    }
}
