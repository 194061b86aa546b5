//! [`KpiTable`]: the key performance indicators per problem instance and planner, like the
//! paper's Table I.

use std::fmt::Write as _;

use mit_star::Configuration;
use serde::Serialize;

use crate::outcome::experiment_results::ExperimentResults;
use crate::statistics::{ClopperPearson, MedianEstimate};

/// The KPIs of one planner on one problem instance.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct KpiRow {
    /// The instance's title (`dividing-walls R^4`).
    pub instance: String,
    /// The planner's name.
    pub planner: String,
    /// The planner's configuration.
    pub configuration: Configuration,
    /// Finished runs.
    pub runs: usize,
    /// Runs with a validated solution.
    pub successes: usize,
    /// Runs whose path failed validation.
    pub invalid: usize,
    /// Time to the first solution (`∞` for failed runs).
    pub initial_time: MedianEstimate,
    /// The 95th percentile (nearest rank) of the time to the first solution (`∞` for failed
    /// runs).
    pub initial_time_p95: f64,
    /// Cost of the first solution.
    pub initial_cost: MedianEstimate,
    /// Final cost.
    pub final_cost: MedianEstimate,
    /// Success rate at the budget, with its Clopper–Pearson interval.
    pub success: ClopperPearson,
}

/// `1 − t_MIT / t_EIT`: the paper's "t_init gain" of MIT* over EIT* (median initial-solution
/// times). `None` unless both are finite and `t_EIT > 0`.
///
/// ```
/// let gain = mit_star_benches::t_init_gain(0.0053, 0.0068).unwrap();
/// assert!((gain - 0.2206).abs() < 1e-4); // the paper's FG R^4: 22.05 % (rounded times)
/// assert_eq!(mit_star_benches::t_init_gain(f64::INFINITY, 0.1), None);
/// ```
pub fn t_init_gain(t_mit: f64, t_eit: f64) -> Option<f64> {
    (t_mit.is_finite() && t_eit.is_finite() && t_eit > 0.0).then(|| 1.0 - t_mit / t_eit)
}

/// The KPI table of an experiment: for every problem instance and planner, `t_init`,
/// `c_init` and `c_final` (min / median with its confidence interval / max; failed runs
/// count as `∞`) and the success rate; plus the "t_init gain" of MIT* over EIT* per instance
/// when both configurations are present. Several layouts of a problem in one dimension (the
/// paper's 10 random-rectangles instances) are also pooled into one row, as Table I reports
/// them; the paper layout shows the pooled row, the full table every row.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct KpiTable {
    /// Confidence of the intervals.
    pub confidence: f64,
    /// Planner names, in experiment order.
    pub planners: Vec<String>,
    /// The rows of the paper-layout table, in experiment order: instance titles, and for
    /// problems with several layouts in one dimension (random rectangles) one pooled title
    /// (`random-rectangles R^4 (10 layouts)`) whose rows pool the runs of every layout.
    pub instances: Vec<String>,
    /// One row per instance and planner (instance-major), followed, for problems with several
    /// layouts, by the pooled rows.
    pub rows: Vec<KpiRow>,
    /// The titles of the pooled rows (problems with several layouts), in experiment order.
    pub families: Vec<String>,
}

impl KpiTable {
    /// The table of `results` (planners without finished runs on an instance are left out).
    pub fn from_results(results: &ExperimentResults) -> Self {
        let confidence = results.experiment.confidence;
        // Instances of one problem in one dimension (several layouts of a seeded family)
        // form a group; the paper reports such a group as one row.
        let mut groups: Vec<(String, usize, Vec<usize>)> = Vec::new();
        for (index, instance) in results.instances.iter().enumerate() {
            let key = (instance.label.clone(), instance.dimension);
            match groups.iter_mut().find(|(l, d, _)| (l.clone(), *d) == key) {
                Some(group) => group.2.push(index),
                None => groups.push((key.0, key.1, vec![index])),
            }
        }
        let mut rows = Vec::new();
        let mut instances = Vec::new();
        let mut families = Vec::new();
        for (label, dimension, members) in &groups {
            for &index in members {
                let title = results.instances[index].title();
                for spec in &results.experiment.planners {
                    let runs = results.runs_of(index, spec.name());
                    rows.extend(row(&title, spec, &runs, confidence));
                }
            }
            if members.len() == 1 {
                instances.push(results.instances[members[0]].title());
                continue;
            }
            let title = format!("{label} R^{dimension} ({} layouts)", members.len());
            for spec in &results.experiment.planners {
                let runs: Vec<&crate::RunRecord> = members
                    .iter()
                    .flat_map(|&i| results.runs_of(i, spec.name()))
                    .collect();
                rows.extend(row(&title, spec, &runs, confidence));
            }
            families.push(title.clone());
            instances.push(title);
        }
        Self {
            confidence,
            planners: results
                .experiment
                .planners
                .iter()
                .map(|p| p.name().to_owned())
                .collect(),
            instances,
            rows,
            families,
        }
    }

    /// The row of `planner` on `instance`.
    pub fn row(&self, instance: &str, planner: &str) -> Option<&KpiRow> {
        self.rows
            .iter()
            .find(|r| r.instance == instance && r.planner == planner)
    }

    /// The "t_init gain" of MIT* over EIT* on `instance` (the first planner of each
    /// configuration), if both ran and both medians are finite.
    pub fn gain(&self, instance: &str) -> Option<f64> {
        let median = |c: Configuration| {
            self.rows
                .iter()
                .find(|r| r.instance == instance && r.configuration == c)
                .map(|r| r.initial_time.median)
        };
        t_init_gain(
            median(Configuration::MitStar)?,
            median(Configuration::EitStar)?,
        )
    }

    /// `true` if the gain column applies (MIT* and EIT* both present).
    pub(crate) fn has_gain(&self) -> bool {
        let has = |c| self.rows.iter().any(|r| r.configuration == c);
        has(Configuration::MitStar) && has(Configuration::EitStar)
    }

    /// The paper's layout: one row per instance; median `t_init`, `c_init`, `c_final` per
    /// planner; the t_init gain.
    pub fn paper_markdown(&self) -> String {
        let mut s = String::from("| problem |");
        for p in &self.planners {
            let _ = write!(s, " {p} t_init | {p} c_init | {p} c_final |");
        }
        if self.has_gain() {
            s.push_str(" t_init gain |");
        }
        s.push('\n');
        let columns = 1 + 3 * self.planners.len() + usize::from(self.has_gain());
        s.push_str(&"|---".repeat(columns));
        s.push_str("|\n");
        for instance in &self.instances {
            let _ = write!(s, "| {instance} |");
            for p in &self.planners {
                match self.row(instance, p) {
                    Some(r) => {
                        let _ = write!(
                            s,
                            " {} | {} | {} |",
                            number(r.initial_time.median),
                            number(r.initial_cost.median),
                            number(r.final_cost.median)
                        );
                    }
                    None => s.push_str(" – | – | – |"),
                }
            }
            if self.has_gain() {
                match self.gain(instance) {
                    Some(g) => {
                        let _ = write!(s, " {:.2} % |", 100.0 * g);
                    }
                    None => s.push_str(" – |"),
                }
            }
            s.push('\n');
        }
        s
    }

    /// One row per problem with several layouts (a MotionBenchMaker scene, random rectangles)
    /// and planner, pooling its layouts: runs, validated solutions (rate), invalid paths,
    /// median and 95th-percentile `t_init`, median `c_init` and `c_final` (of every run;
    /// failures count as ∞). `None` without such problems.
    pub fn families_markdown(&self) -> Option<String> {
        if self.families.is_empty() {
            return None;
        }
        let mut s = String::from(
            "| problem | planner | runs | solved | invalid paths | t_init median | t_init p95 | \
             c_init median | c_final median |\n",
        );
        s.push_str(&"|---".repeat(9));
        s.push_str("|\n");
        for family in &self.families {
            for r in self.rows.iter().filter(|r| &r.instance == family) {
                let _ = writeln!(
                    s,
                    "| {} | {} | {} | {} ({:.1} %) | {} | {} | {} | {} | {} |",
                    r.instance,
                    r.planner,
                    r.runs,
                    r.successes,
                    100.0 * r.success.rate,
                    r.invalid,
                    number(r.initial_time.median),
                    number(r.initial_time_p95),
                    number(r.initial_cost.median),
                    number(r.final_cost.median),
                );
            }
        }
        Some(s)
    }

    /// Every KPI: min, median `[confidence interval]` and max of `t_init`, `c_init` and
    /// `c_final`, and the success rate, per instance and planner.
    pub fn full_markdown(&self) -> String {
        let mut s = String::from(
            "| problem | planner | success | t_init min | t_init median | t_init max | \
             c_init min | c_init median | c_init max | c_final min | c_final median | c_final max |\n",
        );
        s.push_str(&"|---".repeat(12));
        s.push_str("|\n");
        for r in &self.rows {
            let mut success = format!(
                "{}/{} ({:.0} %)",
                r.successes,
                r.runs,
                100.0 * r.success.rate
            );
            if r.invalid > 0 {
                let _ = write!(success, " **{} INVALID**", r.invalid);
            }
            let _ = writeln!(
                s,
                "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
                r.instance,
                r.planner,
                success,
                number(r.initial_time.min),
                with_interval(&r.initial_time),
                number(r.initial_time.max),
                number(r.initial_cost.min),
                with_interval(&r.initial_cost),
                number(r.initial_cost.max),
                number(r.final_cost.min),
                with_interval(&r.final_cost),
                number(r.final_cost.max),
            );
        }
        s
    }
}

/// The KPIs of `runs` of planner `spec`, titled `title`; `None` without runs.
fn row(
    title: &str,
    spec: &crate::PlannerSpec,
    runs: &[&crate::RunRecord],
    confidence: f64,
) -> Option<KpiRow> {
    let estimate = |f: &dyn Fn(&crate::RunRecord) -> f64| {
        let values: Vec<f64> = runs.iter().map(|r| f(r)).collect();
        MedianEstimate::of(&values, confidence)
    };
    let successes = runs.iter().filter(|r| r.is_success()).count();
    Some(KpiRow {
        instance: title.to_owned(),
        planner: spec.name().to_owned(),
        configuration: spec.configuration(),
        runs: runs.len(),
        successes,
        invalid: runs
            .iter()
            .filter(|r| r.status == crate::RunStatus::InvalidPath)
            .count(),
        initial_time: estimate(&|r| r.initial_time_or_inf())?,
        initial_time_p95: percentile(runs.iter().map(|r| r.initial_time_or_inf()).collect(), 0.95),
        initial_cost: estimate(&|r| r.initial_cost_or_inf())?,
        final_cost: estimate(&|r| r.final_cost_or_inf())?,
        success: ClopperPearson::new(successes, runs.len(), confidence),
    })
}

/// The `q`-quantile of `values` by nearest rank (`∞` for no values; NaN counts as ∞).
pub(crate) fn percentile(mut values: Vec<f64>, q: f64) -> f64 {
    if values.is_empty() {
        return f64::INFINITY;
    }
    for v in &mut values {
        if v.is_nan() {
            *v = f64::INFINITY;
        }
    }
    values.sort_by(f64::total_cmp);
    let rank = (q * values.len() as f64).ceil() as usize;
    values[rank.clamp(1, values.len()) - 1]
}

/// A number as the paper prints them: four decimals (scientific below 0.001), `∞` if not
/// finite.
pub(crate) fn number(v: f64) -> String {
    if !v.is_finite() {
        "∞".to_owned()
    } else if v == 0.0 || v.abs() >= 1e-3 {
        format!("{v:.4}")
    } else {
        format!("{v:.2e}")
    }
}

/// `median [lower, upper]`.
fn with_interval(m: &MedianEstimate) -> String {
    format!(
        "{} [{}, {}]",
        number(m.median),
        number(m.lower),
        number(m.upper)
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::outcome::experiment_results::ExperimentResults;

    #[test]
    fn numbers_print_like_the_paper() {
        assert_eq!(number(0.0068), "0.0068");
        assert_eq!(number(1.764), "1.7640");
        assert_eq!(number(0.000_25), "2.50e-4");
        assert_eq!(number(f64::INFINITY), "∞");
        assert_eq!(number(0.0), "0.0000");
    }

    fn synthetic(times: &[(usize, &str, f64)]) -> ExperimentResults {
        let experiment = crate::Experiment::from_toml_str(
            "runs = 2\nplanners = ['mit-star', 'eit-star']\n[[problems]]\nname = 'random-rectangles'\n\
             dimensions = [2]\ntime = 1\ninstance_seeds = [1, 2]\n",
            "synthetic",
            None,
        )
        .unwrap();
        let instances = experiment.instances().unwrap();
        let mut runs = vec![Vec::new(), Vec::new()];
        for &(instance, planner, time) in times {
            let spec = experiment
                .planners
                .iter()
                .find(|p| p.name() == planner)
                .unwrap();
            let run = runs[instance].len();
            runs[instance].push(crate::RunRecord {
                instance: instances[instance].id.clone(),
                planner: planner.to_owned(),
                configuration: spec.configuration(),
                run,
                seed: 0,
                budget: 1.0,
                status: crate::RunStatus::Solved,
                setup_time: 0.0,
                run_time: 1.0,
                initial_time: Some(time),
                initial_cost: Some(2.0),
                final_cost: Some(1.0),
                trace: Vec::new(),
                path: Vec::new(),
                joints: Vec::new(),
                wrapping: Vec::new(),
                validation: None,
                counters: mit_star::Counters::default(),
                error: None,
            });
        }
        ExperimentResults {
            experiment,
            instances,
            runs,
            started_at: String::new(),
            total_time: 1.0,
            concurrency: 1,
            interrupted: false,
            machine: crate::MachineInfo::detect(),
        }
    }

    #[test]
    fn layouts_are_pooled_into_one_paper_row() {
        let results = synthetic(&[
            (0, "MIT*", 0.1),
            (0, "MIT*", 0.2),
            (1, "MIT*", 0.3),
            (1, "MIT*", 0.4),
            (0, "EIT*", 0.4),
            (0, "EIT*", 0.5),
            (1, "EIT*", 0.6),
            (1, "EIT*", 0.8),
        ]);
        let table = KpiTable::from_results(&results);
        assert_eq!(table.instances, ["random-rectangles R^2 (2 layouts)"]);
        assert_eq!(table.rows.len(), 6);
        let pooled = table
            .row("random-rectangles R^2 (2 layouts)", "MIT*")
            .unwrap();
        assert_eq!(pooled.runs, 4);
        // Sorted 0.1, 0.2, 0.3, 0.4: index ⌈1.5⌉ = 2.
        assert_eq!(pooled.initial_time.median, 0.3);
        let gain = table.gain("random-rectangles R^2 (2 layouts)").unwrap();
        assert!((gain - 0.5).abs() < 1e-12, "{gain}"); // 1 − 0.3 / 0.6
        assert!(table.row("random-rectangles R^2 #2", "EIT*").is_some());
        let paper = table.paper_markdown();
        assert!(
            paper.contains("| random-rectangles R^2 (2 layouts) | 0.3000 |"),
            "{paper}"
        );
        assert!(paper.contains("| 50.00 % |"), "{paper}");
        assert!(!paper.contains("#1"));
        // The families table: 4 runs, p95 by nearest rank is the largest of four.
        assert_eq!(pooled.initial_time_p95, 0.4);
        let families = table.families_markdown().unwrap();
        assert!(
            families.contains(
                "| random-rectangles R^2 (2 layouts) | MIT* | 4 | 4 (100.0 %) | 0 | 0.3000 | 0.4000 |"
            ),
            "{families}"
        );
        assert!(
            table
                .full_markdown()
                .contains("| random-rectangles R^2 #1 | MIT* | 2/2 (100 %) |")
        );
    }

    #[test]
    fn percentiles_by_nearest_rank() {
        let v: Vec<f64> = (1..=100).map(f64::from).collect();
        assert_eq!(percentile(v.clone(), 0.95), 95.0);
        assert_eq!(percentile(v, 0.5), 50.0);
        assert_eq!(percentile(vec![3.0, f64::NAN, 1.0], 0.95), f64::INFINITY);
        assert_eq!(percentile(vec![2.0], 0.95), 2.0);
        assert_eq!(percentile(Vec::new(), 0.95), f64::INFINITY);
    }

    #[test]
    fn gains() {
        assert_eq!(t_init_gain(0.05, 0.1), Some(0.5));
        assert_eq!(t_init_gain(0.1, 0.0), None);
        assert_eq!(t_init_gain(0.1, f64::INFINITY), None);
        // Slower MIT* gives a negative gain.
        assert!(t_init_gain(0.2, 0.1).unwrap() < 0.0);
    }
}
