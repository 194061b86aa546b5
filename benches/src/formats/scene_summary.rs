//! [`SceneSummary`]: what `bench` prints by default — one row per scene and planner, every
//! problem of the scene pooled.

use std::fmt::Write as _;

use serde::Serialize;

use crate::formats::kpi_table::{number, percentile};
use crate::outcome::experiment_results::ExperimentResults;
use crate::outcome::run_record::{RunRecord, RunStatus};
use crate::outcome::scene::Scene;
use crate::statistics::median_index;

/// One planner on one scene, over every run on every instance of the scene.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SceneRow {
    /// The scene's title (`box_panda R^7`, `dividing-walls R^4`).
    pub scene: String,
    /// The planner's name.
    pub planner: String,
    /// Instances of the scene with at least one run of the planner.
    pub instances: usize,
    /// Runs attempted (finished, whatever their outcome).
    pub runs: usize,
    /// Runs with a validated solution.
    pub solved: usize,
    /// Runs whose path failed the independent validation.
    pub invalid: usize,
    /// Median time to the first solution (failed runs count as `∞`).
    pub initial_time_median: f64,
    /// 95th percentile (nearest rank) of the time to the first solution (`∞` likewise).
    pub initial_time_p95: f64,
    /// Median final cost (failed runs count as `∞`).
    pub final_cost_median: f64,
    /// Median planning time of a run: construction and solving, the budget at most.
    pub planning_median: f64,
    /// Median time of the independent audit of a returned path (`None` if no path was
    /// audited); never counted in the planning time.
    pub audit_median: Option<f64>,
}

/// The default summary of an experiment: per [`Scene`] and planner, runs solved of attempted,
/// median and 95th-percentile time to the first solution, median final cost, and the median
/// planning and audit times of a run, apart.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SceneSummary {
    /// One row per scene and planner (scene-major, experiment order); planners without runs
    /// on a scene are left out.
    pub rows: Vec<SceneRow>,
    /// `true` if some row pools several instances (the first column is then a scene).
    pub pooled: bool,
}

impl SceneSummary {
    /// The summary of `results`.
    pub fn from_results(results: &ExperimentResults) -> Self {
        let scenes = Scene::of(&results.instances);
        let mut rows = Vec::new();
        for scene in &scenes {
            for spec in &results.experiment.planners {
                let per_instance: Vec<Vec<&RunRecord>> = scene
                    .instances
                    .iter()
                    .map(|&i| results.runs_of(i, spec.name()))
                    .collect();
                let runs: Vec<&RunRecord> = per_instance.iter().flatten().copied().collect();
                if runs.is_empty() {
                    continue;
                }
                rows.push(row(scene, spec.name(), &runs, &per_instance));
            }
        }
        let pooled = rows.iter().any(|r| r.instances > 1);
        Self { rows, pooled }
    }

    /// The table in Markdown, with a header naming the columns' units; the column of
    /// instances per scene only when some row pools several.
    pub fn markdown(&self) -> String {
        let (first, instances) = if self.pooled {
            ("scene", " problems |")
        } else {
            ("problem", "")
        };
        let mut s = format!(
            "| {first} | planner |{instances} solved | invalid | t_init median [s] | \
             t_init p95 [s] | c_final median | planning median [s] | audit median [s] |\n"
        );
        s.push_str(&"|---".repeat(if self.pooled { 10 } else { 9 }));
        s.push_str("|\n");
        for r in &self.rows {
            let instances = if self.pooled {
                format!(" {} |", r.instances)
            } else {
                String::new()
            };
            let _ = writeln!(
                s,
                "| {} | {} |{instances} {}/{} | {} | {} | {} | {} | {} | {} |",
                r.scene,
                r.planner,
                r.solved,
                r.runs,
                r.invalid,
                number(r.initial_time_median),
                number(r.initial_time_p95),
                number(r.final_cost_median),
                number(r.planning_median),
                r.audit_median.map_or_else(|| "–".to_owned(), number),
            );
        }
        s
    }
}

/// The row of `planner` on `scene` from its `runs` (grouped by instance in `per_instance`).
fn row(
    scene: &Scene,
    planner: &str,
    runs: &[&RunRecord],
    per_instance: &[Vec<&RunRecord>],
) -> SceneRow {
    let column = |f: &dyn Fn(&RunRecord) -> f64| runs.iter().map(|r| f(r)).collect::<Vec<f64>>();
    let audits: Vec<f64> = runs
        .iter()
        .filter_map(|r| r.validation.as_ref().map(|v| v.seconds))
        .collect();
    SceneRow {
        scene: scene.title.clone(),
        planner: planner.to_owned(),
        instances: per_instance.iter().filter(|r| !r.is_empty()).count(),
        runs: runs.len(),
        solved: runs.iter().filter(|r| r.is_success()).count(),
        invalid: runs
            .iter()
            .filter(|r| r.status == RunStatus::InvalidPath)
            .count(),
        initial_time_median: median(column(&RunRecord::initial_time_or_inf)),
        initial_time_p95: percentile(column(&RunRecord::initial_time_or_inf), 0.95),
        final_cost_median: median(column(&RunRecord::final_cost_or_inf)),
        planning_median: median(column(&|r| r.run_time)),
        audit_median: (!audits.is_empty()).then(|| median(audits)),
    }
}

/// The median as the KPI tables take it (the order statistic at [`median_index`]; NaN counts
/// as `∞`, no values give `∞`).
fn median(mut values: Vec<f64>) -> f64 {
    if values.is_empty() {
        return f64::INFINITY;
    }
    for v in &mut values {
        if v.is_nan() {
            *v = f64::INFINITY;
        }
    }
    values.sort_by(f64::total_cmp);
    values[median_index(values.len())]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::path_validation::{PathValidation, ValidationMethod};

    /// A run: instance, planner, first-solution time (`None`: unsolved), final cost, audit
    /// seconds (`None`: no path audited).
    type Run<'a> = (usize, &'a str, Option<f64>, f64, Option<f64>);

    /// Two layouts of random rectangles and one dividing-walls world, MIT* and EIT*, with
    /// `runs`.
    fn results(runs: &[Run<'_>]) -> ExperimentResults {
        let experiment = crate::Experiment::from_toml_str(
            "runs = 3\nplanners = ['mit-star', 'eit-star']\n[[problems]]\n\
             name = 'random-rectangles'\ndimensions = [2]\ntime = 1\ninstance_seeds = [1, 2]\n\
             [[problems]]\nname = 'dividing-walls'\ndimensions = [2]\ntime = 1\n",
            "scenes",
            None,
        )
        .unwrap();
        let instances = experiment.instances().unwrap();
        let mut by_instance = vec![Vec::new(); instances.len()];
        for &(instance, planner, time, cost, audit) in runs {
            let spec = experiment
                .planners
                .iter()
                .find(|p| p.name() == planner)
                .unwrap();
            let run = by_instance[instance].len();
            by_instance[instance].push(RunRecord {
                instance: instances[instance].id.clone(),
                planner: planner.to_owned(),
                configuration: spec.configuration(),
                run,
                seed: 0,
                budget: 1.0,
                status: if time.is_some() {
                    RunStatus::Solved
                } else {
                    RunStatus::Unsolved
                },
                setup_time: 0.0,
                run_time: 1.0 + run as f64,
                initial_time: time,
                initial_cost: time.map(|_| cost),
                final_cost: time.map(|_| cost),
                trace: Vec::new(),
                path: Vec::new(),
                joints: Vec::new(),
                wrapping: Vec::new(),
                validation: audit.map(|seconds| PathValidation {
                    valid: true,
                    method: ValidationMethod::ExactBoxes,
                    states_checked: 2,
                    segments_checked: 1,
                    length: cost,
                    failure: None,
                    seconds,
                }),
                counters: mit_star::Counters::default(),
                error: None,
            });
        }
        ExperimentResults {
            experiment,
            instances,
            runs: by_instance,
            started_at: String::new(),
            total_time: 1.0,
            concurrency: 1,
            interrupted: false,
            machine: crate::MachineInfo::detect(),
        }
    }

    #[test]
    fn rows_pool_the_instances_of_a_scene() {
        let summary = SceneSummary::from_results(&results(&[
            (0, "MIT*", Some(0.1), 3.0, Some(0.01)),
            (0, "MIT*", None, 0.0, None),
            (1, "MIT*", Some(0.3), 2.0, Some(0.03)),
            (1, "MIT*", Some(0.2), 4.0, Some(0.02)),
            (0, "EIT*", Some(0.5), 5.0, Some(0.05)),
            (2, "MIT*", Some(0.7), 1.5, Some(0.07)),
        ]));
        assert!(summary.pooled);
        let scenes: Vec<(&str, &str)> = summary
            .rows
            .iter()
            .map(|r| (r.scene.as_str(), r.planner.as_str()))
            .collect();
        // EIT* never ran on dividing walls: no row.
        assert_eq!(
            scenes,
            [
                ("random-rectangles R^2", "MIT*"),
                ("random-rectangles R^2", "EIT*"),
                ("dividing-walls R^2", "MIT*"),
            ]
        );
        let mit = &summary.rows[0];
        assert_eq!(
            (mit.instances, mit.runs, mit.solved, mit.invalid),
            (2, 4, 3, 0)
        );
        // t_init sorted 0.1, 0.2, 0.3, ∞: median index 2, p95 the largest.
        assert_eq!(mit.initial_time_median, 0.3);
        assert_eq!(mit.initial_time_p95, f64::INFINITY);
        // Costs 2, 3, 4, ∞.
        assert_eq!(mit.final_cost_median, 4.0);
        // Run times 1, 2 on each layout: 1, 1, 2, 2.
        assert_eq!(mit.planning_median, 2.0);
        // The unsolved run has no audit: 0.01, 0.02, 0.03.
        assert_eq!(mit.audit_median, Some(0.02));
        let eit = &summary.rows[1];
        assert_eq!((eit.instances, eit.runs, eit.solved), (1, 1, 1));
        let table = summary.markdown();
        assert!(
            table.starts_with("| scene | planner | problems | solved |"),
            "{table}"
        );
        assert!(
            table.contains("| random-rectangles R^2 | MIT* | 2 | 3/4 | 0 | 0.3000 | ∞ | 4.0000 | 2.0000 | 0.0200 |"),
            "{table}"
        );
        assert!(
            table.contains("| dividing-walls R^2 | MIT* | 1 | 1/1 |"),
            "{table}"
        );
        assert_eq!(table.lines().count(), 2 + 3);
    }

    #[test]
    fn a_box_world_alone_is_a_problem_and_unaudited_runs_print_a_dash() {
        let summary = SceneSummary::from_results(&results(&[(2, "EIT*", None, 0.0, None)]));
        assert!(!summary.pooled);
        assert_eq!(summary.rows.len(), 1);
        assert_eq!(summary.rows[0].audit_median, None);
        let table = summary.markdown();
        assert!(
            table.starts_with("| problem | planner | solved |"),
            "{table}"
        );
        assert!(
            table.contains("| dividing-walls R^2 | EIT* | 0/1 | 0 | ∞ | ∞ | ∞ | 1.0000 | – |"),
            "{table}"
        );
    }
}
