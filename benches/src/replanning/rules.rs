//! [`ReplanningRules`]: the rules of a re-planning trial — planning budget, control window,
//! joint speeds, legs, time limit, contact resolution — and [`PlanningBudget`].

use crate::error::HarnessError;

/// The Panda's joint velocity limits in rad/s, as its shipped URDF gives them
/// (`robot/data/panda/panda_spherized.urdf`, VAMP's model: joints 1–4 2.3925, 5–7 2.8710).
pub const PANDA_VELOCITY_LIMITS: [f64; 7] = [2.3925, 2.3925, 2.3925, 2.3925, 2.871, 2.871, 2.871];

/// The most iterations one plan may be given (`replan --iterations`): 10⁶, hundreds of
/// times what a plan of one 0.1 s cycle runs.
pub const MAX_PLAN_ITERATIONS: u64 = 1_000_000;

/// How much a planner may compute for one plan.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PlanningBudget {
    /// Wall-clock seconds, building the problem and the planner included (the paper's rule:
    /// 0.1 s). Results then depend on the machine's speed.
    WallClock(f64),
    /// A number of planner iterations: deterministic on every machine, for tests and exact
    /// reproduction (the simulated clock still charges one [`ReplanningRules::cycle`]).
    Iterations(u64),
}

/// The rules of a re-planning trial (the user guide's reference page on arm planning,
/// "Re-planning among moving obstacles", states them in words). Times are seconds of the
/// simulated clock.
#[derive(Debug, Clone, PartialEq)]
pub struct ReplanningRules {
    /// Simulated seconds of one control cycle: the arm executes its path for one cycle while
    /// the next plan is made, so one plan takes one cycle of the simulated clock: 0.1.
    pub cycle: f64,
    /// What the planner may compute for one plan: 0.1 s of wall clock by default.
    pub budget: PlanningBudget,
    /// How far ahead, in seconds after the plan is taken up, planners see the moving
    /// obstacles' sweep: 1.0 (halved, down to one cycle, while the arm or the goal is inside
    /// it).
    pub look_ahead: f64,
    /// Joint velocity limits in rad/s, one per joint ([`PANDA_VELOCITY_LIMITS`]).
    pub velocity_limits: Vec<f64>,
    /// The fraction of the velocity limits the arm moves at (MoveIt's velocity scaling): 0.5.
    pub velocity_scaling: f64,
    /// Journeys between the start and the goal: 5 (start → goal, goal → start, …).
    pub legs: usize,
    /// Simulated seconds within which the legs must be done: 60.
    pub time_limit: f64,
    /// The shortest stretch of time the motion judge splits a motion into: a motion it
    /// cannot prove clear over a stretch this short counts as a collision (1e-4 s).
    pub contact_floor: f64,
}

impl Default for ReplanningRules {
    fn default() -> Self {
        Self {
            cycle: 0.1,
            budget: PlanningBudget::WallClock(0.1),
            look_ahead: 1.0,
            velocity_limits: PANDA_VELOCITY_LIMITS.to_vec(),
            velocity_scaling: 0.5,
            legs: 5,
            time_limit: 60.0,
            contact_floor: 1e-4,
        }
    }
}

impl ReplanningRules {
    /// The joint speeds the arm moves at: the limits times the scaling.
    pub fn joint_speeds(&self) -> Vec<f64> {
        self.velocity_limits
            .iter()
            .map(|v| v * self.velocity_scaling)
            .collect()
    }

    /// The rules if every value can be used with an arm of `dimension` joints.
    ///
    /// # Errors
    /// [`HarnessError::ReplanningRule`] naming the first value that cannot be used.
    pub fn checked(self, dimension: usize) -> Result<Self, HarnessError> {
        let fail = |field: &str, message: String| HarnessError::ReplanningRule {
            field: field.to_owned(),
            message,
        };
        let positive = |field: &str, value: f64| {
            if value.is_finite() && value > 0.0 {
                Ok(())
            } else {
                Err(fail(
                    field,
                    format!("is {value}; it must be a positive number"),
                ))
            }
        };
        positive("cycle", self.cycle)?;
        positive("look-ahead", self.look_ahead)?;
        positive("velocity scaling", self.velocity_scaling)?;
        positive("time limit", self.time_limit)?;
        positive("contact floor", self.contact_floor)?;
        match self.budget {
            PlanningBudget::WallClock(seconds) => crate::budget::budget_duration(seconds)
                .map(|_| ())
                .map_err(|e| fail("planning budget", e.to_string()))?,
            PlanningBudget::Iterations(0) => {
                return Err(fail("planning budget", "is 0 iterations".to_owned()));
            }
            PlanningBudget::Iterations(n) if n > MAX_PLAN_ITERATIONS => {
                return Err(fail(
                    "planning budget",
                    format!(
                        "is {n} iterations; at most {MAX_PLAN_ITERATIONS} per plan \
                         (`MAX_PLAN_ITERATIONS`: a plan of a cycle takes a few thousand)"
                    ),
                ));
            }
            PlanningBudget::Iterations(_) => {}
        }
        if self.velocity_scaling > 1.0 {
            return Err(fail(
                "velocity scaling",
                format!("is {}; it must be at most 1", self.velocity_scaling),
            ));
        }
        if self.velocity_limits.len() != dimension {
            return Err(fail(
                "velocity limits",
                format!(
                    "has {} values for an arm of {dimension} joints",
                    self.velocity_limits.len()
                ),
            ));
        }
        for &v in &self.velocity_limits {
            positive("velocity limits", v)?;
        }
        if self.legs == 0 {
            return Err(fail("legs", "is 0; at least one leg is needed".to_owned()));
        }
        if self.contact_floor >= self.cycle {
            return Err(fail(
                "contact floor",
                format!("{} must be shorter than the cycle", self.contact_floor),
            ));
        }
        Ok(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_defaults_are_usable_and_bad_values_are_named() {
        let rules = ReplanningRules::default().checked(7).unwrap();
        assert!((rules.joint_speeds()[0] - 1.19625).abs() < 1e-12);
        let e = ReplanningRules::default()
            .checked(6)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("velocity limits") && e.contains("6 joints"),
            "{e}"
        );
        let bad = ReplanningRules {
            cycle: -0.1,
            ..ReplanningRules::default()
        };
        assert!(bad.checked(7).unwrap_err().to_string().contains("cycle"));
        let bad = ReplanningRules {
            budget: PlanningBudget::WallClock(f64::NAN),
            ..ReplanningRules::default()
        };
        assert!(bad.checked(7).unwrap_err().to_string().contains("budget"));
        let bad = ReplanningRules {
            velocity_scaling: 1.5,
            ..ReplanningRules::default()
        };
        assert!(bad.checked(7).is_err());
    }
}
