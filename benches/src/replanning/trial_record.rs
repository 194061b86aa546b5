//! [`TrialRecord`]: what one re-planning trial did — how it ended, what the arm travelled, how
//! often it planned — and the configurations it passed through, for pictures.

use serde::Serialize;

/// How a trial ended.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum TrialEnd {
    /// Every leg was done without a contact within the time limit.
    Success,
    /// The arm touched an obstacle (or came closer than the judge can resolve) at `time`.
    Collision {
        /// Simulated seconds since the start.
        time: f64,
    },
    /// The time limit passed before the last leg was done.
    Timeout,
}

impl TrialEnd {
    /// `success`, `collision` or `timeout`.
    pub fn label(self) -> &'static str {
        match self {
            Self::Success => "success",
            Self::Collision { .. } => "collision",
            Self::Timeout => "timeout",
        }
    }
}

/// One re-planning trial of one planner in one scene.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TrialRecord {
    /// The scene's name.
    pub scene: String,
    /// The planner's name.
    pub planner: String,
    /// The trial's number, from 1.
    pub trial: usize,
    /// The seed of its first plan (plan `k` uses `seed + k`).
    pub seed: u64,
    /// How it ended.
    pub end: TrialEnd,
    /// Simulated seconds until it ended.
    pub time: f64,
    /// Legs done.
    pub legs_done: usize,
    /// Joint-space length the arm travelled (radians; what the planners' cost measures).
    pub travelled: f64,
    /// Plans asked for.
    pub plans: usize,
    /// Plans that returned no path.
    pub failed_plans: usize,
    /// New paths the arm switched to.
    pub adopted: usize,
    /// Times the arm stopped because its path was blocked and the plan found none.
    pub dropped: usize,
    /// Plans made against the obstacles where they will be when the plan is taken up, because
    /// the arm or the goal lay in their sweep.
    pub unpadded_plans: usize,
    /// Simulated seconds the arm held still for want of a path (the first cycle, while the
    /// first plan is made, included).
    pub held: f64,
    /// Wall-clock seconds the trial took.
    pub wall_seconds: f64,
    /// The configurations the arm passed through, with their simulated times (at every
    /// cycle's end and every path state).
    #[serde(skip)]
    pub trajectory: Vec<(f64, Vec<f64>)>,
    /// When each plan was asked for, and whether it returned a path.
    #[serde(skip)]
    pub plan_times: Vec<(f64, bool)>,
}

impl TrialRecord {
    /// `true` if the trial succeeded.
    pub fn succeeded(&self) -> bool {
        self.end == TrialEnd::Success
    }

    /// The travelled length, `∞` unless the trial succeeded (the paper's rule: unsuccessful
    /// runs have an infinite cost).
    pub fn cost(&self) -> f64 {
        if self.succeeded() {
            self.travelled
        } else {
            f64::INFINITY
        }
    }

    /// The time of the collision, if the trial ended in one.
    pub fn collision_time(&self) -> Option<f64> {
        match self.end {
            TrialEnd::Collision { time } => Some(time),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn failures_cost_infinity() {
        let mut record = TrialRecord {
            scene: "s".into(),
            planner: "p".into(),
            trial: 1,
            seed: 0,
            end: TrialEnd::Success,
            time: 3.0,
            legs_done: 5,
            travelled: 12.5,
            plans: 7,
            failed_plans: 0,
            adopted: 6,
            dropped: 2,
            unpadded_plans: 0,
            held: 0.7,
            wall_seconds: 0.7,
            trajectory: Vec::new(),
            plan_times: Vec::new(),
        };
        assert_eq!(record.cost(), 12.5);
        record.end = TrialEnd::Collision { time: 1.5 };
        assert_eq!(
            (record.cost(), record.collision_time()),
            (f64::INFINITY, Some(1.5))
        );
        assert_eq!(record.end.label(), "collision");
        assert_eq!(TrialEnd::Timeout.label(), "timeout");
        let json = serde_json::to_string(&record).unwrap();
        assert!(
            json.contains(r#""end":{"kind":"collision","time":1.5}"#),
            "{json}"
        );
    }
}
