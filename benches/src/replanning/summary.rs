//! [`ReplanningSummary`]: the trials of each planner in each scene summarised as the paper
//! reports them — success rate and median travelled cost — with intervals and the counts
//! behind them; written as CSV and printed as markdown.

use std::fmt::Write as _;
use std::path::Path;

use serde::Serialize;

use crate::error::HarnessError;
use crate::replanning::trial_record::{TrialEnd, TrialRecord};
use crate::statistics::{ClopperPearson, MedianEstimate};

/// One planner in one scene.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SummaryRow {
    /// The scene.
    pub scene: String,
    /// The planner.
    pub planner: String,
    /// Trials run.
    pub trials: usize,
    /// Trials that succeeded.
    pub successes: usize,
    /// The success rate with its Clopper–Pearson interval.
    pub success: ClopperPearson,
    /// The median travelled cost (failures count as `∞`) with its nonparametric interval;
    /// `None` for fewer trials than an interval needs.
    pub cost: Option<MedianEstimate>,
    /// Trials that ended in a collision.
    pub collisions: usize,
    /// Trials that ran out of time.
    pub timeouts: usize,
    /// Median plans per trial.
    pub plans: f64,
    /// Median failed plans per trial.
    pub failed_plans: f64,
    /// Median new paths adopted per trial.
    pub adopted: f64,
    /// Median stops per trial (path blocked, no new path).
    pub dropped: f64,
    /// Median simulated seconds of the successful trials (`∞` without one).
    pub time: f64,
}

/// The summary of every planner in every scene, in the order the trials came.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ReplanningSummary {
    /// The confidence of the intervals.
    pub confidence: f64,
    /// The rows.
    pub rows: Vec<SummaryRow>,
}

/// The median of `values` (the lower of the two middle ones), `∞` if empty.
fn median(mut values: Vec<f64>) -> f64 {
    if values.is_empty() {
        return f64::INFINITY;
    }
    values.sort_by(f64::total_cmp);
    values[crate::statistics::median_index(values.len())]
}

impl ReplanningSummary {
    /// The summary of `records`, grouped by scene and planner in order of first appearance.
    pub fn new(records: &[TrialRecord], confidence: f64) -> Self {
        let mut keys: Vec<(&str, &str)> = Vec::new();
        for r in records {
            let key = (r.scene.as_str(), r.planner.as_str());
            if !keys.contains(&key) {
                keys.push(key);
            }
        }
        let rows = keys
            .into_iter()
            .map(|(scene, planner)| {
                let group: Vec<&TrialRecord> = records
                    .iter()
                    .filter(|r| r.scene == scene && r.planner == planner)
                    .collect();
                let count =
                    |f: &dyn Fn(&TrialRecord) -> bool| group.iter().filter(|r| f(r)).count();
                let successes = count(&|r| r.succeeded());
                let per_trial = |f: &dyn Fn(&TrialRecord) -> usize| {
                    median(group.iter().map(|r| f(r) as f64).collect())
                };
                let costs: Vec<f64> = group.iter().map(|r| r.cost()).collect();
                SummaryRow {
                    scene: scene.to_owned(),
                    planner: planner.to_owned(),
                    trials: group.len(),
                    successes,
                    success: ClopperPearson::new(successes, group.len(), confidence),
                    cost: MedianEstimate::of(&costs, confidence),
                    collisions: count(&|r| matches!(r.end, TrialEnd::Collision { .. })),
                    timeouts: count(&|r| r.end == TrialEnd::Timeout),
                    plans: per_trial(&|r| r.plans),
                    failed_plans: per_trial(&|r| r.failed_plans),
                    adopted: per_trial(&|r| r.adopted),
                    dropped: per_trial(&|r| r.dropped),
                    time: median(
                        group
                            .iter()
                            .filter(|r| r.succeeded())
                            .map(|r| r.time)
                            .collect(),
                    ),
                }
            })
            .collect();
        Self { confidence, rows }
    }

    /// The table in markdown: one row per scene and planner.
    pub fn markdown(&self) -> String {
        let pct = |x: f64| format!("{:.1}", 100.0 * x);
        let number = |x: f64| {
            if x.is_finite() {
                format!("{x:.2}")
            } else {
                "∞".to_owned()
            }
        };
        let level = pct(self.confidence);
        let mut out = format!(
            "| scene | planner | success % [{level} % CI] | median cost [{level} % CI] | collisions | timeouts | plans | failed plans | paths adopted | stops | median time (s) |\n|---|---|---|---|---|---|---|---|---|---|---|\n"
        );
        for r in &self.rows {
            let cost = r.cost.map_or("–".to_owned(), |c| {
                format!(
                    "{} [{}, {}]",
                    number(c.median),
                    number(c.lower),
                    number(c.upper)
                )
            });
            let _ = writeln!(
                out,
                "| {} | {} | {}/{} = {} [{}, {}] | {} | {} | {} | {} | {} | {} | {} | {} |",
                r.scene,
                r.planner,
                r.successes,
                r.trials,
                pct(r.success.rate),
                pct(r.success.lower),
                pct(r.success.upper),
                cost,
                r.collisions,
                r.timeouts,
                r.plans,
                r.failed_plans,
                r.adopted,
                r.dropped,
                number(r.time),
            );
        }
        out
    }

    /// Writes the table as CSV to `path`.
    ///
    /// # Errors
    /// [`HarnessError::Io`] if the file cannot be written.
    pub fn write_csv(&self, path: &Path) -> Result<(), HarnessError> {
        let mut out = String::from(
            "scene,planner,trials,successes,success_rate,success_lower,success_upper,median_cost,cost_lower,cost_upper,collisions,timeouts,median_plans,median_failed_plans,median_adopted,median_stops,median_time\n",
        );
        for r in &self.rows {
            let (m, lo, hi) = r.cost.map_or((f64::NAN, f64::NAN, f64::NAN), |c| {
                (c.median, c.lower, c.upper)
            });
            let _ = writeln!(
                out,
                "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
                r.scene,
                r.planner,
                r.trials,
                r.successes,
                r.success.rate,
                r.success.lower,
                r.success.upper,
                m,
                lo,
                hi,
                r.collisions,
                r.timeouts,
                r.plans,
                r.failed_plans,
                r.adopted,
                r.dropped,
                r.time
            );
        }
        write_text(path, &out)
    }
}

/// Writes the trials one per line as CSV to `path`.
///
/// # Errors
/// [`HarnessError::Io`] if the file cannot be written.
pub fn write_trials_csv(records: &[TrialRecord], path: &Path) -> Result<(), HarnessError> {
    let mut out = String::from(
        "scene,planner,trial,seed,end,collision_time,time,legs_done,travelled,cost,plans,failed_plans,adopted,stops,unpadded_plans,held,wall_seconds\n",
    );
    for r in records {
        let _ = writeln!(
            out,
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
            r.scene,
            r.planner,
            r.trial,
            r.seed,
            r.end.label(),
            r.collision_time().map_or(String::new(), |t| t.to_string()),
            r.time,
            r.legs_done,
            r.travelled,
            r.cost(),
            r.plans,
            r.failed_plans,
            r.adopted,
            r.dropped,
            r.unpadded_plans,
            r.held,
            r.wall_seconds
        );
    }
    write_text(path, &out)
}

fn write_text(path: &Path, text: &str) -> Result<(), HarnessError> {
    std::fs::write(path, text).map_err(|source| HarnessError::Io {
        path: path.to_path_buf(),
        source,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn record(planner: &str, end: TrialEnd, travelled: f64, plans: usize) -> TrialRecord {
        TrialRecord {
            scene: "vertical".into(),
            planner: planner.into(),
            trial: 1,
            seed: 0,
            end,
            time: 9.0,
            legs_done: 5,
            travelled,
            plans,
            failed_plans: 0,
            adopted: 1,
            dropped: 1,
            unpadded_plans: 0,
            held: 1.0,
            wall_seconds: 1.0,
            trajectory: Vec::new(),
            plan_times: Vec::new(),
        }
    }

    #[test]
    fn rates_medians_and_counts() {
        let mut records: Vec<TrialRecord> = (0..9)
            .map(|i| record("MIT*", TrialEnd::Success, 10.0 + f64::from(i), 6))
            .collect();
        records.push(record("MIT*", TrialEnd::Collision { time: 2.0 }, 3.0, 4));
        records.push(record("EIT*", TrialEnd::Timeout, 1.0, 600));
        let summary = ReplanningSummary::new(&records, 0.95);
        assert_eq!(summary.rows.len(), 2);
        let mit = &summary.rows[0];
        assert_eq!(
            (mit.trials, mit.successes, mit.collisions, mit.timeouts),
            (10, 9, 1, 0)
        );
        assert!((mit.success.rate - 0.9).abs() < 1e-12 && mit.success.lower < 0.9);
        // Sorted costs 10..18, ∞: index 5 → 15.
        assert_eq!(mit.cost.unwrap().median, 15.0);
        assert_eq!(mit.plans, 6.0);
        let eit = &summary.rows[1];
        assert_eq!(
            (eit.successes, eit.timeouts, eit.time),
            (0, 1, f64::INFINITY)
        );
        let table = summary.markdown();
        assert!(
            table.contains("| vertical | MIT* | 9/10 = 90.0 ["),
            "{table}"
        );
        assert!(table.contains("| vertical | EIT* | 0/1 = 0.0 ["), "{table}");
        let folder = std::env::temp_dir().join(format!("replan-summary-{}", std::process::id()));
        std::fs::create_dir_all(&folder).unwrap();
        summary.write_csv(&folder.join("summary.csv")).unwrap();
        write_trials_csv(&records, &folder.join("trials.csv")).unwrap();
        let trials = std::fs::read_to_string(folder.join("trials.csv")).unwrap();
        assert_eq!(trials.lines().count(), 12);
        assert!(trials.contains(",collision,2,"), "{trials}");
        std::fs::remove_dir_all(&folder).unwrap();
    }
}
